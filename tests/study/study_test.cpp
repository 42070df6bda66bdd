// Study files: overrides, sweeps, samples, errors; ranking; parallel evaluation.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "report/streamed_comparison.hpp"
#include "study/study_files.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string study_file(const std::string& body, const std::string& head = "") {
  return write_study(example3_wagon(), body, head);
}

double vertical_stiffness(const Vehicle& v) { return series_stiffness(v.elements.front().vertical_stages); }

// The error a study gives, with its location.
InputError study_error(const std::string& body) { return study_error_at(study_file(body), body); }

TEST(StudyReader, OverrideWithUnitsChangesTheSpringBeforeTheReaderChecksIt) {
  const Study s = load_study(study_file(R"(
[[variant]]
name = "soft"
overrides = { "suspension.spring[0].static_deflection" = "80 mm" }
)"));
  ASSERT_EQ(s.variants.size(), 2u);
  EXPECT_EQ(s.variants[0].name, "base");
  EXPECT_EQ(s.variants[1].name, "soft");
  // Same load per spring, so the stiffness scales as 1/f: exact up to rounding of one division.
  EXPECT_NEAR(vertical_stiffness(s.variants[1].vehicle) / vertical_stiffness(s.variants[0].vehicle), 57.2 / 80.0, 1e-14);
  ASSERT_EQ(s.variants[1].parameters.size(), 1u);
  EXPECT_EQ(s.variants[1].parameters[0].first, "suspension.spring[0].static_deflection");
  EXPECT_EQ(s.variants[1].parameters[0].second, "80 mm");
}

TEST(StudyReader, OverrideMayReplaceAWholeTable) {
  const Study s = load_study(study_file(R"(
[[variant]]
name = "coil"
overrides = { "suspension.spring" = [{ stiffness = "900 kgf/cm", kind = "coil" }] }
)"));
  EXPECT_DOUBLE_EQ(vertical_stiffness(s.variants[1].vehicle), 900 * kKgfPerCm);
  EXPECT_EQ(s.variants[1].vehicle.elements.front().vertical_stages.front().kind, "coil");
  // Shown on one line with sorted keys, whatever order the TOML library keeps.
  EXPECT_EQ(s.variants[1].parameters[0].second, "[{ kind = \"coil\", stiffness = \"900 kgf/cm\" }]");
}

TEST(StudyReader, ElementOfTheGeneralFormIsPickedByName) {
  write_temp("general.toml", R"(
[vehicle]
name = "two springs"
[[body]]
name = "body"
mass = "10 t"
radius_of_gyration = { roll = "1 m", pitch = "2 m", yaw = "2 m" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "yaw"]
[[element]]
name = "front spring"
upper = "body"
point = ["2 m", "0 m", "0 m"]
vertical = { stiffness = "1000 kgf/cm" }
[[element]]
name = "rear spring"
upper = "body"
point = ["-2 m", "0 m", "0 m"]
vertical = { stiffness = "1000 kgf/cm" }
)");
  const Study s = load_study(study_file(R"(
[[variant]]
name = "stiff rear"
vehicle = "general.toml"
overrides = { 'element."rear spring".vertical.stiffness' = "2000 kgf/cm" }
)"));
  const Vehicle& v = s.variants[1].vehicle;
  EXPECT_DOUBLE_EQ(series_stiffness(v.elements[0].vertical_stages), 1000 * kKgfPerCm);
  EXPECT_DOUBLE_EQ(series_stiffness(v.elements[1].vertical_stages), 2000 * kKgfPerCm);
}

// A variant's vehicle path the system cannot follow is the study's error at the key, with the
// system's reason; std::filesystem::exists threw it as an internal error (issue 18, item 12).
TEST(StudyReader, UnreachableVehiclePathNamesTheKey) {
  std::string long_name;
  for (int i = 0; i < 2500; ++i) long_name += "a/";
  const InputError e = study_error("\n[[variant]]\nname = \"far\"\nvehicle = \"" + long_name + "wagon.toml\"\n");
  EXPECT_EQ(e.line(), 8);
  EXPECT_EQ(e.column(), 11);
  EXPECT_NE(e.message().find("key 'variant[0].vehicle': cannot reach the file"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("File name too long"), std::string::npos) << e.what();
}

TEST(StudyReader, BadOverridesNameTheStudyLineVariantAndKey) {
  // Unknown key: the vehicle reader's complaint, sent back to the study's line.
  InputError e = study_error("\n[[variant]]\nname = \"typo\"\noverrides = { \"suspension.spring[0].static_deflecton\" = \"80 mm\" }\n");
  EXPECT_NE(e.file().find("study.toml"), std::string::npos);
  EXPECT_EQ(e.line(), 8);
  EXPECT_NE(e.message().find("variant 'typo': key 'suspension.spring[0].static_deflecton': unknown key"), std::string::npos)
      << e.what();
  // Wrong unit.
  e = study_error("\n[[variant]]\nname = \"unit\"\noverrides = { \"body.cg_height\" = \"100 kgf\" }\n");
  EXPECT_EQ(e.line(), 8);
  EXPECT_NE(e.message().find("variant 'unit': key 'body.cg_height': expected a length"), std::string::npos) << e.what();
  // A value the reader rejects.
  e = study_error("\n[[variant]]\nname = \"negative\"\noverrides = { \"suspension.wheelbase\" = \"-1 m\" }\n");
  EXPECT_NE(e.message().find("variant 'negative': key 'suspension.wheelbase': must be positive"), std::string::npos) << e.what();
  // A path that does not exist in the file.
  e = study_error("\n[[variant]]\nname = \"nowhere\"\noverrides = { \"secondary.spring.stiffness\" = \"1 kgf/cm\" }\n");
  EXPECT_EQ(e.line(), 8);
  EXPECT_NE(e.message().find("no key 'secondary' in the file"), std::string::npos) << e.what();
  // An index beyond the array.
  e = study_error("\n[[variant]]\nname = \"beyond\"\noverrides = { \"suspension.spring[3].stiffness\" = \"1 kgf/cm\" }\n");
  EXPECT_NE(e.message().find("has 1 entries: [3] is beyond them"), std::string::npos) << e.what();
  // A sweep value that the scene rejects names the sweep's line and the generated variant.
  e = study_error("\n[[sweep]]\nname = \"L\"\nparameters = [{ scene_key = \"source[0].rail_length\", values = [\"10 m\", \"-1 m\"] }]\n");
  EXPECT_EQ(e.line(), 8);
  EXPECT_NE(e.message().find("variant 'L: rail_length = -1 m': key 'source[0].rail_length': must be positive"),
            std::string::npos)
      << e.what();
}

TEST(StudyReader, GridIsTheProductWithTheFirstParameterSlowest) {
  const Study s = load_study(study_file(R"(
[[sweep]]
name = "g"
parameters = [
  { key = "suspension.spring[0].static_deflection", from = "40 mm", to = "80 mm", step = "20 mm", label = "f" },
  { scene_key = "source[0].rail_length", values = ["10 m", "15 m"], label = "L" },
]
)",
                                        "base = false\n"));
  ASSERT_EQ(s.variants.size(), 6u);  // 3 deflections × 2 rail lengths
  const char* names[] = {"g: f = 40 mm, L = 10 m", "g: f = 40 mm, L = 15 m", "g: f = 60 mm, L = 10 m",
                         "g: f = 60 mm, L = 15 m", "g: f = 80 mm, L = 10 m", "g: f = 80 mm, L = 15 m"};
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(s.variants[i].name, names[i]);
  EXPECT_EQ(s.variants[5].parameters[1].first, "scene:source[0].rail_length");
  EXPECT_DOUBLE_EQ(s.variants[5].scene.sources[0]->wavelength(), 15.0);  // rail joints repeat every rail
  // Stiffness ∝ 1/f under the same load.
  EXPECT_NEAR(vertical_stiffness(s.variants[0].vehicle) / vertical_stiffness(s.variants[4].vehicle), 2.0, 1e-14);
}

TEST(StudyReader, GridSizeIsCheckedWithoutWrappingAround) {
  // 65 536⁴ = 2^64 points: a running product in 64 bits wraps to 0, which would be an empty
  // sweep and no error. The limit (a million variants in the study) is met on the second factor.
  std::string parameters;
  for (const char* key : {"body.cg_height", "suspension.wheelbase", "suspension.spring_spacing",
                          "suspension.spring[0].static_deflection"})
    parameters += std::string("  { key = \"") + key + "\", from = \"1 mm\", to = \"65536 mm\", step = \"1 mm\" },\n";
  const InputError e = study_error("\n[[sweep]]\nname = \"huge\"\nparameters = [\n" + parameters + "]\n");
  EXPECT_EQ(e.line(), 8);
  EXPECT_NE(e.message().find("the grid would take the study over a million variants"), std::string::npos) << e.what();
  // The limit is the study's: a grid of exactly 10^6 points, or a sample of 10^6, is one too
  // many beside the base (checked before any variant is made, so this test stays fast).
  const InputError grid = study_error(R"(
[[sweep]]
parameters = [{ key = "body.cg_height", from = "1 mm", to = "1000 mm", step = "1 mm" },
              { key = "suspension.wheelbase", from = "1 mm", to = "1000 mm", step = "1 mm" }]
)");
  EXPECT_NE(grid.message().find("the grid would take the study over a million variants"), std::string::npos) << grid.what();
  const InputError sample = study_error(R"(
[[sweep]]
sample = { count = 1000000 }
parameters = [{ key = "body.cg_height", from = "1.0 mm", to = "1000.0 mm" }]
)");
  EXPECT_EQ(sample.line(), 7);
  EXPECT_NE(sample.message().find("key 'sweep[0].sample.count': would take the study over a million variants"),
            std::string::npos)
      << sample.what();
}

TEST(StudyReader, SampleIsSeededAndPortable) {
  const std::string body = R"(
[[sweep]]
name = "box"
parameters = [{ key = "suspension.spring[0].static_deflection", from = "40.0 mm", to = "80.0 mm" }]
sample = { count = 3, seed = 42 }
)";
  const Study s = load_study(study_file(body, "base = false\n"));
  ASSERT_EQ(s.variants.size(), 3u);
  EXPECT_EQ(s.variants[0].name, "box #1");
  // The first uniforms of xoshiro256** seeded by splitmix64(42), computed independently
  // (Python integers): the same on every platform, so compared exactly.
  const double u[] = {0.08386297105988216, 0.3789802506626686, 0.6800434110281394};
  for (int i = 0; i < 3; ++i) {
    const std::string& text = s.variants[i].parameters[0].second;
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), 40.0 + u[i] * (80.0 - 40.0)) << text;
    EXPECT_EQ(text.substr(text.size() - 3), " mm");
  }
  // A second reading gives the same points.
  const Study again = load_study(study_file(body, "base = false\n"));
  for (int i = 0; i < 3; ++i) EXPECT_EQ(again.variants[i].parameters, s.variants[i].parameters);
}

