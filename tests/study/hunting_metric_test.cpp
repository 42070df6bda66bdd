// The study metric "hunting_speed" (issue 20): the linear hunting critical speed of a variant, so
// that `railmodal compare` ranks designs by it. A design stable over the whole range is +∞
// ("above 500", as `railmodal stability` says it), one already unstable at the lowest speed 0:
// maximised, the first ranks best and the second last. Evaluated only when the study names the
// metric.
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "report/comparison_rows.hpp"
#include "study/metrics.hpp"
#include "study/study_files.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

VariantResult hunting(int index, const std::string& name, std::optional<double> speed) {
  VariantResult r;
  r.index = index;
  r.name = name;
  r.hunting_speed = speed;
  return r;
}

Study hand_study(const std::vector<std::string>& names) {
  Study s;
  s.name = "hand";
  for (const auto& n : names) s.variants.push_back({n, {}, {}, {}});
  return s;
}

TEST(HuntingMetric, IsAMetricOfSpeedShownInKmh) {
  EXPECT_TRUE(is_metric("hunting_speed"));
  EXPECT_FALSE(is_metric("hunting_speed:wheelset 1"));
  EXPECT_STREQ(metric_unit("hunting_speed"), "m/s");
  EXPECT_DOUBLE_EQ(*metric_value(hunting(0, "a", 50.0), "hunting_speed"), 50.0);
  EXPECT_TRUE(std::isinf(*metric_value(hunting(0, "a", kInf), "hunting_speed")));
  EXPECT_FALSE(metric_value(hunting(0, "a", std::nullopt), "hunting_speed"));  // not evaluated
  VariantResult failed = hunting(0, "a", 50.0);
  failed.failure = "unstable";
  EXPECT_FALSE(metric_value(failed, "hunting_speed"));
}

// Maximised: stable throughout (+∞) first, then by speed, unstable at the lowest speed (0) last
// among the feasible; a min constraint makes the last infeasible; a variant without wheelsets
// (no value) violates it by having none.
TEST(HuntingMetric, MaximisedRanksStableFirstAndUnstableAtTheLowestSpeedLast) {
  Study s = hand_study({"a", "stable", "hunts at once", "d", "no wheelsets"});
  s.ranking.objective.push_back({"hunting_speed", true, 1.0, {}});
  std::vector<VariantResult> results{hunting(0, "a", 200.0 / 3.6), hunting(1, "stable", kInf),
                                     hunting(2, "hunts at once", 0.0), hunting(3, "d", 300.0 / 3.6),
                                     hunting(4, "no wheelsets", std::nullopt)};
  Comparison c = rank_variants(s, results);
  std::vector<std::string> order;
  for (const auto& v : c.variants) order.push_back(v.result.name);
  EXPECT_EQ(order[0], "stable");
  EXPECT_EQ(order[1], "d");
  EXPECT_EQ(order[2], "a");
  EXPECT_EQ(std::find(order.begin(), order.end(), "hunts at once") - order.begin() >
                std::find(order.begin(), order.end(), "a") - order.begin(),
            true);

  s.ranking.constraints.push_back({"hunting_speed", 150.0 / 3.6, std::nullopt, {}});
  c = rank_variants(s, results);
  order.clear();
  for (const auto& v : c.variants) order.push_back(v.result.name);
  EXPECT_EQ(order, (std::vector<std::string>{"stable", "d", "a", "hunts at once", "no wheelsets"}));
  EXPECT_TRUE(c.variants[2].feasible);
  EXPECT_FALSE(c.variants[3].feasible);
  ASSERT_EQ(c.variants[3].violations.size(), 1u);
  EXPECT_EQ(c.variants[3].violations[0], "hunting_speed 0 km/h < 150 km/h");
  ASSERT_EQ(c.variants[4].violations.size(), 1u);
  EXPECT_EQ(c.variants[4].violations[0], "no hunting_speed");
  // People read the metric by its title, and +∞ as "above 500" (stable up to the scan's top, in
  // the words of `railmodal stability`; it read "none", a missing result, until the user audit of
  // 2026-11-28, F4), 0 as a speed below the range.
  std::ostringstream table;
  write_comparison(table, c, OutputFormat::table);
  EXPECT_NE(table.str().find("linear hunting speed, maximised [km/h]"), std::string::npos) << table.str();
  // The note shows the value as the column does (0.1 km/h), the limit as given.
  EXPECT_NE(table.str().find("linear hunting speed 0.0 km/h < 150 km/h"), std::string::npos) << table.str();
  EXPECT_EQ(table.str().find("none"), std::string::npos) << table.str();
  const std::vector<std::vector<std::string>> rows = report::comparison_rows(c);
  ASSERT_EQ(rows[1][1], "stable");
  EXPECT_EQ(rows[1][3], "above 500");
}

