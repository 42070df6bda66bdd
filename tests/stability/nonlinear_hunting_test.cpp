// The nonlinear critical speed: the lateral equations against the linear model at small
// amplitude, Shen–Hedrick–Elkins' saturation, and the ramp-down of a wheelset on springs with
// saturation and flange (docs/stability.md, "The nonlinear critical speed").
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "railmodal/railmodal.hpp"
#include "stability/creep_saturation.hpp"
#include "stability/lateral_equations.hpp"
#include "stability/ramp_down.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal {
namespace {

using test::WheelsetData;
using test::wheelset_on_springs;

// The linear critical speed of the wheelset on springs (k_y = 1e6 N/m, k_ψ = 2e6 N·m/rad), by
// Routh–Hurwitz in hunting_validation_test.cpp (WheelsetOnSpringsCriticalSpeed).
constexpr double kLinearCriticalSpeed = 66.205641;  // 65.330265 before κ entered the force projection

// Two wheelsets in a frame on soft, damped primary springs, each wheelset's reference point off
// its axle (so the contact forces reach the DOFs through the lever), and a series damper added by
// hand: every term of the equations takes part.
LinearSystem bogie_system() {
  Vehicle v;
  v.name = "bogie";
  Body frame;
  frame.name = "frame";
  frame.mass = 2000.0;
  frame.inertia = {1000.0, 1500.0, 2000.0};
  v.bodies.push_back(frame);
  for (int i = 0; i < 2; ++i) {
    WheelsetData w;
    w.name = i == 0 ? "wheelset1" : "wheelset2";
    w.x = i == 0 ? 1.25 : -1.25;
    test::add_wheelset(v, w);
    v.bodies.back().reference_point = {w.x + 0.4, 0.0, 0.0};
    for (double y : {-1.0, 1.0}) {
      Element e = test::spring(w.name + ".primary", "frame", w.name, {w.x, y, 0.0}, 5e6, 2e6, 1e6);
      e.lateral_damping = 1e4;
      v.elements.push_back(e);
    }
  }
  LinearSystem s = assemble(v, DofSet::lateral);
  SeriesDamperRow d;
  d.stretch = Eigen::RowVectorXd::Zero(s.size());
  d.stretch[s.index_of("frame.lateral")] = 1.0;
  d.damping = 2e4;
  d.stiffness = 5e6;
  s.series_dampers.push_back(d);
  return s;
}

// M⁻¹(−(C + C_c/V + V·G) q̇ − (K + K_c) q − stretchᵀF): the linear model's accelerations.
Eigen::VectorXd linear_acceleration(const LinearSystem& s, const ContactMatrices& c, double speed,
                                    const Eigen::VectorXd& x) {
  const int n = s.size();
  const Eigen::VectorXd q = x.head(n), rate = x.segment(n, n);
  Eigen::VectorXd force =
      -(s.damping + c.creep_damping / speed + speed * c.gyroscopic) * rate - (s.stiffness + c.stiffness) * q;
  for (std::size_t k = 0; k < s.series_dampers.size(); ++k)
    force -= s.series_dampers[k].stretch.transpose() * x[2 * n + static_cast<int>(k)];
  return s.mass.ldlt().solve(force);
}

TEST(NonlinearHunting, LinearLawReproducesTheLinearModel) {
  const LinearSystem s = bogie_system();
  NonlinearHuntingOptions options;
  options.effects.clear();  // the linear creep law, no flange
  const stability::LateralEquations e(s, options);
  const ContactMatrices c = contact_matrices(s);
  ASSERT_EQ(e.size(), 2 * s.size() + 1);
  std::srand(7);
  for (double speed : {2.0, 30.0, 90.0})
    for (double amplitude : {1e-6, 1e-3}) {
      const Eigen::VectorXd x = amplitude * Eigen::VectorXd::Random(e.size());
      Eigen::VectorXd dx;
      e.derivative(speed, x, &dx);
      const Eigen::VectorXd expected = linear_acceleration(s, c, speed, x);
      // Round-off: the same sums in another order, over forces of the size of the largest term.
      EXPECT_LE((dx.segment(s.size(), s.size()) - expected).norm(), 1e-11 * expected.norm())
          << "V = " << speed << ", amplitude " << amplitude;
      EXPECT_EQ(dx.head(s.size()), x.segment(s.size(), s.size()));
      const SeriesDamperRow& d = s.series_dampers[0];
      const double f = x[2 * s.size()];
      EXPECT_NEAR(dx[2 * s.size()], d.stiffness * (d.stretch.dot(x.segment(s.size(), s.size())) - f / d.damping),
                  1e-12 * d.stiffness * amplitude);
    }
}

TEST(NonlinearHunting, SaturationAndFlangeVanishAtSmallAmplitude) {
  // Below the clearance the flange does nothing; the saturation's cubic has slope 1 at zero, so
  // its relative departure from the linear law is F/(3μN): at 1e-7 m, under 1e-4.
  const LinearSystem s = bogie_system();
  const stability::LateralEquations e(s, NonlinearHuntingOptions{});
  const ContactMatrices c = contact_matrices(s);
  std::srand(11);
  const Eigen::VectorXd x = 1e-7 * Eigen::VectorXd::Random(e.size());
  Eigen::VectorXd dx;
  e.derivative(40.0, x, &dx);
  const Eigen::VectorXd expected = linear_acceleration(s, c, 40.0, x);
  const double departure = (dx.segment(s.size(), s.size()) - expected).norm() / expected.norm();
  EXPECT_LT(departure, 1e-4);
  EXPECT_GT(departure, 0.0);  // but the law is not the linear one
}

TEST(NonlinearHunting, CentredSpinCancelsAtRestButTakesAdhesion) {
  // With δ0 = 0.05 rad the wheels spin at ∓δ0/r0 when centred: equal and opposite forces
  // (f23·δ0/r0 ≈ 1.1 kN each, against μN = 20 kN), so the centred wheelset stays at rest; but
  // each wheel's creep forces saturate sooner: a small lateral force along the spin force meets
  // the cubic's slope at u0 = 1.1/20, 1 − 2u0/3 + u0²/9, so it is smaller than the linear law's
  // by about 2u0/3 ≈ 3.6% (without δ0 it is within 1e-4, SaturationAndFlangeVanishAtSmallAmplitude).
  const LinearSystem s = assemble(wheelset_on_springs(), DofSet::lateral);
  NonlinearHuntingOptions o;
  o.wheel_load = 50e3;
  o.contact_angle = 0.05;
  const stability::LateralEquations with_spin(s, o);
  Eigen::VectorXd dx;
  with_spin.derivative(40.0, Eigen::VectorXd::Zero(with_spin.size()), &dx);
  EXPECT_EQ(dx.norm(), 0.0);  // the two wheels' terms are exact negatives of each other
  Eigen::VectorXd x = Eigen::VectorXd::Zero(with_spin.size());
  x[s.index_of("wheelset.yaw")] = 1e-7;  // a yaw: lateral creepage, resisted by f22 alone
  with_spin.derivative(40.0, x, &dx);
  const ContactMatrices c = contact_matrices(s);
  const Eigen::VectorXd linear = linear_acceleration(s, c, 40.0, x);
  const int lateral = s.index_of("wheelset.lateral");
  const double departure = 1.0 - dx[s.size() + lateral] / linear[lateral];
  const double u0 = 1.0e4 * 0.05 / 0.46 / (0.4 * 50e3);
  EXPECT_NEAR(departure, 2.0 * u0 / 3.0 - u0 * u0 / 9.0, 1e-3);  // the yaw's own 1e-7 adds ~1e-5
}

TEST(NonlinearHunting, ShenHedrickElkinsSaturation) {
  const CreepCoefficients f{1.0e7, 0.9e7, 1.0e4, 100.0};
  const double limit = 0.4 * 50e3;
  // Small creepage: the linear law, to the cubic's second term u/3.
  const model::WheelCreepage small{1e-6, -2e-6, 0.0};
  const auto lin = model::linear_creep_forces(f, small);
  const auto sat = stability::saturated_creep_forces(f, small, limit);
  const double u = std::hypot(lin.longitudinal, lin.lateral) / limit;
  EXPECT_NEAR(sat.lateral / lin.lateral, 1.0 - u / 3.0, u * u / 9.0);
  // Beyond u = 3: exactly μN, in the direction of the linear forces, the spin moment scaled alike.
  const model::WheelCreepage large{0.01, 0.02, 0.5};
  const auto lin_large = model::linear_creep_forces(f, large);
  const auto sat_large = stability::saturated_creep_forces(f, large, limit);
  EXPECT_NEAR(std::hypot(sat_large.longitudinal, sat_large.lateral), limit, 1e-9 * limit);
  EXPECT_NEAR(sat_large.lateral / sat_large.longitudinal, lin_large.lateral / lin_large.longitudinal, 1e-12);
  EXPECT_NEAR(sat_large.spin_moment / lin_large.spin_moment,
              limit / std::hypot(lin_large.longitudinal, lin_large.lateral), 1e-12);
  // Continuous at u = 3, where the cubic reaches μN with zero slope.
  const double at_three = 3.0 * limit / f.f11;
  const auto below = stability::saturated_creep_forces(f, {at_three * (1 - 1e-9), 0.0, 0.0}, limit);
  EXPECT_NEAR(std::abs(below.longitudinal), limit, 1e-9 * limit);
  // Zero creepage: zero force, not NaN.
  const auto zero = stability::saturated_creep_forces(f, {}, limit);
  EXPECT_EQ(zero.lateral, 0.0);
}

NonlinearHuntingOptions wheelset_options() {
  NonlinearHuntingOptions o;
  o.wheel_load = 50e3;  // N: the load creep coefficients of this size belong to (hunting_test_support.hpp)
  o.friction_coefficient = 0.4;
  o.flange_clearance = 0.008;
  o.flange_stiffness = 1.0e7;
  o.start_speed = 75.0;
  o.end_speed = 30.0;
  o.ramp_rate = 0.5;
  o.disturbance = 0.005;
  return o;
}

// The nonlinear critical speed of the wheelset on springs (hunting_test_support.hpp) under `o`.
NonlinearHuntingResult solve_wheelset_on_springs(const NonlinearHuntingOptions& o) {
  return solve_nonlinear_hunting(assemble(wheelset_on_springs(), DofSet::lateral), o);
}

TEST(NonlinearHunting, WheelsetOnSpringsLimitCycle) {
  const NonlinearHuntingOptions o = wheelset_options();
  const NonlinearHuntingResult r = solve_wheelset_on_springs(o);
  ASSERT_EQ(r.verdict, NonlinearHuntingVerdict::limit_cycle_dies_out);
  ASSERT_TRUE(r.critical_speed.has_value());
  RecordProperty("nonlinear_critical_speed", std::to_string(*r.critical_speed));
  RecordProperty("limit_cycle_amplitude", std::to_string(r.amplitude));
  RecordProperty("halved_rate_critical_speed", std::to_string(*r.halved_rate.critical_speed));
  // The limit cycle dies out at or below the linear critical speed (above it the centred running
  // is unstable, so no oscillation can die out there), but not far below: the subcritical branch
  // of this wheelset is short.
  EXPECT_LE(*r.critical_speed, kLinearCriticalSpeed);
  EXPECT_GT(*r.critical_speed, kLinearCriticalSpeed - 2.0);
  // The amplitude is bounded by the clearance plus the flange's quasi-static deflection under the
  // largest force it can meet: both wheels' creep forces at μN and the lateral springs' k_y·A,
  // A ≤ (d + 2μN/k_f)/(1 − k_y/k_f) = 13.3 mm; the flange is reached, so the bound is not idle.
  const double bound =
      (o.flange_clearance + 2.0 * o.friction_coefficient * *o.wheel_load / o.flange_stiffness) / (1.0 - 1.0e6 / 1.0e7);
  double largest = 0.0;
  for (const LimitCyclePoint& p : r.curve) {
    EXPECT_TRUE(std::isfinite(p.amplitude));
    largest = std::max(largest, p.amplitude);
  }
  EXPECT_LE(largest, bound);
  EXPECT_GT(largest, o.flange_clearance);
  EXPECT_GT(r.amplitude, 0.5 * o.flange_clearance);
  // The curve runs down in speed, from the start to the collapse.
  EXPECT_GT(r.curve.front().speed, r.curve.back().speed);
  // Halving the ramp rate moves the ramp's answer by less than 0.1 m/s (0.011 measured); the held
  // critical speed is bracketed to the tolerance, and survives a hold twice as long.
  EXPECT_LT(r.convergence_difference, 0.1);
  EXPECT_EQ(r.convergence, NonlinearConvergence::converged);
  EXPECT_TRUE(r.converged);
  ASSERT_TRUE(r.hold.lowest_surviving && r.hold.highest_dying);
  EXPECT_EQ(*r.critical_speed, *r.hold.lowest_surviving);
  EXPECT_LE(*r.hold.lowest_surviving - *r.hold.highest_dying, o.tolerance);
  EXPECT_TRUE(r.hold.doubled_hold_survives);
  EXPECT_TRUE(r.summary.passed());
}

TEST(NonlinearHunting, SubcriticalLimitCycleBelowTheLinearCriticalSpeed) {
  // Held from 66.18 m/s (0.03 m/s below the linear critical speed; the ramp of 0.0005 m/s² moves
  // it by 0.02 m/s in 40 s, some 280 periods) from a 9 mm disturbance, the saturated and flanged
  // wheelset keeps a limit cycle above 7 mm: the branch is subcritical. The linear law, from the
  // same start, decays below 5 mm, and from 65.90 m/s (0.12 m/s below the ramp-down's 66.02) the
  // nonlinear one decays too (under 3 mm): the branch's fold lies between, as the ramp-down of
  // WheelsetOnSpringsLimitCycle says. (Before κ entered the lateral force, with the linear
  // critical speed 65.33 m/s, the speeds were 65.30 and 65.1 m/s held for 20 s; the decay so
  // near the critical speed is slow, hence the longer hold.)
  NonlinearHuntingOptions o = wheelset_options();
  o.start_speed = 66.18;
  o.end_speed = 66.16;
  o.ramp_rate = 0.0005;
  o.disturbance = 0.009;
  const LinearSystem s = assemble(wheelset_on_springs(), DofSet::lateral);
  const NonlinearHuntingResult r = solve_nonlinear_hunting(s, o);
  ASSERT_EQ(r.verdict, NonlinearHuntingVerdict::survives_to_end_speed);
  EXPECT_GT(r.curve.back().amplitude, 0.007) << r.curve.back().amplitude;
  o.effects.clear();
  const NonlinearHuntingResult linear = solve_nonlinear_hunting(s, o);
  EXPECT_LT(linear.curve.back().amplitude, 0.005) << linear.curve.back().amplitude;
  o = wheelset_options();
  o.start_speed = 65.90;
  o.end_speed = 65.88;
  o.ramp_rate = 0.0005;
  o.disturbance = 0.009;
  EXPECT_LT(solve_nonlinear_hunting(s, o).curve.back().amplitude, 0.003);
}

TEST(NonlinearHunting, HeldCriticalSpeedAgreesWithALongHold) {
  // Saturation only (no flange): the ramp at 0.5 m/s² lost the cycle at 65.03 m/s, but a physics
  // review's long holds put the fold at 64.7–64.9 m/s, and the confirmation answers 64.815 m/s
  // (docs/stability.md; figures of the contact model as of this test, not asserted, since the
  // contact terms may be refined). What is asserted holds for any model: holds five times as long
  // as the bisection's (1500 periods) agree with it, just above the answer the cycle survives,
  // just below it dies.
  NonlinearHuntingOptions o = wheelset_options();
  o.effects = {NonlinearEffect::creep_saturation};
  const LinearSystem s = assemble(wheelset_on_springs(), DofSet::lateral);
  const NonlinearHuntingResult r = solve_nonlinear_hunting(s, o);
  ASSERT_EQ(r.verdict, NonlinearHuntingVerdict::limit_cycle_dies_out);
  ASSERT_TRUE(r.critical_speed && r.stated_rate.critical_speed && r.richardson_critical_speed);
  RecordProperty("held_critical_speed", std::to_string(*r.critical_speed));
  RecordProperty("ramp_critical_speed", std::to_string(*r.stated_rate.critical_speed));
  RecordProperty("richardson_critical_speed", std::to_string(*r.richardson_critical_speed));
  EXPECT_EQ(r.convergence, NonlinearConvergence::converged);
  EXPECT_LE(*r.critical_speed, kLinearCriticalSpeed + o.tolerance);  // a subcritical branch or none
  // The long holds, from the ramp's state on the branch, as the bisection starts them.
  const stability::LateralEquations e(s, o);
  stability::BranchStates branch;
  const RampDown ramp = stability::ramp_down(e, o, o.ramp_rate, &branch);
  const Eigen::VectorXd& start = branch.states[branch.branch_end];
  const SpeedHold above = stability::hold_speed(e, o, *r.critical_speed + o.tolerance, start, 0, 1500);
  const SpeedHold below = stability::hold_speed(e, o, *r.critical_speed - o.tolerance, start, 0, 1500);
  EXPECT_TRUE(above.survives) << above.end_amplitude;
  EXPECT_FALSE(below.survives) << below.end_amplitude;
  EXPECT_GT(above.end_amplitude, 0.02);  // a cycle of over 20 mm, not a slow decay
}

// A hold just below the fold whose cycle dies slowly (fix-checks, 2026-11-27). Saturation only,
// 0.0115 m/s below the held critical speed (65.625 m/s with the contact model of this test; the
// fold lies 0.005–0.017 m/s below the answer): held 1500 periods the cycle falls to half (at about
// 1000 periods), so it dies; held 200 periods it has lost only 14 %, and its decay over the last
// quarter, rate × 50 periods ≈ 0.85 %, is under the 1 % by which the earlier rule called it
// surviving. The measured rate, −1.7e-4 a period, is resolved below the −1e-4 threshold by more
// than its worst case over the residual's envelope (the most a wobble as large as the largest
// residual can move a fitted slope, whatever its pattern: the residuals are the peaks' sampling
// and the settling, deterministic and correlated, so no standard error describes them): it dies.
TEST(NonlinearHunting, SlowDeathJustBelowTheFoldIsNotASurvival) {
  NonlinearHuntingOptions o = wheelset_options();
  o.effects = {NonlinearEffect::creep_saturation};
  const LinearSystem s = assemble(wheelset_on_springs(), DofSet::lateral);
  const NonlinearHuntingResult r = solve_nonlinear_hunting(s, o);
  ASSERT_TRUE(r.critical_speed.has_value());
  const stability::LateralEquations e(s, o);
  stability::BranchStates branch;
  stability::ramp_down(e, o, o.ramp_rate, &branch);
  const Eigen::VectorXd& start = branch.states[branch.branch_end];
  const double speed = *r.critical_speed - 0.0115;
  // The premise: a long hold sees it die (falls below half the start: no rate needed).
  const SpeedHold long_hold = stability::hold_speed(e, o, speed, start, 0, 1500);
  ASSERT_FALSE(long_hold.survives);
  ASSERT_LT(long_hold.periods, 1500);
  // The short hold: the earlier rule's blind spot (a fall of under 1 % over its last quarter) ...
  const int periods = 200;
  const SpeedHold hold = stability::hold_speed(e, o, speed, start, 0, periods);
  EXPECT_EQ(hold.periods, periods);                       // it did not fall to half
  EXPECT_LT(-hold.rate_per_period * periods / 4.0, 0.01);  // so the old rule said "survives"
  // ... and the rate, resolved (its worst case clear of −1e-4), says it dies. The bound is a real
  // one: finite and positive (the residuals are not zero: measured 4.3e-5 a period against the
  // rate's −1.69e-4, where two "standard errors" said 1.4e-6), and the rate plus it is below the
  // threshold, so no wobble within the residual's envelope could have made it a survival.
  EXPECT_GT(hold.rate_error, 0.0);
  EXPECT_TRUE(std::isfinite(hold.rate_error));
  EXPECT_LT(hold.rate_per_period + hold.rate_error, -1e-4);
  RecordProperty("slow_death_rate_per_period", std::to_string(hold.rate_per_period));
  RecordProperty("slow_death_rate_bound", std::to_string(hold.rate_error));
  EXPECT_FALSE(hold.survives);
  EXPECT_FALSE(hold.undecided);
  // A hold too short to fit a rate (fewer than 4 half cycles in its second half) is undecided,
  // never surviving.
  const SpeedHold brief = stability::hold_speed(e, o, speed, start, 0, 3);
  EXPECT_TRUE(brief.undecided);
  EXPECT_FALSE(brief.survives);
}

// Half-cycle peaks whose ln A is l(k), k = 0 … count − 1 (hold_rate fits k = 100 … 199 of 201).
std::vector<LimitCyclePoint> peaks_of(const std::function<double(double)>& l, int count = 201) {
  std::vector<LimitCyclePoint> peaks;
  for (int k = 0; k < count; ++k) peaks.push_back({50.0, std::exp(l(k))});
  return peaks;
}

// The sampling's δ (review of 2026-11-28): a cosine sampled at steps h, at every phase of the
// samples against its peak, has its largest sample no lower than exp(−δ) of the peak, and at
// the worst phase (the peak midway between two samples) exactly that: δ is the least bound.
TEST(NonlinearHunting, SamplingErrorIsTheLargestSamplesWorstShortfall) {
  const double omega = 2.0 * 3.14159265358979 * 2.4, h = 1.0 / (2.4 * 100.0);  // 100 samples a period
  const double delta = stability::sampling_error(omega, h);
  EXPECT_NEAR(delta, std::pow(omega * h, 2) / 8.0, 1e-3 * delta);  // its small-angle form, (ωh)²/8
  double worst = 0.0;
  for (int phase = 0; phase <= 100; ++phase) {  // the peak at t = 0, samples at (phase/100 + j)·h
    double largest = 0.0;
    for (int j = -3; j <= 3; ++j) largest = std::max(largest, std::cos(omega * (phase / 100.0 + j) * h));
    EXPECT_GE(std::log(largest), -delta - 1e-15);  // 1e-15: the round-off of a log near 1
    worst = std::max(worst, -std::log(largest));
  }
  EXPECT_NEAR(worst, delta, 1e-12);  // phase 50 puts the peak midway: δ itself, to round-off
  EXPECT_TRUE(std::isinf(stability::sampling_error(omega, 4.0 * 3.14159265358979 / omega)));  // ωh = 2π: no bound
}

// A sampling error that grows steadily along the fit (−δ at its start to 0 at its end) is a
// straight line in ln A: the fit absorbs it whole and leaves no residual, so a bound from the
// residual alone is 0 while the slope is wrong by δ/(n − 1) a half cycle. The δ term of the bound
// covers it, and is not loose by more than the 1.5 of δ·Σ|d|/(2Σd²) against δ/(n − 1).
TEST(NonlinearHunting, HoldRateBoundCoversASamplingErrorTheFitAbsorbs) {
  const double delta = stability::sampling_error(2.0 * 3.14159265358979, 0.01);  // ≈ 4.9e-4
  const double true_rate = -2e-4;                                                 // per period
  const auto l = [&](double k) { return 0.5 * true_rate * k - delta * (1.0 - std::clamp((k - 100.0) / 99.0, 0.0, 1.0)); };
  const stability::HoldRate r = stability::hold_rate(peaks_of(l), delta);
  const double error = std::abs(r.rate.per_period - true_rate);
  EXPECT_NEAR(error, 2.0 * delta / 99.0, 1e-12);  // the shift the line makes, per period
  EXPECT_LE(error, r.rate.bound);
  EXPECT_GT(error, 0.6 * r.rate.bound);  // (2/99)/(2·2500/(2·83325)) = 0.673: the δ term, not a loose one
}

// Settling onto a cycle from above: ln A = 0.2·exp(−k/60), a decay that slows toward 0. Over the
// hold's second half the fitted rate, −5.9e-4 ± 2.9e-4 a period, is resolved below −1e-4 (a
// verdict from the rate alone: dies), but it rises by 4.8e-4 from the first half of the span to
// the second, more than their bounds (3.2e-4): still changing, toward the threshold, so undecided.
// The collapse that speeds up (the mirror image, the rate falling) changes away from the
// threshold and dies (−3.1e-3 a period, falling by 2.5e-3); a steady decay at −3e-4 a period does
// not change and dies.
TEST(NonlinearHunting, HoldRateStillChangingTowardTheThresholdIsUndecided) {
  const double delta = stability::sampling_error(2.0 * 3.14159265358979, 0.01);
  const stability::HoldRate settling = stability::hold_rate(peaks_of([](double k) { return 0.2 * std::exp(-k / 60.0); }), delta);
  EXPECT_LT(settling.rate.per_period + settling.rate.bound, -1e-4);  // the rate alone says: dies
  EXPECT_GT(settling.change, settling.change_bound);                 // but it is still rising
  EXPECT_EQ(stability::rate_verdict(settling), stability::RateVerdict::undecided);

  const stability::HoldRate collapse =
      stability::hold_rate(peaks_of([](double k) { return -0.2 * std::exp((k - 200.0) / 60.0); }), delta);
  EXPECT_LT(collapse.change, -collapse.change_bound);  // resolved, falling: away from −1e-4
  EXPECT_EQ(stability::rate_verdict(collapse), stability::RateVerdict::dies);

  const stability::HoldRate steady = stability::hold_rate(peaks_of([](double k) { return -1.5e-4 * k; }), delta);
  EXPECT_NEAR(steady.rate.per_period, -3e-4, 1e-12);  // exact data: the fit to round-off
  EXPECT_LE(std::abs(steady.change), steady.change_bound);
  EXPECT_EQ(stability::rate_verdict(steady), stability::RateVerdict::dies);
  // A growth that slows (approaching a cycle from below: 0.2·(1 − exp(−k/60))) falls toward the
  // threshold but cannot cross it: it survives.
  const stability::HoldRate approach =
      stability::hold_rate(peaks_of([](double k) { return 0.2 * (1.0 - std::exp(-k / 60.0)); }), delta);
  EXPECT_LT(approach.change, -approach.change_bound);
  EXPECT_GT(approach.rate.per_period - approach.rate.bound, 0.0);
  EXPECT_EQ(stability::rate_verdict(approach), stability::RateVerdict::survives);
  // Too few half cycles in the halves (9 peaks: a span of 4, halves of 2): undecided.
  EXPECT_EQ(stability::rate_verdict(stability::hold_rate(peaks_of([](double k) { return -0.01 * k; }, 9), delta)),
            stability::RateVerdict::undecided);
}

TEST(NonlinearHunting, HuntingOfTheSecondWheelsetIsSeen) {
  // Two wheelsets on their own springs to the ground, not coupled: the first so stiffly held in
  // yaw that it does not hunt at all in the ramp, the second the wheelset on springs. The hunting
  // is the second's, and its critical speed is the single wheelset's (HeldCriticalSpeedAgrees...):
  // watching the first wheelset alone found no limit cycle.
  Vehicle v;
  v.name = "two wheelsets";
  WheelsetData first, second;
  first.name = "first";
  first.x = 1.5;
  second.name = "second";
  second.x = -1.5;
  test::add_wheelset(v, first);
  test::add_springs_to_ground(v, first, 1.0e6, 6.0e6);
  test::add_wheelset(v, second);
  test::add_springs_to_ground(v, second, 1.0e6, 2.0e6);
  NonlinearHuntingOptions o = wheelset_options();
  o.end_speed = 60.0;  // the fold is near 65 m/s: the ramp below 60 m/s would only cost time
  const NonlinearHuntingResult r = solve_nonlinear_hunting(assemble(v, DofSet::lateral), o);
  const NonlinearHuntingResult alone = solve_wheelset_on_springs(o);
  EXPECT_EQ(r.stated_rate.watched_wheelset, 1);
  ASSERT_EQ(r.verdict, NonlinearHuntingVerdict::limit_cycle_dies_out);
  ASSERT_TRUE(r.critical_speed && alone.critical_speed);
  // The same equations for the second wheelset, integrated with other step sizes (the step
  // control sees both): the bisections may end one tolerance apart.
  EXPECT_NEAR(*r.critical_speed, *alone.critical_speed, 2.0 * o.tolerance);
}

// The audit of 2026-11-27: the bundled scene at ten times its ramp rate (5 m/s², 270 to 180 km/h).
// The ramp drags the cycle down before it settles on its branch and loses it some 5 m/s above
// where a held speed keeps it; the holds widen downwards four times and every one survives.
// Before, the answer was the hold one widening above the lowest that survived (243.04 km/h
// reported with a cycle held at 239.44), and the Richardson extrapolation of the two too-fast
// ramps (262 km/h) was given as if the ramps lagged.
TEST(NonlinearHunting, TooFastRampIsFlaggedAndTheAnswerIsTheLowestSurvivingHold) {
  NonlinearHuntingOptions o = wheelset_options();
  o.start_speed = 75.0;
  o.end_speed = 50.0;
  o.ramp_rate = 5.0;
  const NonlinearHuntingResult r = solve_wheelset_on_springs(o);
  ASSERT_EQ(r.verdict, NonlinearHuntingVerdict::limit_cycle_dies_out);
  ASSERT_TRUE(r.critical_speed && r.hold.lowest_surviving && r.stated_rate.critical_speed);
  ASSERT_FALSE(r.hold.holds.empty());
  // The answer is never above a hold whose cycle survived, and is itself such a hold.
  bool held_there = false;
  for (const SpeedHold& h : r.hold.holds) {
    if (h.survives) {
      EXPECT_LE(*r.critical_speed, h.speed) << "a cycle survived a hold at " << h.speed;
    }
    held_there = held_there || (h.survives && h.speed == *r.critical_speed);
    if (!h.survives && r.hold.highest_dying) {
      EXPECT_LE(h.speed, *r.hold.highest_dying);
    }
  }
  EXPECT_TRUE(held_there);
  EXPECT_EQ(*r.critical_speed, *r.hold.lowest_surviving);
  // The ramp's answer lies more than hold_margin above a surviving hold: too fast, no
  // extrapolation over the ramps, and no converged answer.
  EXPECT_GT(*r.stated_rate.critical_speed, *r.hold.lowest_surviving + o.hold_margin);
  EXPECT_TRUE(r.ramp_too_fast);
  EXPECT_FALSE(r.richardson_critical_speed.has_value());
  EXPECT_EQ(r.convergence, NonlinearConvergence::not_converged);
  EXPECT_FALSE(r.summary.passed());
  const std::string why = nonlinear_hunting_warning(r, o);
  EXPECT_NE(why.find("too fast for its answer"), std::string::npos) << why;
  EXPECT_NE(why.find("lower ramp_rate"), std::string::npos) << why;
}

// The rate that suits the wheelset (0.5 m/s²) is not flagged: its answer lies within a fraction
// of a m/s of the held one, and both ramps' answers extrapolate.
TEST(NonlinearHunting, SuitableRampIsNotFlagged) {
  NonlinearHuntingOptions o = wheelset_options();
  o.end_speed = 60.0;  // the fold is near 66 m/s: the ramp below 60 m/s would only cost time
  const NonlinearHuntingResult r = solve_wheelset_on_springs(o);
  EXPECT_FALSE(r.ramp_too_fast);
  EXPECT_FALSE(r.collapsing_at_end_speed);
  EXPECT_TRUE(r.richardson_critical_speed.has_value());
  EXPECT_EQ(r.convergence, NonlinearConvergence::converged);
  EXPECT_EQ(nonlinear_hunting_warning(r, o), "");
}

// The audit's 20 m/s²: the cycle never settles, and at the end speed the amplitude still falls by
// some 19 % a half cycle (under a third of the clearance, still above the extinction amplitude).
// Before, "survives_to_end_speed ... Lower end_speed" with convergence not_applicable.
TEST(NonlinearHunting, RampEndingInsideACollapseIsNotConverged) {
  NonlinearHuntingOptions o = wheelset_options();
  o.start_speed = 75.0;
  o.end_speed = 50.0;
  o.ramp_rate = 20.0;
  const NonlinearHuntingResult r = solve_wheelset_on_springs(o);
  ASSERT_EQ(r.verdict, NonlinearHuntingVerdict::survives_to_end_speed);
  const auto& c = r.curve;
  ASSERT_GE(c.size(), 3u);
  EXPECT_LT(c[c.size() - 2].amplitude, 0.9 * c[c.size() - 3].amplitude);  // collapsing, by far more than 0.5 %
  EXPECT_TRUE(r.collapsing_at_end_speed);
  EXPECT_EQ(r.convergence, NonlinearConvergence::not_converged);
  EXPECT_FALSE(r.summary.passed());
  EXPECT_NE(nonlinear_hunting_warning(r, o).find("ended while the cycle collapsed"), std::string::npos);
}

TEST(NonlinearHunting, LinearLawRampFindsTheLinearCriticalSpeed) {
  // With the linear law the ramp-down has no limit cycle to follow: the oscillation grows while
  // the speed is above the linear critical speed and decays below it, and the onset of decay is
  // that speed. The ramp lags by about rate·(half a period) ≈ 0.02 m/s.
  NonlinearHuntingOptions o = wheelset_options();
  o.effects.clear();
  o.start_speed = 68.0;
  o.disturbance = 1e-4;
  const NonlinearHuntingResult r = solve_wheelset_on_springs(o);
  ASSERT_TRUE(r.halved_rate.critical_speed.has_value() && r.stated_rate.critical_speed.has_value());
  EXPECT_NEAR(*r.halved_rate.critical_speed, kLinearCriticalSpeed, 0.05);
  EXPECT_NEAR(*r.stated_rate.critical_speed, kLinearCriticalSpeed, 0.05);
  // Held, the linear law's oscillation grows above the linear critical speed and decays below:
  // the bisection brackets that speed, within the tolerance and the slow growth of the last
  // hundredths of a m/s (whose growth over 300 periods is under the 1% settling test).
  ASSERT_TRUE(r.critical_speed.has_value());
  EXPECT_NEAR(*r.critical_speed, kLinearCriticalSpeed, 0.1);
}

TEST(NonlinearHunting, LinearLawGrowsWithoutBound) {
  // The linear law well above its critical speed on a long ramp: the oscillation grows
  // exponentially; the run stops at the amplitude bound with that verdict, not an overflow.
  NonlinearHuntingOptions o = wheelset_options();
  o.effects.clear();
  o.start_speed = 100.0;
  o.ramp_rate = 0.2;
  const NonlinearHuntingResult r = solve_wheelset_on_springs(o);
  EXPECT_EQ(r.verdict, NonlinearHuntingVerdict::unbounded_growth);
  EXPECT_EQ(r.halved_rate.verdict, NonlinearHuntingVerdict::unbounded_growth);
  EXPECT_FALSE(r.critical_speed.has_value());
  EXPECT_EQ(r.convergence, NonlinearConvergence::not_applicable);
  EXPECT_FALSE(r.converged);
  ASSERT_FALSE(r.curve.empty());
  for (const LimitCyclePoint& p : r.curve) EXPECT_TRUE(std::isfinite(p.amplitude));
  EXPECT_GT(r.curve.back().speed, kLinearCriticalSpeed);  // stopped while still above it
}

TEST(NonlinearHunting, OptionsAreValidated) {
  std::string why;
  EXPECT_TRUE(NonlinearHuntingOptions{}.is_valid(&why));
  NonlinearHuntingOptions o;
  o.friction_coefficient = 0.0;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("friction_coefficient"), std::string::npos);
  o = {};
  o.end_speed = o.start_speed;
  EXPECT_FALSE(o.is_valid(&why));
  o = {};
  o.ramp_rate = -1.0;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("ramp_rate"), std::string::npos);
  o = {};
  o.hold_periods = 5;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("hold_periods"), std::string::npos);
  o = {};
  o.amplitude_bound = o.extinction_amplitude;
  EXPECT_FALSE(o.is_valid(&why));
  o = {};
  o.disturbance = 0.0;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_THROW(solve_wheelset_on_springs(o), std::invalid_argument);
  Vehicle no_wheelsets = wheelset_on_springs();
  no_wheelsets.wheelsets.clear();
  EXPECT_THROW(solve_nonlinear_hunting(assemble(no_wheelsets, DofSet::lateral)), std::invalid_argument);
}

TEST(NonlinearHunting, EnumNamesRoundTrip) {
  for (NonlinearEffect e : {NonlinearEffect::creep_saturation, NonlinearEffect::flange_contact})
    EXPECT_EQ(nonlinear_effect_from_string(to_string(e)), e);
  for (NonlinearHuntingVerdict v :
       {NonlinearHuntingVerdict::limit_cycle_dies_out, NonlinearHuntingVerdict::survives_to_end_speed,
        NonlinearHuntingVerdict::no_limit_cycle_at_start, NonlinearHuntingVerdict::unbounded_growth})
    EXPECT_EQ(nonlinear_hunting_verdict_from_string(to_string(v)), v);
  EXPECT_STREQ(to_string(NonlinearConvergence::not_applicable), "not_applicable");
  EXPECT_FALSE(nonlinear_effect_from_string("flange").has_value());
}

}  // namespace
}  // namespace railmodal
