// What the analyses' reports share beside the page's head and foot (document_table.hpp): the
// dispatch on the output format, and the checks paragraph that says the analysis' own checks in
// words, and the plain-text page's widths and wrapping (ride, linear and nonlinear hunting, balance).
//
//   report::write_in_format(format, "write_ride", [&] { write_text(out, page); }, [&] { write_csv(out, r); },
//                           [&] { write_json(out, page); }, [&] { write_markdown(out, page); },
//                           [&] { write_html(out, page); });
#pragma once

#include <stdexcept>
#include <cstddef>
#include <string>
#include <vector>

#include "railmodal/output_format.hpp"
#include "railmodal/summary.hpp"
#include "report/unwritten_format.hpp"

namespace railmodal::report {

/// Calls the report's writer for `format`, each a callable with no argument; `writer` names the
/// public function in the message of a format that is none of the five.
template <typename Table, typename Csv, typename Json, typename Markdown, typename Html>
void write_in_format(OutputFormat format, const char* writer, Table table, Csv csv, Json json, Markdown markdown,
                     Html html) {
  switch (format) {
    case OutputFormat::table:
      table();
      return;
    case OutputFormat::csv:
      csv();
      return;
    case OutputFormat::json:
      json();
      return;
    case OutputFormat::markdown:
      markdown();
      return;
    case OutputFormat::html:
      html();
      return;
  }
  throw std::invalid_argument(unwritten_format(writer, "table, csv, json, markdown or html", format));
}

/// A check's value or limit as the checks paragraph writes it: a whole number as it is (a count,
/// a bound), any other to two significant digits (a residual: enough to judge, and the same
/// bytes from run to run).
std::string check_value(double value);

/// The analysis' own checks, values and limits ("name value (limit L)", "; " between, ", FAILED"
/// in the parentheses of one that failed; "none recorded"); never the stage times, which vary
/// from run to run (docs/architecture.md: outputs are byte for byte reproducible).
std::string checks_text(const AnalysisSummary& summary);

/// One line per failed check: "name value, limit L (docs/accuracy.md)".
std::vector<std::string> failed_checks(const AnalysisSummary& summary);

/// The summary's method, "not recorded" when it is empty.
std::string method_text(const AnalysisSummary& summary);

/// Characters in UTF-8 `text` (continuation bytes take none): a text table's column width.
size_t width_of(const std::string& text);

/// `text` broken into lines of at most 100 characters at spaces, for a plain-text report.
std::string wrapped(const std::string& text);

}  // namespace railmodal::report