// +∞ is at least the scan's top in every format: "above 500" in the CSV's criterion and
// constrained columns, "above 500 km/h" in a violation's words (a max constraint it exceeds).
TEST(HuntingMetric, StableThroughoutReadsAboveTheScansTopInEveryFormat) {
  EXPECT_EQ(study::infinite_word("hunting_speed"), "above 500");
  EXPECT_EQ(study::shown("hunting_speed", kInf), "above 500 km/h");
  Study s = hand_study({"a", "stable"});
  s.ranking.objective.push_back({"hunting_speed", true, 1.0, {}});
  Comparison c = rank_variants(s, {hunting(0, "a", 200.0 / 3.6), hunting(1, "stable", kInf)});
  std::ostringstream csv;
  write_comparison(csv, c, OutputFormat::csv);
  EXPECT_NE(csv.str().find("\n1,stable,yes,,above 500,"), std::string::npos) << csv.str();
  // Constrained only (a ride study's hunting limit): its own column, and the note of a max.
  Study constrained = hand_study({"a", "stable"});
  constrained.ranking.constraints.push_back({"hunting_speed", std::nullopt, 400.0 / 3.6, {}});
  c = rank_variants(constrained, {hunting(0, "a", 200.0 / 3.6), hunting(1, "stable", kInf)});
  std::ostringstream table, constrained_csv;
  write_comparison(table, c, OutputFormat::table);
  EXPECT_NE(table.str().find("stable: linear hunting speed above 500 km/h > 400 km/h"), std::string::npos)
      << table.str();
  write_comparison(constrained_csv, c, OutputFormat::csv);
  EXPECT_NE(constrained_csv.str().find(",above 500,"), std::string::npos) << constrained_csv.str();
}

// In JSON a design stable throughout (+∞) and one with no value (no wheelsets) read differently:
// the scan's top, a number, flagged by hunting_speed_above_range, against null. Before, both
// objectives were null; until the user audit of 2026-11-28 (F4) +∞ was the string "none".
TEST(HuntingMetric, JsonTellsStableThroughoutFromNoValue) {
  Study s = hand_study({"a", "stable", "no wheelsets"});
  s.ranking.objective.push_back({"hunting_speed", true, 1.0, {}});
  const Comparison c = rank_variants(
      s, {hunting(0, "a", 200.0 / 3.6), hunting(1, "stable", kInf), hunting(2, "no wheelsets", std::nullopt)});
  std::ostringstream out;
  write_comparison(out, c, OutputFormat::json);
  const nlohmann::json j = nlohmann::json::parse(out.str());
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& v : j.at("variants")) by_name[v.at("name").get<std::string>()] = v;
  const double top = HuntingOptions{}.max_speed;  // 500 km/h, the scan `railmodal stability` makes
  EXPECT_EQ(by_name.at("stable").at("objective").get<double>(), top);
  EXPECT_EQ(by_name.at("stable").at("criteria").at(0).get<double>(), top);
  EXPECT_EQ(by_name.at("stable").at("hunting_speed_m_s").get<double>(), top);
  // km/h to the last bit or two of the m/s figure times 3.6
  EXPECT_NEAR(by_name.at("stable").at("hunting_speed_kmh").get<double>(), 500.0, 1e-9);
  EXPECT_TRUE(by_name.at("stable").at("hunting_speed_above_range").get<bool>());
  EXPECT_FALSE(by_name.at("a").at("hunting_speed_above_range").get<bool>());
  EXPECT_TRUE(by_name.at("no wheelsets").at("objective").is_null());
  EXPECT_TRUE(by_name.at("no wheelsets").at("criteria").at(0).is_null());
  EXPECT_FALSE(by_name.at("no wheelsets").contains("hunting_speed_m_s"));
  EXPECT_DOUBLE_EQ(by_name.at("a").at("objective").get<double>(), 200.0 / 3.6);
}

