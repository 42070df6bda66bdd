// The hunting-stability solver on systems built by hand, whose answers are known in closed
// form: oscillators whose damping coefficient d(V) = c0 + c_c/V + g·V changes sign at the
// roots of a quadratic, a free wheelset, and a wheelset on springs checked against the
// Routh–Hurwitz condition of its characteristic polynomial. The contact terms are given
// directly (stability::hunting_analysis), so these tests do not wait for contact_matrices().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "railmodal/errors.hpp"
#include "railmodal/railmodal.hpp"
#include "stability/branches.hpp"
#include "stability/damping_search.hpp"
#include "stability/hunting_analysis.hpp"
#include "stability/root_tracking.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal::stability {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;

// Uncoupled unit oscillators "osc<i>.lateral" (no bodies: named after the DOF) with
// m = 1, k = ω², d_i(V) = c0 + c_c/V + g·V.
struct Oscillator {
  double omega, c0, cc, g;
};

struct HandBuilt {
  LinearSystem system;
  ContactMatrices contact;
  ContactSource source() const {
    return [this](std::optional<double>) { return contact; };
  }
};

HandBuilt oscillators(const std::vector<Oscillator>& list) {
  const int n = static_cast<int>(list.size());
  HandBuilt h;
  for (int i = 0; i < n; ++i)
    h.system.dofs.push_back({"osc" + std::to_string(i + 1) + ".lateral", -1, Motion::lateral});
  h.system.mass = Eigen::MatrixXd::Identity(n, n);
  h.system.damping = Eigen::MatrixXd::Zero(n, n);
  h.system.stiffness = Eigen::MatrixXd::Zero(n, n);
  h.contact.creep_damping = Eigen::MatrixXd::Zero(n, n);
  h.contact.gyroscopic = Eigen::MatrixXd::Zero(n, n);
  h.contact.stiffness = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    h.system.stiffness(i, i) = list[i].omega * list[i].omega;
    h.system.damping(i, i) = list[i].c0;
    h.contact.creep_damping(i, i) = list[i].cc;
    h.contact.gyroscopic(i, i) = list[i].g;
  }
  return h;
}

// The oscillator whose d(V) = c_c/V + c0 + g·V vanishes at V = a and V = b (g > 0):
// g·V² + c0·V + c_c = g(V − a)(V − b).
Oscillator unstable_between(double a, double b, double omega = kTwoPi) {
  return {omega, -0.01 * (a + b), 0.01 * a * b, 0.01};
}

HuntingOptions range(double low, double high, int count) {
  HuntingOptions o;
  o.min_speed = low;
  o.max_speed = high;
  o.speed_count = count;
  o.threads = 1;
  return o;
}

TEST(HuntingStability, CriticalSpeedOfAnOscillatorToTheRequestedTolerance) {
  // d(V) = 10/V + 1 − 0.01V vanishes at V* = (1 + √1.4)/0.02; there λ = ±iω: 1 Hz.
  const HandBuilt h = oscillators({{kTwoPi, 1.0, 10.0, -0.01}});
  const double exact = (1.0 + std::sqrt(1.4)) / 0.02;
  int previous = 0;
  for (double tolerance : {1e-4, 1e-8, 1e-12}) {
    HuntingOptions o = range(1.0, 200.0, 50);
    o.relative_tolerance = tolerance;
    const HuntingResult r = hunting_analysis(h.system, h.source(), o);
    ASSERT_EQ(r.verdict, HuntingVerdict::critical_speed_in_range);
    ASSERT_TRUE(r.critical);
    // The bracket ends within tolerance·V; ζ near its root is exact to round-off (1e-15 in
    // ζ over a slope of 1e-3 per m/s: 1e-12 m/s), so the error is the bracket's.
    EXPECT_LE(std::abs(r.critical->speed - exact), tolerance * exact + 1e-11) << tolerance;
    EXPECT_NEAR(r.critical->frequency_hz, 1.0, 1e-9);
    EXPECT_EQ(r.critical->branch, "osc1.lateral");
    EXPECT_GE(r.critical->evaluations, previous);  // a tighter tolerance never costs less
    previous = r.critical->evaluations;
    ASSERT_EQ(r.unstable_intervals.size(), 1u);
    EXPECT_TRUE(r.unstable_intervals[0].to_highest_speed);
    EXPECT_FALSE(r.unstable_intervals[0].from_lowest_speed);
  }
  EXPECT_LE(previous, 20);  // Brent converges superlinearly: 1e-12 from a 4 m/s bracket
}

TEST(HuntingStability, AnUndampedModeDoesNotStopTheRefinementAtTheGrid) {
  // An undamped 3 Hz mode makes the least-damped ζ exactly 0 at every stable speed; the
  // crossing must still be refined to where the other mode's ζ turns negative.
  const HandBuilt h = oscillators({{3.0 * kTwoPi, 0.0, 0.0, 0.0}, {kTwoPi, 1.0, 10.0, -0.01}});
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(1.0, 200.0, 50));
  ASSERT_TRUE(r.critical);
  const double exact = (1.0 + std::sqrt(1.4)) / 0.02;
  // Here the crossing ends at the edge of the round-off band |ζ| ≤ 1e-11 (damping_search.hpp):
  // 1e-11 / |dζ/dV| = 1e-11 / 8.6e-4 per m/s = 1.2e-8 m/s from the exact root, within the
  // 1e-8 relative bracket.
  EXPECT_LE(std::abs(r.critical->speed - exact), 1e-8 * exact + 2e-8);
  EXPECT_EQ(r.critical->branch, "osc2.lateral");
}