TEST(StudyReader, AShardReadsOnlyItsOwnVariants) {
  // Indices: 0 base, 1 soft, 2 stiff, 3 bad (wheelbase -1 m, line 16). Shard 1 of 2 reads 0 and 2.
  const std::string path = study_file(R"(
[[variant]]
name = "soft"
overrides = { "suspension.spring[0].static_deflection" = "80 mm" }

[[variant]]
name = "stiff"
overrides = { "suspension.spring[0].static_deflection" = "40 mm" }

[[variant]]
name = "bad"
overrides = { "suspension.wheelbase" = "-1 m" }
)");
  const Study shard = load_study(path, [](int index) { return in_shard(index, 1, 2); });
  ASSERT_EQ(shard.variants.size(), 4u);  // every variant named, for the shard's JSON and the merge
  EXPECT_EQ(shard.variants[3].name, "bad");
  EXPECT_TRUE(shard.variants[0].read);
  EXPECT_TRUE(shard.variants[2].read);
  EXPECT_FALSE(shard.variants[1].read);
  EXPECT_TRUE(shard.variants[1].vehicle.elements.empty());
  EXPECT_EQ(shard.variants[1].parameters[0].second, "80 mm");
  // Read later, a variant is the one a load that selects it reads (the same code on the same
  // files: equal to the last bit).
  const StudyVariant soft = read_variant(shard, 1);
  EXPECT_TRUE(soft.read);
  EXPECT_EQ(soft.name, "soft");
  const Study all_but_bad = load_study(path, [](int index) { return index != 3; });
  ASSERT_TRUE(all_but_bad.variants[1].read);
  EXPECT_EQ(vertical_stiffness(soft.vehicle), vertical_stiffness(all_but_bad.variants[1].vehicle));
  EXPECT_NE(vertical_stiffness(soft.vehicle), vertical_stiffness(shard.variants[0].vehicle));
  // The other shard's bad override is that shard's error, with the study's line and key.
  try {
    read_variant(shard, 3);
    ADD_FAILURE() << "no error for the bad variant";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 16);
    EXPECT_NE(e.message().find("variant 'bad': key 'suspension.wheelbase': must be positive"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_study(path), InputError);  // a whole load checks every variant
  EvaluationOptions own, other;
  own.threads = other.threads = 1;
  own.shards = other.shards = 2;
  own.shard = 1;
  other.shard = 2;
  EXPECT_EQ(evaluate_study(shard, own).size(), 2u);
  EXPECT_THROW(evaluate_study(shard, other), std::invalid_argument);  // variants it never read
}

TEST(StudyReader, StudyFilesAreEveryFileTheStudyIsReadFrom) {
  // Shard 1 of 4 reads the base (the resort car) only; the Fette car is another shard's, and
  // still the study's file: no output of any shard may be written over it.
  namespace fs = std::filesystem;
  const std::string data = RAILMODAL_DATA_DIR;
  const Study shard =
      load_study(data + "/studies/resort_against_fette.toml", [](int index) { return in_shard(index, 1, 4); });
  ASSERT_FALSE(shard.variants.back().read);
  const std::vector<std::string> files = study_files(shard);
  for (const char* expected : {"/studies/resort_against_fette.toml", "/scenes/fette_car_10m_rails.toml",
                               "/vehicles/resort_car.toml", "/vehicles/fette_car.toml"})
    EXPECT_EQ(std::count_if(files.begin(), files.end(),
                            [&](const std::string& file) { return fs::equivalent(file, data + expected); }),
              1)
        << expected;
  EXPECT_EQ(files.size(), 4u);
}

TEST(StudyReader, RankingKeysAreChecked) {
  InputError e = study_error("\n[ranking]\nmin_critical_speed = \"90 mm\"\n");
  EXPECT_NE(e.message().find("key 'ranking.min_critical_speed': expected a speed"), std::string::npos) << e.what();
  e = study_error("\n[ranking]\nobjective = [{ metric = \"comfort\", goal = \"max\" }]\n");
  EXPECT_NE(e.message().find("unknown metric 'comfort'"), std::string::npos) << e.what();
  e = study_error("\n[[variant]]\nname = \"base\"\n");
  EXPECT_NE(e.message().find("variant 'base': another variant has this name"), std::string::npos) << e.what();
}

// Results made by hand, to test the ranking alone.
VariantResult result(int index, const std::string& name, double bounce_period, double critical_speed) {
  VariantResult r;
  r.index = index;
  r.name = name;
  r.modes.push_back({"body bounce", "oscillatory", 1.0 / bounce_period, bounce_period, 0.0});
  r.critical_speeds.push_back({critical_speed, 0, "rail_joints", 1, "body bounce", false});
  r.critical_speeds_evaluated = true;  // as a variant whose ranking reads them
  return r;
}

Study named(const std::vector<std::string>& names) {
  Study s;
  s.name = "hand";
  for (const auto& n : names) s.variants.push_back({n, {}, {}, {}});
  return s;
}

TEST(Ranking, ConstraintsThenLexicographicCriteriaThenStudyOrder) {
  Study s = named({"a", "b", "c", "d", "e"});
  s.ranking.constraints.push_back({"lowest_critical_speed", 20.0, std::nullopt, {}});
  s.ranking.objective.push_back({"period:body bounce", true, 1.0, {}});
  s.ranking.objective.push_back({"lowest_critical_speed", true, 1.0, {}});
  std::vector<VariantResult> results{result(0, "a", 0.8, 25.0), result(1, "b", 0.9, 15.0), result(2, "c", 0.8, 30.0),
                                     result(3, "d", 0.8, 30.0), result(4, "e", 1.0, 30.0)};
  results[4].failure = "unstable";
  const Comparison c = rank_variants(s, results);
  std::vector<std::string> order;
  for (const auto& v : c.variants) order.push_back(v.result.name);
  // c and d tie on both criteria: study order; b is infeasible; e failed.
  EXPECT_EQ(order, (std::vector<std::string>{"c", "d", "a", "b", "e"}));
  EXPECT_EQ(c.variants[0].rank, 1);
  EXPECT_TRUE(c.variants[2].feasible);
  EXPECT_FALSE(c.variants[3].feasible);
  ASSERT_EQ(c.variants[3].violations.size(), 1u);
  EXPECT_NE(c.variants[3].violations[0].find("54 km/h < 72 km/h"), std::string::npos) << c.variants[3].violations[0];
  EXPECT_FALSE(c.variants[4].feasible);
  EXPECT_DOUBLE_EQ(*c.variants[0].objective, 0.8);
}

TEST(Ranking, WeightedSumIsMinimised) {
  Study s = named({"a", "b"});
  s.ranking.weighted = true;
  s.ranking.objective.push_back({"period:body bounce", true, 100.0, {}});  // 1 s of period is worth 100 m/s
  s.ranking.objective.push_back({"lowest_critical_speed", true, 1.0, {}});
  const Comparison c = rank_variants(s, {result(0, "a", 1.0, 20.0), result(1, "b", 0.8, 45.0)});
  // a: −(100·1.0 + 20) = −120; b: −(80 + 45) = −125: b wins.
  EXPECT_EQ(c.variants[0].result.name, "b");
  EXPECT_DOUBLE_EQ(*c.variants[0].objective, -125.0);
  EXPECT_DOUBLE_EQ(*c.variants[1].objective, -120.0);
  // The table says each criterion's goal and weight in one parenthesis (was "(maximised)
  // (weight 100)").
  std::ostringstream table;
  write_comparison(table, c, OutputFormat::table);
  EXPECT_NE(table.str().find("objective: period of body bounce (maximised, weight 100) + lowest critical speed "
                             "(maximised, weight 1)\n"),
            std::string::npos)
      << table.str();
}

// A study written for "bogies pitch, in phase" (since renamed "bogies pitch (repeated)", issue 17
// item 8) lost that metric silently: every variant lacked it. It is an error at the study's key.
TEST(Ranking, AModeNoVariantHasIsAnErrorAtTheStudysKey) {
  Study s = named({"a", "b"});
  s.source = "study.toml";
  s.ranking.objective.push_back({"period:body bounce", true, 1.0, {"ranking.objective[0].metric", {7, 15}}});
  s.ranking.constraints.push_back(
      {"period:bogies pitch, in phase", std::nullopt, 0.3, {"ranking.constraints[0].metric", {9, 17}}});
  try {
    rank_variants(s, {result(0, "a", 1.0, 20.0), result(1, "b", 0.8, 45.0)});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "study.toml:9:17: error: key 'ranking.constraints[0].metric': no variant has a mode named 'bogies pitch, "
              "in phase'; the modes are 'body bounce' (README, \"Mode names\")");
  }
  // A name some variant has is no error; one only failed variants could have had is not checked.
  s.ranking.constraints.back().metric = "period:body bounce";
  EXPECT_NO_THROW(rank_variants(s, {result(0, "a", 1.0, 20.0), result(1, "b", 0.8, 45.0)}));
  s.ranking.constraints.back().metric = "critical_speed:bogies pitch";
  std::vector<VariantResult> failed{result(0, "a", 1.0, 20.0), result(1, "b", 0.8, 45.0)};
  for (VariantResult& r : failed) r.failure = "unstable";
  EXPECT_NO_THROW(rank_variants(s, failed));
}

