// A study plan's variants, in the study layer alone: a plan written here, no study file and
// no reader.
#include "study/planned_variants.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace railmodal::study {
namespace {

SweepParameter grid_parameter(const std::string& key, const std::string& label, std::vector<std::string> texts) {
  SweepParameter p;
  p.key = key;
  p.label = label;
  for (size_t i = 0; i < texts.size(); ++i) p.values.push_back({texts[i], static_cast<int>(i)});
  return p;
}

// Every variant of the plan, in study order.
std::vector<VariantSpec> all(const StudyPlan& plan) {
  const PlannedVariants planned(plan);
  std::vector<VariantSpec> specs;
  for (size_t i = 0; i < planned.size(); ++i) {
    specs.push_back(planned.at(i));
    EXPECT_EQ(planned.name(i), specs.back().name);
  }
  return specs;
}

Sweep sample_sweep(const std::string& name, int count, uint64_t seed) {
  Sweep sample;
  sample.name = name;
  sample.samples = count;
  sample.seed = seed;
  for (const char* key : {"spring.f", "body.weight"}) {
    SweepParameter p;
    p.key = key;
    p.from = {40.0, "mm", false};
    p.to = {80.0, "mm", false};
    sample.parameters.push_back(p);
  }
  return sample;
}

TEST(PlannedVariants, WrittenVariantsComeFirstThenTheGridFirstParameterSlowest) {
  StudyPlan plan;
  plan.vehicle_file = "wagon.toml";
  plan.variants.push_back({"base", {3, 0}, "wagon.toml", {}, {}});
  Sweep grid;
  grid.name = "grid";
  grid.line = 9;
  grid.parameters = {grid_parameter("body.weight", "W", {"30 t", "40 t"}),
                     grid_parameter("spring.f", "f", {"40 mm", "50 mm", "60 mm"})};
  grid.parameters[1].scene = true;
  plan.sweeps.push_back(grid);
  const std::vector<VariantSpec> specs = all(plan);
  ASSERT_EQ(specs.size(), 7u);
  EXPECT_EQ(specs[0].name, "base");
  EXPECT_EQ(specs[1].name, "grid: W = 30 t, f = 40 mm");
  EXPECT_EQ(specs[3].name, "grid: W = 30 t, f = 60 mm");
  EXPECT_EQ(specs[4].name, "grid: W = 40 t, f = 40 mm");
  EXPECT_EQ(specs[6].vehicle_file, "wagon.toml");
  EXPECT_EQ(specs[6].place.line, 9);
  const std::vector<StudyParameter> expected{{"body.weight", "40 t"}, {"scene:spring.f", "60 mm"}};
  EXPECT_EQ(specs[6].parameters, expected);
  ASSERT_EQ(specs[6].assignments.size(), 2u);
  EXPECT_EQ(specs[6].assignments[1].written, 2);  // the third value written for f
  EXPECT_TRUE(specs[6].assignments[1].scene);
}

TEST(PlannedVariants, SampleDrawsWrittenLikeTheLowerEnd) {
  StudyPlan plan;
  Sweep sample;
  sample.name = "box";
  sample.samples = 3;
  sample.seed = 42;
  SweepParameter p;
  p.key = "spring.f";
  p.from = {40.0, "mm", false};
  p.to = {80.0, "mm", false};
  sample.parameters.push_back(p);
  plan.sweeps.push_back(sample);
  const std::vector<VariantSpec> specs = all(plan);
  ASSERT_EQ(specs.size(), 3u);
  // The first uniforms of xoshiro256** seeded by splitmix64(42) (tests/study/study_test.cpp).
  const double u[] = {0.08386297105988216, 0.3789802506626686, 0.6800434110281394};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(specs[i].name, "box #" + std::to_string(i + 1));
    const Assignment& a = specs[i].assignments.at(0);
    EXPECT_EQ(a.written, -1);
    EXPECT_EQ(a.drawn.number, 40.0 + u[i] * (80.0 - 40.0));
    EXPECT_EQ(a.drawn.unit, "mm");
    EXPECT_EQ(a.text, a.drawn.text());
    EXPECT_EQ(specs[i].parameters.at(0).second, a.text);
  }
}

// A sample point is drawn from the generator's checkpoint before it: the same numbers as
// drawing every point in turn, on both sides of the checkpoints (every 32 points), in any order.
TEST(PlannedVariants, ASamplePointAskedForAloneIsThePointOfTheSequence) {
  StudyPlan plan;
  plan.variants.push_back({"base", {3, 0}, "wagon.toml", {}, {}});
  plan.sweeps.push_back(sample_sweep("box", 1000, 7));
  const PlannedVariants planned(plan);
  ASSERT_EQ(planned.size(), 1001u);
  Xoshiro256 generator(7);
  std::vector<double> drawn;
  for (int i = 0; i < 2000; ++i) drawn.push_back(40.0 + generator.uniform() * (80.0 - 40.0));
  for (size_t n : {999u, 0u, 31u, 32u, 33u, 255u, 256u, 257u, 511u, 512u, 700u}) {
    const VariantSpec spec = planned.at(1 + n);
    EXPECT_EQ(spec.name, "box #" + std::to_string(n + 1));
    ASSERT_EQ(spec.assignments.size(), 2u);
    EXPECT_EQ(spec.assignments[0].drawn.number, drawn[2 * n]) << n;
    EXPECT_EQ(spec.assignments[1].drawn.number, drawn[2 * n + 1]) << n;
  }
}

TEST(PlannedVariants, TheFirstRepeatedNameIsTheLaterOfTheFirstPair) {
  StudyPlan plan;
  plan.variants.push_back({"box #3", {3, 0}, "wagon.toml", {}, {}});
  plan.sweeps.push_back(sample_sweep("box", 5, 1));
  plan.sweeps.push_back(sample_sweep("other", 300, 1));
  EXPECT_EQ(PlannedVariants(plan).first_repeated_name(), std::optional<size_t>(3));  // "box #3", 1 + 2
  plan.variants.front().name = "base";
  EXPECT_EQ(PlannedVariants(plan).first_repeated_name(), std::nullopt);
  plan.sweeps.push_back(sample_sweep("box", 2, 1));
  EXPECT_EQ(PlannedVariants(plan).first_repeated_name(), std::optional<size_t>(306));  // the second "box #1"
}

TEST(PlannedVariants, WrittenNumberReadsBack) {
  EXPECT_EQ((WrittenNumber{0.1, "m", false}.text()), "0.1 m");
  EXPECT_EQ((WrittenNumber{2.6, "", true}.text()), "3");
  EXPECT_EQ((WrittenNumber{0.30000000000000004, "", false}.text()), "0.30000000000000004");
}

}  // namespace
}  // namespace railmodal::study
