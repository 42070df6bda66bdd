// The hunting-stability report on results built by hand (tests/report/hunting_results.hpp):
// every verdict, every unstable interval with its open ends, the design curve and zero
// conicity, in every format. The charts' structure is checked in svg_structure_test.cpp.
#include "railmodal/hunting_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "hunting_results.hpp"

namespace railmodal {
namespace {

std::string written(const HuntingResult& r, OutputFormat format) {
  std::ostringstream out;
  write_hunting_stability(out, r, format, "hand-built wheelset", Provenance{});
  return out.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A speed as the report's tables print it (one decimal).
std::string report_speed_kmh(double speed) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << speed * 3.6;
  return s.str();
}

// Whether `part` is in `text` (whose notes the plain-text report wraps at spaces: a line break
// reads as a space).
bool has(std::string text, const std::string& part) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text.find(part) != std::string::npos;
}

TEST(HuntingReport, StableThroughoutSaysSoAndInventsNoCriticalSpeed) {
  const HuntingResult r = test::stable_result();
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "verdict: stable_throughout")) << table;
  EXPECT_TRUE(has(table, "stable at every speed from 10 km/h to 500 km/h")) << table;
  EXPECT_TRUE(has(table, "unstable speed intervals: none")) << table;
  EXPECT_FALSE(has(table, "critical speed 2")) << table;
  EXPECT_TRUE(has(table, "the nonlinear critical speed")) << table;  // the linear remark
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  EXPECT_EQ(j["verdict"], "stable_throughout");
  EXPECT_TRUE(j["critical"].is_null());
  EXPECT_TRUE(j["unstable_intervals"].empty());
  EXPECT_EQ(j["analysis"], "linear");
}

// A real root's interval is named a divergence, never cited as a branch (it has no row); a
// bogie's V/Λ_b names the bogie (review of 2026-11-28).
TEST(HuntingReport, DivergenceAndTheBogieOfVOverLambdaBAreNamed) {
  HuntingResult r = test::two_interval_result();
  UnstableInterval divergence{10.0 / 3.6, 500.0 / 3.6, true, true, "osc1.lateral (real root)", true};
  r.unstable_intervals.insert(r.unstable_intervals.begin(), divergence);
  r.critical->bogie_frequency_hz = 1.25;
  r.critical->bogie = "bogie2";
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "(divergence, osc1.lateral (real root))")) << table;
  EXPECT_TRUE(has(table, "V/Λ_b of 'bogie2' as a rigid bogie: 1.250 Hz")) << table;
  EXPECT_TRUE(has(written(r, OutputFormat::markdown), "divergence, osc1.lateral (real root)"));
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  EXPECT_TRUE(j["unstable_intervals"][0]["divergence"].get<bool>());
  EXPECT_FALSE(j["unstable_intervals"][1]["divergence"].get<bool>());
  EXPECT_EQ(j["critical"]["bogie"], "bogie2");
  EXPECT_EQ(j["critical"]["bogie_frequency_hz"].get<double>(), 1.25);
}

TEST(HuntingReport, EveryUnstableIntervalIsListedWithItsOpenEnd) {
  const HuntingResult r = test::two_interval_result();
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "linear critical speed 200.00 km/h (55.555556 m/s)")) << table;
  EXPECT_TRUE(has(table, "hunting frequency 2.778 Hz (Klingel's V/Λ there: 2.500 Hz)")) << table;
  // Every mention of a branch cites its row of the branches table (user audit 2026-11-27b, 1.4).
  EXPECT_TRUE(has(table, "from 200.00 km/h, to 300.00 km/h (#1 wheelset 1 hunting (kinematic))")) << table;
  EXPECT_TRUE(has(table, "branch #1 'wheelset 1 hunting (kinematic)', hunting frequency")) << table;
  EXPECT_FALSE(has(table, "V/Λ_b")) << table;  // no bogies: no rigid-bogie frequency
  EXPECT_TRUE(has(table, "from 400.00 km/h, still unstable at the highest, 500 km/h")) << table;
  EXPECT_TRUE(has(table, "falls to ζ = 5 % at 150.00 km/h")) << table;
  const std::string markdown = written(r, OutputFormat::markdown);
  EXPECT_TRUE(has(markdown, "| 400.00 | 500.00 (still unstable at the highest) |")) << markdown;
  EXPECT_TRUE(
      has(markdown, "| speed at which a branch falls to ζ = 5 % | 150.00 km/h (#1 wheelset 1 hunting (kinematic)) |"))
      << markdown;
  EXPECT_TRUE(has(markdown, "Written by railmodal")) << markdown;

  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  ASSERT_EQ(j["unstable_intervals"].size(), 2u);
  EXPECT_FALSE(j["unstable_intervals"][0]["to_highest_speed"].get<bool>());
  EXPECT_TRUE(j["unstable_intervals"][1]["to_highest_speed"].get<bool>());
  EXPECT_EQ(j["unstable_intervals"][0]["branch_number"], 1);
  EXPECT_EQ(j["critical"]["branch_number"], 1);
  EXPECT_TRUE(j["critical"]["bogie_frequency_hz"].is_null());
  // km/h to 1e-12 relative: the JSON keeps every digit (shortest round trip).
  EXPECT_NEAR(j["critical"]["speed_kmh"].get<double>(), 200.0, 1e-12 * 200.0);
  EXPECT_DOUBLE_EQ(j["critical"]["speed_m_s"].get<double>(), 200.0 / 3.6);
  EXPECT_EQ(j["critical"]["evaluations"], 31);
  EXPECT_DOUBLE_EQ(j["damping_threshold"].get<double>(), 0.05);
  EXPECT_NEAR(j["threshold_speed_kmh"].get<double>(), 150.0, 1e-12 * 150.0);
  EXPECT_EQ(j["threshold_branch"], "wheelset 1 hunting (kinematic)");
  EXPECT_TRUE(j["below_threshold_at_lowest_speed"].empty());
  ASSERT_EQ(j["branches"].size(), 2u);
  EXPECT_EQ(j["branches"][0]["eigenvalue_re"].size(), r.speeds.size());
  EXPECT_EQ(j["speeds_kmh"].size(), r.speeds.size());
}

TEST(HuntingReport, ABranchBelowTheThresholdFromTheLowestSpeedIsListedNotTheCrossing) {
  const HuntingResult r = test::threshold_below_at_lowest_result();
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "branch #1 'wheelset 1 hunting (kinematic)' falls to ζ = 12 % at 82.20 km/h")) << table;
  EXPECT_TRUE(has(table, "not what decides it: 'body lateral' (ζ = 10 %)")) << table;
  const std::string markdown = written(r, OutputFormat::markdown);
  EXPECT_TRUE(has(markdown, "| at or below ζ = 12 % at the lowest speed | 'body lateral' (ζ = 10 %) |")) << markdown;
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  EXPECT_EQ(j["threshold_branch"], "wheelset 1 hunting (kinematic)");
  ASSERT_EQ(j["below_threshold_at_lowest_speed"].size(), 1u);
  EXPECT_EQ(j["below_threshold_at_lowest_speed"][0]["branch"], "body lateral");
  EXPECT_DOUBLE_EQ(j["below_threshold_at_lowest_speed"][0]["damping_ratio"].get<double>(), 0.1);
}

TEST(HuntingReport, UnstableAtTheLowestSpeedGivesNoCriticalSpeed) {
  const HuntingResult r = test::unstable_at_lowest_result();
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "already unstable at the lowest speed, 10 km/h: no critical speed is given")) << table;
  EXPECT_TRUE(has(table, "unstable at the lowest speed, 10 km/h, to 120.00 km/h")) << table;
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  EXPECT_EQ(j["verdict"], "unstable_at_lowest_speed");
  EXPECT_TRUE(j["critical"].is_null());
  EXPECT_TRUE(j["unstable_intervals"][0]["from_lowest_speed"].get<bool>());
}

TEST(HuntingReport, ConicityCurveGivesBoundsNotValuesOutsideTheRange) {
  const HuntingResult r = test::conicity_result();
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "critical speed against conicity")) << table;
  EXPECT_TRUE(has(table, "above 500 ")) << table;  // λ = 0.05, stable throughout
  EXPECT_TRUE(has(table, "below 10 ")) << table;   // λ = 0.4, unstable at the lowest speed
  EXPECT_TRUE(has(table, "400.00")) << table;       // λ = 0.1: 40/0.1 km/h
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  ASSERT_EQ(j["conicity_curve"].size(), 4u);
  EXPECT_TRUE(j["conicity_curve"][0]["critical"].is_null());
  EXPECT_NEAR(j["conicity_curve"][2]["critical"]["speed_kmh"].get<double>(), 200.0, 1e-9);
  EXPECT_EQ(j["conicity_curve"][3]["verdict"], "unstable_at_lowest_speed");
  const std::string html = written(r, OutputFormat::html);
  EXPECT_TRUE(has(html, "Linear critical speed against equivalent conicity")) << html.substr(0, 400);
}