TEST(Ranking, MissingOrDuplicateResultsAreRefused) {
  const Study s = named({"a", "b"});
  EXPECT_THROW(rank_variants(s, {result(0, "a", 1.0, 20.0)}), std::invalid_argument);
  EXPECT_THROW(rank_variants(s, {result(0, "a", 1.0, 20.0), result(0, "a", 1.0, 20.0)}), std::invalid_argument);
}

TEST(Evaluation, ResultsDoNotDependOnThreadsOrShards) {
  const Study s = load_study(study_file(R"(
[[sweep]]
parameters = [{ key = "suspension.spring[0].static_deflection", from = "40 mm", to = "80 mm", step = "10 mm" }]
)"));
  EvaluationOptions one;
  one.threads = 1;
  EvaluationOptions two;
  two.threads = 2;
  const auto serial = evaluate_study(s, one);
  const auto parallel = evaluate_study(s, two);
  std::ostringstream a, b;
  write_comparison(a, rank_variants(s, serial), OutputFormat::json);
  write_comparison(b, rank_variants(s, parallel), OutputFormat::json);
  EXPECT_EQ(a.str(), b.str());
  // Shard 2/3 holds indices 1 and 4.
  EvaluationOptions shard = one;
  shard.shard = 2;
  shard.shards = 3;
  const auto part = evaluate_study(s, shard);
  ASSERT_EQ(part.size(), 2u);
  EXPECT_EQ(part[0].index, 1);
  EXPECT_EQ(part[1].index, 4);
  // The shard's JSON reads back into the same results.
  std::ostringstream text;
  write_shard(text, s, shard, part);
  const std::string file = write_temp("shard.json", text.str());
  const auto back = read_shard(file, s);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].modes[1].period_s, part[1].modes[1].period_s);
  EXPECT_EQ(back[1].critical_speeds.front().speed, part[1].critical_speeds.front().speed);
  EXPECT_EQ(back[1].static_deflections, part[1].static_deflections);
  // A source is its number from 1 in the file (`source_index`, as critical-speed writes it; no
  // key `source`), its index from 0 in the results.
  ASSERT_FALSE(part[1].peaks.empty());
  EXPECT_EQ(back[1].critical_speeds.front().source, part[1].critical_speeds.front().source);
  EXPECT_EQ(back[1].peaks.front().source, part[1].peaks.front().source);
  EXPECT_EQ(part[1].peaks.front().source, 0);
  EXPECT_NE(text.str().find("\"source_index\": 1,"), std::string::npos);
  EXPECT_EQ(text.str().find("\"source\":"), std::string::npos);
}

