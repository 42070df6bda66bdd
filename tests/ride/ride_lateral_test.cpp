// The lateral ride through the creep forces (docs/ride.md, "Lateral ride through the creep
// forces"): one wheelset on lateral and yaw springs to the track frame under alignment, against
// its receptance written out by hand; above the linear critical speed every output is unbounded.
// Cross-level through the contact and the lateral wheel–rail force against the same hand model.
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

// The wheelset on springs (hunting_test_support.hpp) with its axle load, which the lateral
// ride's contact takes.
Vehicle loaded_wheelset_on_springs(const test::WheelsetData& d) {
  Vehicle v = test::wheelset_on_springs(d, kLateral, kYaw);
  v.wheelsets.back().contact.axle_load = kAxleLoad;
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
  const LinearSystem s = assemble(loaded_wheelset_on_springs(d), DofSet::lateral);
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
  const LinearSystem s = assemble(loaded_wheelset_on_springs(d), DofSet::lateral);
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
  const LinearSystem s = assemble(loaded_wheelset_on_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {0.95 * vc, 1.05 * vc};
  const RideResult r = solve_ride(s, ore_alignment(), {lateral_displacement("axle", 0.0)}, options);
  EXPECT_FALSE(r.speeds[0].outputs[0].unbounded);
  EXPECT_TRUE(std::isfinite(r.speeds[0].outputs[0].rms));
  EXPECT_TRUE(r.speeds[1].outputs[0].unbounded);
  bool noted = false;
  for (const std::string& n : r.notes) noted = noted || n.find("above its linear critical speed") != std::string::npos;
  EXPECT_TRUE(noted);
  // And the report says where the hunting begins: the critical speed of the hand equations'
  // Routh–Hurwitz test, to the note's four significant digits.
  const std::string lead = "the linear critical speed of the vehicle on its wheelsets is ";
  double said = 0.0;
  for (const std::string& n : r.notes)
    if (n.rfind(lead, 0) == 0) said = std::stod(n.substr(lead.size()));
  EXPECT_NEAR(said / (vc * 3.6), 1.0, 5e-4);
}

// Audit 2026-11-27c, 1.6: above the critical speed only what the growing motion moves has no
// stationary response. The coach's vertical motions are decoupled from its lateral ones in the
// linear model, so its vertical floor accelerations keep their numbers, the same as those of its
// vertical model alone (DofSet::vertical) on the same vertical level, while every lateral one is
// unbounded.
TEST(RideLateral, AboveTheCriticalSpeedDecoupledVerticalOutputsKeepTheirNumbers) {
  const Vehicle coach = load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml"));
  const LinearSystem all = assemble(coach, DofSet::all), vertical = assemble(coach, DofSet::vertical);
  TrackIrregularitySpectra track = ore_alignment();
  track.vertical_level =
      TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {2 * kPi / 100, 2 * kPi / 3});
  RideOptions options;
  options.speeds = {400 / 3.6};  // above its linear critical speed, 353 km/h (docs/stability.md)
  const RideResult r = solve_ride(all, track, default_ride_outputs(all), options);
  TrackIrregularitySpectra level;
  level.vertical_level = track.vertical_level;
  const RideResult alone = solve_ride(vertical, level, default_ride_outputs(vertical), options);
  // The two grids differ (the full model's has the lateral modes' peaks too): each RMS is within
  // its grid error estimate of the exact integral, so the two within the sum of both (and 1e-9
  // for the estimates' own round-off).
  const double tolerance = r.grid_error_estimate + alone.grid_error_estimate + 1e-9;
  size_t vertical_outputs = 0;
  for (size_t o = 0; o < r.outputs.size(); ++o) {
    const RideOutputAtSpeed& at = r.speeds[0].outputs[o];
    if (r.outputs[o].axis == RideAxis::lateral) {
      EXPECT_TRUE(at.unbounded) << r.outputs[o].name;
      continue;
    }
    ASSERT_FALSE(at.unbounded) << r.outputs[o].name;
    const RideOutputAtSpeed& ref = alone.speeds[0].outputs[vertical_outputs];
    ASSERT_EQ(alone.outputs[vertical_outputs].name, r.outputs[o].name);
    EXPECT_NEAR(at.rms / ref.rms, 1.0, tolerance) << r.outputs[o].name;
    EXPECT_NEAR(*at.weighted_rms / *ref.weighted_rms, 1.0, tolerance) << r.outputs[o].name;
    ++vertical_outputs;
  }
  EXPECT_EQ(vertical_outputs, alone.outputs.size());
  EXPECT_GT(r.grid_error_estimate, 0.0);  // estimated from the bounded outputs: there are some
  bool said = false;  // the note names what grows and says the others keep their numbers
  for (const std::string& n : r.notes)
    said = said || (n.find(" grow") != std::string::npos && n.find("keep their numbers") != std::string::npos);  // "grow(s)"
  EXPECT_TRUE(said);
}

