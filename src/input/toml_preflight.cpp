#include "input/toml_preflight.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string_view>

#include "input/utf8.hpp"
#include "railmodal/errors.hpp"

namespace railmodal::input {
namespace {

class Scanner {
 public:
  Scanner(const std::string& content, const std::string& file) : s_(content), file_(file) {}

  [[noreturn]] void fail(size_t at, const std::string& why) const {
    const size_t newline = at == 0 ? std::string::npos : s_.rfind('\n', at - 1);
    const size_t line_begin = newline == std::string::npos ? 0 : newline + 1;
    const auto line = 1 + std::count(s_.begin(), s_.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    throw InputError(file_, static_cast<int>(line), static_cast<int>(at - line_begin) + 1, why);
  }

  void run() {
    int depth = 0;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '#') {
        skip_to_line_end();
      } else if (c == '"' || c == '\'') {
        skip_string(c);
      } else if (c == '[' || c == '{') {
        if (++depth > kMaxTomlNesting)
          fail(i_, "arrays and inline tables nested more than " + std::to_string(kMaxTomlNesting) + " deep");
        ++i_;
      } else if (c == ']' || c == '}') {
        depth = std::max(depth - 1, 0);
        ++i_;
      } else if (is_word_char(c)) {
        check_word();
      } else {
        ++i_;
      }
    }
  }

 private:
  static bool is_word_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '+' || c == '.' || c == ':';
  }

  void skip_to_line_end() {
    while (i_ < s_.size() && s_[i_] != '\n') ++i_;
  }

  // Past a basic ("), literal ('), or multi-line (""" ''') string. The closing delimiter of a
  // multi-line string may be preceded by up to two more quotes (TOML 1.0): the run of quotes
  // that closes it is taken whole, up to five. A single-line string ends at its line's end
  // at the latest, where toml11 reports it unterminated.
  void skip_string(char quote) {
    const bool escapes = quote == '"';
    if (s_.compare(i_, 3, std::string(3, quote)) == 0) {
      i_ += 3;
      while (i_ < s_.size()) {
        if (escapes && s_[i_] == '\\') {
          i_ += 2;
        } else if (s_.compare(i_, 3, std::string(3, quote)) == 0) {
          size_t run = 3;
          while (run < 5 && i_ + run < s_.size() && s_[i_ + run] == quote) ++run;
          i_ += run;
          return;
        } else {
          ++i_;
        }
      }
      return;
    }
    ++i_;
    while (i_ < s_.size() && s_[i_] != '\n') {
      if (escapes && s_[i_] == '\\') {
        i_ += 2;
        continue;
      }
      if (s_[i_++] == quote) return;
    }
  }

  // A bare word: a key, a number, a boolean, a date. Only integers are checked.
  void check_word() {
    const size_t begin = i_;
    while (i_ < s_.size() && is_word_char(s_[i_])) ++i_;
    std::string_view word(s_.data() + begin, i_ - begin);
    const bool negative = !word.empty() && word[0] == '-';
    if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.remove_prefix(1);
    const uint64_t largest = negative ? uint64_t(1) << 63 : uint64_t(INT64_MAX);
    int radix = 10;
    if (word.size() > 2 && word[0] == '0' && (word[1] == 'x' || word[1] == 'o' || word[1] == 'b')) {
      radix = word[1] == 'x' ? 16 : word[1] == 'o' ? 8 : 2;
      word.remove_prefix(2);
    }
    // Binary literals: toml11 doubles its place value once per digit, leading zeros included.
    size_t digits = 0;
    uint64_t value = 0;
    bool too_large = false;
    for (const char c : word) {
      if (c == '_') continue;
      int d = -1;
      if (std::isdigit(static_cast<unsigned char>(c))) d = c - '0';
      else if (radix == 16 && std::isxdigit(static_cast<unsigned char>(c))) d = std::tolower(c) - 'a' + 10;
      if (d < 0 || d >= radix) return;  // not an integer literal
      ++digits;
      if (value > (largest - static_cast<uint64_t>(d)) / static_cast<uint64_t>(radix)) too_large = true;
      else value = value * static_cast<uint64_t>(radix) + static_cast<uint64_t>(d);
    }
    if (digits == 0) return;
    if (too_large || (radix == 2 && digits > 62))
      fail(begin, "the integer " + std::string(s_.substr(begin, std::min<size_t>(i_ - begin, 40))) +
                      (i_ - begin > 40 ? "..." : "") + " does not fit in 64 bits");
  }

  const std::string& s_;
  const std::string& file_;
  size_t i_ = 0;
};

}  // namespace

void check_toml_preflight(const std::string& content, const std::string& file) {
  Scanner scanner(content, file);
  if (const size_t bad = invalid_utf8_at(content); bad != std::string::npos)
    scanner.fail(bad, "byte " + byte_name(static_cast<unsigned char>(content[bad])) +
                          " is not UTF-8 text (a TOML file must be UTF-8)");
  scanner.run();
}

}  // namespace railmodal::input