TEST(HuntingStability, EveryUnstableIntervalEvenWhereTheVehicleRestabilises) {
  const HandBuilt h = oscillators({unstable_between(30.0, 170.0), unstable_between(250.0, 350.0, 1.3 * kTwoPi)});
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(10.0, 400.0, 80));
  EXPECT_EQ(r.verdict, HuntingVerdict::critical_speed_in_range);
  ASSERT_EQ(r.unstable_intervals.size(), 2u);
  const double ends[2][2] = {{30.0, 170.0}, {250.0, 350.0}};
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(r.unstable_intervals[i].from, ends[i][0], 1e-7 * ends[i][0]);  // 1e-8 bracket, with margin
    EXPECT_NEAR(r.unstable_intervals[i].to, ends[i][1], 1e-7 * ends[i][1]);
    EXPECT_FALSE(r.unstable_intervals[i].from_lowest_speed);
    EXPECT_FALSE(r.unstable_intervals[i].to_highest_speed);
  }
  EXPECT_EQ(r.unstable_intervals[0].branch, "osc1.lateral");
  EXPECT_EQ(r.unstable_intervals[1].branch, "osc2.lateral");
  ASSERT_TRUE(r.critical);
  EXPECT_NEAR(r.critical->speed, 30.0, 1e-7 * 30.0);
}

TEST(HuntingStability, FindsANarrowIntervalBetweenTwoStableGridSpeeds) {
  // Unstable over [203, 204] only; the grid (step 10 m/s) has stable speeds at 200 and 210.
  const HandBuilt h = oscillators({unstable_between(203.0, 204.0)});
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(10.0, 400.0, 40));
  ASSERT_EQ(r.unstable_intervals.size(), 1u);
  EXPECT_NEAR(r.unstable_intervals[0].from, 203.0, 1e-6);
  EXPECT_NEAR(r.unstable_intervals[0].to, 204.0, 1e-6);
  EXPECT_EQ(r.verdict, HuntingVerdict::critical_speed_in_range);
}

TEST(HuntingStability, VerdictsInventNoCriticalSpeed) {
  const HandBuilt unstable = oscillators({unstable_between(1.0, 1000.0)});
  const HuntingResult u = hunting_analysis(unstable.system, unstable.source(), range(10.0, 100.0, 20));
  EXPECT_EQ(u.verdict, HuntingVerdict::unstable_at_lowest_speed);
  EXPECT_FALSE(u.critical);
  ASSERT_EQ(u.unstable_intervals.size(), 1u);
  EXPECT_TRUE(u.unstable_intervals[0].from_lowest_speed);
  EXPECT_TRUE(u.unstable_intervals[0].to_highest_speed);

  const HandBuilt stable = oscillators({{kTwoPi, 0.5, 10.0, 0.01}});
  const HuntingResult s = hunting_analysis(stable.system, stable.source(), range(10.0, 100.0, 20));
  EXPECT_EQ(s.verdict, HuntingVerdict::stable_throughout);
  EXPECT_FALSE(s.critical);
  EXPECT_TRUE(s.unstable_intervals.empty());
}

TEST(HuntingStability, ThresholdSpeedWhereZetaFallsToTheValueAsked) {
  // d(V) = 2 − 0.01V: ζ = d/(2ω) = 0.05 at V = (2 − 0.1ω)/0.01.
  const HandBuilt h = oscillators({{kTwoPi, 2.0, 0.0, -0.01}});
  HuntingOptions o = range(1.0, 300.0, 30);
  o.damping_threshold = 0.05;
  const HuntingResult r = hunting_analysis(h.system, h.source(), o);
  ASSERT_TRUE(r.threshold_speed);
  EXPECT_NEAR(*r.threshold_speed, (2.0 - 0.1 * kTwoPi) / 0.01, 1e-7 * 200.0);
  EXPECT_EQ(r.threshold_branch, "osc1.lateral");
  EXPECT_TRUE(r.below_threshold_at_lowest_speed.empty());
  o.damping_threshold = 0.5;  // already below at the lowest speed: no crossing, the branch listed
  const HuntingResult below = hunting_analysis(h.system, h.source(), o);
  EXPECT_FALSE(below.threshold_speed);
  EXPECT_EQ(below.below_threshold_at_lowest_speed, std::vector<std::string>{"osc1.lateral"});
  o.damping_threshold = -0.9;  // never reached
  EXPECT_FALSE(hunting_analysis(h.system, h.source(), o).threshold_speed);
}

