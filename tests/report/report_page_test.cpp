// The report scaffolding the analyses' reports share (src/report/report_page.hpp, json_lines.hpp):
// the checks paragraph's words, the dispatch on the format, and the JSON layout of one member a
// line with a long array last.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/json_lines.hpp"
#include "report/report_page.hpp"

namespace railmodal::report {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

TEST(ReportPage, ChecksTextSaysValuesLimitsAndFailures) {
  AnalysisSummary s;
  s.checks = {{"residual", 1.234e-9, 1e-6, true}, {"steps", 3.0, kUnbounded, true}, {"drift", 2.5, 1.0, false}};
  // a whole number as it is, any other to two significant digits; no limit for +inf
  EXPECT_EQ(checks_text(s), "residual 1.2e-09 (limit 1e-06); steps 3; drift 2.5 (limit 1, FAILED)");
  EXPECT_EQ(failed_checks(s), std::vector<std::string>{"drift 2.5, limit 1 (docs/accuracy.md)"});
}

TEST(ReportPage, NothingRecordedIsSaid) {
  const AnalysisSummary s;
  EXPECT_EQ(checks_text(s), "none recorded");
  EXPECT_TRUE(failed_checks(s).empty());
  EXPECT_EQ(method_text(s), "not recorded");
}

TEST(ReportPage, WriteInFormatCallsTheFormatsWriter) {
  const std::vector<OutputFormat> formats = {OutputFormat::table, OutputFormat::csv, OutputFormat::json,
                                             OutputFormat::markdown, OutputFormat::html};
  for (OutputFormat f : formats) {
    std::string called;
    write_in_format(
        f, "write_test", [&] { called += "table"; }, [&] { called += "csv"; }, [&] { called += "json"; },
        [&] { called += "markdown"; }, [&] { called += "html"; });
    EXPECT_EQ(called, to_string(f));
  }
  const auto none = [] {};
  try {
    write_in_format(static_cast<OutputFormat>(99), "write_test", none, none, none, none, none);
    FAIL() << "a format that is none of the five was written";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("write_test"), std::string::npos) << e.what();
  }
}

TEST(JsonLines, OneMemberALineAndTheLongArrayLast) {
  std::ostringstream out;
  write_line_member(out, "title", [](JsonWriter& j) { j.value("a \"car\""); }, true);
  write_line_member(out, "band", [](JsonWriter& j) { j.value(std::vector<double>{0.5, 2.0}); });
  write_last_line_array(out, "speeds", std::vector<int>{1, 2},
                        [](JsonWriter& j, int k) { j.begin_object().member("k", k).end_object(); });
  EXPECT_EQ(out.str(),
            "{\n  \"title\": \"a \\\"car\\\"\",\n  \"band\": [0.5,2.0],\n  \"speeds\": [\n    {\"k\":1},\n"
            "    {\"k\":2}\n  ]\n}\n");
  EXPECT_TRUE(nlohmann::json::accept(out.str()));
}

TEST(JsonLines, AnEmptyLastArrayIsOneLine) {
  std::ostringstream out;
  write_line_member(out, "title", [](JsonWriter& j) { j.value(nullptr); }, true);
  write_last_line_array(out, "speeds", std::vector<int>{}, [](JsonWriter& j, int k) { j.value(k); });
  EXPECT_EQ(out.str(), "{\n  \"title\": null,\n  \"speeds\": []\n}\n");
  EXPECT_TRUE(nlohmann::json::accept(out.str()));
}

}  // namespace
}  // namespace railmodal::report
