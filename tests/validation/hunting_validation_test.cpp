// Validation of the linearised wheel–rail contact terms through the general assembly:
// vehicles built in code, assemble(vehicle, DofSet::lateral), contact_matrices(system), and the
// eigenvalues of the first-order form taken here with Eigen (hunting_test_support.hpp), never
// the library's stability solver. docs/stability.md, "Validation", lists the cases and figures.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "stability/branch_naming.hpp"
#include "test_support.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal::test {
namespace {

// The speed at which the assembled system's largest real part crosses zero.
double eigen_critical_speed(const HuntingModel& m, double lo, double hi) {
  return bisect([&](double v) { return max_real_part(m, v); }, lo, hi);
}

Vehicle single_wheelset(const WheelsetData& d, double k_y = 0.0, double k_psi = 0.0) {
  Vehicle v;
  v.name = "wheelset";
  add_wheelset(v, d);
  if (k_y > 0.0 || k_psi > 0.0) add_springs_to_ground(v, d, k_y, k_psi);
  return v;
}

// ---------------------------------------------------------------------------------------------
// The terms themselves, on one free wheelset: each entry against the equations written out in
// hunting_test_support.hpp (and docs/stability.md).
TEST(HuntingContactTerms, FreeWheelsetMatricesMatchTheEquations) {
  WheelsetData d;
  const auto m = hunting_model(single_wheelset(d));
  ASSERT_EQ(m.system.dofs[0].label, "wheelset.lateral");
  ASSERT_EQ(m.system.dofs[1].label, "wheelset.yaw");
  const auto& f = d.creep;
  const double w = d.mass * kG, lam = d.conicity, kappa = 1.0 + lam * d.r0 / d.l0;
  const auto& k = m.contact.stiffness;
  const auto& c = m.contact.creep_damping;
  const auto& g = m.contact.gyroscopic;
  // Relative 1e-12: the same few products in another order.
  auto near = [](double got, double want) { EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::abs(want))); };
  near(k(0, 0), w * lam / d.l0);  // ε = σ = λ: the spin terms in (ε − σ) vanish
  near(k(0, 1), -2 * f.f22 * kappa);  // the generalised lateral force is κ·ΣFy
  near(k(1, 0), 2 * f.f11 * lam * d.l0 / d.r0);
  near(k(1, 1), 2 * f.f23);
  near(c(0, 0), 2 * f.f22 * kappa * kappa);  // κ in the creepage and in the projection
  near(c(0, 1), 2 * f.f23 * kappa);
  near(c(1, 0), -2 * f.f23 * kappa);
  near(c(1, 1), 2 * f.f11 * d.l0 * d.l0 + 2 * f.f33);
  near(g(0, 1), -d.spin_inertia * lam / (d.r0 * d.l0));
  near(g(1, 0), d.spin_inertia * lam / (d.r0 * d.l0));
  EXPECT_EQ(g(0, 0), 0.0);
  EXPECT_EQ(g(1, 1), 0.0);

  ASSERT_EQ(m.contact.wheelsets.size(), 1u);
  const auto& r = m.contact.wheelsets[0];
  EXPECT_EQ(r.body, "wheelset");
  near(r.axle_load, w);
  EXPECT_EQ(r.contact_angle_parameter, lam);
  EXPECT_EQ(r.roll_parameter, lam);
  near(r.klingel_wavelength, 2 * kPi * std::sqrt(d.r0 * d.l0 / lam));
  near(r.klingel_wavelength, klingel_wavelength(lam, 2 * d.l0, d.r0));  // the book's (264b), s = 2l0
  EXPECT_FALSE(r.ellipse.has_value());
}