TEST(HuntingStability, ALightlyDampedModeFromTheLowestSpeedDoesNotDecideTheThreshold) {
  // osc1 at ζ = 3 % at every speed (a lightly damped suspension mode), osc2 from ζ = 16 % down
  // through 5 % at V = (2 − 0.1ω)/0.01: the threshold speed is osc2's crossing, osc1 is listed.
  const HandBuilt h = oscillators({{2.0 * kTwoPi, 0.06 * 2.0 * kTwoPi, 0.0, 0.0}, {kTwoPi, 2.0, 0.0, -0.01}});
  HuntingOptions o = range(1.0, 300.0, 30);
  o.damping_threshold = 0.05;
  const HuntingResult r = hunting_analysis(h.system, h.source(), o);
  ASSERT_TRUE(r.threshold_speed);
  // Brent's bracket is 1e-8 relative (the default); 1e-7 leaves a margin.
  EXPECT_NEAR(*r.threshold_speed, (2.0 - 0.1 * kTwoPi) / 0.01, 1e-7 * 200.0);
  EXPECT_EQ(r.threshold_branch, "osc2.lateral");
  EXPECT_EQ(r.below_threshold_at_lowest_speed, std::vector<std::string>{"osc1.lateral"});
}

// A two-axle wagon built in code: a car body on two wheelsets through lateral, longitudinal and
// vertical springs with lateral and vertical dampers, the body's roll coupled to its sway.
Vehicle two_axle_wagon() {
  Vehicle v;
  v.name = "two-axle wagon";
  Body body;
  body.name = "wagon body";
  body.mass = 12000.0;
  body.inertia = {15000.0, 80000.0, 80000.0};
  body.centre_of_gravity = {0.0, 0.0, 1.4};
  v.bodies.push_back(body);
  for (int i = 0; i < 2; ++i) {
    test::WheelsetData w;
    w.name = i == 0 ? "ws1" : "ws2";
    w.x = i == 0 ? 3.0 : -3.0;
    test::add_wheelset(v, w);
    for (double y : {-1.0, 1.0}) {
      Element e =
          test::spring(w.name + (y > 0 ? ".left" : ".right"), "wagon body", w.name, {w.x, y, 0.5}, 2e6, 1e6, 1e6);
      e.lateral_damping = 1e4;
      e.vertical_damping = 2e4;
      v.elements.push_back(e);
    }
  }
  return v;
}

TEST(HuntingStability, NamesOfRelaxationAndOverdampedRootsAndOfTwins) {
  // Yaw dampers with a series spring (k = 5 MN/m, c = 20 kN·s/m) between the body and each
  // wheelset: each adds a state whose root starts near the relaxation −k/c = −250/s (−251.6 at
  // 10 km/h) and, at higher speed, meets a creep root and forms a complex pair. It is named as
  // the relaxation it is, not after a body ("wagon body yaw" before); no branch that does not
  // oscillate at the lowest speed is called hunting; the two wheelsets ws1, ws2 that share a
  // mode are named by their names as written ("wss" or "ws 1" before).
  Vehicle v = two_axle_wagon();
  for (Element& e : v.elements) e.series_dampers.push_back({Motion::longitudinal, 2e4, 5e6});
  const test::HuntingModel m = test::hunting_model(v);
  const ContactSource source = [&](std::optional<double>) { return m.contact; };
  const HuntingResult r = hunting_analysis(m.system, source, range(10.0 / 3.6, 300.0 / 3.6, 60));
  int relaxations = 0, twins = 0;
  for (const HuntingBranch& b : r.branches) {
    const std::complex<double> first = b.eigenvalues.front();
    if (b.name.rfind("series damper relaxation (", 0) == 0) {
      ++relaxations;
      EXPECT_NEAR(first.real(), -250.0, 0.05 * 250.0) << b.name;
    }
    if (b.name.find("hunting") != std::string::npos) {
      EXPECT_GT(first.imag(), 0.01 * std::abs(first)) << b.name;
    }
    if (b.name.rfind("ws1+ws2 ", 0) == 0) ++twins;
    EXPECT_EQ(b.name.find("wss"), std::string::npos) << b.name;
  }
  EXPECT_GE(relaxations, 1);
  EXPECT_GE(twins, 1);
}

TEST(HuntingStability, BodyModesKeepTheirDampingAtAVanishingSpeed) {
  // At V = 1e-6 m/s the creep roots are ~1e13/s against the body's ~10/s; the bands that tell a
  // rigid-body or undamped root were relative to the largest |λ| and so swallowed every body
  // mode (ζ = 0 at the lowest speed). The damping of the body modes has a limit as V → 0 (the
  // wheelsets are held by creep): the same at 1e-6 and 1e-4 m/s.
  const test::HuntingModel m = test::hunting_model(two_axle_wagon());
  const ContactSource source = [&](std::optional<double>) { return m.contact; };
  // 1e-3 m/s is the lowest speed HuntingOptions accepts: below it the eigen-solve's round-off of
  // the 1/V creep terms reaches the kinematic roots, which shrink as V.
  const HuntingResult tiny = hunting_analysis(m.system, source, range(1e-3, 1.0, 5));
  const HuntingResult small = hunting_analysis(m.system, source, range(2e-3, 1.0, 5));
  EXPECT_EQ(tiny.neutral_roots, 0);
  int body_branches = 0;
  for (const HuntingBranch& b : tiny.branches) {
    if (b.name.rfind("wagon body", 0) != 0) continue;
    ++body_branches;
    const HuntingBranch* same = nullptr;
    for (const HuntingBranch& c : small.branches)
      if (c.name == b.name) same = &c;
    ASSERT_NE(same, nullptr) << b.name;
    EXPECT_GT(b.damping_ratio[0], 0.01) << b.name;
    // ζ approaches its limit in proportion to V (the wheelsets' creep slip, m·ω·V/f): 3.1e-6
    // off it at 1e-3 m/s (measured), so the two lowest speeds differ by about that; 1e-5 leaves
    // a margin of three.
    EXPECT_NEAR(b.damping_ratio[0], same->damping_ratio[0], 1e-5) << b.name;
  }
  EXPECT_GE(body_branches, 2);  // sway/roll pairs of the body
  // The least-damped root at the lowest speed is the kinematic one, whose ζ moves by about 1.1e-5
  // per mm/s there (the bundled coach: 0.009621 at 0.1 mm/s, 0.009728 at 10 mm/s); 3e-5 leaves
  // a margin of three, and round-off at these speeds would be of order one.
  EXPECT_NEAR(tiny.summary.checks[2].value, small.summary.checks[2].value, 3e-5);
}

