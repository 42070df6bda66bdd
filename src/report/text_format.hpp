// Text helpers shared by the report writers.
#pragma once

#include <iomanip>
#include <cmath>
#include <sstream>
#include <string>

namespace railmodal::report {

/// A CSV field, quoted when it holds a comma, quote or newline (RFC 4180).
inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

/// `value` with `digits` significant digits.
inline std::string significant(double value, int digits) {
  std::ostringstream s;
  s << std::setprecision(digits) << value;
  return s.str();
}

/// `value` with `decimals` digits after the point; round-off never prints as "-0.0".
inline std::string fixed(double value, int decimals) {
  std::ostringstream s;
  const double half_unit = 0.5 * std::pow(10.0, -decimals);
  s << std::fixed << std::setprecision(decimals) << (std::abs(value) < half_unit ? 0.0 : value);
  return s.str();
}

}  // namespace railmodal::report