// The conicity chart of an HTML page: from its heading to the end of its SVG.
std::string conicity_chart_of(const std::string& html) {
  const size_t from = html.find("<h2>Critical speed against conicity</h2>");
  if (from == std::string::npos) return "";
  return html.substr(from, html.find("</svg>", from) - from);
}

// The vehicle's own conicity is marked on the design curve as the speed charts mark speeds: a
// labelled vertical line, listed in the legend, inside the axis even when the curve's
// conicities do not reach it (the label is drawn only for a line within the plot).
TEST(HuntingReport, ConicityChartMarksTheVehiclesOwnConicity) {
  HuntingResult r = test::conicity_result();  // its wheelset at λ = 0.2, inside the curve's 0.05–0.4
  std::string chart = conicity_chart_of(written(r, OutputFormat::html));
  ASSERT_FALSE(chart.empty());
  EXPECT_TRUE(has(chart, ">vehicle λ = 0.2</text>")) << chart;
  EXPECT_TRUE(has(chart, "the vehicle's own equivalent conicity")) << chart;
  // Outside the curve's conicities: the axis widens to show it.
  r.contacts = {test::hand_contact("wheelset1", 0.6)};
  chart = conicity_chart_of(written(r, OutputFormat::html));
  EXPECT_TRUE(has(chart, ">vehicle λ = 0.6</text>")) << chart;
  // Wheelsets at different conicities: one line each, the legend naming the wheelsets.
  r.contacts = {test::hand_contact("wheelset1", 0.15), test::hand_contact("wheelset2", 0.25),
                test::hand_contact("wheelset3", 0.15)};
  chart = conicity_chart_of(written(r, OutputFormat::html));
  EXPECT_TRUE(has(chart, ">vehicle λ = 0.15</text>")) << chart;
  EXPECT_TRUE(has(chart, ">vehicle λ = 0.25</text>")) << chart;
  EXPECT_TRUE(has(chart, "the equivalent conicity of wheelset1, wheelset3")) << chart;
  EXPECT_TRUE(has(chart, "the equivalent conicity of wheelset2")) << chart;
  // Only the conicity chart carries the mark: the speed charts have no λ line.
  const std::string html = written(test::conicity_result(), OutputFormat::html);
  EXPECT_EQ(html.find("vehicle λ"), html.find("vehicle λ", html.find("<h2>Critical speed against conicity</h2>")));
}

TEST(HuntingReport, ZeroConicityWritesNoInfinity) {
  const HuntingResult r = test::zero_conicity_result();
  for (OutputFormat f :
       {OutputFormat::table, OutputFormat::csv, OutputFormat::json, OutputFormat::markdown, OutputFormat::html}) {
    const std::string text = written(r, f);
    EXPECT_FALSE(has(text, "inf")) << to_string(f);
    EXPECT_FALSE(has(text, "nan")) << to_string(f);
  }
  EXPECT_TRUE(has(written(r, OutputFormat::table), "none (λ = 0: no kinematic oscillation)"));
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  EXPECT_TRUE(j["contacts"][0]["klingel_wavelength_m"].is_null());
  EXPECT_DOUBLE_EQ(j["contacts"][0]["conicity"].get<double>(), 0.0);
}

// A branch that is a pair of real (overdamped) roots at some speeds: the CSV holds oscillations
// only (--help and docs/stability.md say real roots are left out), so those speeds have no row;
// the branches table says "real" for its frequency there, not "0.000". Before, the coach's CSV had
// 68 rows with Im λ = 0 and its table "f 0.000 Hz, ζ 100 %" at 10 km/h.
TEST(HuntingReport, RealRootsOfABranchAreLeftOutOfTheCsvAndSaidInTheTable) {
  HuntingResult r = test::two_interval_result();
  HuntingBranch& b = r.branches.front();
  b.eigenvalues.front() = {-3.0, 0.0};
  b.frequency_hz.front() = 0.0;
  b.damping_ratio.front() = 1.0;
  const std::vector<std::string> lines = lines_of(written(r, OutputFormat::csv));
  EXPECT_EQ(lines.size(), r.branches.size() * r.speeds.size());  // the heading, less the real row
  for (size_t k = 1; k < lines.size(); ++k) {
    std::istringstream row(lines[k]);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 4u);
    EXPECT_NE(std::stod(cells[3]), 0.0) << lines[k];
  }
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "  real  ")) << table;
}

