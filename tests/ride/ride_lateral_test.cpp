// The lateral ride through the creep forces (docs/ride.md, "Lateral ride through the creep
// forces"): one wheelset on lateral and yaw springs to the track frame under alignment, against
// its receptance written out by hand; above the linear critical speed every output is unbounded.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal {
namespace {

using test::kPi;
using Complex = std::complex<double>;

constexpr double kAxleLoad = 1.0e5;  // N: two 50 kN wheels (data/vehicles/wheelset_on_springs.toml)
constexpr double kLateral = 1.0e6;   // N/m to the frame
constexpr double kYaw = 2.0e6;       // N·m/rad to the frame

Vehicle wheelset_on_springs(const test::WheelsetData& d) {
  Vehicle v;
  v.name = "wheelset on springs";
  test::add_wheelset(v, d);
  v.wheelsets.back().contact.axle_load = kAxleLoad;
  test::add_springs_to_ground(v, d, kLateral, kYaw);
  return v;
}

RideOutput lateral_displacement(const std::string& name, double x) {
  RideOutput o;
  o.name = name;
  o.body = "wheelset";
  o.point = Eigen::Vector3d(x, 0.0, 0.0);
  o.axis = RideAxis::lateral;
  o.quantity = ResponseQuantity::displacement;
  return o;
}

// (y, ψ) per metre of alignment y_t, by hand. The free equations are hunting_test_support's
// (wheelset_quartic's names a, e, p, c, q, h, b; the frame is the track, so its springs stand on
// it). The alignment enters wherever the contact sees the wheelset relative to the rail: every
// y term (the conicity's rolling-radius difference, the contact angles' gravitational and spin
// terms, the springs) acts on y − y_t, so the right-hand side has p·y_t and b·y_t; of the ẏ terms
// only the roll's: the lateral creepage is ẏ/V − ψ + (κ − 1)(ẏ − ẏ_t)/V, the yaw moment of the
// gyroscopic coupling g·V·(ẏ − ẏ_t), so 2f22κ(κ − 1)/V·ẏ_t laterally and (gV − 2f23(κ − 1)/V)·ẏ_t
// in yaw (the spin moment f23·ξy has the same split).
Eigen::Vector2cd receptance(const test::WheelsetData& d, double speed, double omega) {
  const double eps = d.epsilon.value_or(d.conicity), sig = d.sigma.value_or(d.conicity);
  const double r0 = d.r0, l0 = d.l0, v = speed;
  const CreepCoefficients& f = d.creep;
  const double kappa = 1.0 + sig * r0 / l0, g = d.spin_inertia * sig / (r0 * l0);
  const double a = 2 * f.f22 * kappa * kappa / v;
  const double p = kLateral + kAxleLoad * eps / l0 - 2 * f.f23 * kappa * (eps - sig) / (r0 * l0);
  const double e = g * v - 2 * f.f23 * kappa / v, c = (2 * f.f11 * l0 * l0 + 2 * f.f33) / v, q = kYaw + 2 * f.f23;
  const double h = g * v - 2 * f.f23 * kappa / v;
  const double b = 2 * f.f11 * d.conicity * l0 / r0 - 2 * f.f33 * (eps - sig) / (r0 * l0);
  const Complex s(0.0, omega);
  Eigen::Matrix2cd m;
  m << d.mass * s * s + a * s + p, -e * s - 2 * f.f22 * kappa, h * s + b, d.yaw_inertia * s * s + c * s + q;
  const Eigen::Vector2cd rhs(p + 2 * f.f22 * kappa * (kappa - 1) / v * s, b + (g * v - 2 * f.f23 * (kappa - 1) / v) * s);
  return m.partialPivLu().solve(rhs);
}

double critical_speed(const test::WheelsetData& d) {
  return test::routh_critical_speed(d, kAxleLoad, kLateral, kYaw, 10 / 3.6, 500 / 3.6);
}

TrackIrregularitySpectra ore_alignment() {
  TrackIrregularitySpectra track;
  track.alignment = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {2 * kPi / 100, 2 * kPi / 3});
  return track;
}

