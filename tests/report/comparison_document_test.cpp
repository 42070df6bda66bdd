// The design-comparison report (Markdown and HTML): what it claims about the winner follows
// from the ranking, the sweep tables and plots hold every evaluated variant, the curves are
// those of the base and the best variants, and the page needs nothing outside itself.
#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "report/text_format.hpp"
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

TEST(ComparisonReport, PeakTableHasTheBaseAndTheBestVariantsByRank) {
  const TwoAxleStudy& s = two_axle();
  const auto rows = table_after(s.report(OutputFormat::markdown), "## Peak responses");
  ASSERT_EQ(rows.size(), 2u + 1u + static_cast<size_t>(kReportBest));
  const RankedVariant* base = comparison_base(s.comparison);
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(cells(rows[2]).at(0), base->feasible ? "base" : "base (infeasible)");
  int shown = 0;
  for (const RankedVariant& v : s.comparison.variants) {
    if (&v == base || shown == kReportBest) continue;
    EXPECT_EQ(cells(rows[3 + shown]).at(0),
              std::to_string(v.rank) + ". " + v.result.name + (v.feasible ? "" : " (infeasible)"));
    ++shown;
  }
}

// The audit's two-axle wagon (user audit 2026-11-28b: 42.2 t on 1.2 MN/m leaf springs with
// φ = 0.1, rails of 18 and 25 m, speeds 20–200 km/h) and its study of three layouts: the stiff
// leaf B is the one feasible design (pitch critical speed 136.3 km/h ≥ 120 km/h on 18 m rails),
// the soft series layout C ranks second, infeasible (89.0 km/h), and the base third (105.4 km/h).
struct AuditWagonStudy {
  Study study;
  Comparison comparison;
  // `friction`: the leaf springs' relative friction φ, none when 0.
  explicit AuditWagonStudy(double friction) {
    const std::string leaf = R"(kind = "leaf", stiffness = "1.2 MN/m")" +
                             (friction > 0.0 ? ", relative_friction = " + std::to_string(friction) : std::string());
    write_temp("wagon.toml", R"([vehicle]
name = "Two-axle wagon, laden, audit"
template = "two-axle"
[body]
mass = "42.2 t"
cg_height = "1.0 m"
radius_of_gyration = { roll = "1.2 m", pitch = "4.04 m", yaw = "4.04 m" }
[suspension]
wheelbase = "8 m"
spring_spacing = "2.0 m"
spring = [{ )" + leaf + R"( }]
)");
    write_temp("scene.toml", R"([scene]
name = "18 m and 25 m rails"
vehicle = "wagon.toml"
dofs = "vertical"
[speed]
min = "20 km/h"
max = "200 km/h"
step = "0.5 km/h"
[[source]]
kind = "rail_joints"
rail_length = "18 m"
joints = "opposite"
dip_depth = "5 mm"
[[source]]
kind = "rail_joints"
rail_length = "25 m"
joints = "opposite"
dip_depth = "5 mm"
[[output]]
dof = "body.bounce"
[[output]]
dof = "body.pitch"
)");
    study = load_study(write_temp("study.toml", R"([study]
name = "three spring layouts"
vehicle = "wagon.toml"
scene = "scene.toml"
base = true
[[variant]]
name = "B stiff leaf"
overrides = { "suspension.spring[0].stiffness" = "2.0 MN/m" }
[[variant]]
name = "C leaf + coil in series"
overrides = { "suspension.spring" = [{ )" + leaf + R"( }, { kind = "coil", stiffness = "3 MN/m" }] }
[permissible_dynamic_deflection]
rule = "lehner"
service = "freight"
[ranking]
min_lowest_critical_speed = "120 km/h"
max_dynamic_deflection_ratio = 1
objective = [{ metric = "bounce_period", goal = "max" }]
)"));
    comparison = rank_variants(study, evaluate_study(study, {}));
  }
  std::string report(OutputFormat format) const {
    std::ostringstream out;
    write_comparison_report(out, study, comparison, comparison_curves(study, comparison, kReportBest), format);
    return out.str();
  }
};

// F5: the report draws what it says, the best variants by rank, an infeasible runner-up with
// its mark and the reason it fails, not the feasible winner alone.
TEST(ComparisonReport, InfeasibleRunnerUpIsDrawnAndMarked) {
  const AuditWagonStudy s(0.1);
  const auto& v = s.comparison.variants;
  ASSERT_EQ(v.size(), 3u);
  ASSERT_EQ(v[0].result.name, "B stiff leaf");
  ASSERT_TRUE(v[0].feasible);
  ASSERT_EQ(v[1].result.name, "C leaf + coil in series");
  ASSERT_FALSE(v[1].feasible);
  ASSERT_FALSE(v[2].feasible);  // the base
  const std::string md = s.report(OutputFormat::markdown);
  const auto peaks = table_after(md, "## Peak responses");
  ASSERT_EQ(peaks.size(), 2u + 3u) << md;
  EXPECT_EQ(cells(peaks[2]).at(0), "base (infeasible)");
  EXPECT_EQ(cells(peaks[3]).at(0), "1. B stiff leaf");
  EXPECT_EQ(cells(peaks[4]).at(0), "2. C leaf + coil in series (infeasible)");
  EXPECT_NE(md.find("for the base and the best 2 variants by rank, feasible or not"), std::string::npos) << md;
  const auto deflections = table_after(md, "## Permissible dynamic deflections");
  ASSERT_EQ(deflections.size(), 2u + 4u) << md;  // the leaf springs' limit each, and C's coils'
  EXPECT_EQ(cells(deflections[4]).at(0), "C leaf + coil in series (infeasible)");
  EXPECT_EQ(cells(deflections[5]).at(0), "C leaf + coil in series (infeasible)");
  EXPECT_NE(md.find("The runner-up **C leaf + coil in series** is infeasible: it violates lowest critical speed "),
            std::string::npos)
      << md;
  const std::string html = s.report(OutputFormat::html);
  EXPECT_NE(html.find("Drawn: the base and the best 2 variants by rank"), std::string::npos);
  EXPECT_EQ(count(html, ">2. C leaf + coil in series (infeasible)</text>"), count(html, "clipPath id=\"plot-curves-"));
}

// F6: B wins only because it alone is feasible; its bounce period is shorter than the base's,
// and the objective maximises it.
TEST(ComparisonReport, AWinnerWorseThanTheBaseSaysItWinsOnTheConstraints) {
  const AuditWagonStudy s(0.1);
  const RankedVariant* base = comparison_base(s.comparison);
  ASSERT_NE(base, nullptr);
  ASSERT_TRUE(s.comparison.variants[0].criteria[0] && base->criteria[0]);
  ASSERT_LT(*s.comparison.variants[0].criteria[0], *base->criteria[0]);  // 0.456 s against 0.589 s
  const std::string md = s.report(OutputFormat::markdown);
  EXPECT_NE(md.find("The winner is worse than the base on the objective: it wins only as the one feasible design."),
            std::string::npos)
      << md;
  // The bundled study's winner beats its base: no such sentence there.
  EXPECT_EQ(two_axle().report(OutputFormat::markdown).find("worse than the base"), std::string::npos);
}

// F6: the peaks are those of the frictionless linear model; the caption says so where a design
// has leaf friction, and only there.
TEST(ComparisonReport, PeakCaptionSaysTheAmplitudesAreFrictionless) {
  const std::string caption = "Leaf friction: Coulomb, in the resonance criterion only: these amplitudes are those of "
                              "the frictionless linear model";
  const std::string md = AuditWagonStudy(0.1).report(OutputFormat::markdown);
  EXPECT_NE(md.substr(md.find("## Peak responses")).find(caption), std::string::npos) << md;
  EXPECT_NE(AuditWagonStudy(0.1).report(OutputFormat::html).find(caption), std::string::npos);
  EXPECT_EQ(AuditWagonStudy(0.0).report(OutputFormat::markdown).find("Leaf friction"), std::string::npos);
}

// F9(a): a largest deflection found at the top speed of the scene may lie above it: said in the
// verdict and the table, and not of one inside the range.
TEST(ComparisonReport, AWorstDeflectionAtTheRangesEndSaysSo) {
  const AuditWagonStudy s(0.1);
  const auto worst_speed = [](const VariantResult& r) {
    const VariantResult::DeflectionCheck* worst = nullptr;
    for (const auto& d : r.deflections)
      if (!worst || d.deflection / d.permissible > worst->deflection / worst->permissible) worst = &d;
    return worst ? worst->speed * 3.6 : NAN;
  };
  // 1e-6 km/h: the grid's last speed is the scene's 200 km/h up to the round-off of its steps.
  ASSERT_NEAR(worst_speed(s.comparison.variants[0].result), 200.0, 1e-6);  // B, the winner
  const RankedVariant* base = comparison_base(s.comparison);
  ASSERT_LT(worst_speed(base->result), 199.0);  // the base's is inside the range (155.5 km/h)
  const std::string md = s.report(OutputFormat::markdown);
  EXPECT_NE(md.find("at 200.0 km/h, the range's end: the largest may lie above it."), std::string::npos) << md;
  const auto rows = table_after(md, "## Permissible dynamic deflections");
  ASSERT_EQ(rows.size(), 2u + 4u) << md;  // the base, B, C's leaf and coil stages
  EXPECT_EQ(cells(rows[2]).at(5).find("range's end"), std::string::npos) << rows[2];  // the base
  EXPECT_NE(cells(rows[3]).at(5).find("(the range's end: the largest may lie above it)"), std::string::npos) << rows[3];
}

// F8: the lowest critical speed names its mode (B's binding one is the pitch on 18 m rails,
// V = f·L, not the bounce), in the tables and in a CSV column of its own; chart titles and
// legends say which rails a source is.
TEST(ComparisonReport, LowestCriticalSpeedNamesItsModeAndSourcesTheirWavelength) {
  const AuditWagonStudy s(0.1);
  const VariantResult& b = s.comparison.variants[0].result;
  ASSERT_FALSE(b.critical_speeds.empty());
  EXPECT_EQ(b.critical_speeds.front().mode_name, "body pitch");
  const std::string expected = report::fixed(b.critical_speeds.front().speed * 3.6, 1) + " (body pitch)";
  const std::string md = s.report(OutputFormat::markdown);
  const auto ranked = table_after(md, "## Ranked variants");
  const auto head = cells(ranked.at(0));
  const size_t column = std::find(head.begin(), head.end(), "lowest critical speed [km/h]") - head.begin();
  ASSERT_LT(column, head.size()) << ranked.at(0);
  EXPECT_EQ(cells(ranked.at(2)).at(column), expected);
  std::ostringstream csv;
  write_comparison(csv, s.comparison, OutputFormat::csv);
  std::istringstream lines(csv.str());
  std::string heading, first;
  std::getline(lines, heading);
  std::getline(lines, first);
  EXPECT_NE(heading.find(",lowest_critical_speed [km/h],lowest_critical_speed_mode,static_deflection [mm],"),
            std::string::npos)
      << heading;
  EXPECT_TRUE(std::regex_search(first, std::regex(R"(,136\.[0-9]+,body pitch,51\.)"))) << first;
  const std::string html = s.report(OutputFormat::html);
  EXPECT_NE(html.find("[1] rail joints, Λ = 18 m: body.bounce displacement"), std::string::npos);
  EXPECT_NE(html.find("[2] rail joints, Λ = 25 m: body.pitch displacement"), std::string::npos);
  EXPECT_EQ(html.find("rail_joints"), std::string::npos);
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
  // An infeasible design is marked so (the base here: its bounce resonance on short rails lies
  // below the 90 km/h the study asks).
  const RankedVariant* base = comparison_base(s.comparison);
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(count(html, base->feasible ? ">base</text>" : ">base (infeasible)</text>"), curves);
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