TEST(HuntingReport, CsvHasOneRowPerBranchAndSpeedWithUnitsInTheHeadings) {
  const HuntingResult r = test::two_interval_result();
  const std::vector<std::string> lines = lines_of(written(r, OutputFormat::csv));
  ASSERT_EQ(lines.size(), 1 + r.branches.size() * r.speeds.size());
  EXPECT_EQ(lines[0],
            "speed [km/h],branch,eigenvalue_re [1/s],eigenvalue_im [1/s],frequency [Hz],damping_ratio,continuity");
  // The last row: the body branch at 500 km/h, ζ = 0.1, f = 0.8 Hz, Im λ = 2π·0.8.
  std::istringstream last(lines.back());
  std::vector<std::string> cells;
  for (std::string cell; std::getline(last, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), 7u);
  EXPECT_NEAR(std::stod(cells[0]), 500.0, 1e-7);  // 10 significant digits
  EXPECT_EQ(cells[1], "body lateral");
  EXPECT_NEAR(std::stod(cells[3]), 2.0 * M_PI * 0.8, 1e-8);
  EXPECT_NEAR(std::stod(cells[5]), 0.1, 1e-10);
  // ζ = −Re λ/|λ| holds on every row (the eigenvalue and the ratio come from one branch).
  for (size_t k = 1; k < lines.size(); ++k) {
    std::istringstream row(lines[k]);
    std::vector<double> v;
    std::string cell;
    for (int c = 0; std::getline(row, cell, ','); ++c)
      if (c != 1) v.push_back(std::stod(cell));
    EXPECT_NEAR(-v[1] / std::hypot(v[1], v[2]), v[4], 1e-8) << lines[k];
  }
}

TEST(HuntingReport, VeeringBranchesAreFlagged) {
  HuntingResult r = test::two_interval_result();
  r.branches[1].continuity[20] = 0.42;
  r.branches[1].veers = true;
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "VEERS near " + report_speed_kmh(r.speeds[20]))) << table;
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  EXPECT_TRUE(j["branches"][1]["veers"].get<bool>());
  EXPECT_DOUBLE_EQ(j["branches"][1]["continuity"][20].get<double>(), 0.42);
}

TEST(HuntingReport, ContactsAreListed) {
  const std::string table = written(test::stable_result(), OutputFormat::table);
  // f11 9.43 MN, f22 8.46 MN, f23 12 kN·m, f33 100 N·m², W 100 kN, Λ = 2π√(0.46·0.75/0.2) = 8.252 m.
  for (const char* part : {"wheelset1", "9.43", "8.46", "12", "100", "0.46", "0.75", "8.252"})
    EXPECT_TRUE(has(table, part)) << part << "\n" << table;
}

TEST(HuntingReport, HtmlIsOnePageWithItsThreeChartsAndFooter) {
  const std::string html = written(test::conicity_result(), OutputFormat::html);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  size_t charts = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++charts;
  EXPECT_EQ(charts, 3u);
  EXPECT_TRUE(has(html, "<footer class=note>Written by railmodal"));
  EXPECT_TRUE(has(html, "Root locus"));
  EXPECT_FALSE(has(html, "<script"));
  // Without a design curve, two charts.
  const std::string plain = written(test::two_interval_result(), OutputFormat::html);
  charts = 0;
  for (size_t at = plain.find("<svg"); at != std::string::npos; at = plain.find("<svg", at + 1)) ++charts;
  EXPECT_EQ(charts, 2u);
}

TEST(HuntingReport, EveryFormatIsWritten) {
  for (OutputFormat f :
       {OutputFormat::table, OutputFormat::csv, OutputFormat::json, OutputFormat::markdown, OutputFormat::html})
    EXPECT_FALSE(written(test::stable_result(), f).empty()) << to_string(f);
  std::ostringstream out;
  EXPECT_THROW(write_hunting_stability(out, test::stable_result(), static_cast<OutputFormat>(99)),
               std::invalid_argument);
}

