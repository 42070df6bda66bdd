// The library's hunting-stability solver (solve_hunting_stability) against the independent
// derivations of hunting_validation_test.cpp: the Routh–Hurwitz critical speed of a wheelset on
// springs, the verdicts of the free wheelset and of zero conicity, and Klingel's frequency.
// These tests wait for the solver (src/stability/hunting_stability.cpp); until it lands they
// fail with its placeholder's std::logic_error.
#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal::test {
namespace {

HuntingOptions options(double from, double to) {
  HuntingOptions o;
  o.min_speed = from;
  o.max_speed = to;
  o.speed_count = 100;
  return o;
}

TEST(HuntingSolverValidation, WheelsetOnSpringsCriticalSpeedMatchesRouthHurwitz) {
  WheelsetData d;
  const double k_y = 1.0e6, k_psi = 2.0e6;
  const auto system = assemble(wheelset_on_springs(d, k_y, k_psi), DofSet::lateral);
  const auto result = solve_hunting_stability(system, options(1.0, 400.0));
  const double routh = routh_critical_speed(d, d.mass * kG, k_y, k_psi, 1.0, 400.0);
  ASSERT_EQ(result.verdict, HuntingVerdict::critical_speed_in_range);
  ASSERT_TRUE(result.critical.has_value());
  // The solver refines its bracket to 1e-8 of the speed; 2e-8 allows the bracket's midpoint.
  EXPECT_NEAR(result.critical->speed, routh, 2e-8 * routh);
  // Klingel's frequency there: V/Λ with Λ = 2π√(r0·l0/λ).
  const double klingel = 2 * kPi * std::sqrt(d.r0 * d.l0 / d.conicity);
  EXPECT_NEAR(result.critical->klingel_frequency_hz, result.critical->speed / klingel, 1e-9 * result.critical->speed);
  ASSERT_EQ(result.contacts.size(), 1u);
  EXPECT_EQ(result.contacts[0].body, "wheelset");
}

// The free wheelset without gravitational stiffness is unstable already at the lowest speed: a
// verdict, no critical speed invented.
TEST(HuntingSolverValidation, FreeWheelsetWithoutGravitationalStiffnessIsUnstableAtTheLowestSpeed) {
  WheelsetData d;
  d.epsilon = 0.0;
  d.sigma = 0.0;
  d.creep.f23 = 0.0;
  const auto system = assemble(wheelset_on_springs(d, 0.0, 0.0), DofSet::lateral);
  const auto result = solve_hunting_stability(system, options(1.0, 200.0));
  EXPECT_EQ(result.verdict, HuntingVerdict::unstable_at_lowest_speed);
  EXPECT_FALSE(result.critical.has_value());
}

// The free wheelset with its gravitational stiffness: the Routh–Hurwitz speed again. With the
// spin coupling f23 of the default data (1e4 N·m) it is unstable already at low speed (2·f23 >
// W·r0·(1 + f33/(f11·l0²)): hunting_validation_test.cpp); f23 = 1e3 N·m, as there, for a
// critical speed (1.395 m/s) inside the range.
TEST(HuntingSolverValidation, FreeWheelsetCriticalSpeedMatchesRouthHurwitz) {
  WheelsetData d;
  d.creep.f23 = 1.0e3;
  const auto system = assemble(wheelset_on_springs(d, 0.0, 0.0), DofSet::lateral);
  const auto result = solve_hunting_stability(system, options(1.0, 200.0));
  const double routh = routh_critical_speed(d, d.mass * kG, 0.0, 0.0, 1.0, 200.0);
  ASSERT_TRUE(result.critical.has_value());
  EXPECT_NEAR(result.critical->speed, routh, 2e-8 * routh);
}

// Zero conicity feeds no energy in: stable throughout, never NaN.
TEST(HuntingSolverValidation, ZeroConicityIsStableThroughout) {
  WheelsetData d;
  d.conicity = 0.0;
  const auto system = assemble(wheelset_on_springs(d, 1.0e6, 2.0e6), DofSet::lateral);
  const auto result = solve_hunting_stability(system, options(0.1, 500.0));
  EXPECT_EQ(result.verdict, HuntingVerdict::stable_throughout);
  for (const auto& branch : result.branches)
    for (double z : branch.damping_ratio) EXPECT_TRUE(std::isfinite(z));
}

}  // namespace
}  // namespace railmodal::test