// `railmodal compare` reads no variant in load_study: each is read by the thread that evaluates
// it (issue 19, item 2). The results are those of variants read beforehand, to the last bit,
// on any number of threads and in any shard.
TEST(Evaluation, VariantsReadInTheWorkersGiveTheResultsOfVariantsReadBeforehand) {
  const std::string path = study_file(R"(
[[variant]]
name = "soft"
overrides = { "suspension.spring[0].static_deflection" = "80 mm" }

[[sweep]]
parameters = [{ key = "suspension.spring[0].static_deflection", from = "40 mm", to = "70 mm", step = "10 mm" }]
)");
  const Study read_first = load_study(path);
  const Study unread = load_study(path, [](int) { return false; });
  ASSERT_EQ(unread.variants.size(), 6u);
  ASSERT_FALSE(unread.variants[1].read);
  EvaluationOptions before;
  before.threads = 1;
  const auto json = [](const Study& s, const std::vector<VariantResult>& results) {
    std::ostringstream out;
    write_comparison(out, rank_variants(s, results), OutputFormat::json);
    return out.str();
  };
  const std::string expected = json(read_first, evaluate_study(read_first, before));
  for (int threads : {1, 2, 3}) {
    EvaluationOptions workers;
    workers.threads = threads;
    workers.read_in_workers = true;
    EXPECT_EQ(json(unread, evaluate_study(unread, workers)), expected) << threads << " threads";
  }
  // A shard reads its own variants only: 2/3 holds indices 1 (soft) and 4.
  EvaluationOptions shard;
  shard.threads = 2;
  shard.shard = 2;
  shard.shards = 3;
  shard.read_in_workers = true;
  const auto part = evaluate_study(unread, shard);
  ASSERT_EQ(part.size(), 2u);
  EXPECT_EQ(part[0].name, "soft");
  shard.read_in_workers = false;
  const auto part_read_first = evaluate_study(read_first, shard);
  EXPECT_EQ(part[0].modes.front().period_s, part_read_first[0].modes.front().period_s);
  EXPECT_EQ(part[1].critical_speeds.front().speed, part_read_first[1].critical_speeds.front().speed);
}