// The physics of the signs: a wheelset displaced to the left (y > 0) runs on a larger left
// radius, so the creep forces turn it clockwise (a negative yaw moment), back towards the
// centre; yawed anticlockwise (ψ > 0) its lateral creepage is −ψ and the creep force 2f22ψ pushes
// it to the left, where its wheels point.
TEST(HuntingContactTerms, SignsFollowTheFrame) {
  const auto m = hunting_model(single_wheelset(WheelsetData{}));
  // Force = −K q: a left displacement gives a negative (clockwise) yaw moment.
  EXPECT_LT(-m.contact.stiffness(1, 0), 0.0);
  // A positive yaw gives a lateral force to the left (the wheelset steers where it points).
  EXPECT_GT(-m.contact.stiffness(0, 1), 0.0);
  // Creep damping dissipates on its own: its symmetric part is positive definite.
  const Eigen::Matrix2d cs = 0.5 * (m.contact.creep_damping + m.contact.creep_damping.transpose());
  EXPECT_GT(cs.determinant(), 0.0);
  EXPECT_GT(cs(0, 0), 0.0);
  // The gyroscopic matrix is skew-symmetric: it does no work.
  EXPECT_NEAR((m.contact.gyroscopic + m.contact.gyroscopic.transpose()).norm(), 0.0, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Free wheelset without gravitational stiffness (ε = 0): unstable at every speed (the issue's
// item 6; the classical result of Wickens's analysis). With σ = 0 and f23 = 0, a1 = 0 in the
// quartic (hunting_test_support.hpp), so it cannot be Hurwitz; the roots show a positive real
// part.
TEST(HuntingValidation, FreeWheelsetWithoutGravitationalStiffnessIsUnstableAtEverySpeed) {
  WheelsetData d;
  d.epsilon = 0.0;
  d.sigma = 0.0;
  d.creep.f23 = 0.0;
  const auto m = hunting_model(single_wheelset(d));
  for (double v : {0.1, 1.0, 5.0, 10.0, 30.0, 60.0, 100.0, 200.0, 400.0}) {
    const auto root = slowest_oscillatory_root(m, v);
    EXPECT_GT(root.real(), 0.0) << "V = " << v;
    EXPECT_GT(max_real_part(m, v), 0.0) << "V = " << v;
  }
}

// Its kinematic wavelength 2πV/ω tends to Klingel's 2π√(r0·l0/λ) as V → 0 at fixed creep
// coefficients: the creep forces, ∝ 1/V in their damping, then dominate the inertia and force
// the wheelset to roll without creep. Measured: 4.2e-3, 4.2e-7, 3.7e-11 at 30, 3 and 0.3 m/s,
// falling as V⁴ (the inertia's share, ∝ V², enters the frequency squared).
TEST(HuntingValidation, FreeWheelsetWavelengthTendsToKlingelAsSpeedFalls) {
  WheelsetData d;
  d.epsilon = 0.0;
  d.sigma = 0.0;
  d.creep.f23 = 0.0;
  d.creep.f33 = 0.0;
  const auto m = hunting_model(single_wheelset(d));
  const double klingel = m.contact.wheelsets[0].klingel_wavelength;
  auto error = [&](double v) { return std::abs(2 * kPi * v / slowest_oscillatory_root(m, v).imag() / klingel - 1); };
  const double e30 = error(30.0), e3 = error(3.0), e03 = error(0.3);
  EXPECT_GT(e30, 1e-4);       // not vacuous: at speed the wavelength is not Klingel's
  EXPECT_LT(e3, e30 / 1000.0);  // ≈ V⁴: four decades for one
  EXPECT_LT(e03, 1e-9);         // 3.7e-11; the eigen-solve's rounding is ~2e-11 of the root
}

// The same limit with creep → ∞ at a fixed, high speed, with σ = ε = λ, gravitational
// stiffness and spin inertia at their defaults: the wavelength tends to 2π√(r0·l0·κ/λ),
// κ = 1 + σ·r0/l0: the roll rate's contribution to the lateral creepage lengthens Klingel's wave
// by √κ (here 4.5 %). The spin coefficients are left out here (f23 = f33 = 0): with them the
// limit is the next test's.
double wavelength_with_creep_scaled(WheelsetData d, double scale, double speed) {
  d.creep = {d.creep.f11 * scale, d.creep.f22 * scale, d.creep.f23 * scale, d.creep.f33 * scale};
  const auto m = hunting_model(single_wheelset(d));
  return 2 * kPi * speed / slowest_oscillatory_root(m, speed).imag();
}

TEST(HuntingValidation, InfiniteCreepRecoversTheKinematicLimit) {
  WheelsetData d;
  d.creep.f23 = 0.0;
  d.creep.f33 = 0.0;
  const double kappa = 1.0 + d.conicity * d.r0 / d.l0;
  const double kinematic = 2 * kPi * std::sqrt(d.r0 * d.l0 * kappa / d.conicity);
  double previous = 1.0;
  for (double scale : {1.0, 1e2, 1e4}) {
    const double err = std::abs(wavelength_with_creep_scaled(d, scale, 50.0) / kinematic - 1);
    EXPECT_LT(err, previous) << "scale " << scale;  // converges monotonically, as 1/scale
    previous = err;
  }
  // f ×1e4: the inertial and gravitational corrections are 3.6e-10. (Further up the eigen-solve's
  // rounding, ~1e-16 of creep terms 1e4 times larger, takes over: 3.6e-8 at ×1e6.)
  EXPECT_LT(previous, 1e-8);
  // And Klingel's own formula is off by √κ, not by rounding.
  EXPECT_NEAR(kinematic / (2 * kPi * std::sqrt(d.r0 * d.l0 / d.conicity)), std::sqrt(kappa), 1e-15);
  EXPECT_GT(std::sqrt(kappa) - 1, 0.04);
}

// With f23 and f33, infinite creep leaves the first-order system (C_c/V)·q̇ + K_c(creep)·q = 0
// (inertia and W·ε/l0 negligible). With u = s/V and ε = σ its determinant, by hand from the
// equations (docs/stability.md), is
//   κ[f22(f11 l0² + f33) + f23²]·u² − f23·f11·λ·l0/r0·u + f22·f11·λ·l0/r0 = 0,
// whose complex root gives the wavelength 2π/Im u: the spin terms shift it, and lend it a real
// part (the f23 coupling is not conservative).
TEST(HuntingValidation, InfiniteCreepWithSpinTermsMatchesTheFirstOrderLimit) {
  WheelsetData d;
  d.creep.f23 = 2.0e4;  // large, so that the shift is visible
  d.creep.f33 = 2.0e4;
  const auto& f = d.creep;
  const double kappa = 1.0 + d.conicity * d.r0 / d.l0, b = f.f11 * d.conicity * d.l0 / d.r0;
  const double qa = kappa * (f.f22 * (f.f11 * d.l0 * d.l0 + f.f33) + f.f23 * f.f23), qb = -f.f23 * b, qc = f.f22 * b;
  const double im_u = std::sqrt(4 * qa * qc - qb * qb) / (2 * qa);
  const double limit = 2 * kPi / im_u;
  const double plain = 2 * kPi * std::sqrt(d.r0 * d.l0 * kappa / d.conicity);
  EXPECT_GT(std::abs(limit / plain - 1), 1e-3);  // the spin terms matter here
  EXPECT_NEAR(wavelength_with_creep_scaled(d, 1e4, 50.0), limit, 1e-7 * limit);
}

// Free wheelset with the gravitational stiffness W·ε/l0 (every default): stable below a speed.
// The assembled system's critical speed (bisection on the largest real part) against the
// Routh–Hurwitz root of the hand-derived quartic.
//
// The spin coupling f23 matters here: as V → 0 the quartic's a1·V tends to
// 2(f11·l0² + f33)·W·ε/l0 − 4·f23·κ·f11·λ·l0/r0 (ε = σ), so the free wheelset on knife-edge rails
// (ε = λ) is stable at low speed only while 2·f23·κ < W·r0·(1 + f33/(f11·l0²)) (next test). Our
// wheelset alone weighs 14.7 kN, so its creep coefficients are taken for that load: f23 = 1e3
// N·m (f23 = G·(ab)^{3/2}·C23 grows with the load faster than f11 and f22; CreepCoefficients).
TEST(HuntingValidation, FreeWheelsetWithGravitationalStiffnessMatchesRouthHurwitz) {
  WheelsetData d;
  d.creep.f23 = 1.0e3;
  const auto m = hunting_model(single_wheelset(d));
  const double weight = d.mass * kG;
  EXPECT_LT(max_real_part(m, 1.0), 0.0);
  EXPECT_GT(max_real_part(m, 200.0), 0.0);
  const double routh = routh_critical_speed(d, weight, 0.0, 0.0, 1.0, 200.0);
  const double eigen = eigen_critical_speed(m, 1.0, 200.0);
  EXPECT_TRUE(wheelset_quartic(d, weight, 0.0, 0.0, routh).coefficients_positive());
  // 1e-8 relative: both are bisected to 1e-13; the eigenvalue's real part near zero is good to
  // ~1e-15·‖A‖ and crosses zero with a slope that keeps that below 1e-10 in speed.
  EXPECT_NEAR(eigen, routh, 1e-8 * routh);
  RecordProperty("free_wheelset_critical_speed", std::to_string(routh));  // 1.340082 m/s (1.395148 before the κ fix)
}

TEST(HuntingValidation, FreeWheelsetLowSpeedStabilityNeedsSpinCouplingBelowTheGravitationalTerm) {
  WheelsetData d;
  const double weight = d.mass * kG;
  const double kappa = 1.0 + d.conicity * d.r0 / d.l0;
  const double threshold =
      weight * d.r0 * (1 + d.creep.f33 / (d.creep.f11 * d.l0 * d.l0)) / (2.0 * kappa);  // f23 at which a1·V → 0
  for (double factor : {0.95, 1.05}) {
    WheelsetData s = d;
    s.creep.f23 = factor * threshold;
    const auto m = hunting_model(single_wheelset(s));
    const bool stable = max_real_part(m, 0.2) < 0.0;
    EXPECT_EQ(stable, factor < 1.0) << "f23 = " << s.creep.f23;
    EXPECT_EQ(wheelset_quartic(s, weight, 0.0, 0.0, 0.2).a1 > 0.0, factor < 1.0);
  }
}

// ---------------------------------------------------------------------------------------------
// A wheelset on lateral and yaw springs to a fixed frame (the bundled wheelset_on_springs case).
TEST(HuntingValidation, WheelsetOnSpringsMatchesRouthHurwitz) {
  WheelsetData d;
  const double k_y = 1.0e6, k_psi = 2.0e6;  // N/m, N·m/rad
  const auto m = hunting_model(single_wheelset(d, k_y, k_psi));
  const double weight = d.mass * kG;
  const double routh = routh_critical_speed(d, weight, k_y, k_psi, 1.0, 400.0);
  const double eigen = eigen_critical_speed(m, 1.0, 400.0);
  EXPECT_TRUE(wheelset_quartic(d, weight, k_y, k_psi, routh).coefficients_positive());
  EXPECT_NEAR(eigen, routh, 1e-8 * routh);
  EXPECT_LT(max_real_part(m, 0.9 * routh), 0.0);
  EXPECT_GT(max_real_part(m, 1.1 * routh), 0.0);
  RecordProperty("wheelset_on_springs_critical_speed",
                 std::to_string(routh));  // 66.205641 m/s (65.330265 before the κ fix)
}

// The axle load counts the static loads the wheelset carries, and a reference point away from
// the axle moves the terms by the lever (the same critical speed either way).
TEST(HuntingValidation, AxleLoadAndReferencePointGoThroughTheAssembly) {
  WheelsetData d;
  Vehicle v = single_wheelset(d, 1.0e6, 2.0e6);
  // A 4000 kg mass standing on the wheelset on two vertical springs.
  Body load;
  load.name = "load";
  load.mass = 4000.0;
  load.inertia = {1000.0, 1000.0, 1000.0};
  load.held = {Motion::lateral, Motion::roll, Motion::pitch, Motion::yaw};
  v.bodies.push_back(load);
  for (double y : {-1.0, 1.0}) v.elements.push_back(spring("load", "load", "wheelset", {0.0, y, 0.3}, 0, 0, 1e6));
  const auto m = hunting_model(v);
  const double weight = (d.mass + load.mass) * kG;
  EXPECT_NEAR(m.contact.wheelsets[0].axle_load, weight, 1e-9 * weight);
  const double routh = routh_critical_speed(d, weight, 1.0e6, 2.0e6, 1.0, 400.0);

  Vehicle moved = v;
  moved.bodies[0].reference_point = {0.7, 0.0, 0.0};  // 0.7 m ahead of the axle
  const auto mm = hunting_model(moved);
  EXPECT_NEAR(eigen_critical_speed(m, 1.0, 400.0), routh, 1e-8 * routh);
  EXPECT_NEAR(eigen_critical_speed(mm, 1.0, 400.0), routh, 1e-8 * routh);
}

// W given (WheelRailContact::axle_load) replaces the vertical equilibrium, in the gravitational
// stiffness and as the Hertz wheel load's default; ResolvedContact says where W came from, so a
// W that is only the wheelset's own weight can be marked (issue 20 review: the bundled wheelset
// on springs had W = 14.7 kN against creep coefficients sized for a 50 kN wheel).
TEST(HuntingValidation, AxleLoadGivenOrFromTheStaticLoads) {
  WheelsetData d;
  const double lam = d.conicity;
  const Vehicle own = single_wheelset(d, 1.0e6, 2.0e6);  // springs to the ground carry nothing
  const auto m_own = hunting_model(own);
  EXPECT_EQ(m_own.contact.wheelsets[0].axle_load_source, "own weight only");
  EXPECT_NEAR(m_own.contact.wheelsets[0].axle_load, d.mass * kG, 1e-9 * d.mass * kG);

  Vehicle given = own;
  given.wheelsets[0].contact.axle_load = 1.0e5;
  const auto m_given = hunting_model(given);
  EXPECT_EQ(m_given.contact.wheelsets[0].axle_load_source, "given");
  EXPECT_EQ(m_given.contact.wheelsets[0].axle_load, 1.0e5);
  // Only the gravitational term changes: W·ε/l0 with ε = λ (1e-9 relative: one sum of two terms).
  const double diff = m_given.contact.stiffness(0, 0) - m_own.contact.stiffness(0, 0);
  EXPECT_NEAR(diff, (1.0e5 - d.mass * kG) * lam / d.l0, 1e-9 * 1.0e5 * lam / d.l0);
  EXPECT_EQ(m_given.contact.stiffness(1, 0), m_own.contact.stiffness(1, 0));
  EXPECT_EQ(m_given.contact.creep_damping, m_own.contact.creep_damping);
  // Against the hand-derived quartic with that W: the critical speed moves with it.
  const double routh = routh_critical_speed(d, 1.0e5, 1.0e6, 2.0e6, 1.0, 400.0);
  EXPECT_NEAR(eigen_critical_speed(m_given, 1.0, 400.0), routh, 1e-8 * routh);

  // The Hertz contact takes W/2 per wheel unless its wheel load is given.
  Vehicle hertz = given;
  hertz.wheelsets[0].contact.creep.reset();
  HertzContactInput h;
  h.rail_head_radius = 0.3;
  hertz.wheelsets[0].contact.hertz = h;
  const auto m_hertz = hunting_model(hertz);
  const auto& e = m_hertz.contact.wheelsets[0].ellipse;
  ASSERT_TRUE(e.has_value());
  h.wheel_load = 0.5e5;
  const HertzContact want = hertz_contact(h, d.r0);
  EXPECT_DOUBLE_EQ(e->a, want.a);
  EXPECT_DOUBLE_EQ(e->b, want.b);

  // And with a mass standing on it: the static loads.
  Vehicle loaded = own;
  Body load;
  load.name = "load";
  load.mass = 4000.0;
  load.inertia = {1000.0, 1000.0, 1000.0};
  load.held = {Motion::lateral, Motion::roll, Motion::pitch, Motion::yaw};
  loaded.bodies.push_back(load);
  for (double y : {-1.0, 1.0}) loaded.elements.push_back(spring("load", "load", "wheelset", {0.0, y, 0.3}, 0, 0, 1e6));
  EXPECT_EQ(hunting_model(loaded).contact.wheelsets[0].axle_load_source, "static loads");
}

// ---------------------------------------------------------------------------------------------
// A rigid bogie: two wheelsets at x = ±a in a frame, tied by primary springs stiff enough to be
// rigid. Its low-speed (kinematic) wavelength is 2π√((r0·l0/λ)(1 + a²f22/(l0²f11))) (derived in
// docs/stability.md: no net lateral creep force and no net yaw moment with the bogie rigid);
// with f11 = f22 it is Rocard's 2π√(s·r/(2n))·√(1 + (2a/s)²) of the digest (bogie wagons forced
// and hunting, §2.1, E2; s = 2l0).
struct BogieData {
  double a = 1.25;        // m, half the wheelbase
  double primary = 1e10;  // N/m, each primary spring, longitudinal and lateral
  WheelsetData wheelset;
  int axles = 2;          // at x = a and −a; three: a, 0 and −a
};

Vehicle rigid_bogie(const BogieData& bd) {
  Vehicle v;
  v.name = "rigid bogie";
  Body frame;
  frame.name = "frame";
  frame.mass = 2000.0;
  frame.inertia = {1000.0, 1500.0, 2000.0};  // bounce, roll and pitch free, on the vertical springs
  v.bodies.push_back(frame);
  for (int i = 0; i < bd.axles; ++i) {
    WheelsetData w = bd.wheelset;
    w.name = "wheelset" + std::to_string(i + 1);
    w.x = bd.a - 2.0 * bd.a * i / (bd.axles - 1);
    add_wheelset(v, w);
    for (double y : {-1.0, 1.0})
      v.elements.push_back(spring(w.name + ".primary", "frame", w.name, {w.x, y, 0.0}, bd.primary, bd.primary, 1e6));
  }
  return v;
}

// ā² = Σx_i²/N about the axles' centre: a² for two axles at ±a, 2a²/3 for three at a, 0, −a
// (no net yaw moment: (N·f11·l0² + f22·Σx_i²)ψ̇ = −N·f11·l0·λ·V·y/r0, docs/stability.md).
double bogie_kinematic_wavelength(const BogieData& bd) {
  const auto& w = bd.wheelset;
  const double a2 = bd.axles == 3 ? 2.0 * bd.a * bd.a / 3.0 : bd.a * bd.a;
  return 2 * kPi * std::sqrt(w.r0 * w.l0 / w.conicity * (1 + a2 * w.creep.f22 / (w.l0 * w.l0 * w.creep.f11)));
}

BogieData kinematic_bogie() {
  BogieData bd;
  bd.wheelset.epsilon = 0.0;    // the formula has no gravitational stiffness,
  bd.wheelset.sigma = 0.0;      // no roll term,
  bd.wheelset.creep.f23 = 0.0;  // and no spin creep
  bd.wheelset.creep.f33 = 0.0;
  return bd;
}

TEST(HuntingValidation, RigidBogieLowSpeedWavelength) {
  BogieData bd = kinematic_bogie();
  // 0.1 m/s: inertia against creep, m·ω·V/f22, is ~2e-7; slower, the eigen-solve's rounding
  // (~1e-16 of the stiff springs' k/m ~ 1e7 against ω ~ 0.02/s) grows instead.
  const double v = 0.1;
  const double expected = bogie_kinematic_wavelength(bd);
  auto wavelength = [&](double primary) {
    BogieData b = bd;
    b.primary = primary;
    const auto m = hunting_model(rigid_bogie(b));
    return 2 * kPi * v / slowest_oscillatory_root(m, v).imag();
  };
  // The springs' compliance leaves an error ∝ 1/k (creep forces ~f22·ψ deflect them by
  // ~f22·ψ/k): measured 2.3e-5 at k = 1e9 N/m, falling tenfold per decade of k.
  const double e9 = std::abs(wavelength(1e9) / expected - 1), e10 = std::abs(wavelength(1e10) / expected - 1);
  EXPECT_GT(e9, 1e-5);
  EXPECT_LT(e10, e9 / 5.0);
  EXPECT_LT(e10, 5e-6);
  // Not Klingel's single-wheelset wave: the bogie's is longer by the factor √(1 + a²f22/(l0²f11)).
  EXPECT_GT(expected / (2 * kPi * std::sqrt(bd.wheelset.r0 * bd.wheelset.l0 / bd.wheelset.conicity)), 1.5);
}

// A rigid three-axle truck (review of 2026-11-28): its low-speed wavelength has ā² = 2a²/3 where
// two axles have a², the mean square of the axles' offsets (WheelsetBogie::axle_spread), not the
// half wheelbase's square, which would make it over 5 % longer; the hunting result's V/Λ_b uses
// that spread (wheelset_carriers, one body: a one-bogie vehicle gets its V/Λ_b too).
TEST(HuntingValidation, RigidThreeAxleTruckLowSpeedWavelength) {
  BogieData bd = kinematic_bogie();
  bd.axles = 3;
  const double v = 0.1;
  const auto m = hunting_model(rigid_bogie(bd));
  const double measured = 2 * kPi * v / slowest_oscillatory_root(m, v).imag();
  // As for two axles at 1e10 N/m (RigidBogieLowSpeedWavelength: the springs' compliance, < 5e-6).
  EXPECT_LT(std::abs(measured / bogie_kinematic_wavelength(bd) - 1), 5e-6);
  BogieData half_wheelbase = bd;
  half_wheelbase.axles = 2;  // the same a used as for two axles
  EXPECT_GT(bogie_kinematic_wavelength(half_wheelbase) / measured - 1, 0.05);
  const std::vector<stability::WheelsetBogie> carriers = stability::wheelset_carriers(rigid_bogie(bd));
  ASSERT_EQ(carriers.size(), 1u);  // one body carrying three: no bogies for the naming, a carrier here
  EXPECT_TRUE(stability::wheelset_bogies(rigid_bogie(bd)).empty());
  EXPECT_EQ(carriers[0].wheelsets.size(), 3u);
  // Round-off only, in units u = ε/2 of relative rounding: the axles at a, 0, −a (exact) have
  // mean exactly 0 (a/3 and −a/3 round alike), so the spread is √(2·fl(fl(a²)/3)), the doubling
  // exact: pow within 1 ulp (2u) and /3 (u) give 3u, halved by √, which adds u: 2.5u. The
  // reference √(2/3)·a: 2/3 (u, halved by √), √ (u), ×a (u): 2.5u. 5u together; 8u = 4ε allowed.
  const double expected_spread = std::sqrt(2.0 / 3.0) * bd.a;
  EXPECT_NEAR(carriers[0].axle_spread, expected_spread, 4.0 * std::numeric_limits<double>::epsilon() * expected_spread);
}

// The digest's case: s = 1.58 m (l0 = 0.79), r = 0.525 m, n = 1/20, base 2.5 m (a = 1.25),
// f11 = f22: recomputed 33.87 m (the book printed 33.3 m; the digest shows 33.87 is consistent).
TEST(HuntingValidation, RigidBogieDigestWavelength) {
  BogieData bd = kinematic_bogie();
  bd.wheelset.r0 = 0.525;
  bd.wheelset.l0 = 0.79;
  bd.wheelset.conicity = 1.0 / 20.0;
  bd.wheelset.creep.f22 = bd.wheelset.creep.f11;
  const double v = 0.1;
  const auto m = hunting_model(rigid_bogie(bd));
  const double wavelength = 2 * kPi * v / slowest_oscillatory_root(m, v).imag();
  EXPECT_NEAR(wavelength, 33.87, 0.005);                                       // the digest prints two decimals
  EXPECT_NEAR(wavelength, bogie_kinematic_wavelength(bd), 1e-5 * wavelength);  // k = 1e10: ~2e-6, above
  // Each wheelset carries its weight and half the frame's.
  for (const auto& r : m.contact.wheelsets)
    EXPECT_NEAR(r.axle_load, (bd.wheelset.mass + 1000.0) * kG, 1e-9 * r.axle_load);
}

// ---------------------------------------------------------------------------------------------
// Symmetry: two identical wheelsets, each on its own springs to the ground, joined by lateral
// springs at their axles to a frame midway that is symmetric fore and aft. Exchanging the
// wheelsets (y1↔y2, ψ1↔ψ2) together with the frame's yaw sign (ψf → −ψf, the frame mirrored
// fore–aft) maps the equations onto themselves, so the motions split into the in-phase
// half (y1 = y2, ψ1 = ψ2, ψf = 0) and the anti-phase half (y1 = −y2, ψ1 = −ψ2, yf = 0), three
// DOFs and six eigenvalues each, and the whole's twelve eigenvalues are the halves' together.
// (Eigenvectors are not compared: the creep-damped roots of the two barely coupled wheelsets
// come in nearly equal pairs whose vectors the solver may mix.) The contact terms do not depend on where along the
// track a wheelset runs, so they keep the symmetry. (A real bogie's yaw springs tie wheelset yaw to frame yaw, which
// flips under the mirror while the wheelsets' running direction does not: its branches do not pair.)
TEST(HuntingValidation, SymmetricPairBranchesAreInPhaseOrAntiPhase) {
  Vehicle v;
  v.name = "pair";
  Body frame;
  frame.name = "frame";
  frame.mass = 3000.0;
  frame.inertia = {1000.0, 1500.0, 2500.0};
  frame.held = {Motion::bounce, Motion::roll, Motion::pitch};
  v.bodies.push_back(frame);
  for (int i = 0; i < 2; ++i) {
    WheelsetData w;
    w.name = i == 0 ? "wheelset1" : "wheelset2";
    w.x = i == 0 ? 1.25 : -1.25;
    add_wheelset(v, w);
    add_springs_to_ground(v, w, 1.0e6, 2.0e6);
    v.elements.push_back(spring(w.name + ".link", w.name, "frame", {w.x, 0.0, 0.0}, 0.0, 3.0e5));
  }
  const auto m = hunting_model(v);
  const auto& s = m.system;
  ASSERT_EQ(s.size(), 6);
  const int y1 = s.index_of("wheelset1.lateral"), p1 = s.index_of("wheelset1.yaw");
  const int y2 = s.index_of("wheelset2.lateral"), p2 = s.index_of("wheelset2.yaw");
  const int yf = s.index_of("frame.lateral"), pf = s.index_of("frame.yaw");
  const double h = std::sqrt(0.5);
  Eigen::MatrixXd even = Eigen::MatrixXd::Zero(6, 3), odd = Eigen::MatrixXd::Zero(6, 3);
  even(yf, 0) = 1;
  even(y1, 1) = even(y2, 1) = h;
  even(p1, 2) = even(p2, 2) = h;
  odd(pf, 0) = 1;
  odd(y1, 1) = h, odd(y2, 1) = -h;
  odd(p1, 2) = h, odd(p2, 2) = -h;
  // Each half of the motions as a system of its own: M, C, K projected onto it.
  auto half = [&](const Eigen::MatrixXd& basis, double speed) {
    HuntingModel r = m;
    const Eigen::MatrixXd c = m.system.damping + m.contact.creep_damping / speed + speed * m.contact.gyroscopic;
    const Eigen::MatrixXd k = m.system.stiffness + m.contact.stiffness;
    r.system.dofs.resize(3);
    r.system.mass = basis.transpose() * m.system.mass * basis;
    r.system.damping = basis.transpose() * c * basis;
    r.system.stiffness = basis.transpose() * k * basis;
    r.contact.creep_damping = r.contact.gyroscopic = r.contact.stiffness = Eigen::MatrixXd::Zero(3, 3);
    // The half is invariant: the full matrices map it into itself (to rounding).
    for (const Eigen::MatrixXd* a : {&c, &k})
      EXPECT_LT((*a * basis - basis * (basis.transpose() * *a * basis)).norm(), 1e-12 * a->norm());
    return eigenvalues(r, 1.0);  // speed already folded into C
  };
  for (double speed : {5.0, 40.0, 120.0}) {
    Eigen::VectorXcd all = eigenvalues(m, speed);
    Eigen::VectorXcd halves(12);
    halves << half(even, speed), half(odd, speed);
    // Every eigenvalue of the whole is one of the halves' (matched one to one). 1e-9 of the
    // largest modulus: the eigen-solves' rounding is ~1e-15 of it, times the conditioning of
    // the nearly equal pairs of creep-damped roots (the two wheelsets barely coupled).
    const double scale = all.cwiseAbs().maxCoeff();
    std::vector<bool> used(12, false);
    for (const auto& l : halves) {
      int best = -1;
      for (int k = 0; k < 12; ++k)
        if (!used[k] && (best < 0 || std::abs(all(k) - l) < std::abs(all(best) - l))) best = k;
      used[best] = true;
      EXPECT_LT(std::abs(all(best) - l), 1e-9 * scale) << "V = " << speed << ", λ = " << l;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Creep coefficients from Hertz and Kalker (helper "creep"'s functions): the wheel load defaults
// to W/2 and the result is what creep_coefficients gives for that ellipse. Waits for
// src/model/hertz_contact.cpp and kalker_table.cpp.
TEST(HuntingValidation, HertzContactGivesTheCreepCoefficients) {
  Vehicle v = single_wheelset(WheelsetData{}, 1.0e6, 2.0e6);
  HertzContactInput in;
  in.rail_head_radius = 0.3;
  v.wheelsets[0].contact.creep.reset();
  v.wheelsets[0].contact.hertz = in;
  const auto m = hunting_model(v);
  const auto& r = m.contact.wheelsets[0];
  ASSERT_TRUE(r.ellipse.has_value());
  HertzContactInput loaded = in;
  loaded.wheel_load = r.axle_load / 2.0;
  const auto ellipse = hertz_contact(loaded, 0.46);
  EXPECT_DOUBLE_EQ(r.ellipse->a, ellipse.a);
  const auto f = creep_coefficients(ellipse, in.youngs_modulus, in.poisson_ratio);
  EXPECT_DOUBLE_EQ(r.creep.f11, f.f11);
  EXPECT_DOUBLE_EQ(r.creep.f33, f.f33);
  EXPECT_NEAR(m.contact.stiffness(1, 0), 2 * f.f11 * 0.15 * 0.75 / 0.46, 1e-12 * m.contact.stiffness(1, 0));
}

}  // namespace
}  // namespace railmodal::test
