// The std::to_chars number writers: the shortest round-trip text of CSV, JSON and the study files
// (write_number, shortest_text), and the fixed and significant precisions of the tables and
// pages (report::fixed, report::significant), which must write what printf's %.Nf, %.Ne and
// %.Ng write, ties included, since the goldens were written by printf through iostreams.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "report/number_text.hpp"
#include "report/text_format.hpp"
#include "shortest_text.hpp"

namespace railmodal::report {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNan = std::numeric_limits<double>::quiet_NaN();

std::string printf_text(const char* format, int precision, double x) {
  char text[512];
  std::snprintf(text, sizeof text, format, precision, x);
  return text;
}

double bits_to_double(uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// The edge cases of a double and of rounding: ±0, the smallest subnormal and the largest, the
// smallest normal, 1e±308, the largest double, and ties in decimal (0.125, 2.5) as well as
// decimal fractions that are not ties in binary (2.675 is 2.67499999…).
std::vector<double> edge_values() {
  std::vector<double> values{0.0,
                             -0.0,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             bits_to_double(0x000fffffffffffffULL),  // the largest subnormal
                             std::numeric_limits<double>::min(),
                             1e-308,
                             -1e-308,
                             1e308,
                             -1e308,
                             std::numeric_limits<double>::max(),
                             0.5,
                             1.5,
                             2.5,
                             -2.5,
                             0.125,
                             0.375,
                             -0.125,
                             2.675,
                             1.005,
                             0.0001,
                             0.00001,
                             123456.5,
                             999999999.95,
                             1e9,
                             -1e9,
                             1e15,
                             1e16,
                             1.0 / 3.0,
                             -2.0 / 3.0,
                             41.666666666666664};
  // And doubles of every magnitude from their bits: a fixed seed, so that a failure repeats.
  uint64_t state = 0x9e3779b97f4a7c15ULL;
  for (int i = 0; i < 2000; ++i) {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;  // xorshift64
    const double x = bits_to_double(state);
    if (std::isfinite(x)) values.push_back(x);
  }
  return values;
}

// The same double, bit for bit, except that −0 is written (and so reads back) as +0.
bool same_double(double a, double b) { return a == b && (a == 0.0 || std::signbit(a) == std::signbit(b)); }

TEST(NumberText, CsvAndJsonReadBackAsTheSameDouble) {
  for (const double x : edge_values()) {
    for (const NumberStyle style : {NumberStyle::csv, NumberStyle::json}) {
      const std::string text = number_text(x, style);
      EXPECT_TRUE(same_double(std::strtod(text.c_str(), nullptr), x)) << text;
      EXPECT_LE(text.size(), static_cast<size_t>(kNumberTextMax)) << text;
    }
    // The study files', the comparison CSV's and the messages' text is the CSV style's, −0
    // included ("0": 2026-11-28; it wrote "-0").
    EXPECT_EQ(shortest_text(x), number_text(x, NumberStyle::csv));
    std::string appended = "a,";
    append_shortest_text(&appended, x);
    EXPECT_EQ(appended, "a," + shortest_text(x));
  }
}

// Shortest: no longer than the shortest scientific text that reads back (printf's %.{n-1}e
// with the fewest digits n, which rounds correctly); to_chars writes fixed notation where that
// is shorter still ("0.001", "123456.5").
TEST(NumberText, CsvIsTheShortestThatRoundTrips) {
  for (const double x : edge_values()) {
    int digits = 1;
    while (std::strtod(printf_text("%.*e", digits - 1, x).c_str(), nullptr) != x) ++digits;
    const std::string scientific = printf_text("%.*e", digits - 1, x);
    EXPECT_LE(number_text(x, NumberStyle::csv).size(), scientific.size())
        << number_text(x, NumberStyle::csv) << " against " << scientific;
  }
}

TEST(NumberText, JsonLayout) {
  EXPECT_EQ(number_text(0.0, NumberStyle::json), "0.0");
  EXPECT_EQ(number_text(-0.0, NumberStyle::json), "0.0");  // no sign on a zero (user audit 2026-11-27c, F7)
  EXPECT_EQ(number_text(-0.0, NumberStyle::csv), "0");
  EXPECT_EQ(number_text(2.0, NumberStyle::json), "2.0");
  EXPECT_EQ(number_text(0.0001, NumberStyle::json), "0.0001");
  EXPECT_EQ(number_text(0.00001, NumberStyle::json), "1e-05");
  EXPECT_EQ(number_text(1e15, NumberStyle::json), "1e+15");
  EXPECT_EQ(number_text(1e14, NumberStyle::json), "100000000000000.0");
  EXPECT_EQ(number_text(1e308, NumberStyle::json), "1e+308");
  EXPECT_EQ(number_text(-1e-308, NumberStyle::json), "-1e-308");
  EXPECT_EQ(number_text(std::numeric_limits<double>::denorm_min(), NumberStyle::json), "5e-324");
}

// Not finite: "inf", "-inf", "nan" in both styles of write_number (the CSV columns that may hold
// them say so); JsonWriter writes null instead, and the CSV writers whose columns are finite or
// blank leave the field empty (streaming_writers_test.cpp, hunting_report_test.cpp).
TEST(NumberText, NonFinite) {
  for (const NumberStyle style : {NumberStyle::csv, NumberStyle::json}) {
    EXPECT_EQ(number_text(kInf, style), "inf");
    EXPECT_EQ(number_text(-kInf, style), "-inf");
    EXPECT_EQ(number_text(kNan, style), "nan");
  }
  EXPECT_EQ(shortest_text(kInf), "inf");
  EXPECT_EQ(shortest_text(-kInf), "-inf");
  EXPECT_EQ(shortest_text(kNan), "nan");
}

// −0 (a negated or rounded-away zero) is written without its sign by every writer: equal in
// value, and a sign on a zero means nothing to a reader (docs/input.md, "a zero").
TEST(NumberText, NoWriterSignsAZero) {
  EXPECT_EQ(shortest_text(-0.0), "0");
  EXPECT_EQ(shortest_text(-0.0, 6), "0");
  std::string appended = "x = ";
  append_shortest_text(&appended, -0.0);
  EXPECT_EQ(appended, "x = 0");
  EXPECT_EQ(significant(-0.0, 4), "0");
  EXPECT_EQ(fixed(-0.0, 2), "0.00");
  EXPECT_EQ(number_text(-0.0, NumberStyle::csv), "0");
  EXPECT_EQ(number_text(-0.0, NumberStyle::json), "0.0");
  // A negative number that is not zero keeps its sign.
  EXPECT_EQ(shortest_text(-1e-300), "-1e-300");
  EXPECT_EQ(significant(-1e-300, 4), "-1e-300");
}

// report::fixed is printf's %.Nf below 1e9 and %.Ne from there on; round-off to zero drops the
// sign ("0.00" for -0.001 and -0.0, never "-0.00").
TEST(NumberText, FixedIsPrintfs) {
  for (const double x : edge_values())
    for (int decimals : {0, 1, 2, 3, 4, 6, 12}) {
      std::string expected = printf_text(std::abs(x) >= 1e9 ? "%.*e" : "%.*f", decimals, x);
      if (expected[0] == '-' && expected.find_first_not_of("0.", 1) == std::string::npos) expected.erase(0, 1);
      EXPECT_EQ(fixed(x, decimals), expected) << x << " to " << decimals;
    }
  EXPECT_EQ(fixed(2.5, 0), "2");       // a tie in binary goes to the even digit, as printf's
  EXPECT_EQ(fixed(0.125, 2), "0.12");  // ditto
  EXPECT_EQ(fixed(0.375, 2), "0.38");
  EXPECT_EQ(fixed(2.675, 2), "2.67");  // 2.67499999999999982236431605997495353221893310546875
  EXPECT_EQ(fixed(-0.001, 2), "0.00");
  EXPECT_EQ(fixed(-0.0, 1), "0.0");
  EXPECT_EQ(fixed(-0.006, 2), "-0.01");
  EXPECT_EQ(fixed(1e308, 2), "1.00e+308");
  EXPECT_EQ(fixed(-1e-308, 3), "0.000");
  EXPECT_EQ(fixed(std::numeric_limits<double>::denorm_min(), 1), "0.0");
  EXPECT_EQ(fixed(kInf, 1), "inf");
  EXPECT_EQ(fixed(-kInf, 1), "-inf");
  EXPECT_EQ(fixed(kNan, 1), "nan");
  EXPECT_EQ(fixed(123.456, kMaxPrecision), printf_text("%.*f", kMaxPrecision, 123.456));
  EXPECT_EQ(fixed(-9.99e8, kMaxPrecision), printf_text("%.*f", kMaxPrecision, -9.99e8));
}

// report::significant is printf's %.Ng (and shortest_text(x, N) the same, for messages), but
// for −0, written as +0 (NoWriterSignsAZero).
TEST(NumberText, SignificantIsPrintfs) {
  for (const double x : edge_values())
    for (int digits : {1, 2, 3, 4, 6, 10, 17}) {
      const std::string expected = printf_text("%.*g", digits, x == 0.0 ? 0.0 : x);
      EXPECT_EQ(significant(x, digits), expected) << x << " to " << digits;
      EXPECT_EQ(shortest_text(x, digits), expected) << x << " to " << digits;
    }
  EXPECT_EQ(significant(2.5, 1), "2");  // ties to even, as printf
  EXPECT_EQ(significant(0.125, 2), "0.12");
  EXPECT_EQ(significant(1e-308, 4), "1e-308");
  EXPECT_EQ(significant(std::numeric_limits<double>::denorm_min(), 4), "4.941e-324");
  EXPECT_EQ(significant(kInf, 4), "inf");
  EXPECT_EQ(significant(-kInf, 4), "-inf");
  EXPECT_EQ(significant(kNan, 4), "nan");
  EXPECT_EQ(significant(-1.0 / 3.0 * 1e-4, kMaxPrecision), printf_text("%.*g", kMaxPrecision, -1.0 / 3.0 * 1e-4));
}

}  // namespace
}  // namespace railmodal::report