// The analysis' checks (HuntingResult::summary) are written in every format, as `modes` writes
// its own; the stage times never are (outputs are byte for byte reproducible). Before, no
// format wrote any of it.
TEST(HuntingReport, ChecksAreWrittenInEveryFormatButNotTheTimes) {
  HuntingResult r = test::stable_result();
  r.summary.analysis = "hunting stability";
  r.summary.method = "QR of the state matrix on 2 thread(s)";
  r.summary.checks = {
      {"max relative eigen residual", 1.234e-14, 1e-8, true},
      {"1 − minimum branch continuity (MAC)", 0.5, 0.2, false},
      {"refinement evaluations (eigenvalues only)", 37.0, std::numeric_limits<double>::infinity(), true}};
  r.summary.stages = {{"eigensolve", 9.8765}};
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "checks: max relative eigen residual 1.2e-14 (limit 1e-08)")) << table;
  EXPECT_TRUE(has(table, "1 − minimum branch continuity (MAC) 0.5 (limit 0.2, FAILED)")) << table;
  EXPECT_TRUE(has(table, "refinement evaluations (eigenvalues only) 37")) << table;
  EXPECT_TRUE(has(table, "method: QR of the state matrix on 2 thread(s)")) << table;
  EXPECT_TRUE(has(table, "warning: check failed: 1 − minimum branch continuity (MAC) 0.5, limit 0.2")) << table;
  // ... and said under the verdict, before any table (the audit of 2026-11-27 found it only at the
  // end of a long report), in every format for people.
  const size_t said = table.find("CHECK FAILED: 1 − minimum branch continuity (MAC) 0.5, limit 0.2");
  ASSERT_NE(said, std::string::npos) << table;
  EXPECT_LT(said, table.find("branches (least damped")) << table;
  EXPECT_GT(said, table.find("verdict: ")) << table;
  const std::string markdown = written(r, OutputFormat::markdown), html = written(r, OutputFormat::html);
  EXPECT_TRUE(has(markdown, "## Checks")) << markdown;
  EXPECT_TRUE(has(markdown, "2 thread(s)")) << markdown;
  EXPECT_TRUE(has(html, "<h2>Checks</h2>")) << html;
  EXPECT_TRUE(has(html, "max relative eigen residual 1.2e-14")) << html;
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  ASSERT_EQ(j["summary"]["checks"].size(), 3u);
  EXPECT_EQ(j["summary"]["checks"][0]["name"], "max relative eigen residual");
  EXPECT_DOUBLE_EQ(j["summary"]["checks"][0]["value"].get<double>(), 1.234e-14);
  EXPECT_FALSE(j["summary"]["checks"][1]["passed"].get<bool>());
  EXPECT_TRUE(j["summary"]["checks"][2]["limit"].is_null());  // +∞: reported, not bounded
  EXPECT_EQ(j["summary"]["method"], "QR of the state matrix on 2 thread(s)");
  for (const std::string& text : {table, markdown, html, j.dump()}) {
    EXPECT_FALSE(has(text, "9.87")) << text;  // the stage time
    EXPECT_FALSE(has(text, "eigensolve")) << text;
  }
}

// Speeds in JSON are SI (m/s), with km/h beside as the comparison's JSON gives them.
TEST(HuntingReport, JsonGivesSpeedsInMetresPerSecondWithKmhBeside) {
  const HuntingResult r = test::two_interval_result();
  const nlohmann::json j = nlohmann::json::parse(written(r, OutputFormat::json));
  ASSERT_EQ(j["speeds_m_s"].size(), r.speeds.size());
  EXPECT_DOUBLE_EQ(j["speeds_m_s"][3].get<double>(), r.speeds[3]);
  EXPECT_DOUBLE_EQ(j["speeds_kmh"][3].get<double>(), r.speeds[3] * 3.6);
  EXPECT_DOUBLE_EQ(j["unstable_intervals"][0]["from_m_s"].get<double>(), 200.0 / 3.6);
  EXPECT_DOUBLE_EQ(j["unstable_intervals"][0]["to_m_s"].get<double>(), 300.0 / 3.6);
  EXPECT_DOUBLE_EQ(j["unstable_intervals"][0]["from_kmh"].get<double>(), 200.0);
  EXPECT_DOUBLE_EQ(j["threshold_speed_m_s"].get<double>(), 150.0 / 3.6);
  EXPECT_DOUBLE_EQ(j["critical"]["speed_m_s"].get<double>(), 200.0 / 3.6);
}

