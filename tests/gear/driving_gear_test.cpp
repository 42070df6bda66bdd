// The driving-gear model (src/gear/): exact kinematics against an independent numerical
// differentiation of the mechanism's positions, the forces against momentum and energy balances
// written here from those positions, the two-mass rod, the harmonic identities of two cranks at
// 90° (digest shared/reference/unbalance-excitation.md §2.7 and §3), wheel loads and α.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "gear/su_gear.hpp"
#include "railmodal/driving_gear.hpp"

namespace railmodal {
namespace {

using testing::kKgf;
using testing::su_cylinder;
using testing::su_rods_only;

constexpr double kOmega = 30.03;  // rad/s, the Су at 100 km/h (E1)

// Positions of the mechanism as a function of the crank angle, from the geometry alone (not
// from crank_kinematics): crank pin A, crosshead B on the cylinder axis at distance L from A.
struct Positions {
  double ax, ay, bx, beta;
};
Positions positions(const GearCylinder& c, double phi) {
  const double ax = -c.crank_radius * std::cos(phi), ay = c.crank_radius * std::sin(phi);
  const double bx = ax + std::sqrt(c.rod_length * c.rod_length - ay * ay);
  return {ax, ay, bx, std::atan2(ay, bx - ax)};
}

// d/dt and d²/dt² of f(φ(t)) with φ = ωt, by central differences in φ (step h rad).
double rate(const std::function<double(double)>& f, double phi, double h) {
  return (f(phi + h) - f(phi - h)) / (2 * h) * kOmega;
}
double second_rate(const std::function<double(double)>& f, double phi, double h) {
  return (f(phi + h) - 2 * f(phi) + f(phi - h)) / (h * h) * kOmega * kOmega;
}

TEST(DrivingGear, KinematicsMatchNumericalDifferentiationOfPositions) {
  const GearCylinder c = su_cylinder(true);
  const auto bx = [&](double p) { return positions(c, p).bx; };
  const auto beta = [&](double p) { return positions(c, p).beta; };
  const double scale = kOmega * kOmega * c.crank_radius;  // ω²r = 315.6 m/s²
  for (int deg = 0; deg < 360; deg += 5) {
    const double phi = deg * M_PI / 180;
    const CrankKinematics k = crank_kinematics(c, phi, kOmega);
    EXPECT_NEAR(k.crosshead_x, bx(phi), 1e-12);
    EXPECT_NEAR(k.rod_angle, beta(phi), 1e-12);
    // Central differences with h = 1e-3 rad: truncation h²/6·f''' ≈ 2e-7 of the scale, round-off
    // ε·|x|/h² ≈ 5e-10 m/rad² (×ω²): a bound of 1e-6 of ω²r (and of ωr, ω²λ) holds both.
    EXPECT_NEAR(k.crosshead_velocity, rate(bx, phi, 1e-3), 1e-6 * kOmega * c.crank_radius) << deg;
    EXPECT_NEAR(k.crosshead_acceleration, second_rate(bx, phi, 1e-3), 1e-6 * scale) << deg;
    EXPECT_NEAR(k.rod_angular_velocity, rate(beta, phi, 1e-3), 1e-6 * kOmega) << deg;
    EXPECT_NEAR(k.rod_angular_acceleration, second_rate(beta, phi, 1e-3), 1e-6 * kOmega * kOmega) << deg;
  }
}

// Kinetic energy of rod and crosshead from the positions alone: the rod's centre G at d from B.
double kinetic_energy(const GearCylinder& c, double phi) {
  const double h = 1e-4;
  const auto g = [&](double p, int axis) {
    const Positions s = positions(c, p);
    const double t = c.rod_centre_of_mass / c.rod_length;
    return axis == 0 ? s.bx + t * (s.ax - s.bx) : t * s.ay;
  };
  const auto v = [&](const std::function<double(double)>& f) { return rate(f, phi, h); };
  const double vgx = v([&](double p) { return g(p, 0); }), vgy = v([&](double p) { return g(p, 1); });
  const double vb = v([&](double p) { return positions(c, p).bx; });
  const double w = v([&](double p) { return positions(c, p).beta; });
  return 0.5 * c.rod_mass * (vgx * vgx + vgy * vgy) + 0.5 * c.rod_inertia * w * w + 0.5 * c.reciprocating_mass * vb * vb;
}

TEST(DrivingGear, ForcesBalanceMomentumAndEnergyOfTheMechanism) {
  // Independent of the Newton–Euler solve: (1) the crank pin's horizontal force on the rod is the
  // rate of the horizontal momentum of rod and crosshead (the guide pushes only vertically);
  // (2) its power on the moving pin is the rate of their kinetic energy (the guide does no work),
  // which fixes the vertical force wherever the pin moves vertically.
  const GearCylinder c = su_cylinder(true);
  const double force_scale = (c.rod_mass + c.reciprocating_mass) * kOmega * kOmega * c.crank_radius;  // ≈ 186 kN
  for (int deg = 5; deg < 360; deg += 10) {
    const double phi = deg * M_PI / 180;
    const RodForces f = rod_forces(c, phi, kOmega);
    const double t = c.rod_centre_of_mass / c.rod_length;
    const auto px = [&](double p) {
      const Positions s = positions(c, p);
      return c.rod_mass * (s.bx + t * (s.ax - s.bx)) + c.reciprocating_mass * s.bx;
    };
    // Second differences of positions (h = 1e-3): ~1e-7 of the scale (see above).
    EXPECT_NEAR(-f.horizontal, second_rate(px, phi, 1e-3), 1e-6 * force_scale) << deg;
    const double vax = kOmega * c.crank_radius * std::sin(phi), vay = kOmega * c.crank_radius * std::cos(phi);
    const double power = -(f.horizontal * vax + f.vertical * vay);  // the pin's force on the rod times v_A
    const double dT = rate([&](double p) { return kinetic_energy(c, p); }, phi, 1e-3);
    // Nested differences (h = 1e-4 inside, 1e-3 outside): round-off ε·T/(h_in·h_out) ≈ 1e-4 W on a
    // power scale force_scale·ωr ≈ 2e6 W; truncation ≈ 1e-7 relative. Bound 1e-6 of the scale.
    EXPECT_NEAR(power, dT, 1e-6 * force_scale * kOmega * c.crank_radius) << deg;
  }
}

TEST(DrivingGear, RodThatIsDynamicallyTwoMassesGivesTheStaticSplitExactly) {
  // J_G = m·d·(L − d) (Kvasnikov H = 0, eq. (33)–(34)): the rod is a mass m·d/L at the crank pin
  // and m·(1 − d/L) at the crosshead pin joined by a massless link, which carries the crosshead
  // group's inertia M·a_B along itself: X = −M·a_B − (pin mass)·ω²r cos φ and
  // Y = (pin mass)·ω²r sin φ + M·a_B·tan β (Kvasnikov (11)–(13) with the rod's line of action).
  GearCylinder c = su_cylinder(true);
  c.rod_inertia = c.rod_mass * c.rod_centre_of_mass * (c.rod_length - c.rod_centre_of_mass);
  EXPECT_DOUBLE_EQ(rod_dynamic_defect(c), 0.0);
  const double pin_mass = c.rod_mass * c.rod_centre_of_mass / c.rod_length;
  const double cross_mass = c.reciprocating_mass + c.rod_mass - pin_mass;
  for (int deg = 0; deg < 360; deg += 15) {
    const double phi = deg * M_PI / 180;
    const RodForces f = rod_forces(c, phi, kOmega);
    const CrankKinematics k = crank_kinematics(c, phi, kOmega);
    const double centrifugal = pin_mass * kOmega * kOmega * c.crank_radius;
    // Round-off only: 1e-9 of the rotating force (≈ 47 kN).
    EXPECT_NEAR(f.vertical, centrifugal * std::sin(phi) + cross_mass * k.crosshead_acceleration * std::tan(k.rod_angle),
                1e-9 * centrifugal)
        << deg;
    EXPECT_NEAR(f.horizontal, -cross_mass * k.crosshead_acceleration - centrifugal * std::cos(phi), 1e-9 * centrifugal);
  }
  // The real Су rod is not: its J_G is 16 % below m·d·(L − d), so the split overstates Y.
  EXPECT_GT(rod_dynamic_defect(su_cylinder(true)), 0.0);
}

TEST(DrivingGear, SecondHarmonicsCancelInSurgingAndAddInNosingForCranksAt90Degrees) {
  // Digest §2.7 [D]: with the left crank 90° behind, the first harmonics of the two sides are in
  // quadrature (the sum √2 times one side), the second harmonics opposite (cancel in ΣX, double
  // in the moment). Exact for any rod: X(φ − 90°) shifts harmonic k by −k·90°.
  const GearResult r = solve_driving_gear(su_rods_only(), 100 / 3.6);
  const GearHarmonic& x1 = r.horizontal_harmonics[0][1];
  const GearHarmonic& x2 = r.horizontal_harmonics[0][2];
  const double arm = 1.14;
  // The sums are exact identities of the sampled forces: round-off bounds 1e-9 relative.
  EXPECT_NEAR(r.surging_harmonics[1].amplitude(), std::sqrt(2.0) * x1.amplitude(), 1e-9 * x1.amplitude());
  EXPECT_NEAR(r.surging_harmonics[2].amplitude(), 0.0, 1e-9 * x1.amplitude());
  EXPECT_NEAR(r.nosing_harmonics[2].amplitude(), 2 * arm * x2.amplitude(), 1e-9 * x2.amplitude() * arm);
  EXPECT_NEAR(r.nosing_harmonics[1].amplitude(), std::sqrt(2.0) * arm * x1.amplitude(), 1e-9 * x1.amplitude() * arm);
  // The same for the vertical forces on the axle: second harmonic out of the bounce sum.
  double bounce2_cos = 0, bounce2_sin = 0;
  for (const GearWheelLoad& w : r.wheels) {
    bounce2_cos += w.harmonics[2].cosine;
    bounce2_sin += w.harmonics[2].sine;
  }
  EXPECT_NEAR(std::hypot(bounce2_cos, bounce2_sin), 0.0, 1e-9 * r.vertical_harmonics[0][1].amplitude());
  EXPECT_GT(r.vertical_harmonics[0][2].amplitude(), 0.0);
  EXPECT_TRUE(r.summary.passed()) << r.summary.brief();
}

TEST(DrivingGear, ThreeCranksAt120DegreesLeaveOnlyTheSixthOrderOfSurging) {
  // Kvasnikov (84)–(86), in-line mechanisms at equal crank spacing: ΣX = Σ_n X_n Σ_i cos n(φ + α_i)
  // and Σ_i cos n α_i vanishes unless n is a multiple of 3; X has orders 1 and the even ones only
  // (A_n, eq. (16)), so with three cranks the lowest order left is the sixth (3·A₆ for a
  // reciprocating mass). Three Су cylinders on the centreline, cranks at 0°, −120°, −240°.
  DrivingGear g = su_rods_only();
  g.cylinders = {su_cylinder(true), su_cylinder(true), su_cylinder(true)};
  for (int i = 0; i < 3; ++i) {
    g.cylinders[i].lateral = 0.0;
    g.cylinders[i].axle = 0;
    g.cylinders[i].crank_offset = -2.0 * M_PI * i / 3;
  }
  const GearResult r = solve_driving_gear(g, 100 / 3.6);
  const double one = r.horizontal_harmonics[0][1].amplitude();  // one cylinder's first order, ≈ 187 kN
  for (int n : {1, 2, 3, 4, 5}) EXPECT_NEAR(r.surging_harmonics[n].amplitude(), 0.0, 1e-9 * one) << n;
  // The sixth: three times one cylinder's (round-off of the sums, 1e-9 of the first order).
  EXPECT_NEAR(r.surging_harmonics[6].amplitude(), 3 * r.horizontal_harmonics[0][6].amplitude(), 1e-9 * one);
  EXPECT_GT(r.surging_harmonics[6].amplitude(), 1e-6 * one);
}

TEST(DrivingGear, WheelLoadsCarryTheRodForceMovedToTheWheelPlanes) {
  // The right rod plane is a = 0.345 m outside the right wheel plane (S = 0.795 m): that wheel
  // carries (2S + a)/2S of the right rod's Y and the left wheel −a/2S (Zhdanov (73a)–(74a)).
  const DrivingGear g = su_rods_only();
  const GearResult r = solve_driving_gear(g, 100 / 3.6);
  const double S = 0.795, a = 0.345;
  for (const GearState& st : r.states) {
    const double y1 = st.cylinders[0].vertical, y2 = st.cylinders[1].vertical;
    // Two products and a sum: round-off.
    EXPECT_NEAR(st.wheel_loads[0], -(y1 + (y1 - y2) * a / (2 * S)), 1e-9 * 1e5);
    EXPECT_NEAR(st.wheel_loads[1], -(y2 - (y1 - y2) * a / (2 * S)), 1e-9 * 1e5);
  }
  // α is the largest |ΔP| over П; with no overbalance (89a) adds nothing.
  double largest = 0;
  for (const GearState& st : r.states) largest = std::max(largest, std::abs(st.wheel_loads[0]));
  EXPECT_DOUBLE_EQ(r.wheels[0].alpha, largest / (9000 * kKgf));
  EXPECT_DOUBLE_EQ(r.wheels[0].alpha_89a, r.wheels[0].alpha);
  EXPECT_FALSE(r.wheels[0].wheel_lift);
}

TEST(DrivingGear, OverbalanceHammerBlowAndWheelLift) {
  DrivingGear g = su_rods_only();
  g.cylinders.clear();
  // 100 kg at 0.35 m at 100 km/h: 100·30.03²·0.35 = 31.6 kN against П = 88.3 kN.
  g.axles[0].right.masses.push_back({"overbalance", 100.0, 0.35, M_PI, 0.0, true});
  const GearResult r = solve_driving_gear(g, 100 / 3.6);
  const double blow = 100.0 * r.omega * r.omega * 0.35;
  // A pure sine sampled every 1°: the peaks are sampled exactly (90° and 270°).
  EXPECT_NEAR(r.wheels[0].max_dynamic_load, blow, 1e-9 * blow);
  EXPECT_NEAR(r.wheels[0].alpha, blow / (9000 * kKgf), 1e-12);
  EXPECT_NEAR(r.wheels[0].alpha_89a, r.wheels[0].alpha, 1e-12);
  EXPECT_NEAR(r.wheels[1].alpha, 0.0, 1e-15);
  // The speed at which α reaches 1 (wheel lift): √(1/α) times faster; there it is flagged.
  const double lift_speed = speed_at_alpha(r.wheels[0].alpha, r.speed, 1.0);
  EXPECT_TRUE(solve_driving_gear(g, lift_speed * 1.0001).wheels[0].wheel_lift);
  EXPECT_FALSE(solve_driving_gear(g, lift_speed * 0.9999).wheels[0].wheel_lift);
  EXPECT_TRUE(std::isinf(speed_at_alpha(0.0, 10.0, 0.3)));
}

TEST(DrivingGear, InvalidDescriptionsAndOptionsAreRejectedByName) {
  DrivingGear g = su_rods_only();
  g.cylinders[0].rod_length = 0.3;  // shorter than the crank: the crank could not turn
  std::string why;
  EXPECT_FALSE(g.is_valid(&why));
  EXPECT_NE(why.find("rod_length"), std::string::npos);
  EXPECT_THROW(solve_driving_gear(g, 10.0), std::invalid_argument);
  g = su_rods_only();
  g.cylinders[1].axle = 3;
  EXPECT_FALSE(g.is_valid(&why));
  EXPECT_NE(why.find("axle 3"), std::string::npos);
  g = su_rods_only();
  g.axles[0].left.static_load = 0;
  EXPECT_FALSE(g.is_valid(&why));
  EXPECT_NE(why.find("static_load"), std::string::npos);
  EXPECT_THROW(solve_driving_gear(su_rods_only(), -1.0), std::invalid_argument);
  GearOptions o;
  o.harmonics = 180;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("harmonics"), std::string::npos);
  EXPECT_THROW(solve_driving_gear(su_rods_only(), 10.0, o), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal
