// The design-comparison report (Markdown and HTML): what it claims about the winner follows
// from the ranking, the sweep tables and plots hold every evaluated variant, the curves are
// those of the base and the best variants, and the page needs nothing outside itself.
#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// The bundled two-axle study: base + 5 spring deflections × 3 rail lengths, the softest ride
// whose bounce resonance stays at or above 90 km/h.
struct TwoAxleStudy {
  Study study = load_study(std::string(RAILMODAL_DATA_DIR) + "/studies/two_axle_rail_length_and_springs.toml");
  Comparison comparison = rank_variants(study, evaluate_study(study, {}));

  std::string report(OutputFormat format) const {
    std::ostringstream out;
    write_comparison_report(out, study, comparison, comparison_curves(study, comparison, kReportBest), format);
    return out.str();
  }
};

const TwoAxleStudy& two_axle() {
  static const TwoAxleStudy s;
  return s;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// The lines of the Markdown table that follows `heading`.
std::vector<std::string> table_after(const std::string& markdown, const std::string& heading) {
  std::istringstream in(markdown.substr(markdown.find(heading)));
  std::vector<std::string> rows;
  std::string line;
  bool started = false;
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) == 0) started = true, rows.push_back(line);
    else if (started) break;
  }
  return rows;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::stringstream s(row.substr(1));
  std::string cell;
  while (std::getline(s, cell, '|')) {
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    out.push_back(cell);
  }
  return out;
}

TEST(ComparisonReport, VerdictNamesTheWinnerAndTheRunnerUpFromTheRanking) {
  const TwoAxleStudy& s = two_axle();
  ASSERT_GE(s.comparison.variants.size(), 3u);
  const RankedVariant& winner = s.comparison.variants[0];
  const RankedVariant& runner = s.comparison.variants[1];
  ASSERT_TRUE(winner.feasible && runner.feasible);
  const std::string md = s.report(OutputFormat::markdown);
  EXPECT_NE(md.find("**" + winner.result.name + "** ranks first of 16 variants"), std::string::npos) << md;
  EXPECT_NE(md.find("ahead of the runner-up **" + runner.result.name + "**"), std::string::npos) << md;
  // The softest springs win: a longer period is what the objective asks for first, and the
  // winner's bounce period beats the runner-up's (the report says on which criterion).
  ASSERT_TRUE(winner.criteria[0] && runner.criteria[0]);
  EXPECT_GT(*winner.criteria[0], *runner.criteria[0]);
  // The criterion as docs/studies.md names it ("period:body bounce" is the period of body bounce).
  EXPECT_NE(md.find("on period of body bounce (maximised): "), std::string::npos) << md;
  EXPECT_NE(md.find("Against the base: period of body bounce "), std::string::npos) << md;
}

TEST(ComparisonReport, ConstraintSentenceCountsTheInfeasibleVariants) {
  const TwoAxleStudy& s = two_axle();
  size_t infeasible = 0;
  for (const RankedVariant& v : s.comparison.variants) infeasible += v.result.ok() && !v.feasible;
  ASSERT_GT(infeasible, 0u);  // soft springs on short rails resonate below 90 km/h
  const std::string md = s.report(OutputFormat::markdown);
  EXPECT_NE(md.find(": " + std::to_string(infeasible) + " of 16 evaluated variants violate it."), std::string::npos) << md;
}

TEST(ComparisonReport, RankedTableHoldsEveryVariantInRankOrder) {
  const TwoAxleStudy& s = two_axle();
  const auto rows = table_after(s.report(OutputFormat::markdown), "## Ranked variants");
  ASSERT_EQ(rows.size(), 2 + s.comparison.variants.size());  // header, rule, variants
  for (size_t i = 0; i < s.comparison.variants.size(); ++i) {
    const auto c = cells(rows[2 + i]);
    EXPECT_EQ(c.at(0), std::to_string(s.comparison.variants[i].rank));
    EXPECT_EQ(c.at(1), s.comparison.variants[i].result.name);
  }
}