// A range from 0.01 km/h printed "0.0–100.0 km/h": as many decimals as tell it from zero.
TEST(HuntingReport, ALowSpeedIsNotPrintedAsZero) {
  HuntingResult r = test::stable_result();
  r.speeds.front() = 0.01 / 3.6;
  const std::string table = written(r, OutputFormat::table);
  EXPECT_TRUE(has(table, "speeds 0.01–500 km/h")) << table;
  EXPECT_TRUE(has(table, "from 0.01 km/h")) << table;
  EXPECT_TRUE(has(table, "f at 0.01 km/h")) << table;
  EXPECT_FALSE(has(table, "0.0–")) << table;
}

// The range's ends are speeds the user gave: printed as given, to at most 6 significant digits
// ("10–500 km/h", "72.5–333.333 km/h"), not "10.0–500.0 km/h" (docs/input.md, "Names and units
// in outputs"); in every place the report names them.
TEST(HuntingReport, TheGivenSpeedsArePrintedAsGiven) {
  const std::string round = written(test::stable_result(), OutputFormat::table);
  EXPECT_TRUE(has(round, "speeds 10–500 km/h")) << round;
  EXPECT_TRUE(has(round, "f at 10 km/h")) << round;
  EXPECT_FALSE(has(round, "10.0–")) << round;
  HuntingResult r = test::stable_result();
  r.speeds.front() = 72.5 / 3.6;
  r.speeds.back() = 1000.0 / 3.0 / 3.6;  // 333.333… km/h: six digits
  for (OutputFormat f : {OutputFormat::table, OutputFormat::markdown, OutputFormat::html}) {
    const std::string text = written(r, f);
    EXPECT_TRUE(has(text, "peeds 72.5–333.333 km/h")) << text;
    EXPECT_TRUE(has(text, "from 72.5 km/h to 333.333 km/h")) << text;
  }
}

// The reports say what the CSV and JSON hold (each branch's root with Im λ > 0; the real roots
// are left out: "every eigenvalue" was not true), and which command gives the nonlinear critical
// speed (railmodal hunting, since issue 20 item 5).
TEST(HuntingReport, NotesSayWhatTheFilesHoldAndWhatIsNotACommand) {
  const std::string markdown = written(test::stable_result(), OutputFormat::markdown);
  EXPECT_FALSE(has(markdown, "every eigenvalue")) << markdown;
  EXPECT_TRUE(has(markdown, "the real roots, which do not oscillate, are left out")) << markdown;
  EXPECT_TRUE(has(markdown, "'railmodal hunting SCENE' computes it")) << markdown;
  EXPECT_FALSE(has(markdown, "no command runs it yet")) << markdown;
}

// A strongly damped 40 Hz branch sets the full locus' scale (Re λ near −80 1/s) and the hunting
// crossing near Re λ = 0 is a few pixels: a zoomed panel shows the points damped less than 10 %.
TEST(HuntingReport, RootLocusHasAZoomedPanelNearTheBoundary) {
  HuntingResult r = test::two_interval_result();
  r.branches.push_back(test::hand_branch(
      "bogie yaw", r.speeds, [](double) { return 40.0; }, [](double) { return 0.3; }));
  const std::string html = written(r, OutputFormat::html);
  size_t charts = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++charts;
  EXPECT_EQ(charts, 3u);  // damping, root locus, and its zoom
  EXPECT_TRUE(has(html, "plot-root-locus-zoom")) << html;
  EXPECT_TRUE(has(html, "Near the stability boundary")) << html;
  // The zoom's Re λ range: the hunting branch's points (ζ < 10 %), within a few 1/s of zero, not
  // the bogie's −80.
  const size_t note = html.find("Re λ from ");
  ASSERT_NE(note, std::string::npos);
  const double left = std::stod(html.substr(note + std::string("Re λ from ").size()));
  EXPECT_GT(left, -3.0);
  EXPECT_LT(left, 0.0);
  // Without a strongly damped branch the full locus already shows the crossing: no zoom.
  EXPECT_FALSE(has(written(test::two_interval_result(), OutputFormat::html), "root-locus-zoom"));
}

}  // namespace
}  // namespace railmodal