// ---- Cross-level through the contact, and the lateral wheel–rail force ----------------------
//
// The hand model of docs/ride.md, "Cross-level through the contact": the same wheelset, its
// springs to the frame raised to h = 0.3 m above the axle plane (so both of their ends roll with
// the track: the frame's about the rail top, the wheelset's with the rails), under cross-level
// Δz, θ = Δz/(2·l0). Written from the creepages, not from the code's matrices: with
// y_r = y + r0·θ the wheelset's place on the rolled rails,
//   ξy = κ·ẏ_r/V − ψ   (contact point velocity ẏ + r0·φ̇, φ = θ + σ·y_r/l0 its absolute roll),
//   ξx = ∓(λ·y_r/r0 + l0·ψ̇/V),   ξsp = ψ̇/V − (ε − σ)·y_r/(r0·l0),
//   lateral: m·ÿ = κ·ΣFy − W·ε·y_r/l0 − W·θ + g·V·ψ̇ − k_y·(y + r0·θ),
//   yaw:     I·ψ̈ = −2l0·f11(λ·y_r/r0 + l0·ψ̇/V) + ΣMz − I_y(V/r0)·φ̇ − k_ψ·ψ.
// So every y and ẏ term of the free equations acts on y_r, and −W·θ and −I_y(V/r0)·θ̇ come in
// besides: the free matrix of `receptance` with right-hand side −θ·([p + a·s; h·s + b]·r0 +
// [W; I_y·V·s/r0]).
constexpr double kSpringHeight = 0.3;  // m above the axle plane

Vehicle wheelset_on_raised_springs(const test::WheelsetData& d) {
  Vehicle v;
  v.name = "wheelset on raised springs";
  test::add_wheelset(v, d);
  v.wheelsets.back().contact.axle_load = kAxleLoad;
  for (double y : {-1.0, 1.0})
    v.elements.push_back(test::spring(y > 0 ? "left" : "right", d.name, "", {d.x, y, kSpringHeight}, kYaw / 2.0,
                                      kLateral / 2.0));
  return v;
}

// (y, ψ) per metre of cross-level Δz, by hand (above).
Eigen::Vector2cd cross_level_receptance(const test::WheelsetData& d, double speed, double omega) {
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
  const double theta = 1.0 / (2.0 * l0);
  const Eigen::Vector2cd rhs(-theta * ((p + a * s) * r0 + kAxleLoad),
                             -theta * ((h * s + b) * r0 + d.spin_inertia * v * s / r0));
  return m.partialPivLu().solve(rhs);
}

RideOutput lateral_wheel_rail_force() {
  RideOutput o;
  o.name = "lateral wheel-rail force";
  o.kind = RideOutput::Kind::wheel_rail_force;
  o.element = "wheelset";
  o.axis = RideAxis::lateral;
  return o;
}

TrackIrregularitySpectra ore_cross_level() {
  TrackIrregularitySpectra track;
  track.cross_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, {2 * kPi / 100, 2 * kPi / 3});
  return track;
}