// The spring deflection sets the bounce period, the rail length does not (T = 2π√(f/g), two-
// axle digest): each deflection's row holds one period, shared by its three rail lengths, and
// each rail length's row spans all five.
TEST(ComparisonReport, SweepTablesGroupTheVariantsByEachParameterValue) {
  const TwoAxleStudy& s = two_axle();
  const std::string md = s.report(OutputFormat::markdown);
  const auto springs = table_after(md, "### f: `suspension.spring[0].static_deflection`");
  ASSERT_EQ(springs.size(), 2u + 5u) << md;
  const auto head = cells(springs[0]);
  const size_t bounce = std::find(head.begin(), head.end(), "T body bounce [s]") - head.begin();
  ASSERT_LT(bounce, head.size()) << springs[0];
  for (size_t r = 2; r < springs.size(); ++r) {
    const auto c = cells(springs[r]);
    EXPECT_EQ(c.at(1), "3") << springs[r];                                // three rail lengths each
    EXPECT_EQ(c.at(bounce).find("–"), std::string::npos) << springs[r];  // one period, not a range
    const double f = std::stod(c.at(0)) * 1e-3;
    EXPECT_NEAR(std::stod(c.at(bounce)), 2 * M_PI * std::sqrt(f / 9.81), 2e-3 * 2 * M_PI * std::sqrt(f / 9.81))
        << "4 significant digits; g = 981 cm/s², the leaf spring's own deflection: " << springs[r];
  }
  const auto rails = table_after(md, "### L: `scene:source[0].rail_length`");
  ASSERT_EQ(rails.size(), 2u + 3u) << md;
  for (size_t r = 2; r < rails.size(); ++r) {
    EXPECT_EQ(cells(rails[r]).at(1), "5") << rails[r];
    EXPECT_NE(cells(rails[r]).at(bounce).find("–"), std::string::npos) << rails[r];
  }
}

// Column headers and verdicts in the words of the study and of docs/studies.md, not the
// metrics' key paths ("max period:body bounce [s]") or "0.33 kept".
TEST(ComparisonReport, TablesSpeakTheUsersWords) {
  const TwoAxleStudy& s = two_axle();
  const std::string md = s.report(OutputFormat::markdown);
  const auto ranked = cells(table_after(md, "## Ranked variants").at(0));
  EXPECT_NE(std::find(ranked.begin(), ranked.end(), "period of body bounce, maximised [s]"), ranked.end()) << md;
  EXPECT_NE(std::find(ranked.begin(), ranked.end(), "critical speed of body bounce, maximised [km/h]"), ranked.end());
  EXPECT_NE(std::find(ranked.begin(), ranked.end(), "largest dynamic deflection [% of permissible]"), ranked.end());
  EXPECT_EQ(md.find(" kept"), std::string::npos);
  const auto first = cells(table_after(md, "## Ranked variants").at(2));
  EXPECT_TRUE(std::regex_search(first.at(7), std::regex(R"(^[0-9]+\.[0-9] \(within\)$)")))
      << first.at(7);
  EXPECT_EQ(cells(table_after(md, "### f: ").at(0)).at(0), "f [mm]");  // the study's label and unit
  EXPECT_EQ(cells(table_after(md, "### L: ").at(0)).at(0), "L [m]");
  const auto deflections = table_after(md, "## Permissible dynamic deflections");
  EXPECT_EQ(cells(deflections.at(0)).back(), "verdict");
  EXPECT_EQ(cells(deflections.at(2)).back(), "within the limit");
}

// What a person reads of a page: its text outside code spans (where key paths are shown on
// purpose, "`suspension.spring[0].static_deflection`"), tags and the style sheet.
std::string prose(std::string text) {
  for (const char* pattern : {R"(<style>[\s\S]*?</style>)", R"(<code>[^<]*</code>)", R"(`[^`]*`)", R"(<[^>]*>)"})
    text = std::regex_replace(text, std::regex(pattern), " ");
  return text;
}

// No metric's key ("critical_speed:body bounce", "dynamic_deflection_ratio") reaches the text
// table, the Markdown or the HTML of any bundled study: their headings, notes and sentences
// (violations included) use the metrics' titles; the keys stay in CSV and JSON.
TEST(ComparisonReport, NoMetricKeyReachesThePagesOfTheBundledStudies) {
  const std::regex key(
      R"([a-z_]+:[a-z]|dynamic_deflection_ratio|lowest_critical_speed|static_deflection|metacentric_height)");
  for (const char* name :
       {"two_axle_rail_length_and_springs", "two_axle_joint_dip_deflection", "resort_against_fette"}) {
    const Study study = load_study(std::string(RAILMODAL_DATA_DIR) + "/studies/" + name + ".toml");
    const Comparison c = rank_variants(study, evaluate_study(study, {}));
    const auto curves = comparison_curves(study, c, kReportBest);
    std::ostringstream table, md, html, csv;
    write_comparison(table, c, OutputFormat::table);
    write_comparison(csv, c, OutputFormat::csv);
    write_comparison_report(md, study, c, curves, OutputFormat::markdown);
    write_comparison_report(html, study, c, curves, OutputFormat::html);
    const std::vector<std::pair<std::string, std::string>> pages{
        {"table", table.str()}, {"markdown", md.str()}, {"html", html.str()}};
    for (const auto& [format, page] : pages) {
      std::smatch found;
      const std::string text = prose(page);
      EXPECT_FALSE(std::regex_search(text, found, key)) << name << " " << format << ": " << found.str(0) << " in\n"
                                                        << text;
    }
    // The CSV is for programs: the raw names stay.
    EXPECT_TRUE(std::regex_search(csv.str(), key)) << name;
  }
}