// A bad override met by a thread stops the evaluation with the error load_study gives for the
// whole study: its first bad variant's, whatever the thread count.
TEST(Evaluation, ABadVariantReadInTheWorkersIsTheErrorLoadStudyGives) {
  std::string body;
  for (int i = 0; i < 12; ++i)  // variants 1-12; 5 and 9 are bad (wheelbase -1 m)
    body += "\n[[variant]]\nname = \"v" + std::to_string(i + 1) + "\"\noverrides = { \"suspension." +
            (i == 4 || i == 8 ? std::string("wheelbase\" = \"-1 m\"") : std::string("spring[0].static_deflection\" = \"") +
                                                                              std::to_string(40 + i) + " mm\"") +
            " }\n";
  const std::string path = study_file(body);
  std::string expected;
  try {
    load_study(path);
    FAIL() << "load_study took the bad variants";
  } catch (const InputError& e) {
    expected = e.what();
  }
  EXPECT_NE(expected.find("variant 'v5': key 'suspension.wheelbase'"), std::string::npos) << expected;
  const Study unread = load_study(path, [](int) { return false; });
  for (int threads : {1, 2, 4}) {
    EvaluationOptions workers;
    workers.threads = threads;
    workers.read_in_workers = true;
    try {
      evaluate_study(unread, workers);
      ADD_FAILURE() << "no error on " << threads << " threads";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), expected) << threads << " threads";
    }
  }
}

