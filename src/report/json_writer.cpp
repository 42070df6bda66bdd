#include "report/json_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "report/number_text.hpp"

namespace railmodal::report {

namespace {

// The length of the valid UTF-8 sequence starting at text[i], or 0 if it is not one
// (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
size_t utf8_length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  size_t n;
  unsigned char low = 0x80, high = 0xbf;  // the second byte's range
  if (b < 0x80) return 1;
  if (b >= 0xc2 && b <= 0xdf) n = 2;
  else if (b >= 0xe0 && b <= 0xef) n = 3, low = b == 0xe0 ? 0xa0 : 0x80, high = b == 0xed ? 0x9f : 0xbf;
  else if (b >= 0xf0 && b <= 0xf4) n = 4, low = b == 0xf0 ? 0x90 : 0x80, high = b == 0xf4 ? 0x8f : 0xbf;
  else return 0;
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  return n;
}

// A character a JSON string holds as it is and nlohmann::json wrote as it is: printable ASCII
// but the quote and the backslash.
bool is_plain(char ch) {
  const unsigned char c = static_cast<unsigned char>(ch);
  return c >= 0x20 && c < 0x80 && c != '"' && c != '\\';
}

}  // namespace

void append_json_string(std::string& out, std::string_view text) {
  static const char kHex[] = "0123456789abcdef";
  out += '"';
  for (size_t i = 0; i < text.size();) {
    // A run of printable ASCII other than the quote and the backslash (a key, most names) is
    // appended as it is, in one go rather than a character at a time.
    size_t plain = i;
    while (plain < text.size() && is_plain(text[plain])) ++plain;
    if (plain > i) {
      out.append(text.data() + i, plain - i);
      i = plain;
      continue;
    }
    const unsigned char c = static_cast<unsigned char>(text[i]);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          out += "\\u00";
          out += kHex[c >> 4];
          out += kHex[c & 0xf];
        } else if (c < 0x80) {
          out += static_cast<char>(c);
        } else if (const size_t n = utf8_length(text, i); n > 0) {
          out.append(text.substr(i, n));
          i += n;
          continue;
        } else {
          out += "\xef\xbf\xbd";  // U+FFFD REPLACEMENT CHARACTER
        }
    }
    ++i;
  }
  out += '"';
}

std::vector<size_t> member_order(const std::vector<std::string>& names) {
  std::vector<size_t> order(names.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return names[a] < names[b]; });
  std::vector<size_t> unique;
  for (size_t k = 0; k < order.size(); ++k)
    if (k + 1 == order.size() || names[order[k + 1]] != names[order[k]]) unique.push_back(order[k]);
  return unique;
}

void JsonWriter::flush() {
  if (!out_) return;
  out_->write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void JsonWriter::new_line() {
  if (indent_ < 0) return;
  buffer_ += '\n';
  buffer_.append(static_cast<size_t>(indent_) * (depth_ + open_.size()), ' ');
}

void JsonWriter::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (open_.empty()) return;
  if (open_.back().second) buffer_ += ',';
  open_.back().second = true;
  new_line();
}

JsonWriter& JsonWriter::key(std::string_view name) {
  flush_if_full();
  const bool comma = open_.back().second;
  open_.back().second = true;
  // A plain name (every key we write, and the line it starts, is short) in one append rather
  // than a character at a time: a study's JSON writes a hundred keys a variant.
  const size_t spaces = indent_ < 0 ? 0 : static_cast<size_t>(indent_) * (depth_ + open_.size());
  char line[128];
  if (spaces + name.size() + 6 <= sizeof line && std::all_of(name.begin(), name.end(), is_plain)) {
    char* p = line;
    if (comma) *p++ = ',';
    if (indent_ >= 0) *p++ = '\n', p = std::fill_n(p, spaces, ' ');
    *p++ = '"';
    p = std::copy(name.begin(), name.end(), p);
    *p++ = '"', *p++ = ':';
    if (indent_ >= 0) *p++ = ' ';
    buffer_.append(line, p);
    after_key_ = true;
    return *this;
  }
  if (comma) buffer_ += ',';
  new_line();
  append_json_string(buffer_, name);
  buffer_ += indent_ < 0 ? ":" : ": ";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::open(char bracket) {
  before_value();
  buffer_ += bracket;
  open_.push_back({bracket, false});
  return *this;
}

JsonWriter& JsonWriter::close(char bracket) {
  const bool any = open_.back().second;
  open_.pop_back();
  if (any) new_line();
  buffer_ += bracket;
  if (open_.empty()) {
    if (indent_ >= 0 && depth_ == 0) buffer_ += '\n';
    flush();
  }
  return *this;
}

JsonWriter& JsonWriter::literal(std::string_view text) {
  flush_if_full();
  before_value();
  buffer_.append(text);
  return *this;
}

JsonWriter& JsonWriter::value(double x) {
  if (!std::isfinite(x)) return literal("null");
  char text[kNumberTextMax];
  return literal(std::string_view(text, write_number(text, x, NumberStyle::json) - text));
}

JsonWriter& JsonWriter::value(bool b) { return literal(b ? "true" : "false"); }

JsonWriter& JsonWriter::value(std::string_view text) {
  flush_if_full();
  before_value();
  append_json_string(buffer_, text);
  return *this;
}

JsonWriter& JsonWriter::integer(long long n) {
  char text[24];
  return literal(std::string_view(text, std::to_chars(text, text + sizeof text, n).ptr - text));
}

}  // namespace railmodal::report