// A NaN (no value the analysis could give) reads as a value not there in every format: "-" in
// the table (it had read "-inf", the text of −∞), a blank CSV field, null in JSON.
TEST(HuntingMetric, NanIsNoValueInEveryFormat) {
  Study s = hand_study({"a", "undefined"});
  s.ranking.objective.push_back({"hunting_speed", true, 1.0, {}});
  const Comparison c = rank_variants(
      s, {hunting(0, "a", 200.0 / 3.6), hunting(1, "undefined", std::numeric_limits<double>::quiet_NaN())});
  const std::vector<std::vector<std::string>> rows = report::comparison_rows(c);
  ASSERT_EQ(rows.size(), 3u);
  const size_t criterion = 3;  // rank, variant, feasible, then the objective's criterion
  ASSERT_GT(rows[0].size(), criterion);
  ASSERT_EQ(rows[0][criterion], "linear hunting speed, maximised [km/h]");
  int seen = 0;  // both variants' rows must be there, or the checks below would check nothing
  for (const auto& row : rows) {
    if (row[1] == "undefined") {
      EXPECT_EQ(row[criterion], "-");
      ++seen;
    } else if (row[1] == "a") {
      EXPECT_EQ(row[criterion], "200.0");
      ++seen;
    }
  }
  EXPECT_EQ(seen, 2);
  std::ostringstream csv, json;
  write_comparison(csv, c, OutputFormat::csv);
  EXPECT_EQ(csv.str().find("inf"), std::string::npos) << csv.str();
  EXPECT_EQ(csv.str().find("nan"), std::string::npos) << csv.str();
  write_comparison(json, c, OutputFormat::json);
  const nlohmann::json j = nlohmann::json::parse(json.str());
  int undefined = 0;
  for (const auto& v : j.at("variants")) {
    if (v.at("name") == "undefined") {
      EXPECT_TRUE(v.at("criteria").at(0).is_null()) << v;
      ++undefined;
    }
  }
  EXPECT_EQ(undefined, 1);
}

TEST(HuntingMetric, OnlyAStudyThatNamesItPaysForIt) {
  Study s = hand_study({"a"});
  s.ranking.objective.push_back({"lowest_critical_speed", true, 1.0, {}});
  EXPECT_FALSE(hunting_options_of(s));
  s.ranking.constraints.push_back({"hunting_speed", 150.0 / 3.6, std::nullopt, {}});
  const std::optional<HuntingOptions> options = hunting_options_of(s);
  ASSERT_TRUE(options);
  EXPECT_EQ(options->threads, 1);  // the variants are spread over the threads
  EXPECT_DOUBLE_EQ(options->max_speed, HuntingOptions().max_speed);
  EXPECT_TRUE(options->conicities.empty());
}

