// Every options struct validates itself: is_valid names the option and the rule it breaks,
// and the analysis that takes the options throws std::invalid_argument with that message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// is_valid is false, says why in words holding `names` (the option and its rule), and does
// not need somewhere to say it.
template <class Options>
void expect_invalid(const Options& options, const std::string& names) {
  std::string why;
  EXPECT_FALSE(options.is_valid(&why));
  EXPECT_NE(why.find(names), std::string::npos) << why;
  EXPECT_FALSE(options.is_valid(nullptr));
}

template <class Options>
void expect_valid(const Options& options) {
  std::string why = "untouched";
  EXPECT_TRUE(options.is_valid(&why)) << why;
  EXPECT_EQ(why, "untouched");
}

// The message of the std::invalid_argument that `call` throws ("" if it throws none).
template <class Call>
std::string invalid_argument_of(const Call& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

CriticalSpeedOptions speed_range(double low, double high) {
  CriticalSpeedOptions o;
  o.min_speed = low;
  o.max_speed = high;
  return o;
}

TEST(CriticalSpeedOptions, NeedsASpeedRangeAndSaneFloors) {
  expect_valid(speed_range(1.0, 50.0));
  expect_valid(speed_range(10.0, 10.0));
  expect_invalid(CriticalSpeedOptions{}, "0 < min_speed ≤ max_speed");  // no range given
  expect_invalid(speed_range(-1.0, 10.0), "0 < min_speed ≤ max_speed");
  expect_invalid(speed_range(20.0, 10.0), "0 < min_speed ≤ max_speed");
  expect_invalid(speed_range(1.0, kInf), "0 < min_speed ≤ max_speed");
  expect_invalid(speed_range(kNaN, 10.0), "0 < min_speed ≤ max_speed");
  CriticalSpeedOptions o = speed_range(1.0, 50.0);
  o.friction_reference_amplitude = -0.01;
  expect_invalid(o, "friction_reference_amplitude");
  o.friction_reference_amplitude = kNaN;
  expect_invalid(o, "friction_reference_amplitude");
  o = speed_range(1.0, 50.0);
  o.outputs = {OutputRequest{-1}};
  expect_invalid(o, "outputs must name DOFs by their index, ≥ 0");
}

TEST(CriticalSpeedOptions, FindCriticalSpeedsThrowsTheRule) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  EXPECT_EQ(invalid_argument_of([&] { find_critical_speeds(sys, modes, {}, speed_range(20.0, 10.0)); }),
            "critical speeds: need 0 < min_speed ≤ max_speed");
  CriticalSpeedOptions o = speed_range(1.0, 50.0);
  o.friction_reference_amplitude = -1.0;
  EXPECT_EQ(invalid_argument_of([&] { find_critical_speeds(sys, modes, {}, o); }),
            "critical speeds: friction_reference_amplitude must be 0 (friction only in the criterion) or a "
            "positive stretch");
  o = speed_range(1.0, 50.0);
  o.outputs = {OutputRequest{sys.size()}};
  EXPECT_EQ(invalid_argument_of([&] { find_critical_speeds(sys, modes, {}, o); }),
            "critical speeds: output DOF " + std::to_string(sys.size()) + " is out of range (" +
                std::to_string(sys.size()) + " DOFs)");
}

SimulationOptions run(double duration, double time_step) {
  SimulationOptions o;
  o.duration = duration;
  o.time_step = time_step;
  return o;
}

TEST(SimulationOptions, NeedsADurationAStepAndPositiveTolerances) {
  expect_valid(run(1.0, 1e-3));
  expect_invalid(SimulationOptions{}, "duration and time step must be positive");  // no duration given
  expect_invalid(run(0.0, 1e-3), "duration and time step must be positive");
  expect_invalid(run(1.0, 0.0), "duration and time step must be positive");
  expect_invalid(run(kInf, 1e-3), "duration and time step must be positive");
  SimulationOptions o = run(1.0, 1e-3);
  o.tolerance = 0.0;
  expect_invalid(o, "tolerance and event tolerance must be positive");
  o = run(1.0, 1e-3);
  o.event_tolerance = -1e-12;
  expect_invalid(o, "event tolerance must be positive");
  o = run(1.0, 1e-3);
  o.final_speed = -1.0;
  expect_invalid(o, "final speed must be positive");
  o.final_speed = kInf;
  expect_invalid(o, "final speed must be positive");
  o.final_speed = 20.0;  // a ramp is valid options; whether the path takes it is the path's rule
  expect_valid(o);
}

