#include "input/toml_preflight.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <set>
#include <string_view>
#include <vector>

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

  // The first place, and what is wrong there, of: a byte that is not UTF-8, a byte TOML 1.0
  // allows nowhere (control characters other than tab and the newline CR LF or LF), or a line
  // longer than kMaxTomlLineLength. npos when there is none.
  size_t text_problem(std::string* why) const {
    const size_t end = std::min(invalid_utf8_at(s_), s_.size());
    size_t line_begin = 0;
    for (size_t k = 0; k < end; ++k) {
      const auto b = static_cast<unsigned char>(s_[k]);
      if (b == '\n') {
        line_begin = k + 1;
        continue;
      }
      const bool newline = b == '\r' && k + 1 < s_.size() && s_[k + 1] == '\n';
      if (k - line_begin == kMaxTomlLineLength && !newline) {
        *why = "the line is longer than " + std::to_string(kMaxTomlLineLength) +
               " bytes (toml11 scans the whole line once per value on it; an array may span lines)";
        return k;
      }
      if ((b < 0x20 && b != '\t' && !newline) || b == 0x7f) {
        *why = control_name(b) +
               " is not allowed in TOML, not even in a comment or string (write it as an escape "
               "in a \"basic\" string)";
        return k;
      }
    }
    if (end < s_.size())
      *why =
          "byte " + byte_name(static_cast<unsigned char>(s_[end])) + " is not UTF-8 text (a TOML file must be UTF-8)";
    return end < s_.size() ? end : std::string::npos;
  }

  // The structure before `end`; what follows is not looked at.
  void run(size_t end) {
    bool statement_start = true;  // at the start of a line outside any array or inline table
    while (i_ < end) {
      const char c = s_[i_];
      if (statement_start && (c == ' ' || c == '\t' || c == '\r')) {
        ++i_;
        continue;
      }
      if (statement_start && c != '\n' && c != '#') {
        statement_start = false;
        if (statement()) continue;
      }
      if (expecting_key_ && c != ' ' && c != '\t' && c != '}') {
        inline_key();
        continue;
      }
      if (c == '\n') {
        statement_start = open_.empty();
        ++i_;
      } else if (c == '#') {
        skip_to_line_end();
      } else if (c == '"' || c == '\'') {
        skip_string(c);
      } else if (c == '[' || c == '{') {
        open(c);
      } else if (c == ']' || c == '}') {
        close();
      } else if (c == ',') {
        expecting_key_ = !open_.empty() && open_.back().inline_table;
        ++i_;
      } else if (is_word_char(c)) {
        check_word();
      } else {
        ++i_;
      }
    }
  }

 private:
  using KeyPath = std::vector<std::string>;

  // An array or inline table being read, and the dotted key inside it whose value is being read
  // (`{a.b.c = 1}` nests c two tables below the inline table).
  struct Open {
    bool inline_table;
    int key_depth;  // the parts of the current key after the first
  };

  // The depth a value opened here would have: the table header's parts, the line's key parts
  // after the first, and every open array or inline table with its key. toml11 recurses once per
  // level of all of these alike (dotted keys and headers make nested tables).
  void open(char c) {
    ++depth_;
    if (depth_ > kMaxTomlNesting) fail(i_, nesting_message());
    open_.push_back({c == '{', 0});
    expecting_key_ = c == '{';
    ++i_;
  }

  void close() {
    if (!open_.empty()) {
      depth_ -= 1 + open_.back().key_depth;
      open_.pop_back();
    }
    expecting_key_ = false;
    ++i_;
  }

  // The key of an inline table's key = value pair, its parts counted into the depth.
  void inline_key() {
    expecting_key_ = false;
    Open& table = open_.back();
    size_t j = i_;
    KeyPath key;
    if (!key_path(j, key, depth_ - table.key_depth)) return;
    depth_ += static_cast<int>(key.size()) - 1 - table.key_depth;
    table.key_depth = static_cast<int>(key.size()) - 1;
    i_ = j;
  }

  static std::string nesting_message() {
    return "tables, arrays and inline tables nested more than " + std::to_string(kMaxTomlNesting) +
           " deep (each part of a dotted key or table header is a table)";
  }

  // A table header, or the key of a key = value line. A header whose path runs through a key
  // that holds an array value (`a = []`, then `[a.b]`) is refused: it is not TOML, and toml11
  // 3.7.1 takes the last element of that array as the table to extend, which for an empty
  // array is undefined behaviour (upstream 8e95891). Returns false, having consumed nothing,
  // where the line is neither (toml11 then reports it).
  bool statement() {
    size_t j = i_;
    depth_ = table_depth_;
    if (s_[j] == '[') {
      const bool array_of_tables = j + 1 < s_.size() && s_[j + 1] == '[';
      j += array_of_tables ? 2 : 1;
      KeyPath path;
      if (!key_path(j, path, 1)) return false;
      if (s_.compare(j, array_of_tables ? 2 : 1, array_of_tables ? "]]" : "]") != 0) return false;
      KeyPath prefix;
      for (const std::string& part : path) {
        prefix.push_back(part);
        if (array_values_.count(prefix))
          fail(i_, std::string("the table ") + (array_of_tables ? "[[" : "[") + join(path) + (array_of_tables ? "]]" : "]") +
                       " extends '" + join(prefix) + "', which is an array value (a key = [...] line), not a table");
      }
      table_ = path;
      depth_ = table_depth_ = static_cast<int>(path.size());
      i_ = j + (array_of_tables ? 2 : 1);
      return true;
    }
    KeyPath key;
    if (!key_path(j, key, table_depth_)) return false;
    depth_ = table_depth_ + static_cast<int>(key.size()) - 1;
    if (j >= s_.size() || s_[j] != '=') return false;
    ++j;
    while (j < s_.size() && (s_[j] == ' ' || s_[j] == '\t')) ++j;
    if (j < s_.size() && s_[j] == '[') {
      KeyPath full = table_;
      full.insert(full.end(), key.begin(), key.end());
      array_values_.insert(full);
    }
    i_ = j;  // the value is scanned as any other text
    return true;
  }

  // A dotted key (bare, "basic" or 'literal' parts; whitespace around the dots) from j, and
  // the whitespace after it. Quoted parts are kept as written (escapes not decoded). Its first
  // part names a key of a table at `first_depth`; each further part nests a table one deeper,
  // and a part deeper than kMaxTomlNesting is refused where it starts.
  bool key_path(size_t& j, KeyPath& out, int first_depth) const {
    auto blank = [&] {
      while (j < s_.size() && (s_[j] == ' ' || s_[j] == '\t')) ++j;
    };
    for (;;) {
      blank();
      if (j >= s_.size()) return false;
      const char q = s_[j];
      size_t begin = j, end = j;
      if (q == '"' || q == '\'') {
        ++j;
        begin = j;
        while (j < s_.size() && s_[j] != q && s_[j] != '\n') j += (q == '"' && s_[j] == '\\') ? 2 : 1;
        if (j >= s_.size() || s_[j] != q) return false;
        end = j++;
      } else {
        while (j < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[j])) || s_[j] == '_' || s_[j] == '-')) ++j;
        end = j;
        if (end == begin) return false;
      }
      if (first_depth + static_cast<int>(out.size()) > kMaxTomlNesting)
        fail(q == '"' || q == '\'' ? begin - 1 : begin, nesting_message());
      out.emplace_back(s_, begin, end - begin);
      blank();
      if (j < s_.size() && s_[j] == '.') {
        ++j;
        continue;
      }
      return true;
    }
  }

  static std::string join(const KeyPath& path) {
    std::string out;
    for (const std::string& part : path) out += (out.empty() ? "" : ".") + part;
    return out;
  }

  static std::string control_name(unsigned char b) {
    if (b == 0) return "a NUL byte (0x00)";
    if (b == '\r') return "a carriage return (0x0d) not followed by a line feed";
    return "the control character " + byte_name(b);
  }

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
      // Past its digits a decimal word is something else (a float, a date, a key); toml11 reads
      // the digits of 0x, 0o and 0b as an integer whatever follows them.
      if (d < 0 || d >= radix) {
        if (radix == 10) return;
        break;
      }
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
  KeyPath table_;                   // the current table's path
  int table_depth_ = 0;             // its parts
  int depth_ = 0;                   // see open()
  std::vector<Open> open_;          // arrays and inline tables not yet closed
  bool expecting_key_ = false;      // after '{' or an inline table's ','

  std::set<KeyPath> array_values_;  // keys given an array value, with their table's path
};

}  // namespace

void check_toml_preflight(const std::string& content, const std::string& file) {
  Scanner scanner(content, file);
  // Reported in file order: a deep key on a long line is reported as deep.
  std::string why;
  const size_t bad = scanner.text_problem(&why);
  scanner.run(std::min(bad, content.size()));
  if (bad != std::string::npos) scanner.fail(bad, why);
}

}  // namespace railmodal::input