// Two oscillators whose damped frequencies cross: DOF 1 (2 Hz) is damped more and more with
// speed, DOF 2 (1.6 Hz) lightly. Uncoupled, each branch must stay with its DOF (the frequency
// order swaps at ζ1 = 0.6, V ≈ 75 m/s); with a weak stiffness coupling the pair veers and each
// branch follows a continuous eigenvalue path.
TEST(HuntingStability, BranchesKeepTheirIdentityThroughACrossing) {
  HandBuilt h = oscillators({{2.0 * kTwoPi, 0.0, 0.0, 0.2}, {1.6 * kTwoPi, 0.1, 0.0, 0.0}});
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(1.0, 150.0, 300));
  ASSERT_EQ(r.branches.size(), 2u);
  for (const HuntingBranch& b : r.branches) {
    const bool first = b.name == "osc1.lateral";
    ASSERT_TRUE(first || b.name == "osc2.lateral") << b.name;
    for (size_t s = 0; s < r.speeds.size(); ++s) {
      const double d = first ? 0.2 * r.speeds[s] : 0.1, w = first ? 2.0 * kTwoPi : 1.6 * kTwoPi;
      if (d >= 2.0 * w) continue;  // overdamped: the larger real root, checked by the verdict
      const std::complex<double> exact(-d / 2.0, std::sqrt(w * w - d * d / 4.0));
      EXPECT_LT(std::abs(b.eigenvalues[s] - exact), 1e-9 * w) << b.name << " at " << r.speeds[s];
    }
    EXPECT_FALSE(b.veers);
  }
}

TEST(HuntingStability, AVeeringPairIsFollowedContinuouslyAndReportedHonestly) {
  HandBuilt h = oscillators({{2.0 * kTwoPi, 0.0, 0.0, 0.2}, {1.6 * kTwoPi, 0.1, 0.0, 0.0}});
  h.system.stiffness(0, 1) = h.system.stiffness(1, 0) = 20.0;  // weak coupling
  for (int count : {1000, 12}) {
    HuntingOptions o = range(1.0, 150.0, count);
    const HuntingResult r = hunting_analysis(h.system, h.source(), o);
    ASSERT_EQ(r.branches.size(), 2u);
    EXPECT_NE(r.branches[0].name, r.branches[1].name);
    for (const HuntingBranch& b : r.branches) {
      bool veers = false;
      for (double c : b.continuity) {
        EXPECT_TRUE(c >= 0.0 && c <= 1.0 + 1e-12);
        veers = veers || c < o.continuity_threshold;
      }
      EXPECT_EQ(b.veers, veers);  // the flag says what the continuities say
      // Fine grid: no jump from one speed to the next through the veering (near 75 m/s). Above
      // 110 m/s osc1 nears critical damping (d = 2ω at 125.7 m/s), where its roots meet and
      // move as √(V − V_c): steps are large there by nature, not by mistracking.
      if (count == 1000) {
        for (size_t s = 1; s < r.speeds.size() && r.speeds[s] < 110.0; ++s)
          EXPECT_LT(std::abs(b.eigenvalues[s] - b.eigenvalues[s - 1]), 0.2) << b.name << " at " << r.speeds[s];
      }
    }
  }
}

// A free wheelset (m ÿ + 2f22/V ẏ − 2f22ψ = 0, I ψ̈ + 2f11l0²/V ψ̇ + 2f11λl0/r0 y = 0, Wickens'
// equations without gravitational stiffness) and, with springs to a fixed frame, one that has
// a critical speed.
HandBuilt wheelset(double lateral_spring, double yaw_spring, double conicity = 0.2) {
  const double m = 1500.0, I = 700.0, f = 1e7, l0 = 0.75, r0 = 0.46;
  HandBuilt h;
  Body b;
  b.name = "wheelset1";
  b.mass = m;
  h.system.vehicle.bodies.push_back(b);
  Wheelset w;
  w.body = "wheelset1";
  h.system.vehicle.wheelsets.push_back(w);
  h.system.dofs = {{"wheelset1.lateral", 0, Motion::lateral}, {"wheelset1.yaw", 0, Motion::yaw}};
  h.system.mass = Eigen::Vector2d(m, I).asDiagonal();
  h.system.damping = Eigen::MatrixXd::Zero(2, 2);
  h.system.stiffness = Eigen::Vector2d(lateral_spring, yaw_spring).asDiagonal();
  h.contact.creep_damping = Eigen::Vector2d(2.0 * f, 2.0 * f * l0 * l0).asDiagonal();
  h.contact.gyroscopic = Eigen::MatrixXd::Zero(2, 2);
  h.contact.stiffness = Eigen::MatrixXd::Zero(2, 2);
  h.contact.stiffness(0, 1) = -2.0 * f;
  h.contact.stiffness(1, 0) = 2.0 * f * conicity * l0 / r0;
  ResolvedContact c;
  c.body = "wheelset1";
  c.conicity = conicity;
  c.klingel_wavelength = conicity > 0.0 ? kTwoPi * std::sqrt(r0 * l0 / conicity) : INFINITY;
  h.contact.wheelsets.push_back(c);
  return h;
}

