// What Debian's toml11 (3.7.1) must never be handed. Each check stands for a bug fixed upstream
// only after that release, and each turns a crash or a silently wrong value into an InputError
// naming the file, line and column:
//   - bytes that are not UTF-8 (TOML requires it; toml11 reads past its buffer reporting them
//     inside a literal string, upstream e3639d2);
//   - arrays and inline tables nested deeper than 64 (toml11 recurses once per level and
//     overflows the stack at a few thousand; upstream 8e214ec limits it to 64);
//   - integer literals outside 64 bits (toml11 overflows a signed integer reading a long binary
//     literal, and clamps long decimal, octal and hexadecimal ones to the largest integer);
//   - a table header through a key that holds an array value (`a = []`, then `[a.b]`: toml11
//     takes the last element of the empty array, upstream 8e95891).
#pragma once

#include <string>

namespace railmodal::input {

inline constexpr int kMaxTomlNesting = 64;

// Throws InputError(file, line, column, why) at the first such place in `content`.
void check_toml_preflight(const std::string& content, const std::string& file);

}  // namespace railmodal::input
