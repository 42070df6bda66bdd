// The balancing calculator (src/gear/balance.cpp): the two-plane reduction against Zhdanov's
// closed form for two loads at 90°, the three vertical rules against each other, the overbalance
// by fraction and by allowed α, and the trade-off table.
#include <gtest/gtest.h>

#include <cmath>

#include "gear/su_gear.hpp"
#include "railmodal/balance.hpp"

namespace railmodal {
namespace {

using testing::kKgf;
using testing::su_engine;
using testing::su_rods_only;

constexpr double kSpeed = 100 / 3.6;

BalanceOptions quick(VerticalRule rule) {
  BalanceOptions o;
  o.rule = rule;
  o.trade_off_fractions.clear();
  return o;
}

TEST(Balance, RotatingMassesReduceToTheWheelPlanesAsZhdanovWrites) {
  // Two equal loads G at 90° a outside the wheel planes (eq. (63)–(64)): each wheel's counterweight
  // G·√((2S + a)² + a²)/2S on the crank radius, tg α = a/(2S + a) from the line opposite its crank.
  DrivingGear g = su_rods_only();
  g.cylinders.clear();
  const double G = 65.79, S = 0.795, a = 0.345;  // the driving pin parts (§5.1)
  g.axles[0].right.masses = g.axles[0].left.masses = {{"crank pin", G, 0.35, 0.0, a, false}};
  const BalanceResult b = balance_driving_gear(g, kSpeed, quick(VerticalRule::book));
  const double expected = G * std::hypot(2 * S + a, a) / (2 * S);
  const double alpha = std::atan(a / (2 * S + a));
  // Closed forms of the same sums: round-off only.
  EXPECT_NEAR(b.wheels[0].rotating_mass, expected, 1e-9 * G);
  EXPECT_NEAR(b.wheels[1].rotating_mass, expected, 1e-9 * G);
  // Right plane: G(2S + a)/2S on its crank and −G·a/2S of the left pin, 90° behind: their sum
  // lies α ahead of the right crank, the counterweight at π + α. Left plane: G(2S + a)/2S on its
  // crank and −G·a/2S of the right pin, 90° ahead: the sum α behind, the counterweight at π − α.
  EXPECT_NEAR(b.wheels[0].rotating_angle, M_PI + alpha, 1e-12);
  EXPECT_NEAR(b.wheels[1].rotating_angle, M_PI - alpha, 1e-12);
  // Balanced: no dynamic wheel load, no surging, no nosing.
  for (const GearWheelLoad& w : b.after.wheels) EXPECT_NEAR(w.alpha, 0.0, 1e-12);
  EXPECT_NEAR(b.after.max_surging, 0.0, 1e-9 * b.before.max_surging);
  EXPECT_NEAR(b.after.max_nosing, 0.0, 1e-9 * b.before.max_nosing);
  EXPECT_TRUE(b.summary.passed()) << b.summary.brief();
}

double largest_driving_residual(const BalanceResult& b) {
  return std::max(b.after.wheels[2].alpha, b.after.wheels[3].alpha) * 9000 * kKgf;
}

TEST(Balance, ThreeVerticalRulesOrderAsTheyShould) {
  const DrivingGear g = su_engine();
  const BalanceResult ls = balance_driving_gear(g, kSpeed, quick(VerticalRule::least_squares));
  const BalanceResult mm = balance_driving_gear(g, kSpeed, quick(VerticalRule::minimax));
  const BalanceResult book = balance_driving_gear(g, kSpeed, quick(VerticalRule::book));
  // Least squares leaves no first harmonic of the driving wheels' load (the rotating masses are
  // cancelled exactly); 1e-9 of the rod force.
  const double scale = ls.before.vertical_harmonics[0][1].amplitude();
  EXPECT_NEAR(ls.after.wheels[2].harmonics[1].amplitude(), 0.0, 1e-9 * scale);
  EXPECT_NEAR(ls.after.wheels[3].harmonics[1].amplitude(), 0.0, 1e-9 * scale);
  // Minimax is never worse than either (to the golden-section tolerance, 1e-6 N).
  EXPECT_LE(largest_driving_residual(mm), largest_driving_residual(ls) + 1e-6);
  EXPECT_LE(largest_driving_residual(mm), largest_driving_residual(book) + 1e-6);
  EXPECT_TRUE(mm.summary.passed()) << mm.summary.brief();
  // What no counterweight removes: the second harmonic (Zhdanov: "complete vertical equilibrium
  // cannot be reached"): the residual keeps at least a tenth of the rod's first harmonic.
  EXPECT_GT(largest_driving_residual(mm), 0.1 * scale);
  // The book's rule takes |Y| at the wheel's crank at 90° for its amplitude (the rods' force on the
  // right driving wheel, whose crank is the reference).
  DrivingGear rods = g;
  for (GearAxle& axle : rods.axles) axle.right.masses.clear(), axle.left.masses.clear();
  const double y90 = std::abs(solve_driving_gear(rods, kSpeed).states[90].wheel_loads[2]);
  EXPECT_NEAR(book.wheels[2].vertical_mass * ls.before.omega * ls.before.omega * 0.35, y90, 1e-6 * y90);
}

TEST(Balance, FullReciprocatingBalanceTakesTheReciprocatingFirstHarmonicOutOfSurging) {
  // The overbalance is linear in the fraction: balancing all of each cylinder's reciprocating mass
  // M = m_k + m(1 − d/L) changes ΣX by minus the first harmonic of those masses' own ΣX, whatever
  // the wheel planes it is shared over (the two-plane shares sum to one).
  const DrivingGear g = su_engine();
  BalanceOptions none = quick(VerticalRule::least_squares), full = none;
  full.reciprocating_fraction = 1.0;
  full.overbalance_driving_axles = true;
  const BalanceResult b0 = balance_driving_gear(g, kSpeed, none);
  const BalanceResult b1 = balance_driving_gear(g, kSpeed, full);
  DrivingGear crossheads = su_rods_only();
  for (GearCylinder& c : crossheads.cylinders) {
    c.reciprocating_mass += c.rod_mass * (1 - c.rod_centre_of_mass / c.rod_length);
    c.rod_mass = c.rod_inertia = c.rod_centre_of_mass = 0.0;
  }
  const GearHarmonic reciprocating = solve_driving_gear(crossheads, kSpeed).surging_harmonics[1];
  const GearHarmonic h0 = b0.after.surging_harmonics[1], h1 = b1.after.surging_harmonics[1];
  // Sums of the same samples: round-off, 1e-9 of the reciprocating harmonic (≈ 1.7e5 N).
  EXPECT_NEAR(h1.cosine - h0.cosine, -reciprocating.cosine, 1e-9 * reciprocating.amplitude());
  EXPECT_NEAR(h1.sine - h0.sine, -reciprocating.sine, 1e-9 * reciprocating.amplitude());
  EXPECT_LT(b1.percent_unbalanced_surging, 0.1 * b0.percent_unbalanced_surging);
  // Three overbalanced axles share it: more than a third each, the rod plane lying outside.
  const double m_rec = 365.75 + 225.28 * (1 - 1.5575 / 2.35);
  EXPECT_GT(b1.wheels[0].overbalance_mass, m_rec / 3);
}

TEST(Balance, AllowedAlphaSizesTheCoupledWheelsOverbalance) {
  // Zhdanov §III.3: Q_в = α·П·g/(ω²r) in each coupled wheel; their own blow is then exactly α·П.
  BalanceOptions o = quick(VerticalRule::book);
  o.allowed_alpha = 0.3;
  const BalanceResult b = balance_driving_gear(su_engine(), kSpeed, o);
  for (int w : {0, 1, 4, 5}) {
    EXPECT_NEAR(b.wheels[w].overbalance_mass, 0.3 * 9000 * kKgf / (b.after.omega * b.after.omega * 0.35), 1e-9);
    // A pure sine, its peak between two 1° steps at worst: 1 − cos 0.5° = 3.8e-5 of it.
    EXPECT_NEAR(b.wheels[w].alpha, 0.3, 0.3 * 4e-5);
  }
  EXPECT_EQ(b.wheels[2].overbalance_mass, 0.0);  // the driving wheels carry none
  EXPECT_LT(b.percent_unbalanced_surging, 100.0);
  EXPECT_TRUE(b.summary.passed()) << b.summary.brief();
}

TEST(Balance, TradeOffTableGrowsAlphaAsItCutsSurging) {
  BalanceOptions o;
  o.trade_off_fractions = {0.0, 0.5, 1.0};
  const BalanceResult b = balance_driving_gear(su_engine(), kSpeed, o);
  ASSERT_EQ(b.trade_off.size(), 3u);
  EXPECT_GT(b.trade_off[0].max_surging, b.trade_off[1].max_surging);
  EXPECT_GT(b.trade_off[1].max_surging, b.trade_off[2].max_surging);
  EXPECT_LT(b.trade_off[0].max_alpha, b.trade_off[2].max_alpha);
}

TEST(Balance, OptionsAreCheckedByName) {
  BalanceOptions o;
  std::string why;
  o.allowed_alpha = 1.5;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("allowed_alpha"), std::string::npos);
  o = {};
  o.reciprocating_fraction = -0.1;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("reciprocating_fraction"), std::string::npos);
  EXPECT_THROW(balance_driving_gear(su_engine(), kSpeed, o), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal
