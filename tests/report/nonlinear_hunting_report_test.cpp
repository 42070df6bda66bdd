// The nonlinear-hunting report on results built by hand: the critical speed and amplitude, the
// linear critical speed beside them, both ramps, the holds, the bifurcation curve and the effects
// in every format; verdicts without a critical speed write words or null, never inf or NaN; a
// continuation branch, when given, in every format.
#include "railmodal/nonlinear_hunting_report.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "railmodal/limit_cycles.hpp"

namespace railmodal {
namespace {

// A ramp that lost its cycle at 65 m/s with 7.9 mm, after three half cycles above it.
RampDown hand_built_lost_ramp(double rate, double speed) {
  RampDown d;
  d.ramp_rate = rate;
  d.verdict = NonlinearHuntingVerdict::limit_cycle_dies_out;
  d.critical_speed = speed;
  d.amplitude = 0.0079;
  d.curve = {{75.0, 0.0105}, {70.0, 0.0095}, {66.0, 0.0084}, {64.0, 0.0038}, {62.0, 0.0001}};
  d.steps = 1234;
  return d;
}

NonlinearHuntingResult hand_built_converged_result() {
  NonlinearHuntingResult r;
  r.stated_rate = hand_built_lost_ramp(0.5, 66.021);
  r.halved_rate = hand_built_lost_ramp(0.25, 66.032);
  r.verdict = r.stated_rate.verdict;
  r.critical_speed = 66.052;
  r.amplitude = r.stated_rate.amplitude;
  r.curve = r.stated_rate.curve;
  r.convergence_difference = 0.011;
  r.richardson_critical_speed = 66.043;
  r.hold.lowest_surviving = 66.052;
  r.hold.highest_dying = 66.011;
  r.hold.doubled_hold_survives = true;
  r.hold.holds = {{66.021, false, 0.0079, 0.003, 40, 900}, {66.052, true, 0.0079, 0.0078, 300, 9000}};
  r.convergence = NonlinearConvergence::converged;
  r.converged = true;
  r.summary.method = "ramp-down";
  r.summary.checks.push_back({"bracket of the held critical speed, m/s", 0.041, 0.05, true});
  return r;
}

NonlinearHuntingOptions hand_built_both_effects() {
  NonlinearHuntingOptions o;
  o.start_speed = 75.0;
  o.end_speed = 50.0;
  return o;
}

std::string nonlinear_report_text(const NonlinearHuntingResult& r, const NonlinearHuntingOptions& o, OutputFormat f,
                    std::optional<double> linear = 66.318144, const LimitCycleBranch* branch = nullptr) {
  std::ostringstream out;
  write_nonlinear_hunting(out, r, o, f, "hand-built wheelset", Provenance{}, linear, branch);
  return out.str();
}

// A subcritical branch from the Hopf point at 66.318 m/s: two unstable orbits, the fold at
// 66.02 m/s and 6.5 mm, two stable orbits above it (the shape of the bundled scene's branch).
LimitCycleBranch hand_built_subcritical_branch() {
  LimitCycleBranch b;
  b.kind = LimitCycleBranchKind::subcritical;
  b.hopf_speed = 66.318144;
  b.hopf_frequency = 2.41;
  b.points = {{66.30, 0.0001, 0.415, false, 1.02, 1e-12},
              {66.10, 0.0030, 0.416, false, 1.3, 2e-11},
              {66.05, 0.0080, 0.420, true, 0.71, 5e-12},
              {66.40, 0.0100, 0.430, true, 0.52, 1e-11}};
  b.fold = LimitCycleBranchPoint{66.02, 0.0065, 0.418, false, 1.0, 3e-12};
  b.folds = {*b.fold};
  b.end = ContinuationEnd::amplitude_reached;
  b.flows = 321;
  b.summary.checks.push_back({"largest Newton residual of the branch", 2e-11,
                              std::numeric_limits<double>::infinity(), true});
  return b;
}

bool nonlinear_report_has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(NonlinearHuntingReport, TableGivesTheSpeedsTheAmplitudeAndTheEffects) {
  const std::string t = nonlinear_report_text(hand_built_converged_result(), hand_built_both_effects(), OutputFormat::table);
  EXPECT_TRUE(nonlinear_report_has(t, "railmodal hunting: hand-built wheelset")) << t;
  EXPECT_TRUE(nonlinear_report_has(t, "237.79 km/h (66.052 m/s)")) << t;  // the held critical speed
  EXPECT_TRUE(nonlinear_report_has(t, "7.90 mm")) << t;
  EXPECT_TRUE(nonlinear_report_has(t, "238.75 km/h (66.318 m/s)")) << t;  // the linear one beside it
  EXPECT_TRUE(nonlinear_report_has(t, "creep_saturation (Shen–Hedrick–Elkins, μ = 0.4")) << t;
  EXPECT_TRUE(nonlinear_report_has(t, "flange_contact (clearance 8.00 mm, stiffness 10 MN/m)")) << t;
  EXPECT_TRUE(nonlinear_report_has(t, "converged")) << t;
  EXPECT_TRUE(nonlinear_report_has(t, "continuation")) << t;  // what the ramp-down cannot show
  // The convergence check: halving the rate moved it by 0.011 m/s = 0.040 km/h.
  EXPECT_TRUE(nonlinear_report_has(t, "0.040")) << t;
}

TEST(NonlinearHuntingReport, WithoutEffectsTheLawIsSaidToBeLinear) {
  NonlinearHuntingOptions o = hand_built_both_effects();
  o.effects.clear();
  const std::string t = nonlinear_report_text(hand_built_converged_result(), o, OutputFormat::markdown);
  EXPECT_TRUE(nonlinear_report_has(t, "none: Kalker's linear creep law and no flange")) << t;
  EXPECT_FALSE(nonlinear_report_has(t, "Shen")) << t;
}

TEST(NonlinearHuntingReport, CsvHoldsEveryHalfCycleOfBothRamps) {
  const std::string csv = nonlinear_report_text(hand_built_converged_result(), hand_built_both_effects(), OutputFormat::csv);
  EXPECT_EQ(csv.rfind("ramp,ramp_rate [m/s²],half_cycle,speed [km/h],amplitude [mm]\n", 0), 0u) << csv;
  EXPECT_TRUE(nonlinear_report_has(csv, "stated,0.5,1,270,10.5\n")) << csv;
  // every digit the double needs (shortest round-trip): 62 m/s × 3.6 is 223.20000000000002 km/h
  EXPECT_TRUE(nonlinear_report_has(csv, "halved,0.25,5,223.20000000000002,0.1\n")) << csv;
  size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 1u + 5u + 5u);
}

TEST(NonlinearHuntingReport, JsonHasNullNeverInfOrNaN) {
  NonlinearHuntingResult r = hand_built_converged_result();
  const nlohmann::json j = nlohmann::json::parse(nonlinear_report_text(r, hand_built_both_effects(), OutputFormat::json));
  EXPECT_DOUBLE_EQ(j["critical_speed_m_s"].get<double>(), 66.052);
  EXPECT_DOUBLE_EQ(j["linear_critical_speed_m_s"].get<double>(), 66.318144);
  EXPECT_EQ(j["ramps"][0]["curve"]["speed_m_s"].size(), 5u);
  EXPECT_EQ(j["options"]["creep_saturation"]["law"], "shen_hedrick_elkins");
  EXPECT_DOUBLE_EQ(j["options"]["flange_contact"]["clearance_m"].get<double>(), 0.008);
  EXPECT_EQ(j["convergence"], "converged");

  // Survives to the end speed: no critical speed, an infinite difference, no linear one.
  NonlinearHuntingResult s;
  s.verdict = s.stated_rate.verdict = s.halved_rate.verdict = NonlinearHuntingVerdict::survives_to_end_speed;
  s.convergence_difference = std::numeric_limits<double>::infinity();
  s.convergence = NonlinearConvergence::not_applicable;
  const std::string text = nonlinear_report_text(s, hand_built_both_effects(), OutputFormat::json, std::nullopt);
  EXPECT_FALSE(nonlinear_report_has(text, "inf")) << text;
  EXPECT_FALSE(nonlinear_report_has(text, "NaN")) << text;
  const nlohmann::json k = nlohmann::json::parse(text);
  EXPECT_TRUE(k["critical_speed_m_s"].is_null());
  EXPECT_TRUE(k["convergence_difference_m_s"].is_null());
  EXPECT_TRUE(k["linear_critical_speed_m_s"].is_null());
  EXPECT_TRUE(k["amplitude_m"].is_null());
  const std::string table = nonlinear_report_text(s, hand_built_both_effects(), OutputFormat::table, std::nullopt);
  EXPECT_TRUE(nonlinear_report_has(table, "survives_to_end_speed: the limit cycle still lives at the end speed")) << table;
}

TEST(NonlinearHuntingReport, HtmlHasTheBifurcationPlot) {
  const std::string html = nonlinear_report_text(hand_built_converged_result(), hand_built_both_effects(), OutputFormat::html);
  EXPECT_TRUE(nonlinear_report_has(html, "<h2>Bifurcation plot</h2>")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "<svg")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "Limit-cycle amplitude against speed")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "critical speed (Hopf point)")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "clearance")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "</html>")) << html;
}