// Routh–Hurwitz for a4λ⁴ + a3λ³ + a2λ² + a1λ + a0 (all a > 0): stable iff a3a2a1 − a4a1² − a0a3² > 0.
double hurwitz(const HandBuilt& h, double V) {
  const Eigen::MatrixXd& M = h.system.mass;
  const Eigen::MatrixXd C = h.contact.creep_damping / V;
  const Eigen::MatrixXd K = h.system.stiffness + h.contact.stiffness;
  const double a4 = M(0, 0) * M(1, 1), a3 = M(0, 0) * C(1, 1) + M(1, 1) * C(0, 0);
  const double a2 = M(0, 0) * K(1, 1) + C(0, 0) * C(1, 1) + M(1, 1) * K(0, 0);
  const double a1 = C(0, 0) * K(1, 1) + C(1, 1) * K(0, 0), a0 = K(0, 0) * K(1, 1) - K(0, 1) * K(1, 0);
  return (a3 * a2 * a1 - a4 * a1 * a1 - a0 * a3 * a3) / (a3 * a2 * a1);
}

TEST(HuntingStability, WheelsetOnSpringsAgainstRouthHurwitz) {
  const HandBuilt h = wheelset(1e6, 5e6);
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(1.0, 200.0, 100));
  ASSERT_EQ(r.verdict, HuntingVerdict::critical_speed_in_range);
  // The Hurwitz determinant changes sign once: bisect it independently.
  double lo = 1.0, hi = 200.0;
  ASSERT_GT(hurwitz(h, lo), 0.0);
  ASSERT_LT(hurwitz(h, hi), 0.0);
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) (hurwitz(h, 0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_NEAR(r.critical->speed, lo, 1e-7 * lo);
  EXPECT_EQ(r.critical->branch.rfind("wheelset1 hunting", 0), 0u) << r.critical->branch;
  EXPECT_GT(r.critical->klingel_frequency_hz, 0.0);
}

TEST(HuntingStability, FreeWheelsetHuntsAtEverySpeedAndIsNamedKinematic) {
  const HandBuilt h = wheelset(0.0, 0.0);
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(1.0, 100.0, 50));
  EXPECT_EQ(r.verdict, HuntingVerdict::unstable_at_lowest_speed);
  EXPECT_FALSE(r.critical);
  ASSERT_EQ(r.unstable_intervals.size(), 1u);
  EXPECT_EQ(r.unstable_intervals[0].branch, "wheelset1 hunting (kinematic)");
  // Klingel: the kinematic frequency tends to V/Λ at low speed (within 1 % at 1 m/s, where
  // the creep forces are 1e7 N per unit creepage against a 1500 kg wheelset).
  const HuntingBranch* kinematic = nullptr;
  for (const HuntingBranch& b : r.branches)
    if (b.name == "wheelset1 hunting (kinematic)") kinematic = &b;
  ASSERT_NE(kinematic, nullptr);
  EXPECT_NEAR(kinematic->frequency_hz[0] / (1.0 / r.contacts[0].klingel_wavelength), 1.0, 0.01);
}

TEST(HuntingStability, LowSpeedLimitAndZeroConicityGiveNoNaN) {
  for (double conicity : {0.2, 0.0}) {
    const HandBuilt h = wheelset(1e6, 5e6, conicity);
    const HuntingResult r = hunting_analysis(h.system, h.source(), range(1e-4, 10.0, 30));
    for (const HuntingBranch& b : r.branches)
      for (size_t s = 0; s < r.speeds.size(); ++s) {
        EXPECT_TRUE(std::isfinite(b.damping_ratio[s]) && std::isfinite(b.frequency_hz[s]));
        EXPECT_TRUE(std::isfinite(b.eigenvalues[s].real()) && std::isfinite(b.eigenvalues[s].imag()));
      }
    EXPECT_EQ(r.verdict, HuntingVerdict::stable_throughout) << conicity;
    EXPECT_TRUE(std::isfinite(r.summary.checks[2].value));
    EXPECT_TRUE(r.summary.passed());
  }
  // Zero conicity without springs: y is free (a rigid-body root): neutral, never NaN, never "unstable".
  const HandBuilt free = wheelset(0.0, 0.0, 0.0);
  const HuntingResult r = hunting_analysis(free.system, free.source(), range(0.1, 100.0, 30));
  EXPECT_EQ(r.verdict, HuntingVerdict::stable_throughout);
}

