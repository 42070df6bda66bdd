// What Debian's toml11 (3.7.1) must never be handed. Each check stands for a bug fixed upstream
// only after that release, and each turns a crash or a silently wrong value into an InputError
// naming the file, line and column:
//   - bytes that are not UTF-8 (TOML requires it; toml11 reads past its buffer reporting them
//     inside a literal string, upstream e3639d2);
//   - control characters (TOML allows none but tab and newline; toml11 reports a NUL in a
//     comment as "1:1 invalid key");
//   - tables, arrays and inline tables nested deeper than 64, counting each part of a dotted
//     key or a table header as a table (toml11 recurses once per level, parsing and copying
//     values, and overflows the stack at a few thousand; upstream 8e214ec limits arrays and
//     inline tables to 64);
//   - lines longer than 8192 bytes: toml11 3.7.1 scans a value's whole line once per value
//     (region::comments() from parse_value_helper, and an error message it formats and drops
//     for every "basic" string in parse_basic_string), so the time grows with the square of a
//     line's length: 30 000 strings on one line took 32 s. At 8192 bytes the slowest line
//     (2728 empty strings) takes about 0.05 s, about twice its time split over many lines;
//   - integer literals outside 64 bits (toml11 overflows a signed integer reading a long binary
//     literal, and clamps long decimal, octal and hexadecimal ones to the largest integer);
//   - a table header through a key that holds an array value (`a = []`, then `[a.b]`: toml11
//     takes the last element of the empty array, upstream 8e95891).
#pragma once

#include <cstddef>
#include <string>

namespace railmodal::input {

inline constexpr int kMaxTomlNesting = 64;
inline constexpr size_t kMaxTomlLineLength = 8192;
// toml11 keeps up to about 160 bytes per byte of a file of small values (a value and its
// source region per "1,") and parses 0.15 MB/s of the densest ones (8 MiB took 1.3 GB and 48 s
// as integers, 0.9 GB and 61 s as empty strings): 4 MiB is at most about 0.7 GB and 30 s. A
// study of 10^4 explicit variants takes about 1 MB.
inline constexpr size_t kMaxTomlFileSize = size_t(4) << 20;
inline constexpr const char* kTomlFileSizeReason =
    "a TOML input (parsing takes up to about 160 bytes of memory per byte of file)";

// Throws InputError(file, line, column, why) at the first such place in `content`.
void check_toml_preflight(const std::string& content, const std::string& file);

}  // namespace railmodal::input