// The line of the study file at `path` that holds `text` (1-based; 0 if none).
int line_of(const std::string& path, const std::string& text) {
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(text) != std::string::npos) return n;
  return 0;
}

// A variant's override the readers take but an analysis refuses (an output that is not a DOF of
// the vehicle): the study's input error at that override, naming the variant and the key, as a
// bad override is; its first such variant's whatever the thread count, read beforehand or by the
// workers. Until 2026-11-28 the variant was "failed" with the scene's message alone, naming no
// file. evaluate_variant, without the study, keeps it as the variant's failure, naming the scene.
TEST(Evaluation, AnOverrideAnAnalysisRefusesIsTheStudysInputErrorAtIt) {
  std::string body;
  for (int i = 0; i < 8; ++i)  // variants 1-8; 4 and 7 name an output the wagon lacks
    body += "\n[[variant]]\nname = \"v" + std::to_string(i + 1) + "\"\n" +
            (i == 3 || i == 6 ? std::string("scene_overrides = { \"output[0].dof\" = \"body.sway\" }")
                              : "overrides = { \"suspension.spring[0].static_deflection\" = \"" + std::to_string(40 + i) +
                                    " mm\" }") +
            "\n";
  const std::string path = study_file(body);
  const std::string scene = write_temp("scene.toml", std::string(kJointsScene) + "[[output]]\ndof = \"body.bounce\"\n");
  const int line = line_of(path, "name = \"v4\"") + 1;  // its scene_overrides
  ASSERT_GT(line, 1);
  const std::string message = "variant 'v4': key 'output[0].dof': 'body.sway' is not a degree of freedom of this vehicle";
  const Study loaded = load_study(path);
  const Study unread = load_study(path, [](int) { return false; });
  for (int threads : {1, 2, 4})
    for (const Study* s : {&loaded, &unread}) {
      EvaluationOptions options;
      options.threads = threads;
      options.read_in_workers = s == &unread;
      try {
        evaluate_study(*s, options);
        ADD_FAILURE() << "no error on " << threads << " threads";
      } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_EQ(e.message().rfind(message, 0), 0u) << e.what();
      }
    }
  const VariantResult alone = evaluate_variant(read_variant(loaded, 4), 4);
  EXPECT_FALSE(alone.ok());
  EXPECT_EQ(alone.failure.rfind(scene + ":", 0), 0u) << alone.failure;
  EXPECT_NE(alone.failure.find("key 'output[0].dof': 'body.sway' is not a degree of freedom"), std::string::npos)
      << alone.failure;
}

