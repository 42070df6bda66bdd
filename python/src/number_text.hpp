// Numbers in the module's messages and reprs as the library's messages write them
// (src/shortest_text.hpp, private to the library): a value the caller gave in the shortest text
// that reads back as the same double ("9.5", not std::to_string's "9.500000"), a computed one to
// six significant digits.
#pragma once

#include <charconv>
#include <string>

namespace railmodal::python {

/// The shortest round-trip text of `x` ("0.03", "1e-30", "inf", "nan").
inline std::string number_text(double x) {
  char buffer[32];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, written.ptr);
}

/// At most `digits` significant digits, as printf's %g ("1.0586", "1.23e-08").
inline std::string number_text(double x, int digits) {
  char buffer[48];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, digits);
  return std::string(buffer, written.ptr);
}

}  // namespace railmodal::python
