// Character classes of the C locale, for the readers' plain scans that stand in for
// std::regex's \s and \d (which made those files slow to compile): no locale is consulted.
#pragma once

namespace railmodal::input {

/// \s in the C locale: ' ', '\t', '\n', '\v', '\f', '\r'.
inline bool is_c_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/// \d: an ASCII digit.
inline bool is_ascii_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace railmodal::input
