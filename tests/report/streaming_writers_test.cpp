// The streaming JSON and CSV writers (issue 19 item 3) against nlohmann::json, the library the
// reports wrote JSON with before: the same layout byte for byte, numbers that read back as the
// same double, and the escapes of a JSON string. And the SVG charts' decimated curves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

#include "report/csv_writer.hpp"
#include "report/json_writer.hpp"
#include "report/number_text.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"

namespace railmodal::report {
namespace {

double from_bits(uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// Every finite double of 200 000 random bit patterns (every exponent), and as many of the
// magnitudes reports print (1e-20 to 1e20): number_text reads back exactly, and is no longer
// than the text nlohmann::json wrote (Grisu2, which is not always the shortest).
TEST(NumberText, ReadsBackExactlyAndIsNoLongerThanNlohmann) {
  std::mt19937_64 random(19);
  std::uniform_real_distribution<double> decades(-20.0, 20.0);
  int shorter = 0;
  for (int i = 0; i < 400000; ++i) {
    const double x = i % 2 ? from_bits(random()) : (i % 4 ? -1 : 1) * std::pow(10.0, decades(random));
    if (!std::isfinite(x)) continue;
    const std::string text = number_text(x, NumberStyle::json);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
    ASSERT_EQ(std::strtod(number_text(x).c_str(), nullptr), x) << number_text(x);
    const std::string theirs = nlohmann::json(x).dump();
    ASSERT_LE(text.size(), theirs.size()) << text << " " << theirs;
    shorter += text.size() < theirs.size();
  }
  EXPECT_GT(shorter, 0);  // Grisu2's longer answers exist: the test would see a difference
}

// The layout is nlohmann::json's: fixed from 1e-4 to below 1e15, otherwise d.ddde±XX.
TEST(NumberText, LaysOutNumbersAsNlohmannDid) {
  for (double x : {0.0, 1.0, -2.0, 0.5, 123.25, 1e-4, 1.5e-4, 1e-5, 9.99e-5, 1e14, 123456789012345.0, 1e15,
                   1.5e15, 1e16, 2.5e-300, 1.7976931348623157e308, 4.9e-324, 0.1, 1.0 / 3.0, -1e-7, 3e22})
    EXPECT_EQ(number_text(x, NumberStyle::json), nlohmann::json(x).dump()) << x;
  // CSV: std::to_chars's choice, the shorter of fixed and scientific, as shortest_text's.
  EXPECT_EQ(number_text(2.0), "2");
  // But for −0, which nlohmann wrote "-0.0": written as 0 (user audit 2026-11-27c, F7).
  EXPECT_EQ(number_text(-0.0, NumberStyle::json), "0.0");
  EXPECT_EQ(number_text(-0.0), "0");
  EXPECT_EQ(number_text(0.0001), "1e-04");
  EXPECT_EQ(number_text(0.001), "0.001");
  EXPECT_EQ(number_text(1e15), "1e+15");
  EXPECT_EQ(number_text(123456.5), "123456.5");
  EXPECT_EQ(number_text(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(number_text(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(number_text(std::numeric_limits<double>::quiet_NaN()), "nan");
}

// A document of every kind of value and nesting, empty containers included, written both ways.
TEST(JsonWriter, WritesWhatNlohmannDumpWrote) {
  nlohmann::json doc;
  doc["a_number"] = 0.1;
  doc["b_integer"] = -42;
  doc["c_bool"] = true;
  doc["d_null"] = nullptr;
  doc["e_text"] = "quote \" backslash \\ tab \t newline \n bell \x07 delete \x7f é ✓";
  doc["f_empty_array"] = nlohmann::json::array();
  doc["g_empty_object"] = nlohmann::json::object();
  doc["h_array"] = {1.5, nlohmann::json::array(), {{"x", 2.0}}, nlohmann::json::array({1, 2})};
  doc["i_infinity"] = std::numeric_limits<double>::infinity();  // null, as nlohmann writes it
  std::ostringstream out;
  {
    JsonWriter j(out);
    j.begin_object();
    j.member("a_number", 0.1).member("b_integer", -42).member("c_bool", true).member("d_null", nullptr);
    j.member("e_text", doc["e_text"].get<std::string>());
    j.key("f_empty_array").begin_array().end_array();
    j.key("g_empty_object").begin_object().end_object();
    j.key("h_array").begin_array().value(1.5).begin_array().end_array();
    j.begin_object().member("x", 2.0).end_object();
    j.value(std::vector<int>{1, 2}).end_array();
    j.member("i_infinity", std::numeric_limits<double>::infinity());
    j.end_object();
  }
  EXPECT_EQ(out.str(), doc.dump(2) + "\n");
}

// Bytes that are not UTF-8 (a lone continuation byte, a truncated sequence, an overlong form, a
// surrogate) become U+FFFD, so that the file stays valid JSON; valid sequences pass as they are.
TEST(JsonWriter, ReplacesBytesThatAreNotUtf8) {
  std::string quoted;
  append_json_string(quoted, "a\x80" "b\xe2\x9c" "c\xc0\xaf" "d\xed\xa0\x80" "e\xf0\x9f\x9a\x82");
  EXPECT_EQ(quoted,
            "\"a\xef\xbf\xbd" "b\xef\xbf\xbd\xef\xbf\xbd" "c\xef\xbf\xbd\xef\xbf\xbd" "d\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd"
            "e\xf0\x9f\x9a\x82\"");
  EXPECT_TRUE(nlohmann::json::accept(quoted));
}

// A document larger than the writer's buffer reaches the stream whole, in order.
TEST(JsonWriter, StreamsALongArrayWhole) {
  std::vector<double> values;
  for (int i = 0; i < 100000; ++i) values.push_back(i * 0.37);
  std::ostringstream out;
  {
    JsonWriter j(out);
    j.begin_object().member("values", values).end_object();
  }
  EXPECT_EQ(nlohmann::json::parse(out.str())["values"].get<std::vector<double>>(), values);
}

// A value laid out apart at the depth where it will stand (a shard's result kept in a temporary
// file) and inserted with raw() gives the bytes of writing it in place, at every indent, first
// element or not, empty or not; and the outermost end of the value writes no line break.
TEST(JsonWriter, AValueLaidOutApartIsInsertedAsWrittenInPlace) {
  const auto element = [](JsonWriter& j, int n) {
    j.begin_object().member("n", n).key("values").begin_array();
    for (int i = 0; i < n; ++i) j.value(i * 0.5);
    j.end_array().end_object();
  };
  for (int indent : {-1, 1, 2}) {
    std::ostringstream in_place, inserted;
    {
      JsonWriter j(in_place, indent);
      j.begin_object().key("results").begin_array();
      for (int n : {0, 2}) element(j, n);
      j.end_array().end_object();
    }
    {
      JsonWriter j(inserted, indent);
      j.begin_object().key("results").begin_array();
      for (int n : {0, 2}) {
        std::ostringstream apart;
        {
          JsonWriter a(apart, indent, 2);
          element(a, n);
        }
        EXPECT_NE(apart.str().back(), '\n') << indent;
        j.raw(apart.str());
      }
      j.end_array().end_object();
    }
    EXPECT_EQ(inserted.str(), in_place.str()) << indent;
  }
}

// Repeated names are written once, the last of them, and in bytewise order.
TEST(JsonWriter, MemberOrderIsTheMapsOrder) {
  EXPECT_EQ(member_order({"b", "a", "B", "a", "c"}), (std::vector<size_t>{2, 3, 0, 4}));
  EXPECT_TRUE(member_order({}).empty());
}

TEST(CsvWriter, QuotesTextThatNeedsItAndWritesNumbersShortest) {
  std::ostringstream out;
  {
    CsvWriter csv(out);
    csv.line("# note: a comment");
    csv.field("plain").field("a, b").field("say \"hi\"").field("two\nlines").end_row();
    csv.field(1).field(0.1).field(2.0).blank().field(true).field(std::numeric_limits<double>::infinity()).end_row();
  }
  EXPECT_EQ(out.str(),
            "# note: a comment\n"
            "plain,\"a, b\",\"say \"\"hi\"\"\",\"two\nlines\"\n"
            "1,0.1,2,,true,inf\n");
}

// One quoting rule (RFC 4180: a comma, quote or line break, CR included) for every CSV writer:
// the streaming writer, csv_field, and the rows a study's CSV appends field by field.
TEST(CsvWriter, EveryWriterQuotesAlike) {
  for (const std::string text : {"plain", "a, b", "say \"hi\"", "two\nlines", "carriage\rreturn", ""}) {
    std::ostringstream out;
    CsvWriter(out).field(text);
    std::string row;
    append_csv_field(&row, text);
    EXPECT_EQ(out.str(), csv_field(text));
    EXPECT_EQ(row, csv_field(text));
    EXPECT_EQ(csv_needs_quotes(text), csv_field(text) != text) << text;
  }
  EXPECT_EQ(csv_field("carriage\rreturn"), "\"carriage\rreturn\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
}

// The (x, y) points of every polyline of an SVG chart.
std::vector<std::pair<double, double>> polyline_points(const std::string& svg) {
  std::vector<std::pair<double, double>> points;
  for (size_t at = svg.find("points=\""); at != std::string::npos; at = svg.find("points=\"", at + 1)) {
    std::istringstream in(svg.substr(at + 8, svg.find('"', at + 8) - at - 8));
    double x, y;
    char comma;
    while (in >> x >> comma >> y) points.push_back({x, y});
  }
  return points;
}

Chart chart_of(const std::vector<double>& x, const std::vector<double>& y) {
  Chart chart;
  chart.id = "t";
  chart.series.push_back({});
  chart.series[0].x = x;
  chart.series[0].y = y;
  return chart;
}

// A curve of 10⁵ points with a peak one point wide and a notch one point deep: drawn with at
// most four points a column of the plot (a unit of the 1000-wide viewBox), and the peak's and
// the notch's points are among them.
TEST(SvgChart, DenseCurvesAreDecimatedKeepingEveryPeak) {
  std::vector<double> x, y;
  for (int i = 0; i < 100000; ++i) x.push_back(i), y.push_back(1.0 + 0.1 * std::sin(i * 1e-3));
  y[31415] = 5.0;
  y[77777] = -3.0;
  const std::string svg = svg_chart(chart_of(x, y));
  const auto points = polyline_points(svg);
  EXPECT_LE(points.size(), 4u * 1000u);
  double top = 1e9, bottom = -1e9;  // SVG's y runs down
  for (const auto& [px, py] : points) top = std::min(top, py), bottom = std::max(bottom, py);
  // The same chart of just the two extremes and the curve's ends sets where they are drawn.
  const auto extremes = polyline_points(svg_chart(chart_of({0, 31415, 77777, 99999}, {1.0, 5.0, -3.0, y.back()})));
  ASSERT_EQ(extremes.size(), 4u);
  EXPECT_EQ(top, extremes[1].second);
  EXPECT_EQ(bottom, extremes[2].second);
  EXPECT_EQ(points.front(), extremes.front());  // the ends too
  EXPECT_EQ(points.back(), extremes.back());
}

// A curve with fewer points than the plot has columns is drawn point for point.
TEST(SvgChart, SparseCurvesKeepEveryPoint) {
  std::vector<double> x, y;
  for (int i = 0; i < 300; ++i) x.push_back(i), y.push_back(std::cos(i * 0.1));
  EXPECT_EQ(polyline_points(svg_chart(chart_of(x, y))).size(), 300u);
}

}  // namespace
}  // namespace railmodal::report