TEST(HuntingStability, PositiveRealRootIsDivergentAndNeverNaN) {
  EXPECT_EQ(root_damping({3.0, 0.0}, 3.0).zeta, -1.0);
  EXPECT_EQ(root_damping({-3.0, 0.0}, 3.0).zeta, 1.0);
  EXPECT_TRUE(root_damping({0.0, 0.0}, 0.0).rigid);
  EXPECT_EQ(root_damping({0.0, 0.0}, 0.0).zeta, 0.0);
  HandBuilt h = oscillators({{kTwoPi, 1.0, 0.0, 0.0}});
  h.system.stiffness(0, 0) = -1.0;  // a saddle: one positive real root
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(1.0, 10.0, 5));
  EXPECT_EQ(r.verdict, HuntingVerdict::unstable_at_lowest_speed);
  EXPECT_TRUE(r.branches.empty());  // real roots are not oscillatory branches
  ASSERT_EQ(r.unstable_intervals.size(), 1u);
  EXPECT_EQ(r.unstable_intervals[0].branch, "osc1.lateral (real root)");
  EXPECT_TRUE(r.unstable_intervals[0].divergence);
}

// Every divergence is listed, not only the least-damped root's (review of 2026-11-28): two
// saddles (ζ = −1 both, so the least-damped search names only the first) beside a branch
// unstable from 30 to 170 m/s. Each saddle diverges over the whole range (λ = 0 would need a
// singular stiffness, and K does not change with the speed: the ends are the grid's), marked
// as a divergence; the branch keeps its own refined interval and is no divergence.
TEST(HuntingStability, EveryDivergenceIsListedBesideTheBranches) {
  HandBuilt h = oscillators({{kTwoPi, 1.0, 0.0, 0.0}, unstable_between(30.0, 170.0), {2.0 * kTwoPi, 1.0, 0.0, 0.0}});
  h.system.stiffness(0, 0) = -1.0;
  h.system.stiffness(2, 2) = -4.0;
  const HuntingResult r = hunting_analysis(h.system, h.source(), range(10.0, 200.0, 40));
  ASSERT_EQ(r.unstable_intervals.size(), 3u);
  std::vector<std::string> divergences;
  for (const UnstableInterval& u : r.unstable_intervals) {
    if (u.branch == "osc2.lateral") {
      EXPECT_FALSE(u.divergence);
      EXPECT_NEAR(u.from, 30.0, 1e-6 * 30.0);  // refined to 1e-8 relative (the default); 1e-6 is ample
      EXPECT_NEAR(u.to, 170.0, 1e-6 * 170.0);
      continue;
    }
    EXPECT_TRUE(u.divergence) << u.branch;
    EXPECT_TRUE(u.from_lowest_speed && u.to_highest_speed) << u.branch;
    EXPECT_EQ(u.from, 10.0);
    EXPECT_EQ(u.to, 200.0);
    divergences.push_back(u.branch.substr(0, u.branch.find(' ')));  // the group's name, without " (real root)"
  }
  std::sort(divergences.begin(), divergences.end());
  EXPECT_EQ(divergences, (std::vector<std::string>{"osc1.lateral", "osc3.lateral"}));
}

TEST(HuntingStability, SameResultOnAnyNumberOfThreads) {
  const HandBuilt h = wheelset(1e6, 5e6);
  ContactSource source = [&h](std::optional<double> conicity) {
    return conicity ? wheelset(1e6, 5e6, *conicity).contact : h.contact;
  };
  HuntingOptions o = range(1.0, 200.0, 64);
  o.conicities = {0.05, 0.1, 0.2, 0.3};
  o.damping_threshold = 0.05;
  std::vector<HuntingResult> results;
  for (int threads : {1, 2, 3}) {
    o.threads = threads;
    results.push_back(hunting_analysis(h.system, source, o));
  }
  for (const HuntingResult& r : results) {
    ASSERT_EQ(r.branches.size(), results[0].branches.size());
    for (size_t b = 0; b < r.branches.size(); ++b) {
      EXPECT_EQ(r.branches[b].name, results[0].branches[b].name);
      EXPECT_EQ(r.branches[b].eigenvalues, results[0].branches[b].eigenvalues);
      EXPECT_EQ(r.branches[b].continuity, results[0].branches[b].continuity);
    }
    ASSERT_TRUE(r.critical);
    EXPECT_EQ(r.critical->speed, results[0].critical->speed);
    EXPECT_EQ(r.threshold_speed, results[0].threshold_speed);
    // The summary the reports write is the same too: no thread count in the method, and the MAC
    // check's limit 1 − 0.8 as the decimal 0.2 (the subtraction's double is 0.19999999999999996).
    EXPECT_EQ(r.summary.method, results[0].summary.method);
    EXPECT_EQ(r.summary.method.find("thread"), std::string::npos) << r.summary.method;
    ASSERT_EQ(r.summary.checks[1].name, "1 − minimum branch continuity (MAC)");
    EXPECT_EQ(r.summary.checks[1].limit, 0.2);
    ASSERT_EQ(r.conicity_curve.size(), 4u);
    for (size_t c = 0; c < 4; ++c) {
      EXPECT_EQ(r.conicity_curve[c].verdict, results[0].conicity_curve[c].verdict);
      ASSERT_EQ(r.conicity_curve[c].critical.has_value(), results[0].conicity_curve[c].critical.has_value());
      if (r.conicity_curve[c].critical) {
        EXPECT_EQ(r.conicity_curve[c].critical->speed, results[0].conicity_curve[c].critical->speed);
      }
    }
  }
  // The design curve: a higher conicity hunts at a lower speed.
  const auto& curve = results[0].conicity_curve;
  for (size_t c = 1; c < curve.size(); ++c)
    if (curve[c].critical && curve[c - 1].critical) {
      EXPECT_LT(curve[c].critical->speed, curve[c - 1].critical->speed);
    }
}

