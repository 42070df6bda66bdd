// What the analyses' reports share (report_page.hpp).
#include "report/report_page.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "report/text_format.hpp"

namespace railmodal::report {

std::string check_value(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e9) return fixed(value, 0);
  return significant(value, 2);
}

std::string checks_text(const AnalysisSummary& summary) {
  std::string text;
  for (const Check& c : summary.checks) {
    text += (text.empty() ? "" : "; ") + c.name + " " + check_value(c.value);
    if (std::isfinite(c.limit)) text += " (limit " + check_value(c.limit) + (c.passed ? ")" : ", FAILED)");
  }
  return text.empty() ? "none recorded" : text;
}

std::vector<std::string> failed_checks(const AnalysisSummary& summary) {
  std::vector<std::string> failed;
  for (const Check& c : summary.checks)
    if (!c.passed)
      failed.push_back(c.name + " " + check_value(c.value) + ", limit " + check_value(c.limit) + " (docs/accuracy.md)");
  return failed;
}

std::string method_text(const AnalysisSummary& summary) {
  return summary.method.empty() ? "not recorded" : summary.method;
}

size_t width_of(const std::string& text) {
  return static_cast<size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

std::string wrapped(const std::string& text) {
  std::string out, line;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (!line.empty() && width_of(line) + 1 + width_of(word) > 100) out += line + "\n", line.clear();
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

}  // namespace railmodal::report
