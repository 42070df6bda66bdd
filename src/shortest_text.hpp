// The shortest text that reads back as the same double, where a file or a key must round-trip
// exactly (study values, shard limits, CSV for programs). A foundation: any stage may include it.
#pragma once

#include <charconv>
#include <string>

namespace railmodal {

/// std::to_chars without a precision: shortest round-trip form ("0.03", "1e-30", "inf", "nan").
inline std::string shortest_text(double x) {
  char buffer[32];
  const auto written = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, written.ptr);
}

}  // namespace railmodal
