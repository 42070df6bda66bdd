// Hard cases of the driving gear and its balancing: a rod barely longer than its crank, a gear
// with no mass at all, a crawl and a gallop, the fewest crank angles. Each is an answer (finite
// numbers, flags, checks), never NaN and never an exception.
#include <gtest/gtest.h>

#include <cmath>

#include "gear/su_gear.hpp"
#include "railmodal/balance.hpp"

namespace railmodal {
namespace {

bool finite_everywhere(const GearResult& r) {
  for (const GearState& st : r.states) {
    for (const RodForces& f : st.cylinders)
      if (!std::isfinite(f.horizontal) || !std::isfinite(f.vertical) || !std::isfinite(f.guide)) return false;
    for (double p : st.wheel_loads)
      if (!std::isfinite(p)) return false;
    if (!std::isfinite(st.surging) || !std::isfinite(st.nosing)) return false;
  }
  for (const GearWheelLoad& w : r.wheels)
    if (!std::isfinite(w.alpha) || !std::isfinite(w.alpha_89a)) return false;
  return true;
}

TEST(GearHardCases, RodBarelyLongerThanItsCrank) {
  // λ = 1/1.0001: at 90° the rod stands at 89.2°, cos β = 0.014, and the crosshead's acceleration
  // peaks near 1/cos³β ≈ 3.5e5 times ω²r in a spike narrower than a degree (the 1° steps see
  // some 40 times the Су's surging). Large, finite, and the harmonics' check says how well six
  // orders describe such a force (it need not pass: that is the answer).
  DrivingGear g = testing::su_rods_only();
  for (GearCylinder& c : g.cylinders) {
    c.rod_length = c.crank_radius * 1.0001;
    c.rod_centre_of_mass = c.rod_length / 2;
    c.rod_inertia = c.rod_mass * c.rod_length * c.rod_length / 12;  // a uniform bar
  }
  const GearResult r = solve_driving_gear(g, 100 / 3.6);
  EXPECT_TRUE(finite_everywhere(r));
  EXPECT_GT(r.max_surging, 10 * solve_driving_gear(testing::su_rods_only(), 100 / 3.6).max_surging);
  ASSERT_EQ(r.summary.checks.size(), 1u);
  EXPECT_TRUE(std::isfinite(r.summary.checks[0].value));
}

TEST(GearHardCases, GearWithNoMassBalancesToNothing) {
  DrivingGear g = testing::su_rods_only();
  for (GearCylinder& c : g.cylinders) c.rod_mass = c.rod_inertia = c.reciprocating_mass = 0.0;
  for (VerticalRule rule : {VerticalRule::least_squares, VerticalRule::minimax, VerticalRule::book}) {
    BalanceOptions o;
    o.rule = rule;
    o.allowed_alpha = 0.3;
    o.trade_off_fractions = {0.0, 1.0};
    const BalanceResult b = balance_driving_gear(g, 100 / 3.6, o);
    EXPECT_TRUE(finite_everywhere(b.after)) << to_string(rule);
    for (const WheelBalance& w : b.wheels) {
      EXPECT_EQ(w.rotating_mass, 0.0);
      EXPECT_EQ(w.vertical_mass, 0.0) << to_string(rule);
      EXPECT_TRUE(std::isfinite(w.total_angle));
    }
    EXPECT_EQ(b.percent_unbalanced_surging, 0.0);  // nothing to compare with: reported as 0, not NaN
    EXPECT_TRUE(b.summary.passed()) << b.summary.brief();
  }
}

TEST(GearHardCases, CrawlAndGallop) {
  // Forces go as V²: at 1 mm/s the unbalanced driving wheel's α of 2.2 at 100 km/h falls by
  // (0.001/27.8)² = 1.3e-9; at 1000 km/h the wheel lifts (α ≫ 1): both are answers.
  const DrivingGear g = testing::su_engine();
  const GearResult crawl = solve_driving_gear(g, 1e-3);
  EXPECT_TRUE(finite_everywhere(crawl));
  EXPECT_LT(crawl.wheels[2].alpha, 1e-8);
  const GearResult gallop = solve_driving_gear(g, 1000 / 3.6);
  EXPECT_TRUE(finite_everywhere(gallop));
  EXPECT_TRUE(gallop.wheels[2].wheel_lift);
  EXPECT_TRUE(gallop.summary.passed());
}

TEST(GearHardCases, FewestCrankAngles) {
  GearOptions o;
  o.steps = 8;
  o.harmonics = 3;
  const GearResult r = solve_driving_gear(testing::su_engine(), 100 / 3.6, o);
  EXPECT_EQ(r.states.size(), 8u);
  EXPECT_TRUE(finite_everywhere(r));
  BalanceOptions b;
  b.steps = 8;
  b.rule = VerticalRule::minimax;
  b.trade_off_fractions.clear();
  EXPECT_TRUE(finite_everywhere(balance_driving_gear(testing::su_engine(), 100 / 3.6, b).after));
}

}  // namespace
}  // namespace railmodal
