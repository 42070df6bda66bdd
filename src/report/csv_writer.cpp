#include "report/csv_writer.hpp"

#include <charconv>

#include "report/number_text.hpp"
#include "report/text_format.hpp"

namespace railmodal::report {

void CsvWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void CsvWriter::separate() {
  if (buffer_.size() > kFlushAt) flush();
  if (row_started_) buffer_ += ',';
  row_started_ = true;
}

CsvWriter& CsvWriter::field(double x) {
  separate();
  char text[kNumberTextMax];
  buffer_.append(text, write_number(text, x, NumberStyle::csv));
  return *this;
}

CsvWriter& CsvWriter::field(std::string_view text) {
  separate();
  append_csv_field(&buffer_, text);
  return *this;
}

CsvWriter& CsvWriter::integer(long long n) {
  separate();
  char text[24];
  buffer_.append(text, std::to_chars(text, text + sizeof text, n).ptr);
  return *this;
}

CsvWriter& CsvWriter::blank() {
  separate();
  return *this;
}

CsvWriter& CsvWriter::end_row() {
  buffer_ += '\n';
  row_started_ = false;
  return *this;
}

CsvWriter& CsvWriter::line(std::string_view text) {
  if (buffer_.size() > kFlushAt) flush();
  buffer_.append(text);
  buffer_ += '\n';
  row_started_ = false;
  return *this;
}

}  // namespace railmodal::report