TEST(SimulationOptions, BothPathsThrowTheRule) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  SimulationOptions o = run(1.0, 0.0);
  EXPECT_EQ(invalid_argument_of([&] { simulate_linear(sys, {}, o); }),
            "simulation: duration and time step must be positive");
  EXPECT_EQ(invalid_argument_of([&] { simulate_nonlinear(sys, {}, o, {}); }),
            "simulation: duration and time step must be positive");
  o = run(1.0, 1e-2);
  o.tolerance = -1.0;
  EXPECT_EQ(invalid_argument_of([&] { simulate_linear(sys, {}, o); }),
            "simulation: tolerance and event tolerance must be positive");
  EXPECT_EQ(invalid_argument_of([&] { simulate_nonlinear(sys, {}, o, {}); }),
            "simulation: tolerance and event tolerance must be positive");
  // Path rules stay the path's own.
  o = run(1.0, 1e-2);
  o.final_speed = 10.0;
  EXPECT_NE(invalid_argument_of([&] { simulate_linear(sys, {}, o); }).find("speed ramp"), std::string::npos);
  EXPECT_EQ(invalid_argument_of([&] { simulate_nonlinear(sys, {}, o, {}); }),
            "simulation: a final speed must be positive, and needs sources to run over");
}

TEST(EvaluationOptions, DefaultsAreValidAndShardsAreChecked) {
  expect_valid(EvaluationOptions{});
  EvaluationOptions o;
  o.shard = 2;
  o.shards = 4;
  o.threads = 3;
  expect_valid(o);
  o.shard = 5;
  expect_invalid(o, "shard must be K/N with 1 <= K <= N");
  o.shard = 0;
  expect_invalid(o, "shard must be K/N with 1 <= K <= N");
  o.shard = 1;
  o.shards = 0;
  expect_invalid(o, "shard must be K/N with 1 <= K <= N");
  o.shards = 1;
  o.threads = -1;
  expect_invalid(o, "threads must be 0 (every core) or positive");
}

TEST(EvaluationOptions, EvaluateStudyThrowsTheRule) {
  EvaluationOptions o;
  o.shard = 3;
  o.shards = 2;
  EXPECT_EQ(invalid_argument_of([&] { evaluate_study(Study{}, o); }), "shard must be K/N with 1 <= K <= N");
  o.shard = 1;
  o.threads = -2;
  EXPECT_EQ(invalid_argument_of([&] { evaluate_study(Study{}, o); }), "threads must be 0 (every core) or positive");
}

TEST(HuntingOptions, EveryOptionHasItsRule) {
  expect_valid(HuntingOptions{});
  HuntingOptions o;
  o.min_speed = 0.0;
  expect_invalid(o, "min_speed must be at least 1e-3 m/s");
  o.min_speed = 0.9e-3;  // below the speed whose kinematic roots the eigen-solve resolves
  expect_invalid(o, "min_speed must be at least 1e-3 m/s");
  o.min_speed = kNaN;
  expect_invalid(o, "min_speed must be at least 1e-3 m/s");
  o = {};
  o.max_speed = o.min_speed;
  expect_invalid(o, "max_speed must be finite and greater than min_speed");
  o.max_speed = kInf;
  expect_invalid(o, "max_speed must be finite and greater than min_speed");
  o = {};
  o.speed_count = 1;
  expect_invalid(o, "2 ≤ speed_count");
  o = {};
  o.conicities = {0.1, -0.1};
  expect_invalid(o, "0 ≤ conicity < 1");
  o.conicities = {kNaN};
  expect_invalid(o, "0 ≤ conicity < 1");
  o = {};
  o.damping_threshold = 1.0;
  expect_invalid(o, "−1 < damping_threshold < 1");
  o.damping_threshold = 0.05;
  expect_valid(o);
  o = {};
  o.relative_tolerance = 0.0;
  expect_invalid(o, "1e-14 ≤ relative_tolerance ≤ 0.1");
  o.relative_tolerance = kNaN;
  expect_invalid(o, "1e-14 ≤ relative_tolerance ≤ 0.1");
  o = {};
  o.continuity_threshold = 0.0;
  expect_invalid(o, "0 < continuity_threshold ≤ 1");
  o = {};
  o.threads = -1;
  expect_invalid(o, "threads must be 0 (every core) or positive");
  // The analysis throws the rule, prefixed with the options' name.
  o = {};
  o.speed_count = 0;
  EXPECT_EQ(invalid_argument_of([&] { solve_hunting_stability(LinearSystem{}, o); }),
            "HuntingOptions: speed_count must satisfy 2 ≤ speed_count ≤ 10⁶");
}

}  // namespace
}  // namespace railmodal::test
