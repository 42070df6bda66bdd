// The errors of a command's run and their exit codes (docs/product.md): one place for every
// subcommand, so that the same failure reads and exits alike whichever command meets it.
#include <iostream>

#include "commands.hpp"
#include "railmodal/errors.hpp"

namespace railmodal::cli {

int usage_error(const std::string& command, const std::string& message) {
  std::cerr << "railmodal: error: " << message << "\nRun 'railmodal " << command << " --help' for usage.\n";
  return kUsage;
}

int exit_of_error(const std::string& command, const std::string& blamed) {
  try {
    throw;
  } catch (const UsageError& e) {
    return usage_error(command, e.what());
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return kInput;
  } catch (const NumericalError& e) {
    std::cerr << blamed << ": error: numerical failure: " << e.what() << "\n";
    return kNumerical;
  }
}

}  // namespace railmodal::cli