// Each output's PSD over the input's is |H|² of the hand model: y at the axle, y + 1 m·ψ, and the
// lateral force of the rails on the wheelset, which by the wheelset's own equation is what its
// mass and springs take: F = m·s²·y + k_y·(y + r0·θ) (a closed form that needs no creep term).
TEST(RideLateral, CrossLevelThroughTheContactFollowsTheHandReceptance) {
  const test::WheelsetData d;
  const double vc = critical_speed(d);  // the raised springs change no term of the free equations
  const LinearSystem s = assemble(wheelset_on_raised_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {0.4 * vc, 0.8 * vc};
  const RideResult r = solve_ride(s, ore_cross_level(),
                                  {lateral_displacement("axle", 0.0), lateral_displacement("1 m ahead", 1.0),
                                   lateral_wheel_rail_force()},
                                  options);
  for (size_t v = 0; v < options.speeds.size(); ++v) {
    const RideAtSpeed& at = r.speeds[v];
    ASSERT_FALSE(at.outputs[0].unbounded);
    int compared = 0;
    for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
      const double g = at.input_psd[0](k);
      if (!(g > 0.0)) continue;
      const double omega = 2 * kPi * r.frequencies(k);
      const Eigen::Vector2cd h = cross_level_receptance(d, options.speeds[v], omega);
      const Complex force = -d.mass * omega * omega * h(0) + kLateral * (h(0) + d.r0 / (2.0 * d.l0));
      // As for the alignment: two routes to one 2×2 solve, round-off times its condition. The
      // force is a difference of the mass's and the springs' parts, which cancel near the
      // wheelset's lateral resonance: 1e-8 of |F|² leaves two orders for that cancellation.
      EXPECT_NEAR(at.outputs[0].psd(k) / g, std::norm(h(0)), 1e-9 * std::norm(h(0))) << r.frequencies(k);
      EXPECT_NEAR(at.outputs[1].psd(k) / g, std::norm(h(0) + h(1)), 1e-9 * std::norm(h(0) + h(1)));
      EXPECT_NEAR(at.outputs[2].psd(k) / g, std::norm(force), 1e-8 * std::norm(force)) << r.frequencies(k);
      ++compared;
    }
    EXPECT_GT(compared, 100);
  }
}

// Each term of the cross-level's load is needed: dropping the leaning normal loads (−W·θ) or the
// gyroscopic θ̇ term from the hand model moves |H|² by far more than the 1e-9 the test holds,
// so the comparison above could fail for each of them.
TEST(RideLateral, CrossLevelHandTermsEachMatter) {
  test::WheelsetData d;
  const double speed = 0.6 * critical_speed(d), omega = 2 * kPi * 2.0;
  const double full = std::norm(cross_level_receptance(d, speed, omega)(0));
  test::WheelsetData no_spin = d;
  no_spin.spin_inertia = 0.0;  // drops the gyroscopic terms, the θ̇ one with them
  EXPECT_GT(std::abs(std::norm(cross_level_receptance(no_spin, speed, omega)(0)) / full - 1.0), 1e-3);
  // −W·θ against the rest: the static (ω → 0) part of the lateral load without W is p·r0·θ, which
  // the springs alone would follow (y = −r0·θ): W moves it off that.
  const Eigen::Vector2cd h0 = cross_level_receptance(d, speed, 1e-6);
  EXPECT_GT(std::abs(h0(0) + d.r0 / (2.0 * d.l0)), 1e-3 * d.r0 / (2.0 * d.l0));
}