// Below the critical speed: each output's PSD over the input's is |H|², H the hand receptance of
// y (at the axle) and of y + 1 m·ψ (a point 1 m ahead).
TEST(RideLateral, WheelsetOnSpringsFollowsItsHandReceptance) {
  const test::WheelsetData d;
  const double vc = critical_speed(d);
  const LinearSystem s = assemble(wheelset_on_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {0.4 * vc, 0.8 * vc};
  const RideResult r =
      solve_ride(s, ore_alignment(), {lateral_displacement("axle", 0.0), lateral_displacement("1 m ahead", 1.0)}, options);
  for (size_t v = 0; v < options.speeds.size(); ++v) {
    const RideAtSpeed& at = r.speeds[v];
    ASSERT_FALSE(at.outputs[0].unbounded);
    int compared = 0;
    for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
      const double g = at.input_psd[0](k);
      if (!(g > 0.0)) continue;
      const Eigen::Vector2cd h = receptance(d, options.speeds[v], 2 * kPi * r.frequencies(k));
      // Two routes to one 2×2 solve (assembled matrices against the hand form): they differ by
      // round-off amplified by the solve's condition, far below 1e-9 here.
      EXPECT_NEAR(at.outputs[0].psd(k) / g, std::norm(h(0)), 1e-9 * std::norm(h(0))) << r.frequencies(k);
      EXPECT_NEAR(at.outputs[1].psd(k) / g, std::norm(h(0) + h(1)), 1e-9 * std::norm(h(0) + h(1)));
      ++compared;
    }
    EXPECT_GT(compared, 100);
  }
}

// At low frequency the wheelset follows the rail: y → y_t (its springs stand on the track frame,
// so nothing holds it off the rail's line); a check of the input's signs the hand form shares.
TEST(RideLateral, WheelsetFollowsTheRailAtLowFrequency) {
  const test::WheelsetData d;
  const Eigen::Vector2cd h = receptance(d, 0.5 * critical_speed(d), 2 * kPi * 1e-4);
  EXPECT_NEAR(std::abs(h(0)), 1.0, 1e-3);  // the first-order terms in ω ~ 1e-4 of the static ones
  const LinearSystem s = assemble(wheelset_on_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {0.5 * critical_speed(d)};
  options.min_frequency = 0.01;
  TrackIrregularitySpectra track;
  track.alignment = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {2 * kPi / 1000, 2 * kPi / 3});
  const RideResult r = solve_ride(s, track, {lateral_displacement("axle", 0.0)}, options);
  // At the first grid point inside the band (V/1000 m, some 0.03 Hz) |H|² is 1 within 1e-2: the
  // frequency is ~1 % of the wheelset's kinematic ~2.5 Hz, and the departure from 1 goes as its
  // square times the modes' amplification, well under 1e-2.
  Eigen::Index k = 0;
  while (!(r.speeds[0].input_psd[0](k) > 0.0)) ++k;
  ASSERT_LT(r.frequencies(k), 0.1);
  EXPECT_NEAR(r.speeds[0].outputs[0].psd(k) / r.speeds[0].input_psd[0](k), 1.0, 1e-2) << r.frequencies(k);
}

// Above the linear critical speed a free motion grows: there is no stationary response, every
// output is unbounded (an answer, no number, no NaN) and a note says why.
TEST(RideLateral, AboveTheCriticalSpeedEveryOutputIsUnbounded) {
  const test::WheelsetData d;
  const double vc = critical_speed(d);
  const LinearSystem s = assemble(wheelset_on_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {0.95 * vc, 1.05 * vc};
  const RideResult r = solve_ride(s, ore_alignment(), {lateral_displacement("axle", 0.0)}, options);
  EXPECT_FALSE(r.speeds[0].outputs[0].unbounded);
  EXPECT_TRUE(std::isfinite(r.speeds[0].outputs[0].rms));
  EXPECT_TRUE(r.speeds[1].outputs[0].unbounded);
  bool noted = false;
  for (const std::string& n : r.notes) noted = noted || n.find("above its linear critical speed") != std::string::npos;
  EXPECT_TRUE(noted);
}

// Cross-level on wheelsets that move laterally is still refused: the rails' roll tilts the
// normal loads, which the ride does not model yet.
TEST(RideLateral, CrossLevelOnLateralWheelsetsIsRefused) {
  const test::WheelsetData d;
  const LinearSystem s = assemble(wheelset_on_springs(d), DofSet::lateral);
  TrackIrregularitySpectra track;
  track.cross_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, {0.06, 2.0});
  RideOptions options;
  options.speeds = {20.0};
  try {
    solve_ride(s, track, {lateral_displacement("axle", 0.0)}, options);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cross-level on a vehicle with wheelsets"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace railmodal