// The book's wagon has no wheelsets: asked for, the metric has no value and the variant is still
// evaluated (its modes and critical speeds as always). A study file that asks for it of vehicles
// without wheelsets is refused when loaded (offered_metrics_test.cpp); one built in code is not.
TEST(HuntingMetric, AVehicleWithoutWheelsetsHasNoValueAndDoesNotFail) {
  Study s = load_study(write_study(example3_wagon(), "[ranking]\nmin_lowest_critical_speed = \"10 km/h\"\n"));
  s.ranking.constraints.push_back({"hunting_speed", 150.0 / 3.6, std::nullopt, {}});
  ASSERT_TRUE(hunting_options_of(s));
  const VariantResult r = evaluate_variant(s.variants[0], 0, s.deflection_rule, hunting_options_of(s));
  EXPECT_TRUE(r.ok()) << r.failure;
  EXPECT_FALSE(r.hunting_speed);
  EXPECT_FALSE(r.critical_speeds.empty());
  const std::vector<VariantResult> all = evaluate_study(s, {});
  ASSERT_EQ(all.size(), 1u);
  EXPECT_TRUE(all[0].ok()) << all[0].failure;
}

// A shard keeps the metric exactly, +∞ included; a study that does not ask writes no key.
TEST(HuntingMetric, ShardsCarryItExactly) {
  // The book's wagon has no wheelsets, so a study file may not ask it for the metric (it is
  // refused when loaded): the constraint is added in code.
  Study s = load_study(write_study(example3_wagon(), "[ranking]\nmax_lowest_critical_speed = \"900 km/h\"\n"));
  s.ranking.constraints.push_back({"hunting_speed", std::nullopt, 900.0 / 3.6, {}});
  for (double speed : {kInf, 0.0, 200.0 / 3.6}) {
    std::ostringstream shard;
    write_shard(shard, s, {}, {hunting(0, "base", speed)});
    EXPECT_NE(shard.str().find("\"hunting_speed_m_s\""), std::string::npos);
    const std::vector<VariantResult> back = read_shard(write_temp("hunting_shard.json", shard.str()), s);
    ASSERT_EQ(back.size(), 1u);
    ASSERT_TRUE(back[0].hunting_speed);
    EXPECT_EQ(*back[0].hunting_speed, speed);  // exact: the shard writes round-trip numbers
  }
  std::ostringstream without;
  write_shard(without, s, {}, {hunting(0, "base", std::nullopt)});
  EXPECT_EQ(without.str().find("hunting_speed"), std::string::npos);
}

// The table's figures of a criterion have one number of decimals, the metric's (0.1 km/h): the
// user audit of 2026-11-27 read "353", "348.6", "345" down one column. A figure too small for
// them keeps two significant digits; the CSV keeps every digit of the same numbers.
TEST(HuntingMetric, TableFiguresOfACriterionShareTheirDecimalsAndTheCsvKeepsEveryDigit) {
  const std::vector<std::pair<const char*, double>> kmh{
      {"a", 353.0}, {"b", 348.6123}, {"c", 345.04}, {"d", 99.96}, {"e", 0.004}};
  Study s = hand_study({"a", "b", "c", "d", "e"});
  s.ranking.objective.push_back({"hunting_speed", true, 1.0, {}});
  std::vector<VariantResult> results;
  for (const auto& [name, speed] : kmh) results.push_back(hunting(static_cast<int>(results.size()), name, speed / 3.6));
  const Comparison c = rank_variants(s, results);
  const std::map<std::string, std::string> shown{
      {"a", "353.0"}, {"b", "348.6"}, {"c", "345.0"}, {"d", "100.0"}, {"e", "0.004"}};
  size_t seen = 0;
  for (const auto& row : report::comparison_rows(c))
    if (shown.count(row[1])) {
      EXPECT_EQ(row[3], shown.at(row[1])) << row[1];
      ++seen;
    }
  EXPECT_EQ(seen, kmh.size());
  std::ostringstream csv;
  write_comparison(csv, c, OutputFormat::csv);
  EXPECT_NE(csv.str().find(",348.612"), std::string::npos) << csv.str();  // the digits the table leaves out
}

}  // namespace
}  // namespace railmodal::test
