// railmodal — the two kinds of failure a caller must tell apart.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     try {
//       auto vehicle = railmodal::load_vehicle("tests/cli/bad/wrong_unit.toml");
//     } catch (const railmodal::InputError& e) {
//       std::cerr << e.what() << "\n";  // wrong_unit.toml:9:13: error: key 'body.cg_height': ...
//       return 0;                        // the file is wrong: tell the user
//     } catch (const railmodal::NumericalError& e) {
//       std::cerr << e.what() << "\n";  // the model cannot be solved as given
//     }
//     return 1;
//   }
#pragma once

#include <stdexcept>
#include <string>

namespace railmodal {

/// Where an input file writes a key: line and column, 1-based (0 when not known).
struct KeyPlace {
  int line = 0;
  int column = 0;
};

/// Bad input: names the file, line, column and key. what() is
/// "file:line:col: error: message" (line and column omitted when unknown).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, int column, std::string message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string message_;
};

/// A numerical failure: a mass matrix that is not positive definite after condensation,
/// a massless degree of freedom that nothing restrains, a static equilibrium that does not
/// exist. The message names the degree of freedom.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace railmodal
