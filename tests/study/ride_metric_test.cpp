// The study metrics of the ride (issue 21, item 6): max_wz, max_nmv and
// rms_acceleration:<output>, read from results built by hand: their units, their values (+∞ for
// an unbounded ride, none without a ride), their ranking and their round trip through a shard.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "study/metrics.hpp"
#include "study/study_files.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// A variant whose ride has a floor acceleration (its Wz and RMS as given) and a force output.
VariantResult ridden(int index, const std::string& name, double floor_rms, double wz, double nmv,
                     bool unbounded = false) {
  VariantResult r;
  r.index = index;
  r.name = name;
  r.ride_evaluated = true;
  VariantResult::RideSummary floor{"floor over bogie 1", "m/s²", floor_rms, wz, unbounded};
  if (unbounded) floor.max_rms = 0.0, floor.max_wz.reset();
  r.ride = {floor, {"spring force", "N", 1500.0, std::nullopt, false}};
  r.max_nmv = nmv;
  return r;
}

TEST(RideMetric, NamesUnitsAndTitles) {
  EXPECT_TRUE(is_metric("max_wz"));
  EXPECT_TRUE(is_metric("max_nmv"));
  EXPECT_TRUE(is_metric("rms_acceleration:floor over bogie 1"));
  EXPECT_FALSE(is_metric("rms_acceleration:"));
  EXPECT_FALSE(is_metric("max_wz:floor"));
  EXPECT_STREQ(metric_unit("max_wz"), "");
  EXPECT_STREQ(metric_unit("max_nmv"), "");
  EXPECT_STREQ(metric_unit("rms_acceleration:floor over bogie 1"), "m/s^2");
  // Each RMS metric in its quantity's unit: a force in N, never as an acceleration (the audit).
  EXPECT_TRUE(is_metric("rms_force:spring force"));
  EXPECT_TRUE(is_metric("rms_displacement:spring deflection"));
  EXPECT_TRUE(is_metric("rms_velocity:floor over bogie 1"));
  EXPECT_FALSE(is_metric("rms_force:"));
  EXPECT_STREQ(metric_unit("rms_force:spring force"), "N");
  EXPECT_STREQ(metric_unit("rms_displacement:spring deflection"), "m");
  EXPECT_STREQ(metric_unit("rms_velocity:floor over bogie 1"), "m/s");
}

// What a table heads each RMS metric with: its output's unit, velocities in m/s (not km/h, the
// unit of the critical speeds), displacements in mm.
TEST(RideMetric, RmsHeadingsCarryTheOutputsUnit) {
  EXPECT_EQ(study::heading("rms_acceleration:floor"), "largest RMS acceleration at floor [m/s²]");
  EXPECT_EQ(study::heading("rms_force:spring force"), "largest RMS of spring force [N]");
  EXPECT_EQ(study::heading("rms_velocity:floor"), "largest RMS of floor [m/s]");
  EXPECT_EQ(study::heading("rms_displacement:spring deflection"), "largest RMS of spring deflection [mm]");
  EXPECT_EQ(study::shown("rms_force:spring force", 1500.0), "1500 N");
}

TEST(RideMetric, Values) {
  const VariantResult r = ridden(0, "a", 0.31, 2.4, 1.9);
  EXPECT_DOUBLE_EQ(*metric_value(r, "max_wz"), 2.4);  // the force has no Wz and does not count
  EXPECT_DOUBLE_EQ(*metric_value(r, "max_nmv"), 1.9);
  EXPECT_DOUBLE_EQ(*metric_value(r, "rms_acceleration:floor over bogie 1"), 0.31);
  EXPECT_FALSE(metric_value(r, "rms_acceleration:no such output"));
  EXPECT_DOUBLE_EQ(*metric_value(r, "rms_force:spring force"), 1500.0);
  // Unbounded: +∞, not a number the ranking could prefer.
  const VariantResult u = ridden(1, "undamped", 0.0, 0.0, 1.0, true);
  EXPECT_TRUE(std::isinf(*metric_value(u, "max_wz")));
  EXPECT_TRUE(std::isinf(*metric_value(u, "rms_acceleration:floor over bogie 1")));
  // No ride: no value.
  VariantResult none;
  EXPECT_FALSE(metric_value(none, "max_wz"));
  EXPECT_FALSE(metric_value(none, "max_nmv"));
}