TEST(HuntingStability, SingularMassNamesTheDof) {
  HandBuilt h = wheelset(1e6, 5e6);
  h.system.mass(1, 1) = 0.0;
  try {
    hunting_analysis(h.system, h.source(), range(1.0, 10.0, 5));
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("wheelset1.yaw"), std::string::npos) << e.what();
  }
}

TEST(HuntingStability, AVehicleWithoutWheelsetsIsRefused) {
  const HandBuilt h = oscillators({{kTwoPi, 1.0, 0.0, 0.0}});
  EXPECT_THROW(solve_hunting_stability(h.system), std::invalid_argument);
}

TEST(HuntingStability, HungarianAssignmentIsOptimal) {
  // The greedy choice (row 0 takes column 0 at cost 1) is not optimal here.
  const std::vector<std::vector<double>> cost = {{1.0, 2.0, 9.0}, {1.1, 9.0, 9.0}, {9.0, 9.0, 1.0}};
  EXPECT_EQ(minimum_cost_assignment(cost), (std::vector<int>{1, 0, 2}));
}


// Branch continuity where a pair is real (fix-checks, 2026-11-27). Two real pairs, A (roots −10,
// −12, shapes in the plane of DOFs 1–2) and B (−11, −13, plane of DOFs 3–4), become complex at
// the top speed. Paths 0–1 hold A and 2–3 hold B at the lowest speed; at the middle speed the
// tracking is handed a swap: paths 0–1 go on to B's roots. Both ends of the step are real, where
// the earlier rule counted 1 whatever the shapes, and the swap went unflagged. The planes the
// pairs span (principal angles, Björck–Golub) are orthogonal across the swap: continuity 0 and
// the branch veers. Without the swap the planes continue (continuity 1 to round-off).
TEST(BranchContinuity, RealPairsThatSwapBetweenSpeedsAreCaught) {
  const HandBuilt h = oscillators({{1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}});
  using cd = std::complex<double>;
  const auto e = [](int i) { return Eigen::VectorXcd(Eigen::VectorXcd::Unit(4, i)); };
  // A real pair's two shapes: distinct directions of its plane, nearly parallel (a meeting near).
  const auto real_pair = [&](int i, int j, Eigen::MatrixXcd* shapes, int col) {
    shapes->col(col) = (e(i) + 0.10 * e(j)).normalized();
    shapes->col(col + 1) = (e(i) - 0.12 * e(j)).normalized();
  };
  const auto speeds_with = [&](bool swap) {
    std::vector<SpeedRoots> speeds(3);
    for (int s = 0; s < 3; ++s) {
      speeds[s].speed = 10.0 * (s + 1);
      speeds[s].shapes = Eigen::MatrixXcd(4, 4);
    }
    // Roots in each speed's own order: 0–1 the pair in DOFs 1–2, 2–3 the pair in DOFs 3–4.
    speeds[0].values = Eigen::Vector4cd(cd(-10), cd(-12), cd(-11), cd(-13));
    speeds[1].values = Eigen::Vector4cd(cd(-10.5), cd(-11.5), cd(-10.8), cd(-12.5));
    speeds[2].values = Eigen::Vector4cd(cd(-1, 2), cd(-1, -2), cd(-1, 3), cd(-1, -3));
    for (int s = 0; s < 2; ++s) {
      real_pair(0, 1, &speeds[s].shapes, 0);
      real_pair(2, 3, &speeds[s].shapes, 2);
    }
    const cd i(0.0, 1.0);
    speeds[2].shapes.col(0) = (e(0) + i * e(1)) / std::sqrt(2.0);
    speeds[2].shapes.col(1) = (e(0) - i * e(1)) / std::sqrt(2.0);
    speeds[2].shapes.col(2) = (e(2) + i * e(3)) / std::sqrt(2.0);
    speeds[2].shapes.col(3) = (e(2) - i * e(3)) / std::sqrt(2.0);
    RootPaths paths;
    paths.root = {{0, 1, 2, 3}, swap ? std::vector<int>{2, 3, 0, 1} : std::vector<int>{0, 1, 2, 3},
                  swap ? std::vector<int>{2, 3, 0, 1} : std::vector<int>{0, 1, 2, 3}};
    // The per-root MACs the tracking would report; at the real steps the branch does not use them.
    paths.continuity.assign(3, std::vector<double>(4, 1.0));
    return std::make_pair(speeds, paths);
  };
  const double threshold = 0.8;
  for (bool swap : {false, true}) {
    const auto [speeds, paths] = speeds_with(swap);
    const Branches b = group_branches(h.system, speeds, paths, 20.0, threshold);
    ASSERT_EQ(b.oscillatory.size(), 2u);
    for (const HuntingBranch& branch : b.oscillatory) {
      ASSERT_EQ(branch.continuity.size(), 3u);
      // The real step 0 → 1: across the swap the planes are orthogonal (cos² = 0, to round-off);
      // without it the same plane (1 to round-off, the SVD's 1e-15).
      EXPECT_NEAR(branch.continuity[1], swap ? 0.0 : 1.0, 1e-12) << branch.name;
      EXPECT_EQ(branch.veers, swap) << branch.name;
    }
  }
}

