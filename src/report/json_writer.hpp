// A streaming JSON writer: what a report writes goes into a 64 KiB buffer and on to the stream,
// with no document tree (issue 19 item 3: nlohmann::json held every number of a 10⁵-point curve
// as a node, and a report cost more than its analysis). The text is laid out as
// nlohmann::json::dump(2) laid it out, so the files kept their shape: two spaces a level, one
// member or element a line, "[]" and "{}" when empty; numbers by number_text (shortest
// round-trip, "2.0" for a whole double), null for a non-finite one (as nlohmann wrote it).
//
// Members come in the order they are written: a writer that moved from nlohmann::json writes
// them in the alphabetical order nlohmann's std::map gave them, so its files did not change.
//
//   JsonWriter j(out);
//   j.begin_object();
//   j.member("name", "bogie bounce").member("frequency_hz", 5.25);
//   j.key("shape").begin_array();
//   for (double x : shape) j.value(x);
//   j.end_array();
//   j.end_object();  // the outermost end writes "\n" and flushes
#pragma once

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace railmodal::report {

class JsonWriter {
 public:
  /// `indent` spaces a level, as nlohmann::json::dump's argument (the shard files have 1); −1:
  /// compact, on one line with no spaces (dump()), for a value embedded in a line of text, so
  /// the outermost end writes no line break.
  explicit JsonWriter(std::ostream& out, int indent = 2) : out_(&out), indent_(indent), buffer_(own_) {}
  /// A value laid out as it stands `depth` levels deep in a document of `indent`, for a writer
  /// of that document to insert later with raw() (a shard's result kept in a temporary file
  /// until the results can be written in order); its outermost end writes no line break.
  JsonWriter(std::ostream& out, int indent, size_t depth)
      : out_(&out), indent_(indent), depth_(depth), buffer_(own_) {}
  /// As JsonWriter(out, indent, depth), appending to `*text` as it goes rather than to a stream:
  /// a text kept per variant is made without a stream and a copy.
  JsonWriter(std::string* text, int indent, size_t depth)
      : out_(nullptr), indent_(indent), depth_(depth), buffer_(*text) {}
  JsonWriter(const JsonWriter&) = delete;
  JsonWriter& operator=(const JsonWriter&) = delete;
  ~JsonWriter() { flush(); }

  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }

  /// The next member's name, inside an object; its value follows.
  JsonWriter& key(std::string_view name);

  JsonWriter& value(double x);
  JsonWriter& value(bool b);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
  JsonWriter& value(std::nullptr_t) { return literal("null"); }
  /// null when empty.
  JsonWriter& value(const std::optional<double>& x) { return x ? value(*x) : value(nullptr); }
  template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
  JsonWriter& value(Integer n) {
    return integer(static_cast<long long>(n));
  }
  /// `laid_out`, the text of a value that a JsonWriter(out, indent, depth) of this writer's
  /// indent wrote at this depth, inserted as it is.
  JsonWriter& raw(std::string_view laid_out) { return literal(laid_out); }
  /// An array of the elements, each written by value().
  template <typename T>
  JsonWriter& value(const std::vector<T>& elements) {
    begin_array();
    for (const auto& e : elements) value(e);
    return end_array();
  }

  template <typename T>
  JsonWriter& member(std::string_view name, const T& x) {
    key(name);
    return value(x);
  }

  /// Writes the buffer to the stream (the outermost end_object or end_array does it too);
  /// nothing for a writer into a text.
  void flush();

 private:
  JsonWriter& open(char bracket);
  JsonWriter& close(char bracket);
  JsonWriter& integer(long long n);
  JsonWriter& literal(std::string_view text);
  // Before a value: the comma and line break of an array element (a member's come with its key).
  void before_value();
  void new_line();
  void flush_if_full() {
    if (out_ && buffer_.size() > kFlushAt) flush();
  }

  static constexpr size_t kFlushAt = 1 << 16;

  std::ostream* out_;  // null: the text is the buffer
  const int indent_;
  const size_t depth_ = 0;  // the levels around the outermost value that another writer writes
  std::string own_;         // the buffer of a writer to a stream
  std::string& buffer_;
  // Per open container: its bracket and whether it has an element yet.
  std::vector<std::pair<char, bool>> open_;
  bool after_key_ = false;
};

/// `text` as a JSON string, quoted and escaped as nlohmann::json escaped it: \" \\ \b \f \n \r \t,
/// other control characters as \u00xx, the rest as it is; a byte that is not part of valid UTF-8
/// becomes U+FFFD (nlohmann threw; our inputs are checked to be UTF-8 as they are read).
void append_json_string(std::string& out, std::string_view text);

/// The order in which nlohmann::json's std::map wrote an object whose members are named `names`:
/// the indices of the names sorted bytewise, a repeated name once (the last of it, which the map
/// kept). A writer that streams such an object in this order writes the text the map wrote.
std::vector<size_t> member_order(const std::vector<std::string>& names);

}  // namespace railmodal::report