// Minimised Wz: the smoothest design first, the unbounded one last; a max constraint on N_MV
// makes a rough design infeasible, and people read the metric by its title.
TEST(RideMetric, RanksTheSmoothestFirst) {
  Study s;
  s.name = "hand";
  for (const char* n : {"rough", "smooth", "undamped", "middle"}) s.variants.push_back({n, {}, {}, {}});
  s.ranking.objective.push_back({"max_wz", false, 1.0, {}});
  const std::vector<VariantResult> results{ridden(0, "rough", 0.6, 3.1, 3.2), ridden(1, "smooth", 0.2, 2.0, 1.1),
                                           ridden(2, "undamped", 0, 0, 5, true), ridden(3, "middle", 0.4, 2.5, 2.0)};
  Comparison c = rank_variants(s, results);
  std::vector<std::string> order;
  for (const auto& v : c.variants) order.push_back(v.result.name);
  EXPECT_EQ(order, (std::vector<std::string>{"smooth", "middle", "rough", "undamped"}));
  s.ranking.constraints.push_back({"max_nmv", std::nullopt, 2.5, {}});
  c = rank_variants(s, results);
  ASSERT_EQ(c.variants.size(), 4u);
  EXPECT_TRUE(c.variants[0].feasible);
  EXPECT_FALSE(c.variants[2].feasible);
  std::ostringstream table;
  write_comparison(table, c, OutputFormat::table);
  EXPECT_NE(table.str().find("largest Sperling Wz of the ride"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("unbounded"), std::string::npos) << table.str();
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(RideMetric, ShardsCarryTheRide) {
  const Study s = load_study(write_study(example3_wagon(), "[ranking]\nmax_lowest_critical_speed = \"900 km/h\"\n"));
  std::ostringstream shard;
  write_shard(shard, s, {}, {ridden(0, "base", 0.31, 2.4, 1.9)});
  const std::vector<VariantResult> back = read_shard(write_temp("ride_shard.json", shard.str()), s);
  ASSERT_EQ(back.size(), 1u);
  ASSERT_TRUE(back[0].ride_evaluated);
  ASSERT_EQ(back[0].ride.size(), 2u);
  EXPECT_EQ(back[0].ride[0].output, "floor over bogie 1");
  EXPECT_EQ(back[0].ride[0].max_rms, 0.31);  // exact: the shard writes round-trip numbers
  EXPECT_EQ(*back[0].ride[0].max_wz, 2.4);
  EXPECT_FALSE(back[0].ride[1].max_wz);
  EXPECT_EQ(*back[0].max_nmv, 1.9);
  // The largest Wz under the study metric's name; a shard written before 2026-11-28 under
  // `max_sperling_wz` is refused with both names, not read as missing a field.
  std::string old = shard.str();
  ASSERT_EQ(occurrences(old, "\"max_wz\":"), 2u) << old;
  for (size_t at = old.find("\"max_wz\":"); at != std::string::npos; at = old.find("\"max_wz\":", at))
    old.replace(at, 9, "\"max_sperling_wz\":");
  try {
    read_shard(write_temp("old_ride_shard.json", old), s);
    ADD_FAILURE() << "a shard with max_sperling_wz was read";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("'max_sperling_wz' is now 'max_wz'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("old_ride_shard.json"), std::string::npos) << e.what();
  }
  VariantResult plain;
  plain.name = "base";
  std::ostringstream without;
  write_shard(without, s, {}, {plain});
  EXPECT_EQ(without.str().find("\"ride\""), std::string::npos);
}

// The text of `document` from `heading` to the next `next` after it (or the end).
std::string section(const std::string& document, const std::string& heading, const std::string& next) {
  const size_t from = document.find(heading);
  if (from == std::string::npos) return "";
  const size_t to = document.find(next, from + heading.size());
  return document.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

// A partial N_MV (a floor point without a lateral output: the two-axle wagon's ride reads
// "vertical only") says so in compare as the ride says it: the table's and the document's cell
// "… (vertical only)", the document's per-speed ride table (Markdown and HTML), JSON's and the
// shard's max_nmv_partial, the CSV's column of that name; and a merge of shards labels what one
// run labels (user audit 2026-11-27c, the last stop's item 5; the per-speed table 2026-11-28).
TEST(RideMetric, APartialNmvSaysWhatItCoversInEveryFormat) {
  Study s = load_study(std::string(RAILMODAL_DATA_DIR) + "/studies/two_axle_wagon_ride_springs.toml");
  s.ranking.objective = {{"max_nmv", false, 1.0, {}}};
  s.ranking.constraints = {{"max_nmv", std::nullopt, 0.5, {}}};  // both violate it: the notes show it too
  const std::vector<VariantResult> results = evaluate_study(s, {});
  ASSERT_EQ(results.size(), 2u);
  for (const VariantResult& r : results) {
    ASSERT_TRUE(r.ok() && r.max_nmv) << r.failure;
    EXPECT_EQ(r.max_nmv_partial, "vertical only") << r.name;  // as the ride of its scene (golden ride JSON)
  }
  const Comparison c = rank_variants(s, results);
  std::ostringstream table, csv, json, md, html;
  write_comparison(table, c, OutputFormat::table);
  write_comparison(csv, c, OutputFormat::csv);
  write_comparison(json, c, OutputFormat::json);
  const ComparisonCurves curves = comparison_curves(s, c, kReportBest);
  write_comparison_report(md, s, c, curves, OutputFormat::markdown);
  write_comparison_report(html, s, c, curves, OutputFormat::html);
  // The criterion's cell, and the violation's note under the table.
  const std::string cell = study::table_figure(*results[0].max_nmv, 2) + " (vertical only)";
  EXPECT_NE(table.str().find(cell), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("(vertical only) > 0.5"), std::string::npos) << table.str();
  EXPECT_NE(md.str().find(cell), std::string::npos) << md.str();
  // The N_MV against speed: every cell of both variants at the ride's 4 speeds (40–100 km/h by
  // 20) is of a floor point without lateral output, so each says so, as the ride's table does.
  const std::string per_speed = "N_MV (estimate) at the worst floor point against speed";
  const std::string md_table = section(md.str(), "## " + per_speed, "\n## ");
  EXPECT_EQ(occurrences(md_table, " (vertical only) |"), 2u * 4u) << md_table;
  const std::string html_table = section(html.str(), "<h2>" + per_speed, "<h2>");
  EXPECT_EQ(occurrences(html_table, " (vertical only)</td>"), 2u * 4u) << html_table;
  EXPECT_NE(csv.str().find(",max_nmv_partial,"), std::string::npos) << csv.str();
  EXPECT_NE(csv.str().find(",vertical only,"), std::string::npos) << csv.str();
  const auto j = nlohmann::json::parse(json.str());
  for (const auto& v : j.at("variants")) EXPECT_EQ(v.at("max_nmv_partial"), "vertical only");
  // Through a shard and back.
  std::ostringstream shard;
  write_shard(shard, s, {}, results);
  const std::vector<VariantResult> back = read_shard(write_temp("partial_nmv_shard.json", shard.str()), s);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].max_nmv_partial, "vertical only");
  std::ostringstream merged;
  write_comparison(merged, rank_variants(s, back), OutputFormat::table);
  EXPECT_EQ(merged.str(), table.str());
  // One over both axes writes no key and no label.
  std::ostringstream full;
  write_shard(full, s, {}, {ridden(0, "base", 0.31, 2.4, 1.9)});
  EXPECT_EQ(full.str().find("max_nmv_partial"), std::string::npos);
}

// A study ranked by the RMS alone solves its ride with RideOptions::rms_only: the metric is the
// same number bit for bit (the same sums in the same order: ride.hpp), and Wz and N_MV, not
// computed, are absent rather than wrong. One naming Wz or N_MV anywhere keeps every index.
TEST(RideMetric, RankedByTheRmsAloneSkipsTheOtherIndices) {
  Study s = load_study(std::string(RAILMODAL_DATA_DIR) + "/studies/two_axle_wagon_ride_springs.toml");
  const std::string rms = "rms_acceleration:floor over the front axle, vertical";
  EXPECT_FALSE(ride_rms_only(s));  // its own ranking: max_wz
  s.ranking.objective = {{rms, false, 1.0, {}}};
  EXPECT_TRUE(ride_rms_only(s));
  s.ranking.constraints = {{"max_nmv", std::nullopt, 4.0, {}}};
  EXPECT_FALSE(ride_rms_only(s));
  s.ranking.constraints.clear();

  const VariantResult every = evaluate_variant(s.variants[1], 1, s.deflection_rule, std::nullopt, false);
  const VariantResult only = evaluate_variant(s.variants[1], 1, s.deflection_rule, std::nullopt, true);
  ASSERT_TRUE(every.ok() && only.ok()) << every.failure << only.failure;
  ASSERT_TRUE(metric_value(every, rms) && metric_value(only, rms));
  EXPECT_EQ(*metric_value(only, rms), *metric_value(every, rms));  // bit for bit
  ASSERT_EQ(only.ride.size(), every.ride.size());
  for (size_t i = 0; i < only.ride.size(); ++i) {
    EXPECT_EQ(only.ride[i].max_rms, every.ride[i].max_rms) << only.ride[i].output;
    EXPECT_FALSE(only.ride[i].max_wz) << only.ride[i].output;
  }
  EXPECT_TRUE(every.max_nmv && metric_value(every, "max_wz"));
  EXPECT_FALSE(only.max_nmv);
  EXPECT_FALSE(metric_value(only, "max_wz"));
  // evaluate_study takes the study's own need: its results are the RMS-only ones.
  const std::vector<VariantResult> evaluated = evaluate_study(s, {});
  ASSERT_EQ(evaluated.size(), 2u);
  EXPECT_EQ(*metric_value(evaluated[1], rms), *metric_value(every, rms));
  EXPECT_FALSE(evaluated[1].max_nmv);
}

}  // namespace
}  // namespace railmodal::test