// A shard records the digest of the study file it was evaluated from: merged against a study
// file edited since, its results are of other variants, and it is refused naming the shard.
TEST(Evaluation, ShardOfAnotherVersionOfTheStudyFileIsRefused) {
  const std::string path = study_file("");  // the base design alone
  const Study s = load_study(path);
  const auto results = evaluate_study(s, {});
  std::ostringstream current, edited;
  write_shard(current, s, {}, results, provenance_of({path}));
  write_shard(edited, s, {}, results, Provenance{{{path, content_digest("an earlier version")}}});
  EXPECT_EQ(read_shard(write_temp("current_shard.json", current.str()), s).size(), 1u);
  const std::string shard = write_temp("edited_shard.json", edited.str());
  try {
    read_shard(shard, s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), shard);
    EXPECT_NE(std::string(e.what()).find("a shard of another version of the study file"), std::string::npos)
        << e.what();
  }
}

TEST(Evaluation, UnstableVariantIsReportedAndDoesNotStopTheStudy) {
  // Pitch stiffness 4a1²c − W·l (eq. (156a)) with 4c = W/f: negative for l > a1²/f = 63 m.
  const Study s = load_study(study_file(R"(
[[variant]]
name = "tall"
overrides = { "body.cg_height" = "100 m" }
)"));
  EvaluationOptions options;
  options.threads = 2;
  const auto results = evaluate_study(s, options);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_TRUE(results[0].ok());
  EXPECT_FALSE(results[1].ok());
  EXPECT_NE(results[1].failure.find("unstable: mode 1, body pitch"), std::string::npos) << results[1].failure;
  const Comparison c = rank_variants(s, results);
  EXPECT_EQ(c.variants[1].result.name, "tall");
}

// The workers of an opened study move each variant they read into its evaluation instead of
// copying it (study::evaluate_owned_variant); a variant that fails after its vehicle moved into
// its system is described from there. Every result is the same as from the variants read by
// load_study and evaluated by reference: the shard's JSON of each, byte for byte.
TEST(Evaluation, AnOpenedStudyEvaluatesItsVariantsAsALoadedOne) {
  const std::string path = study_file(R"(
[[variant]]
name = "tall"
overrides = { "body.cg_height" = "100 m" }
)");
  EvaluationOptions in_workers;
  in_workers.read_in_workers = true;
  in_workers.threads = 2;
  const auto loaded = evaluate_study(load_study(path), {});
  const auto opened = evaluate_study(open_study(path), in_workers);
  ASSERT_EQ(loaded.size(), 2u);
  ASSERT_EQ(opened.size(), 2u);
  EXPECT_NE(opened[1].failure.find("unstable: mode 1, body pitch"), std::string::npos) << opened[1].failure;
  EXPECT_FALSE(opened[1].modes.empty());
  for (size_t k = 0; k < loaded.size(); ++k)
    EXPECT_EQ(report::shard_result_json(opened[k]), report::shard_result_json(loaded[k])) << "variant " << k;
}

// Whether two result texts are the same but for their numbers, and every number within
// `relative` of the other's (the first difference is written to *where).
bool same_text_numbers_within(const std::string& a, const std::string& b, double relative, std::string* where) {
  size_t i = 0, j = 0;
  auto starts_number = [](const std::string& s, size_t k) {
    return k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) ||
                            (s[k] == '-' && k + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[k + 1]))));
  };
  while (i < a.size() && j < b.size()) {
    if (starts_number(a, i) && starts_number(b, j)) {
      char *end_a = nullptr, *end_b = nullptr;
      const double x = std::strtod(a.c_str() + i, &end_a), y = std::strtod(b.c_str() + j, &end_b);
      if (!(std::abs(x - y) <= relative * std::max(std::abs(x), std::abs(y)))) {
        *where = a.substr(i, 24) + " against " + b.substr(j, 24);
        return false;
      }
      i = static_cast<size_t>(end_a - a.c_str());
      j = static_cast<size_t>(end_b - b.c_str());
    } else if (a[i++] != b[j++]) {
      *where = "text at " + std::to_string(i - 1);
      return false;
    }
  }
  return i == a.size() && j == b.size();
}

