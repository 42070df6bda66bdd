// Hard cases of the nonlinear critical speed: a ramp down to a crawl, where the creep damping
// grows as 1/V and the equations stiffen; an oscillation that outlives the ramp.
#include <gtest/gtest.h>

#include <cmath>

#include "railmodal/railmodal.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal {
namespace {

TEST(NonlinearHuntingHardCases, RampToACrawlHasNoNaN) {
  // From 40 m/s (stable: the linear critical speed is 65.3 m/s) down to 0.5 m/s, where the creep
  // damping is 2f22κ/(mV) ≈ 2.8e4 1/s: the explicit steps shrink but stay finite.
  NonlinearHuntingOptions o;
  o.wheel_load = 50e3;
  o.start_speed = 40.0;
  o.end_speed = 0.5;
  o.ramp_rate = 2.0;
  o.disturbance = 0.01;  // on the flange
  const NonlinearHuntingResult r = solve_nonlinear_hunting(assemble(test::wheelset_on_springs(), DofSet::lateral), o);
  EXPECT_EQ(r.verdict, NonlinearHuntingVerdict::no_limit_cycle_at_start);
  EXPECT_FALSE(r.critical_speed.has_value());
  // No limit cycle at either rate: no critical speed to converge; not applicable, never "converged".
  EXPECT_EQ(r.halved_rate.verdict, NonlinearHuntingVerdict::no_limit_cycle_at_start);
  EXPECT_EQ(r.convergence, NonlinearConvergence::not_applicable);
  EXPECT_FALSE(r.converged);
  for (const LimitCyclePoint& p : r.curve) EXPECT_TRUE(std::isfinite(p.amplitude) && std::isfinite(p.speed));
  EXPECT_GT(r.stated_rate.steps, 0);
}

TEST(NonlinearHuntingHardCases, LimitCycleOutlivesTheRamp) {
  // Ending above the linear critical speed: the hunting still lives there, and no critical
  // speed is invented.
  NonlinearHuntingOptions o;
  o.wheel_load = 50e3;
  o.start_speed = 80.0;
  o.end_speed = 70.0;
  const NonlinearHuntingResult r = solve_nonlinear_hunting(assemble(test::wheelset_on_springs(), DofSet::lateral), o);
  EXPECT_EQ(r.verdict, NonlinearHuntingVerdict::survives_to_end_speed);
  EXPECT_FALSE(r.critical_speed.has_value());
  EXPECT_EQ(r.halved_rate.verdict, NonlinearHuntingVerdict::survives_to_end_speed);
  EXPECT_EQ(r.convergence, NonlinearConvergence::not_applicable);
  EXPECT_FALSE(r.curve.empty());
}

}  // namespace
}  // namespace railmodal