// The continuation's part of every format, on a hand-built branch (cli.hunting_continuation_json
// writes the bundled scene's; this is the sanitized build's run of the other four writers' part).
TEST(NonlinearHuntingReport, ContinuationInEveryFormat) {
  const LimitCycleBranch b = hand_built_subcritical_branch();
  const NonlinearHuntingResult r = hand_built_converged_result();
  const NonlinearHuntingOptions o = hand_built_both_effects();
  const std::string table = nonlinear_report_text(r, o, OutputFormat::table, 66.318144, &b);
  EXPECT_TRUE(nonlinear_report_has(table, "continuation of the limit cycles")) << table;
  EXPECT_TRUE(nonlinear_report_has(table, "subcritical: the branch leaves the Hopf point")) << table;
  EXPECT_TRUE(nonlinear_report_has(table, "amplitude_reached")) << table;
  const std::string md = nonlinear_report_text(r, o, OutputFormat::markdown, 66.318144, &b);
  EXPECT_TRUE(nonlinear_report_has(md, "## Continuation of the limit cycles")) << md;
  const std::string html = nonlinear_report_text(r, o, OutputFormat::html, 66.318144, &b);
  EXPECT_TRUE(nonlinear_report_has(html, "<h2>Continuation of the limit cycles</h2>")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "continuation: stable limit cycles")) << html;
  EXPECT_TRUE(nonlinear_report_has(html, "</html>")) << html;
  // CSV: one row of ramp "continuation" an orbit, after both ramps' five half cycles each.
  const std::string csv = nonlinear_report_text(r, o, OutputFormat::csv, 66.318144, &b);
  EXPECT_TRUE(nonlinear_report_has(csv, ",stable,period [s],largest_multiplier,newton_residual\n")) << csv;
  size_t rows = 0;
  for (size_t at = csv.find("\ncontinuation,"); at != std::string::npos; at = csv.find("\ncontinuation,", at + 1)) ++rows;
  EXPECT_EQ(rows, b.points.size()) << csv;
  const nlohmann::json j = nlohmann::json::parse(nonlinear_report_text(r, o, OutputFormat::json, 66.318144, &b));
  EXPECT_EQ(j["continuation"]["kind"], "subcritical");
  EXPECT_EQ(j["continuation"]["points"].size(), b.points.size());
  EXPECT_DOUBLE_EQ(j["continuation"]["fold"]["speed_m_s"].get<double>(), 66.02);
  EXPECT_EQ(j["continuation"]["end"], "amplitude_reached");
}

}  // namespace
}  // namespace railmodal