TEST(ComparisonReport, PeakTableHasTheBaseAndTheBestFeasibleVariants) {
  const TwoAxleStudy& s = two_axle();
  const auto rows = table_after(s.report(OutputFormat::markdown), "## Peak responses");
  ASSERT_EQ(rows.size(), 2u + 1u + static_cast<size_t>(kReportBest));
  EXPECT_EQ(cells(rows[2]).at(0), "base");
  int shown = 0;
  for (const RankedVariant& v : s.comparison.variants) {
    if (!v.feasible || shown == kReportBest) continue;
    EXPECT_EQ(cells(rows[3 + shown]).at(0), std::to_string(v.rank) + ". " + v.result.name);
    ++shown;
  }
}

TEST(ComparisonReport, HtmlIsOnePageWithItsPlotsInline) {
  const TwoAxleStudy& s = two_axle();
  const std::string html = s.report(OutputFormat::html);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</body></html>"), std::string::npos);
  for (const char* outside : {"<script", "src=", "href=", "<link", "@import"})
    EXPECT_EQ(html.find(outside), std::string::npos) << outside;
  // Two swept parameters, each against the periods and the objective; then one chart per
  // curve of the scene (its rail joints on the body's bounce and pitch).
  EXPECT_EQ(count(html, "clipPath id=\"plot-sweep-periods-"), 2u);
  EXPECT_EQ(count(html, "clipPath id=\"plot-sweep-objective-"), 2u);
  const size_t curves = count(html, "clipPath id=\"plot-curves-");
  EXPECT_GE(curves, 1u);
  EXPECT_EQ(count(html, "<svg"), 4u + curves);
  // Each curve chart has the base (dashed) and the best variants in its legend.
  EXPECT_EQ(count(html, ">base</text>"), curves);
  for (int k = 0; k < kReportBest; ++k) {
    const RankedVariant& v = s.comparison.variants[k];
    ASSERT_TRUE(v.feasible);
    EXPECT_EQ(count(html, ">" + std::to_string(v.rank) + ". " + v.result.name + "</text>"), curves) << v.result.name;
  }
  // Winner, against the base, the one constraint, the winner's permissible deflections.
  EXPECT_EQ(count(html, "<li>"), 1u + 1u + 1u + 1u);
  EXPECT_NE(html.find("<li>The winner keeps the permissible dynamic deflections"), std::string::npos);
  // The deflection table: the base and the best variants, one row each for the leaf springs' limit.
  EXPECT_NE(html.find("<h2>Permissible dynamic deflections</h2>"), std::string::npos);
  EXPECT_EQ(count(html, "worst of 4"), 1u + static_cast<size_t>(kReportBest));
}

TEST(ComparisonReport, NoFeasibleVariantIsSaidPlainly) {
  TwoAxleStudy s;
  s.study.ranking.constraints = {{"bounce_period", 10.0, std::nullopt, {}}};  // 10 s: no wagon
  s.comparison = rank_variants(s.study, evaluate_study(s.study, {}));
  const std::string md = s.report(OutputFormat::markdown);
  EXPECT_NE(md.find("No variant meets every constraint"), std::string::npos) << md;
  EXPECT_NE(md.find(": 16 of 16 evaluated variants violate it."), std::string::npos) << md;
  // Nothing is feasible: the curves are those of the best-ranked evaluated variants.
  EXPECT_EQ(table_after(md, "## Peak responses").size(), 2u + 1u + static_cast<size_t>(kReportBest));
}

TEST(ComparisonReport, TheRankedFormatsDoNotNeedTheStudyButTheReportsDo) {
  const TwoAxleStudy& s = two_axle();
  std::ostringstream table, via_report;
  write_comparison(table, s.comparison, OutputFormat::table);
  write_comparison_report(via_report, s.study, s.comparison, {}, OutputFormat::table);
  EXPECT_EQ(table.str(), via_report.str());
  std::ostringstream out;
  EXPECT_THROW(write_comparison(out, s.comparison, OutputFormat::html), std::invalid_argument);
  EXPECT_EQ(output_format_from_string("markdown"), OutputFormat::markdown);
  EXPECT_EQ(output_format_from_string("html"), OutputFormat::html);
}

}  // namespace
}  // namespace railmodal::test