// The workers evaluate each variant they read on their kept base (study::Workspace: the
// variant's coefficients written into the base's assembly, model::VariantAssembly); the general
// path (evaluate_variant of the variant read by read_variant, its own assembly from scratch)
// is the reference. Every reported number of every result is within 1e-13 of it relatively: the
// workers find the static loads by a Cholesky factorisation of the sprung block where the
// general path takes a complete orthogonal decomposition (static_loads_on_sprung), and the two
// backward-stable solves differ by the unit round-off times the block's condition number;
// the bundled vehicles' largest change is below 1e-15, and 1e-13 (about 450 units of
// round-off) is the bound a round-off change of a study's numbers is allowed (docs/performance.md,
// study-base2). Among themselves the workers' results are the same bytes whatever the thread
// count and whether the variants were read in the workers or beforehand (the route depends on
// the variant alone), on the bundled studies and a sample of the 10⁵-variant benchmark study.
TEST(Evaluation, VariantsOnTheWorkersBaseAreTheGeneralPathsToRoundOff) {
  std::vector<std::pair<std::string, int>> studies;  // path, shards (every variant of shard 1 evaluated)
  for (const auto& file : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/studies"))
    if (file.path().extension() == ".toml") studies.push_back({file.path().string(), 1});
  studies.push_back({std::string(RAILMODAL_DATA_DIR) + "/../tools/benchmarks/resort_car_sample_study.toml", 1000});
  ASSERT_GE(studies.size(), 5u);
  for (auto [path, shards] : studies) {
    const Study study = open_study(path);
#ifdef RAILMODAL_SANITIZED
    // Under the sanitizers (tests/CMakeLists.txt) a study ranked by its hunting speed evaluates
    // its first variant only: the stability analysis of one variant of the bundled coach study
    // takes about 7 s of CPU under ASan, and five evaluations of all its variants made this the
    // slowest sanitized test (170 s in the CI log of 208d1eb). One variant still takes every
    // route through the stability path; the release build compares them all.
    if (hunting_options_of(study)) shards = variant_count(study);
#endif
    EvaluationOptions options;
    options.shards = shards;
    std::vector<std::string> reference;
    for (int i = 0; i < variant_count(study); ++i)
      if (in_shard(i, 1, shards))
        reference.push_back(report::shard_result_json(evaluate_variant(read_variant(study, i), i, study.deflection_rule,
                                                                       hunting_options_of(study), ride_rms_only(study),
                                 variant_work_of(study.ranking, study.deflection_rule))));
    // Read in the workers (each moved into its evaluation), and read beforehand (each copied).
    const int in = shards;  // a structured binding cannot be captured in C++17
    const Study loaded = load_study(path, [in](int i) { return in_shard(i, 1, in); });
    std::vector<std::string> first;  // the workers' results of the first run, bytes
    for (const Study* s : {&study, &loaded})
      for (int threads : {1, 2}) {
        options.threads = threads;
        options.read_in_workers = s == &study;
        const std::vector<VariantResult> results = evaluate_study(*s, options);
        ASSERT_EQ(results.size(), reference.size()) << path;
        for (size_t k = 0; k < results.size(); ++k) {
          const std::string got = report::shard_result_json(results[k]);
          std::string where;
          EXPECT_TRUE(same_text_numbers_within(got, reference[k], 1e-13, &where))
              << path << ", variant " << results[k].index << ": " << where;
          if (first.size() < results.size())
            first.push_back(got);
          else
            EXPECT_EQ(got, first[k]) << path << ", variant " << results[k].index << ", " << threads << " threads";
        }
      }
  }
}

TEST(Evaluation, StaticDeflectionOfTheTwoAxleWagonIsItsSpringDeflection) {
  const Study s = load_study(study_file(""));
  const VariantResult r = evaluate_variant(s.variants[0], 0);
  ASSERT_TRUE(r.ok()) << r.failure;
  // Four equal springs, each given by its deflection under its share of the weight: the
  // body settles by exactly that (up to rounding of the linear solve).
  EXPECT_NEAR(*metric_value(r, "static_deflection"), 0.0572, 1e-15);
}

}  // namespace
}  // namespace railmodal::test
