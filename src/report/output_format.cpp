#include "railmodal/output_format.hpp"

#include "report/unwritten_format.hpp"

namespace railmodal {

const char* to_string(OutputFormat format) {
  switch (format) {
    case OutputFormat::table: return "table";
    case OutputFormat::csv: return "csv";
    case OutputFormat::json: return "json";
    case OutputFormat::markdown: return "markdown";
    case OutputFormat::html: return "html";
  }
  return "?";
}

std::optional<OutputFormat> output_format_from_string(const std::string& word) {
  for (OutputFormat f : {OutputFormat::table, OutputFormat::csv, OutputFormat::json, OutputFormat::markdown,
                         OutputFormat::html})
    if (word == to_string(f)) return f;
  return std::nullopt;
}

namespace report {

std::string unwritten_format(const std::string& writer, const std::string& written, OutputFormat format) {
  return writer + " writes " + written + ", not " + to_string(format);
}

}  // namespace report
}  // namespace railmodal
