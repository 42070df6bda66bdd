// The shortest text that reads back as the same double, where a file or a key must round-trip
// exactly (study values, shard limits, CSV for programs). A foundation: any stage may include it.
// −0 is written "0", as every number writer writes it (report/number_text.hpp): equal in value,
// and a sign on a zero means nothing to a reader of a file or a message.
#pragma once

#include <charconv>
#include <string>

namespace railmodal {

/// shortest_text(x) appended to `text`, without a string of its own.
inline void append_shortest_text(std::string* text, double x) {
  if (x == 0.0) x = 0.0;  // −0 → 0
  char buffer[32];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, x);
  text->append(buffer, written.ptr);
}

/// std::to_chars without a precision: shortest round-trip form ("0.03", "1e-30", "inf", "nan").
inline std::string shortest_text(double x) {
  std::string text;
  append_shortest_text(&text, x);
  return text;
}

/// At most `digits` significant digits, as printf's %g, for numbers in messages: "1e-11" and
/// "1.23e-08" where std::to_string's %f prints "0.000000".
inline std::string shortest_text(double x, int digits) {
  if (x == 0.0) x = 0.0;  // −0 → 0
  char buffer[48];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, digits);
  return std::string(buffer, written.ptr);
}

}  // namespace railmodal