// The lateral wheel–rail force under alignment: F = m·s²·y + k_y·(y − y_t) (the springs stand
// on the track frame, which the alignment moves), with y the alignment's hand receptance.
TEST(RideLateral, LateralWheelRailForceUnderAlignmentFollowsTheHandModel) {
  const test::WheelsetData d;
  const double vc = critical_speed(d);
  const LinearSystem s = assemble(loaded_wheelset_on_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {0.6 * vc};
  const RideResult r = solve_ride(s, ore_alignment(), {lateral_wheel_rail_force()}, options);
  int compared = 0;
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double g = r.speeds[0].input_psd[0](k);
    if (!(g > 0.0)) continue;
    const double omega = 2 * kPi * r.frequencies(k);
    const Eigen::Vector2cd h = receptance(d, options.speeds[0], omega);
    const Complex force = -d.mass * omega * omega * h(0) + kLateral * (h(0) - 1.0);
    // 1e-8 as for the cross-level's force (the same cancellation near the resonance).
    EXPECT_NEAR(r.speeds[0].outputs[0].psd(k) / g, std::norm(force), 1e-8 * std::norm(force)) << r.frequencies(k);
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

void expect_refused(const LinearSystem& s, const TrackIrregularitySpectra& track, const RideOutput& o,
                    const std::string& words) {
  RideOptions options;
  options.speeds = {20.0};
  try {
    solve_ride(s, track, {o}, options);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

// The longitudinal wheel–rail force of the linear contact is zero (the two wheels' creep forces
// are equal and opposite): refused, not answered with a zero. Without the contact (a vertical
// model of a wheelset vehicle) the lateral one is refused too.
TEST(RideLateral, LongitudinalAndContactlessWheelRailForcesAreRefused) {
  const test::WheelsetData d;
  const LinearSystem s = assemble(loaded_wheelset_on_springs(d), DofSet::lateral);
  RideOutput longitudinal = lateral_wheel_rail_force();
  longitudinal.axis = RideAxis::longitudinal;
  expect_refused(s, ore_alignment(), longitudinal, "equal and opposite");
  TrackIrregularitySpectra level;
  level.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.06, 2.0});
  RideOutput coach = lateral_wheel_rail_force();
  coach.element = "wheelset1";
  expect_refused(assemble(load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::vertical),
                 level, coach, "creep contact's");
}

// summary.method counts every track input the solve takes and names the contact's.
TEST(RideLateral, MethodCountsTheContactInputs) {
  const test::WheelsetData d;
  const LinearSystem s = assemble(wheelset_on_raised_springs(d), DofSet::lateral);
  RideOptions options;
  options.speeds = {20.0};
  TrackIrregularitySpectra track = ore_cross_level();
  track.alignment = ore_alignment().alignment;
  const RideResult r = solve_ride(s, track, {lateral_displacement("axle", 0.0)}, options);
  EXPECT_NE(r.summary.method.find("for all 4 track inputs (2 under the elements, 1 wheelsets' alignment through the "
                                  "contact, 1 wheelsets' roll with the rails through the contact)"),
            std::string::npos)
      << r.summary.method;
}

// The time-domain ride holds no wheel–rail contact: a wheelset free to move laterally would
// stand on its suspension alone, a wrong answer without a word. Refused, naming the wheelset.
TEST(RideLateral, TimeDomainRefusesAWheelsetWithoutItsContact) {
  const test::WheelsetData d;
  TrackGeometry geometry;
  geometry.step = 0.25;
  geometry.alignment = Eigen::VectorXd::Zero(4096);
  geometry.periodic = true;
  RideSimulationOptions options;
  options.speed = 20.0;
  RideOutput y;
  y.name = "wheelset lateral";
  y.kind = RideOutput::Kind::point;
  y.body = "wheelset";
  y.axis = RideAxis::lateral;
  y.quantity = ResponseQuantity::displacement;
  try {
    simulate_ride(assemble(loaded_wheelset_on_springs(d), DofSet::lateral), geometry, {y}, options);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("wheelset 'wheelset' moves lateral"), std::string::npos) << what;
    EXPECT_NE(what.find("frequency domain"), std::string::npos) << what;
  }
}

// The rails' roll twists a roll stiffness on the wheelset and stretches a lateral series damper,
// neither of which the cross-level's contact inputs carry: refused, naming the element, rather
// than answered without them.
TEST(RideLateral, CrossLevelRefusesWhatTheRailsRollWouldLoadUnmodelled) {
  const test::WheelsetData d;
  RideOptions options;
  options.speeds = {20.0};
  Vehicle roll_stiff = wheelset_on_raised_springs(d);
  roll_stiff.elements.front().rotational_stiffness.x() = 1e5;
  Vehicle series = wheelset_on_raised_springs(d);
  series.elements.front().series_dampers.push_back({Motion::lateral, 1e4, 1e6});
  for (const Vehicle& v : {roll_stiff, series}) {
    try {
      solve_ride(assemble(v, DofSet::lateral), ore_cross_level(), {lateral_displacement("axle", 0.0)}, options);
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("element 'right' on wheelset"), std::string::npos) << e.what();
    }
  }
  // Without either, the same model runs (the hand receptance test above checks its answer).
  EXPECT_NO_THROW(solve_ride(assemble(wheelset_on_raised_springs(d), DofSet::lateral), ore_cross_level(),
                             {lateral_displacement("axle", 0.0)}, options));
}

}  // namespace
}  // namespace railmodal
