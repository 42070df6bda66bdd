// A streaming CSV writer (issue 19 item 3): fields go into a 64 KiB buffer and on to the stream,
// numbers as number_text's CSV style writes them (the shortest text that reads back as the same
// double: "0.25", "2", "1e-05"; inf and nan as iostreams wrote them), text quoted where RFC 4180
// needs it (a comma, quote or line break).
//
//   CsvWriter csv(out);
//   csv.line("# note: what the file leaves out");
//   csv.field("index").field("frequency [Hz]").end_row();
//   csv.field(1).field(5.25).end_row();
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

namespace railmodal::report {

class CsvWriter {
 public:
  explicit CsvWriter(std::ostream& out) : out_(out) {}
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  ~CsvWriter() { flush(); }

  CsvWriter& field(double x);
  /// Quoted when it holds a comma, quote or line break.
  CsvWriter& field(std::string_view text);
  CsvWriter& field(const char* text) { return field(std::string_view(text)); }
  CsvWriter& field(const std::string& text) { return field(std::string_view(text)); }
  CsvWriter& field(bool b) { return field(std::string_view(b ? "true" : "false")); }
  template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
  CsvWriter& field(Integer n) {
    return integer(static_cast<long long>(n));
  }
  /// An empty field (a quantity that does not exist for the row).
  CsvWriter& blank();
  CsvWriter& end_row();
  /// A whole line as it is (a comment, a heading written elsewhere), at the start of a row.
  CsvWriter& line(std::string_view text);

  void flush();

 private:
  CsvWriter& integer(long long n);
  void separate();

  static constexpr size_t kFlushAt = 1 << 16;

  std::ostream& out_;
  std::string buffer_;
  bool row_started_ = false;
};

}  // namespace railmodal::report