// A pair at its meeting (fix-logic, 2026-11-28: the test a7243c3 lacked). Where a real pair's
// roots meet, its two eigenvectors coincide: its shapes span one direction, a line. The step onto
// the meeting compares the previous speed's plane with that line; a plane cannot lie in a line,
// and the rule before a7243c3 read 0 there (a false veer). The measure is the line's share
// within the other speed's plane, cos² of the angle between them: 1 for a line in the plane (the
// pair continues), and 0.5 for a line at 45° to it (e0 + e2: half in the plane of DOFs 1–2), a
// veer below the threshold 0.8 that the measure must still see. The step off the meeting onto
// the complex pair's plane (DOFs 1–2) measures the same line within that plane.
TEST(BranchContinuity, StepOntoAMeetingMeasuresItsLineWithinThePlane) {
  const HandBuilt h = oscillators({{1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}});
  using cd = std::complex<double>;
  const auto e = [](int i) { return Eigen::VectorXcd(Eigen::VectorXcd::Unit(4, i)); };
  const auto speeds_meeting_along = [&](const Eigen::VectorXcd& line) {
    std::vector<SpeedRoots> speeds(3);
    for (int s = 0; s < 3; ++s) {
      speeds[s].speed = 10.0 * (s + 1);
      speeds[s].shapes = Eigen::MatrixXcd(4, 4);
    }
    speeds[0].values = Eigen::Vector4cd(cd(-10), cd(-12), cd(-21), cd(-23));
    speeds[1].values = Eigen::Vector4cd(cd(-11), cd(-11), cd(-20), cd(-22));  // pair A meets at −11
    speeds[2].values = Eigen::Vector4cd(cd(-1, 2), cd(-1, -2), cd(-1, 3), cd(-1, -3));
    // Speed 0: A's two real shapes span DOFs 1–2; B's span DOFs 3–4, at every real speed.
    speeds[0].shapes.col(0) = (e(0) + 0.10 * e(1)).normalized();
    speeds[0].shapes.col(1) = (e(0) - 0.12 * e(1)).normalized();
    speeds[1].shapes.col(0) = speeds[1].shapes.col(1) = line.normalized();  // coincident at the meeting
    for (int s = 0; s < 2; ++s) {
      speeds[s].shapes.col(2) = (e(2) + 0.10 * e(3)).normalized();
      speeds[s].shapes.col(3) = (e(2) - 0.12 * e(3)).normalized();
    }
    const cd i(0.0, 1.0);
    speeds[2].shapes.col(0) = (e(0) + i * e(1)) / std::sqrt(2.0);
    speeds[2].shapes.col(1) = (e(0) - i * e(1)) / std::sqrt(2.0);
    speeds[2].shapes.col(2) = (e(2) + i * e(3)) / std::sqrt(2.0);
    speeds[2].shapes.col(3) = (e(2) - i * e(3)) / std::sqrt(2.0);
    RootPaths paths;
    paths.root = {{0, 1, 2, 3}, {0, 1, 2, 3}, {0, 1, 2, 3}};
    paths.continuity.assign(3, std::vector<double>(4, 1.0));
    return std::make_pair(speeds, paths);
  };
  const double threshold = 0.8;
  // The meeting's line in A's plane, and tilted 45° out of it towards B's (e0 + e2). Expected
  // to round-off of the SVDs (1e-15, and 1e-12 allows their sums).
  for (const auto& [line, expected] : {std::pair{Eigen::VectorXcd(e(0) + 0.3 * e(1)), 1.0},
                                       std::pair{Eigen::VectorXcd(e(0) + e(2)), 0.5}}) {
    const auto [speeds, paths] = speeds_meeting_along(line);
    const Branches b = group_branches(h.system, speeds, paths, 20.0, threshold);
    ASSERT_EQ(b.oscillatory.size(), 2u);
    int seen = 0;
    for (const HuntingBranch& branch : b.oscillatory) {
      ASSERT_EQ(branch.continuity.size(), 3u);
      if (std::abs(branch.frequency_hz.back() - 2.0 / kTwoPi) > 1e-9) continue;  // pair A: Im λ = 2 at the top
      ++seen;
      EXPECT_NEAR(branch.continuity[1], expected, 1e-12) << "onto the meeting";
      EXPECT_NEAR(branch.continuity[2], expected, 1e-12) << "off the meeting";
      EXPECT_EQ(branch.veers, expected < threshold);
    }
    EXPECT_EQ(seen, 1);
  }
}

}  // namespace
}  // namespace railmodal::stability
