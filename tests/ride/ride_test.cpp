// The frequency-domain ride (ride.hpp): closed forms, the wheelbase filter, cross-level,
// point kinematics, modal shares, unbounded answers, friction and the error contract.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iostream>
#include <limits>

#include "railmodal/railmodal.hpp"
#include "ride/ride_friction.hpp"
#include "ride/ride_indices.hpp"
#include "ride/ride_transfer.hpp"
#include "ride/track_under_wheels.hpp"
#include "test_support.hpp"

namespace railmodal {
namespace {

using test::kPi;

SpringStage coil(double k) {
  SpringStage s;
  s.kind = "coil";
  s.stiffness = k;
  return s;
}

// One body on track elements at the given (x, y) points, each with vertical stiffness k and
// damping c; with lateral stiffness for DofSet::all.
Vehicle body_on_track(double mass, double pitch_inertia, const std::vector<Eigen::Vector2d>& points, double k,
                      double c, std::vector<Motion> held = {}) {
  Vehicle v;
  v.name = "test body";
  Body b;
  b.name = "body";
  b.mass = mass;
  b.inertia = Eigen::Vector3d(pitch_inertia, pitch_inertia, pitch_inertia);
  b.held = std::move(held);
  v.bodies.push_back(b);
  for (size_t i = 0; i < points.size(); ++i) {
    Element e;
    e.name = "spring" + std::to_string(i + 1);
    e.upper = "body";
    e.point = Eigen::Vector3d(points[i].x(), points[i].y(), 0.0);
    e.vertical_stages = {coil(k)};
    e.lateral_stages = {coil(k)};
    e.vertical_damping = c;
    e.lateral_damping = c;
    v.elements.push_back(e);
  }
  // Every element and centre of gravity at z = 0: gravity adds no stiffness (the −W·l of a CG
  // above its springs), so the closed forms are those of the springs alone.
  return v;
}

// A flat (white) one-sided density S0 in wavenumber over [low, high] rad/m: at speed V white in
// displacement per Hz, G0 = 2πS0/V m²/Hz, over [V·low/2π, V·high/2π] Hz.
TrackSpectrum white(TrackIrregularity kind, double S0, double low, double high) {
  return TrackSpectrum::table(kind, SpectrumAbscissa::wavenumber, {low, high}, {S0, S0});
}

// A track with one irregularity, ORE B176 at `level` over wavenumbers 0.06 to `highest` rad/m
// (wavelengths 105 m down to 3.1 m with the default), the others none: most tests' track.
TrackIrregularitySpectra one_irregularity(TrackIrregularity kind, OreLevel level = OreLevel::low, double highest = 2.0) {
  TrackIrregularitySpectra track;
  const TrackSpectrum spectrum = TrackSpectrum::ore_b176(level, kind, {0.06, highest});
  switch (kind) {
    case TrackIrregularity::vertical_level: track.vertical_level = spectrum; break;
    case TrackIrregularity::alignment: track.alignment = spectrum; break;
    case TrackIrregularity::cross_level: track.cross_level = spectrum; break;
  }
  return track;
}

RideOutput point_output(const std::string& name, Eigen::Vector3d p, RideAxis axis, ResponseQuantity q) {
  RideOutput o;
  o.name = name;
  o.kind = RideOutput::Kind::point;
  o.body = "body";
  o.point = p;
  o.axis = axis;
  o.quantity = q;
  return o;
}

// SDOF: mass m on a spring k and damper c to the track, its displacement under a displacement
// input white in m²/Hz over [f_lo, f_hi]. Closed form (Newland, An Introduction to Random
// Vibrations, 3rd ed., 1993, Appendix 1, the n = 2 integral): ∫_{−∞}^{∞} |(k + iωc)/(k − mω² +
// iωc)|² dω = π(c/m + k/c), so the one-sided ∫₀^∞|T|² df = (c/m + k/c)/4; the band removes f_lo
// below (|T| = 1 there to 1e-5) and c²/(4π²m²f_hi) above (|T|² → c²/(m²ω²)).
struct Sdof {
  double m = 1000.0, k = 1.0e6, c = 0.0;
  double f_lo = 0.01, f_hi = 1000.0, speed = 10.0, S0 = 1e-6;
  double G0() const { return 2.0 * kPi / speed * S0; }
  double variance() const {
    return G0() * ((c / m + k / c) / 4.0 - f_lo - c * c / (4.0 * kPi * kPi * m * m * f_hi));
  }
  RideResult solve(RideOptions options) const {
    const LinearSystem s = assemble(body_on_track(m, 1.0, {{0.0, 0.0}}, k, c, {Motion::pitch}), DofSet::vertical);
    TrackIrregularitySpectra track;
    track.vertical_level = white(TrackIrregularity::vertical_level, S0, 2 * kPi * f_lo / speed, 2 * kPi * f_hi / speed);
    options.speeds = {speed};
    options.min_frequency = 0.001;
    options.max_frequency = 2000.0;
    return solve_ride(s, track, {point_output("mass", Eigen::Vector3d::Zero(), RideAxis::vertical, ResponseQuantity::displacement)},
                      options);
  }
};

TEST(Ride, SdofUnderWhiteDisplacementMatchesTheClosedForm) {
  Sdof sdof;
  sdof.c = 2.0 * 0.1 * std::sqrt(sdof.k * sdof.m);  // ζ = 0.1
  const RideResult r = sdof.solve({});
  ASSERT_EQ(r.speeds.size(), 1u);
  const RideOutputAtSpeed& o = r.speeds[0].outputs[0];
  EXPECT_FALSE(o.unbounded);
  // The tails' approximations hold to ~1e-5 of the variance; the rest is the grid's trapezoid
  // error, which grid_error_estimate bounds (it estimates the error of half the grid).
  const double exact = std::sqrt(sdof.variance());
  EXPECT_NEAR(o.rms, exact, 1e-5 * exact + r.grid_error_estimate * exact);
  EXPECT_LT(std::abs(o.rms / exact - 1.0), 1e-3);
  EXPECT_LT(r.grid_error_estimate, 1e-2);
  // One mode, all of it: share 1, no cross term.
  ASSERT_EQ(o.modes.size(), 1u);
  EXPECT_NEAR(o.modes[0].share, 1.0, 1e-9);
  EXPECT_NEAR(o.cross_term_variance, 0.0, 1e-9 * o.rms * o.rms);
  EXPECT_EQ(r.friction_treatment, "none in the vehicle");
}

// docs/accuracy.md, "Ride: frequency grid": the RMS error against points per bandwidth on a
// lightly damped SDOF (ζ = 1 %), printed; the error must fall as the grid is refined and the
// estimate must bound it within a factor of a few.
TEST(Ride, GridRefinementConvergesOnALightlyDampedPeak) {
  Sdof sdof;
  sdof.c = 2.0 * 0.01 * std::sqrt(sdof.k * sdof.m);
  const double exact = std::sqrt(sdof.variance());
  double previous = std::numeric_limits<double>::infinity();
  std::cout << "points/bandwidth  grid points  relative RMS error  grid_error_estimate\n";
  for (int p : {1, 2, 4, 8, 16, 32}) {
    RideOptions options;
    options.points_per_bandwidth = p;
    const RideResult r = sdof.solve(options);
    const double error = std::abs(r.speeds[0].outputs[0].rms / exact - 1.0);
    std::cout << p << "  " << r.frequencies.size() << "  " << error << "  " << r.grid_error_estimate << "\n";
    // Halving the spacing at least halves the error until round-off of the tails (1e-5).
    EXPECT_TRUE(error < 0.6 * previous || error < 2e-5) << p;
    EXPECT_LT(error, 3.0 * r.grid_error_estimate + 2e-5) << p;
    previous = error;
  }
}

// Two-axle wagon: axles at x = ±a. At speed V the rear axle meets the track 2a/V later, so
// the bounce (at mid-wheelbase of a symmetric wagon) sees 1 + e^{−iω2a/V}, |…|² = 4cos²(πf·2a/V),
// and the pitch 1 − e^{−iω2a/V}, 4sin²(πf·2a/V) (two-axle digest §2.6–2.7, (174) and (176c): the
// factors |cos(π·2a1/L)| and |sin(π·2a1/L)|). Against the same wagon at a speed so high that the
// delay vanishes (both factors 4 and 0), the ratio of PSD/G at each grid frequency is cos².
TEST(Ride, TwoAxleWheelbaseFilterIsCosineAndSine) {
  const double a = 3.0, d = 2.0;
  const LinearSystem s =
      assemble(body_on_track(12000.0, 60000.0, {{a, 0.0}, {-a, 0.0}}, 5e5, 8e3), DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level = white(TrackIrregularity::vertical_level, 1e-6, 1e-12, 1e4);
  const std::vector<RideOutput> outputs = {
      point_output("centre", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::displacement),
      point_output("ahead", Eigen::Vector3d(d, 0, 0), RideAxis::vertical, ResponseQuantity::displacement),
      point_output("behind", Eigen::Vector3d(-d, 0, 0), RideAxis::vertical, ResponseQuantity::displacement)};
  RideOptions options;
  const double V = 20.0, fast = 1e9;
  options.speeds = {V, fast};
  const RideResult r = solve_ride(s, track, outputs, options);
  const RideAtSpeed& slow = r.speeds[0];
  const RideAtSpeed& quick = r.speeds[1];
  double largest_pitch_ratio = 0.0;
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double f = r.frequencies(k);
    const double phase = kPi * f * 2.0 * a / V;
    const double g_slow = slow.input_psd[0](k), g_fast = quick.input_psd[0](k);
    const double bounce = slow.outputs[0].psd(k) / g_slow / (quick.outputs[0].psd(k) / g_fast);
    // 1e-9: the two speeds share the receptances; only the phasors differ (round-off).
    EXPECT_NEAR(bounce, std::pow(std::cos(phase), 2), 1e-9) << f;
    // Pitch: psd(d) + psd(−d) − 2psd(0) = 2d²|θ|², zero at the fast speed; the ratio to the
    // bounce's sin²/cos² pattern is checked where both are away from zero.
    const double pitch = slow.outputs[1].psd(k) + slow.outputs[2].psd(k) - 2.0 * slow.outputs[0].psd(k);
    const double pitch_fast = quick.outputs[1].psd(k) + quick.outputs[2].psd(k) - 2.0 * quick.outputs[0].psd(k);
    EXPECT_NEAR(pitch_fast / g_fast, 0.0, 1e-9 * quick.outputs[0].psd(k) / g_fast);
    largest_pitch_ratio = std::max(largest_pitch_ratio, pitch / g_slow);
    if (std::abs(std::sin(phase)) < 1e-6) {
      EXPECT_NEAR(pitch / g_slow, 0.0, 1e-9 * slow.outputs[0].psd(k) / g_slow);
    }
  }
  EXPECT_GT(largest_pitch_ratio, 0.0);
}

// The pitch's sin² with its own closed form: for a symmetric wagon without gravity the pitch
// transmissibility per unit of (z_front − z_rear)/(2a) is (2ka² + iω2ca²)/(2ka² − Jω² + iω2ca²).
TEST(Ride, TwoAxlePitchMatchesItsClosedForm) {
  const double a = 3.0, d = 2.0, k = 5e5, c = 8e3, m = 12000.0, J = 60000.0, V = 20.0;
  const LinearSystem s = assemble(body_on_track(m, J, {{a, 0.0}, {-a, 0.0}}, k, c), DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level = white(TrackIrregularity::vertical_level, 1e-6, 1e-9, 1e4);
  RideOptions options;
  options.speeds = {V};
  const RideResult r = solve_ride(
      s, track,
      {point_output("centre", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::displacement),
       point_output("ahead", Eigen::Vector3d(d, 0, 0), RideAxis::vertical, ResponseQuantity::displacement),
       point_output("behind", Eigen::Vector3d(-d, 0, 0), RideAxis::vertical, ResponseQuantity::displacement)},
      options);
  const RideAtSpeed& at = r.speeds[0];
  for (Eigen::Index i = 0; i < r.frequencies.size(); i += 7) {
    const double f = r.frequencies(i), w = 2 * kPi * f;
    const std::complex<double> num(2 * k * a * a, w * 2 * c * a * a), den(2 * k * a * a - J * w * w, w * 2 * c * a * a);
    const std::complex<double> nb(2 * k, w * 2 * c), db(2 * k - m * w * w, w * 2 * c);
    const double G = at.input_psd[0](i);
    const double s2 = std::pow(std::sin(kPi * f * 2 * a / V), 2), c2 = std::pow(std::cos(kPi * f * 2 * a / V), 2);
    // θ = T_p·(z_f − z_r)/(2a): |z_f − z_r|² = 4 sin²·G.
    const double pitch = 2 * d * d * std::norm(num / den) * 4 * s2 * G / (4 * a * a);
    const double bounce = std::norm(nb / db) * c2 * G;
    const double got_pitch = at.outputs[1].psd(i) + at.outputs[2].psd(i) - 2.0 * at.outputs[0].psd(i);
    EXPECT_NEAR(at.outputs[0].psd(i), bounce, 1e-9 * (bounce + 1e-12 * G)) << f;
    EXPECT_NEAR(got_pitch, pitch, 1e-8 * (bounce + pitch) + 1e-15) << f;
  }
}

// A point's displacement is rigid-body kinematics of the DOFs: linear in x, so its PSD is a
// quadratic in x (third difference zero); its acceleration PSD is ω⁴ times the displacement's.
TEST(Ride, PointOutputIsRigidBodyCombination) {
  const LinearSystem s =
      assemble(body_on_track(12000.0, 60000.0, {{3.5, 0.0}, {-2.5, 0.0}}, 5e5, 8e3), DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  std::vector<RideOutput> outputs;
  for (double x : {-1.5, 0.0, 1.5, 3.0})
    outputs.push_back(point_output("x" + std::to_string(x), Eigen::Vector3d(x, 0, 0.7), RideAxis::vertical,
                                   ResponseQuantity::displacement));
  outputs.push_back(point_output("acc", Eigen::Vector3d(1.5, 0, 0.7), RideAxis::vertical, ResponseQuantity::acceleration));
  RideOptions options;
  options.speeds = {30.0};
  const RideResult r = solve_ride(s, track, outputs, options);
  const auto& o = r.speeds[0].outputs;
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double third = o[3].psd(k) - 3 * o[2].psd(k) + 3 * o[1].psd(k) - o[0].psd(k);
    EXPECT_NEAR(third, 0.0, 1e-9 * (o[3].psd(k) + o[0].psd(k)) + 1e-300);
    const double w4 = std::pow(2 * kPi * r.frequencies(k), 4);
    EXPECT_NEAR(o[4].psd(k), w4 * o[2].psd(k), 1e-9 * w4 * o[2].psd(k) + 1e-300);
  }
  // Every acceleration output has its indices; a displacement has none.
  EXPECT_TRUE(o[4].weighted_rms && o[4].sperling_wz && o[4].p95_estimate);
  EXPECT_GT(*o[4].p95_estimate, *o[4].weighted_rms);
  EXPECT_FALSE(o[0].weighted_rms.has_value());
  ASSERT_EQ(r.speeds[0].comfort.size(), 1u);  // one acceleration point
  EXPECT_EQ(r.speeds[0].comfort[0].missing_axes.size(), 2u);
  EXPECT_NEAR(r.speeds[0].comfort[0].nmv_estimate, 6.0 * *o[4].p95_estimate, 1e-12);
}

// Modal terms: the shares and the cross term add up to σ²; at the centre of a symmetric wagon
// the pitch does not move the point, so bounce carries it all and the cross term is nil.
TEST(Ride, ModalSharesAndCrossTermAddUpToTheVariance) {
  const LinearSystem s =
      assemble(body_on_track(12000.0, 60000.0, {{3.0, 0.0}, {-3.0, 0.0}}, 5e5, 8e3), DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level, OreLevel::high);
  RideOptions options;
  options.speeds = {25.0, 40.0};
  const RideResult r = solve_ride(
      s, track,
      {point_output("centre", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration),
       point_output("end", Eigen::Vector3d(6, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration)},
      options);
  ASSERT_EQ(r.modes.size(), 2u);
  for (const RideAtSpeed& at : r.speeds) {
    for (const RideOutputAtSpeed& o : at.outputs) {
      double sum = o.cross_term_variance;
      for (const ModalContribution& m : o.modes) sum += m.variance;
      EXPECT_NEAR(sum, o.rms * o.rms, 1e-12 * o.rms * o.rms);
    }
    const RideOutputAtSpeed& centre = at.outputs[0];
    ASSERT_GE(centre.modes.size(), 1u);
    EXPECT_EQ(r.modes[centre.modes[0].mode].name.find("bounce") != std::string::npos, true)
        << r.modes[centre.modes[0].mode].name;
    EXPECT_NEAR(centre.modes[0].share, 1.0, 1e-9);
    EXPECT_NEAR(centre.cross_term_variance, 0.0, 1e-9 * centre.rms * centre.rms);
    // At the end both modes move the point: two shares, and a cross term that is not zero.
    EXPECT_EQ(at.outputs[1].modes.size(), 2u);
    EXPECT_GT(std::abs(at.outputs[1].cross_term_variance), 1e-6 * at.outputs[1].rms * at.outputs[1].rms);
  }
}

// Dampers only at the centre: the pitch is undamped. The track drives it (the axles' inputs
// differ), so a point it moves is unbounded — an answer, no number — while the centre, which
// it does not move, has its finite RMS.
TEST(Ride, UndampedExcitedModeIsUnboundedNotANumber) {
  Vehicle v = body_on_track(12000.0, 60000.0, {{3.0, 0.0}, {-3.0, 0.0}}, 5e5, 0.0);
  Element damper;
  damper.name = "centre damper";
  damper.upper = "body";
  damper.vertical_damping = 8e3;
  v.elements.push_back(damper);
  const LinearSystem s = assemble(v, DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  RideOptions options;
  options.speeds = {30.0};
  const RideResult r = solve_ride(
      s, track,
      {point_output("centre", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration),
       point_output("end", Eigen::Vector3d(6, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration)},
      options);
  const RideOutputAtSpeed& centre = r.speeds[0].outputs[0];
  const RideOutputAtSpeed& end = r.speeds[0].outputs[1];
  EXPECT_FALSE(centre.unbounded);
  EXPECT_TRUE(std::isfinite(centre.rms) && centre.rms > 0.0);
  EXPECT_TRUE(end.unbounded);
  EXPECT_EQ(end.rms, 0.0);
  EXPECT_FALSE(end.weighted_rms || end.p95_estimate || end.sperling_wz);
  EXPECT_EQ(end.psd.size(), 0);
  EXPECT_TRUE(end.modes.empty());
  bool named = false;
  for (const std::string& note : r.notes) named = named || note.find("undamped mode") != std::string::npos;
  EXPECT_TRUE(named);
}

// Only the end, which the undamped pitch moves: no output has a bounded RMS, so there is nothing
// for the grid error estimate to measure. The summary has no such check rather than one reading 0
// (the reports then say "no grid error estimate"; the user audit of 2026-11-27 saw "0 %").
TEST(Ride, AnAllUnboundedRideHasNoGridErrorCheck) {
  Vehicle v = body_on_track(12000.0, 60000.0, {{3.0, 0.0}, {-3.0, 0.0}}, 5e5, 0.0);
  Element damper;
  damper.name = "centre damper";
  damper.upper = "body";
  damper.vertical_damping = 8e3;
  v.elements.push_back(damper);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  RideOptions options;
  options.speeds = {30.0};
  const auto grid_check = [](const RideResult& r) {
    return std::any_of(r.summary.checks.begin(), r.summary.checks.end(),
                       [](const Check& c) { return c.name.rfind("grid error estimate", 0) == 0; });
  };
  const LinearSystem s = assemble(v, DofSet::vertical);
  const RideOutput end = point_output("end", Eigen::Vector3d(6, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration);
  const RideResult unbounded = solve_ride(s, track, {end}, options);
  ASSERT_TRUE(unbounded.speeds[0].outputs[0].unbounded);
  EXPECT_FALSE(grid_check(unbounded));
  EXPECT_EQ(unbounded.grid_error_estimate, 0.0);
  // With the centre's bounded RMS beside it the estimate is made and checked.
  const RideResult mixed = solve_ride(
      s, track, {point_output("centre", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration), end},
      options);
  EXPECT_TRUE(grid_check(mixed));
  EXPECT_GT(mixed.grid_error_estimate, 0.0);
}

// Cross-level Δz = z_left − z_right rolls the rails by θ = Δz/(2b) about the rail top, r0 below
// the axle plane: an input on the left rail (y > 0) rises by θy, and one at height z moves
// sideways by −θ(z + r0). b: the option, else the wheelsets' l0, else 0.75 m; r0: the option,
// else the wheelsets' rolling radius, else 0.
TEST(Ride, CrossLevelSignAndScaling) {
  Vehicle v = body_on_track(12000.0, 60000.0, {{3.0, 1.0}, {3.0, -1.0}, {-3.0, 1.0}, {-3.0, -1.0}}, 5e5, 8e3);
  v.elements[0].point.z() = 0.4;
  const LinearSystem s = assemble(v, DofSet::all);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::cross_level);
  const std::vector<ride::Component> standard = ride::track_components(s, track, 0.0, 0.0);
  ASSERT_EQ(standard.size(), 1u);
  EXPECT_NEAR(standard[0].displacement[0].z(), 1.0 / 1.5, 1e-15);   // left rail up by Δz·y/(2b)
  EXPECT_NEAR(standard[0].displacement[1].z(), -1.0 / 1.5, 1e-15);  // right rail down
  EXPECT_NEAR(standard[0].displacement[0].y(), -0.4 / 1.5, 1e-15);  // −θz: no wheel radius known
  const std::vector<ride::Component> given = ride::track_components(s, track, 0.8, 0.46);
  EXPECT_NEAR(given[0].displacement[0].z(), 1.0 / 1.6, 1e-15);
  EXPECT_NEAR(given[0].displacement[0].y(), -(0.4 + 0.46) / 1.6, 1e-15);  // about the rail top
}

// One convention in both domains: the time domain's track under each wheel moves it by the
// frequency domain's cross-level direction (the same function, so equal to the last bit).
TEST(Ride, CrossLevelIsTheSameInTimeAndFrequency) {
  Vehicle v = body_on_track(12000.0, 60000.0, {{3.0, 0.8}, {3.0, -0.8}, {-3.0, 0.8}, {-3.0, -0.8}}, 5e5, 8e3);
  for (Element& e : v.elements) e.point.z() = 0.3;
  const LinearSystem s = assemble(v, DofSet::all);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::cross_level);
  const std::vector<ride::Component> c = ride::track_components(s, track, 0.0, 0.5);
  TrackGeometry g;
  g.step = 1.0;
  g.cross_level = Eigen::VectorXd::Constant(16, 0.01);
  const ride::TrackUnderWheels wheels(s, g, ride::cross_level_directions(s, 0.0, 0.5));
  for (int i = 0; i < wheels.inputs(); ++i) {
    const Eigen::Vector3d u = wheels.displacement_of(i, 8.0);
    EXPECT_EQ(u, Eigen::Vector3d(0.01 * c[0].displacement[i])) << i;
    EXPECT_NEAR(u.y(), -0.01 * (0.3 + 0.5) / 1.5, 1e-16) << i;  // −θ(z + r0), θ = 0.01/1.5
  }
}

// The direct track term of a track spring's force, F = −(k + iωc)(z − u): D = (k + iωc) per unit
// u, so on white G0 over [f1, f2] its variance is G0[k²(f2 − f1) + (2πc)²(f2³ − f1³)/3]. One
// spring under a mass (no delays). The trapezoid rule on the log grid (about 2.3 % steps) is
// within 1e-4 of a quadratic's integral; 1e-3 allows it. The shares of the mode's term and of the
// direct term, 0.5484 and 0.4558 of σ² (their cross term −0.4 %: they cancel at low frequency),
// come from an independent numpy trapezoid of the closed-form terms on 2·10⁵ points; 2e-3 allows
// the grid error.
TEST(Ride, DirectTrackTermOfASpringForceIsReportedApart) {
  constexpr double m = 1000.0, k = 4e5, c = 2e3, V = 20.0, S0 = 1e-6;
  const Vehicle v = body_on_track(m, 1.0, {{0.0, 0.0}}, k, c, {Motion::pitch, Motion::roll});
  const LinearSystem s = assemble(v, DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level = white(TrackIrregularity::vertical_level, S0, 0.1, 10.0);
  RideOutput force;
  force.name = "spring force";
  force.kind = RideOutput::Kind::element_force;
  force.element = "spring1";
  RideOptions options;
  options.speeds = {V};
  options.max_frequency = 40.0;
  const RideResult r = solve_ride(s, track, {force}, options);
  const RideOutputAtSpeed& out = r.speeds[0].outputs[0];
  const double f1 = V * 0.1 / (2 * M_PI), f2 = V * 10.0 / (2 * M_PI), G0 = 2 * M_PI * S0 / V;
  const double expected = G0 * (k * k * (f2 - f1) + std::pow(2 * M_PI * c, 2) * (f2 * f2 * f2 - f1 * f1 * f1) / 3.0);
  EXPECT_NEAR(out.direct_variance / expected, 1.0, 1e-3);
  ASSERT_EQ(out.modes.size(), 1u);
  EXPECT_NEAR(out.modes[0].share, 0.5484, 2e-3);
  EXPECT_NEAR(out.direct_variance / (out.rms * out.rms), 0.4558, 2e-3);
}

// What would be a silent zero is an error naming what is wrong: a component no DOF feels, an
// output no DOF moves, a band wholly outside the grid. A refused component is an
// IrregularityComponentError that says which (railmodal ride places it at that component's
// table); an output's error is a plain std::invalid_argument, even when its name names a component.
TEST(Ride, RefusesWhatWouldBeASilentZero) {
  const Vehicle v = body_on_track(12000.0, 60000.0, {{3.0, 0.8}, {3.0, -0.8}, {-3.0, 0.8}, {-3.0, -0.8}}, 5e5, 8e3);
  const LinearSystem vertical = assemble(v, DofSet::vertical);
  RideOptions options;
  options.speeds = {30.0};
  const RideOutput floor =
      point_output("floor", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::acceleration);
  auto message = [&](const TrackIrregularitySpectra& t, const std::vector<RideOutput>& o, const RideOptions& opt) {
    // The component a refusal names, then the message: "alignment: ride: ..."; "-: " for none.
    try {
      solve_ride(vertical, t, o, opt);
    } catch (const IrregularityComponentError& e) {
      return std::string(to_string(e.component())) + ": " + e.what();
    } catch (const std::invalid_argument& e) {
      return "-: " + std::string(e.what());
    }
    return std::string("no error");
  };
  TrackIrregularitySpectra alignment;
  alignment.alignment = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {0.06, 2.0});
  const std::string unfelt = message(alignment, {floor}, options);
  EXPECT_EQ(unfelt.rfind("alignment: ride: the alignment component", 0), 0u) << unfelt;
  TrackIrregularitySpectra level;
  level.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.06, 2.0});
  const RideOutput sideways =
      point_output("alignment gauge", Eigen::Vector3d(0, 0, 0), RideAxis::lateral, ResponseQuantity::acceleration);
  const std::string unmoved = message(level, {floor, sideways}, options);
  EXPECT_EQ(unmoved.rfind("-: ride: output 'alignment gauge': no degree of freedom", 0), 0u) << unmoved;
  RideOptions high = options;
  high.min_frequency = 20.0;  // 30 m/s × 2 rad/m / 2π = 9.5 Hz, the band's top
  const std::string outside = message(level, {floor}, high);
  EXPECT_EQ(outside.rfind("vertical_level: ride: at ", 0), 0u) << outside;
  EXPECT_NE(outside.find("wholly outside the grid"), std::string::npos) << outside;
  // partly outside: an answer over the grid's part, with a note
  RideOptions partly = options;
  partly.min_frequency = 1.0;  // the band starts at 30 × 0.06 / 2π = 0.29 Hz
  const RideResult r = solve_ride(vertical, level, {floor}, partly);
  bool noted = false;
  for (const std::string& n : r.notes) noted = noted || n.find("beyond the grid") != std::string::npos;
  EXPECT_TRUE(noted);
  ASSERT_EQ(r.input_rms.size(), 1u);
  EXPECT_DOUBLE_EQ(r.input_rms[0], level.vertical_level->rms());
}

// Quasi-static: on very stiff springs the body follows the rails' roll, so a point 1 m to the
// left rises by Δz/(2b): its PSD over G_Δz tends to 1/(2b)² at low frequency.
TEST(Ride, CrossLevelRollsAStiffBodyByHalfTheHeightDifferenceOverB) {
  const LinearSystem s = assemble(
      body_on_track(12000.0, 60000.0, {{3.0, 1.0}, {3.0, -1.0}, {-3.0, 1.0}, {-3.0, -1.0}}, 5e9, 8e4), DofSet::all);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::cross_level);
  RideOptions options;
  options.speeds = {20.0};
  options.max_frequency = 5.0;
  const RideResult r = solve_ride(
      s, track, {point_output("left", Eigen::Vector3d(0, 1, 0), RideAxis::vertical, ResponseQuantity::displacement)},
      options);
  const RideAtSpeed& at = r.speeds[0];
  // At ~0.7 Hz, far below the 90-Hz roll of the stiff body, which takes the mean of the front and
  // rear axles' roll: the wheelbase filter cos²(πf·2a/V) times (y/(2b))².
  const Eigen::Index k = r.frequencies.size() / 2;
  ASSERT_GT(at.input_psd[0](k), 0.0);
  const double filter = std::pow(std::cos(kPi * r.frequencies(k) * 6.0 / 20.0), 2);
  EXPECT_NEAR(at.outputs[0].psd(k) / at.input_psd[0](k), filter / (1.5 * 1.5), 1e-3);
}

// Alignment on a vehicle without wheelsets enters through the track elements' lateral springs:
// on stiff springs the body follows the track sideways, the mean of the two axles' alignment, so
// the lateral PSD over G tends to the wheelbase filter cos²(πf·2a/V) at low frequency.
TEST(Ride, AlignmentMovesAStiffBodySideways) {
  const LinearSystem s = assemble(
      body_on_track(12000.0, 60000.0, {{3.0, 1.0}, {3.0, -1.0}, {-3.0, 1.0}, {-3.0, -1.0}}, 5e9, 8e4), DofSet::all);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::alignment);
  RideOptions options;
  options.speeds = {20.0};
  options.max_frequency = 5.0;
  const RideResult r = solve_ride(
      s, track, {point_output("side", Eigen::Vector3d(0, 0, 0), RideAxis::lateral, ResponseQuantity::displacement)},
      options);
  const Eigen::Index k = r.frequencies.size() / 2;  // ~0.7 Hz, far below the stiff body's lateral modes
  ASSERT_GT(r.speeds[0].input_psd[0](k), 0.0);
  const double filter = std::pow(std::cos(kPi * r.frequencies(k) * 6.0 / 20.0), 2);
  EXPECT_NEAR(r.speeds[0].outputs[0].psd(k) / r.speeds[0].input_psd[0](k), filter, 1e-3);
}

// The weighted RMS is ∫|W|²S df: against the output's own PSD weighted by en12299_wb and
// integrated by the trapezoid over the intervals inside the band (both ends nonzero), and
// Sperling's Wz from ∫B²S; the P95 estimate lies above the weighted RMS it rests on. Two
// threads give the same numbers as one.
TEST(Ride, WeightedIndicesAreIntegralsOfTheWeightedPsd) {
  const LinearSystem s =
      assemble(body_on_track(12000.0, 60000.0, {{3.5, 0.0}, {-2.5, 0.0}}, 5e5, 8e3), DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  RideOptions options;
  options.speeds = {30.0, 45.0};
  const std::vector<RideOutput> outputs = {
      point_output("acc", Eigen::Vector3d(1.5, 0, 0.7), RideAxis::vertical, ResponseQuantity::acceleration)};
  const RideResult r = solve_ride(s, track, outputs, options);
  const FrequencyWeighting wb = en12299_wb();
  for (const RideAtSpeed& at : r.speeds) {
    const Eigen::VectorXd& S = at.outputs[0].psd;
    double weighted = 0.0, sperling = 0.0, plain = 0.0;
    for (Eigen::Index k = 0; k + 1 < S.size(); ++k) {
      if (!(at.input_psd[0](k) > 0.0 && at.input_psd[0](k + 1) > 0.0)) continue;
      const double h = r.frequencies(k + 1) - r.frequencies(k), f0 = r.frequencies(k), f1 = r.frequencies(k + 1);
      plain += 0.5 * h * (S(k) + S(k + 1));
      weighted += 0.5 * h * (std::norm(wb.response(f0)) * S(k) + std::norm(wb.response(f1)) * S(k + 1));
      sperling += 0.5 * h *
                  (std::pow(sperling_weighting(f0, SperlingDirection::vertical), 2) * S(k) +
                   std::pow(sperling_weighting(f1, SperlingDirection::vertical), 2) * S(k + 1));
    }
    const RideOutputAtSpeed& o = at.outputs[0];
    EXPECT_NEAR(o.rms, std::sqrt(plain), 1e-12 * o.rms);
    EXPECT_NEAR(*o.weighted_rms, std::sqrt(weighted), 1e-12 * o.rms);
    EXPECT_NEAR(*o.sperling_wz, sperling_wz_from_weighted_rms(std::sqrt(sperling)), 1e-12);
    EXPECT_GT(*o.p95_estimate, *o.weighted_rms);
    EXPECT_LT(*o.p95_estimate, 2.0 * *o.weighted_rms);  // ν of tens: the 95th percentile is tens of % above
  }
  options.threads = 2;
  const RideResult shared = solve_ride(s, track, outputs, options);
  for (size_t v = 0; v < r.speeds.size(); ++v) EXPECT_EQ(shared.speeds[v].outputs[0].rms, r.speeds[v].outputs[0].rms);
}

// Modal truncation (docs/accuracy.md, "Ride: modal truncation"): the error against the direct
// solve, printed, never grows as modes are added, and with every mode the basis is complete
// (the same receptances to round-off).
TEST(Ride, ModalTruncationConvergesToTheDirectSolve) {
  const LinearSystem s = assemble(load_vehicle(test::data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level, OreLevel::low, 6.0);
  RideOptions options;
  options.speeds = {150 / 3.6};
  options.keep_spectra = false;
  const std::vector<RideOutput> outputs = default_ride_outputs(s);
  const RideResult direct = solve_ride(s, track, outputs, options);
  double previous = std::numeric_limits<double>::infinity();
  std::cout << "modes  largest relative RMS error\n";
  for (int n = 1; n <= s.size(); ++n) {
    options.modes = n;
    const RideResult r = solve_ride(s, track, outputs, options);
    double error = 0.0;
    for (size_t o = 0; o < outputs.size(); ++o)
      error = std::max(error, std::abs(r.speeds[0].outputs[o].rms / direct.speeds[0].outputs[o].rms - 1.0));
    std::cout << n << "  " << error << "\n";
    EXPECT_LE(error, previous * (1.0 + 1e-9) + 1e-12) << n;
    previous = error;
  }
  EXPECT_LT(previous, 1e-10);  // every mode kept
}

TEST(Ride, ChiSquareQuantilesMatchTheTables) {
  // Abramowitz & Stegun Table 26.8 / NIST handbook 1.3.6.7.4: χ²_{0.95} for ν = 1, 2, 10, 100.
  EXPECT_NEAR(ride::chi_square_quantile(0.95, 1.0), 3.841459, 1e-6);
  EXPECT_NEAR(ride::chi_square_quantile(0.95, 2.0), 5.991465, 1e-6);
  EXPECT_NEAR(ride::chi_square_quantile(0.95, 10.0), 18.307038, 1e-6);
  EXPECT_NEAR(ride::chi_square_quantile(0.95, 100.0), 124.342113, 1e-5);
  // χ²₂ is exponential: P(x) = 1 − e^{−x/2}.
  EXPECT_NEAR(ride::regularized_gamma_p(1.0, 1.5), 1.0 - std::exp(-1.5), 1e-14);
  // A broad band (ν → ∞): the windows' RMS all equal σ.
  EXPECT_NEAR(ride::rms_quantile(4.0, 1e-9, 5.0, 0.95), 2.0, 1e-4);
  // A band of width B flat at S: ν = 2TB; T = 5 s, B = 1 Hz → ν = 10.
  EXPECT_NEAR(ride::rms_quantile(1.0, 1.0, 5.0, 0.95), std::sqrt(18.307038 / 10.0), 1e-6);
}

// The fixed point c = F√(2/π)/σ(c) for σ(c) = A/√c (a white-driven damper's velocity RMS):
// √c = F√(2/π)/A.
TEST(Ride, FrictionIterationConvergesToTheFixedPoint) {
  const LinearSystem s = assemble(body_on_track(1000.0, 1.0, {{0.0, 0.0}}, 1e6, 0.0, {Motion::pitch}), DofSet::vertical);
  const double F = 500.0, A = 2.0;
  const std::vector<ride::FrictionElement> elements = {{0, F}};
  const ride::FrictionLinearisation l = ride::linearise_friction(
      s, elements, 1e-10, 200, [&](const std::vector<double>& c) { return std::vector<double>{A / std::sqrt(c[0])}; });
  EXPECT_TRUE(l.converged);
  const double expected = std::pow(F * std::sqrt(2.0 / kPi) / A, 2);
  EXPECT_NEAR(l.damping[0], expected, 1e-8 * expected);
  EXPECT_LT(l.passes, 60);  // linear convergence at rate 1/2
}

Vehicle leaf_wagon(double friction) {
  Vehicle v = body_on_track(10000.0, 80000.0, {{3.0, 0.0}, {-3.0, 0.0}}, 6e5, 2e3);
  v.gravity = 9.81;
  for (Element& e : v.elements) e.vertical_stages[0].relative_friction = friction;
  return v;
}

TEST(Ride, LeafFrictionIsLinearisedStatisticallyAndVanishesWithPhi) {
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level, OreLevel::high);
  RideOptions options;
  options.speeds = {20.0, 30.0};
  const std::vector<RideOutput> outputs = {
      point_output("centre", Eigen::Vector3d(0, 0, 0), RideAxis::vertical, ResponseQuantity::displacement)};
  const RideResult viscous = solve_ride(assemble(leaf_wagon(0.0), DofSet::vertical), track, outputs, options);
  const RideResult rough = solve_ride(assemble(leaf_wagon(0.05), DofSet::vertical), track, outputs, options);
  EXPECT_EQ(viscous.friction_treatment, "none in the vehicle");
  EXPECT_NE(rough.friction_treatment.find("statistical linearisation"), std::string::npos);
  EXPECT_NE(rough.friction_treatment.find("converged"), std::string::npos);
  EXPECT_EQ(rough.friction_treatment.find("NOT"), std::string::npos);
  EXPECT_TRUE(rough.summary.passed());
  for (size_t v = 0; v < options.speeds.size(); ++v) {
    // Friction adds damping: the resonance and so the displacement RMS fall.
    EXPECT_LT(rough.speeds[v].outputs[0].rms, viscous.speeds[v].outputs[0].rms);
    EXPECT_GT(rough.speeds[v].outputs[0].rms, 0.0);
  }
}

TEST(Ride, BadOptionsAndOutputsThrowNamingThem) {
  const LinearSystem s =
      assemble(body_on_track(12000.0, 60000.0, {{3.0, 0.0}, {-3.0, 0.0}}, 5e5, 8e3), DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  const RideOutput good = point_output("centre", Eigen::Vector3d::Zero(), RideAxis::vertical, ResponseQuantity::acceleration);
  auto message = [&](const TrackIrregularitySpectra& t, const std::vector<RideOutput>& o, const RideOptions& opt) {
    try {
      solve_ride(s, t, o, opt);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  RideOptions ok;
  ok.speeds = {20.0};
  RideOptions bad = ok;
  bad.speeds = {};
  EXPECT_NE(message(track, {good}, bad).find("speeds"), std::string::npos);
  bad = ok;
  bad.max_frequency = 0.05;
  EXPECT_NE(message(track, {good}, bad).find("max_frequency"), std::string::npos);
  bad = ok;
  bad.points_per_bandwidth = 0;
  EXPECT_NE(message(track, {good}, bad).find("points_per_bandwidth"), std::string::npos);
  RideOutput nobody = good;
  nobody.body = "tender";
  EXPECT_NE(message(track, {nobody}, ok).find("no body 'tender'"), std::string::npos);
  RideOutput noelement = good;
  noelement.kind = RideOutput::Kind::element_force;
  noelement.element = "spring9";
  EXPECT_NE(message(track, {noelement}, ok).find("no element 'spring9'"), std::string::npos);
  RideOutput nowheelset = good;
  nowheelset.kind = RideOutput::Kind::wheel_rail_force;
  nowheelset.element = "body";
  EXPECT_NE(message(track, {nowheelset}, ok).find("no wheelset 'body'"), std::string::npos);
  EXPECT_NE(message(track, {good, good}, ok).find("repeated"), std::string::npos);
  EXPECT_NE(message(TrackIrregularitySpectra{}, {good}, ok).find("no irregularity"), std::string::npos);
  TrackIrregularitySpectra swapped;
  swapped.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {0.06, 2.0});
  EXPECT_NE(message(swapped, {good}, ok).find("vertical_level slot holds a alignment"), std::string::npos);
}

// Alignment on wheelsets acts through the creep contact (tests/ride/ride_lateral_test.cpp checks
// its receptance); the coach at 30 m/s, far below its ~350 km/h critical speed, answers bounded.
TEST(Ride, AlignmentOnWheelsetsActsThroughTheCreepContact) {
  const LinearSystem s =
      assemble(load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::alignment);
  RideOptions options;
  options.speeds = {30.0};
  const RideResult r = solve_ride(s, track, default_ride_outputs(s), options);
  for (const RideOutputAtSpeed& o : r.speeds[0].outputs) {
    EXPECT_FALSE(o.unbounded);
    EXPECT_TRUE(std::isfinite(o.rms));
  }
  EXPECT_NE(r.summary.method.find("creep contact"), std::string::npos) << r.summary.method;
}

// Element outputs: a track spring's deflection is body minus track, its force −(k + iωc) times
// it; on a body on one spring the force is also m·ẍ (Newton: the spring alone holds the mass).
TEST(Ride, ElementForceOfTheOnlySpringIsMassTimesAcceleration) {
  const double m = 1000.0;
  const LinearSystem s = assemble(body_on_track(m, 1.0, {{0.0, 0.0}}, 1e6, 3e3, {Motion::pitch}), DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  RideOutput force;
  force.name = "spring force";
  force.kind = RideOutput::Kind::element_force;
  force.element = "spring1";
  RideOptions options;
  options.speeds = {30.0};
  const RideResult r = solve_ride(
      s, track, {force, point_output("acc", Eigen::Vector3d::Zero(), RideAxis::vertical, ResponseQuantity::acceleration)},
      options);
  const auto& o = r.speeds[0].outputs;
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k)
    EXPECT_NEAR(o[0].psd(k), m * m * o[1].psd(k), 1e-9 * m * m * o[1].psd(k) + 1e-300);
}

// The wheel–rail force of a wheelset carrying a mass on a spring: R = F + m_w·ü_rail with F = m·ẍ
// (the spring alone holds the mass), so R/u = −ω²(m·T + m_w), T = (k + iωc)/(k − mω² + iωc).
TEST(Ride, WheelRailForceIsSpringForcePlusTheWheelsetsInertia) {
  const double m = 2000.0, m_w = 1500.0, k = 1e6, c = 5e3;
  Vehicle v;
  v.name = "mass on a wheelset";
  Body w;
  w.name = "wheelset";
  w.mass = m_w;
  w.inertia = Eigen::Vector3d(700, 100, 800);
  w.held = {Motion::bounce, Motion::roll, Motion::pitch};
  Body b;
  b.name = "body";
  b.mass = m;
  b.inertia = Eigen::Vector3d(1, 1, 1);
  b.held = {Motion::pitch};
  v.bodies = {w, b};
  Wheelset ws;
  ws.body = "wheelset";
  ws.spin_inertia = 100;
  ws.contact.rolling_radius = 0.46;
  ws.contact.contact_half_spacing = 0.75;
  ws.contact.conicity = 0.15;
  ws.contact.creep = CreepCoefficients{};
  ws.contact.creep->f11 = 1e7;
  ws.contact.creep->f22 = 9e6;
  v.wheelsets = {ws};
  Element e;
  e.name = "spring";
  e.lower = "wheelset";
  e.upper = "body";
  e.vertical_stages = {coil(k)};
  e.vertical_damping = c;
  v.elements = {e};
  const LinearSystem s = assemble(v, DofSet::vertical);
  TrackIrregularitySpectra track = one_irregularity(TrackIrregularity::vertical_level);
  RideOutput force;
  force.name = "wheel-rail";
  force.kind = RideOutput::Kind::wheel_rail_force;
  force.element = "wheelset";
  RideOptions options;
  options.speeds = {30.0};
  const RideResult r = solve_ride(s, track, {force}, options);
  const RideAtSpeed& at = r.speeds[0];
  for (Eigen::Index i = 0; i < r.frequencies.size(); ++i) {
    const double w2 = std::pow(2 * kPi * r.frequencies(i), 2);
    const std::complex<double> T = std::complex<double>(k, std::sqrt(w2) * c) / std::complex<double>(k - m * w2, std::sqrt(w2) * c);
    const double expected = std::norm(-w2 * (m * T + m_w)) * at.input_psd[0](i);
    EXPECT_NEAR(at.outputs[0].psd(i), expected, 1e-9 * expected + 1e-300) << r.frequencies(i);
  }
}

TEST(Ride, DefaultOutputsOfTheCoachAreItsFloorPoints) {
  const LinearSystem s =
      assemble(load_vehicle(test::data_file("manchester_benchmark_coach.toml")), DofSet::all);
  const std::vector<RideOutput> outputs = default_ride_outputs(s);
  // Over both bogies, mid-car, 1 m from each end; vertical and lateral.
  ASSERT_EQ(outputs.size(), 10u);
  EXPECT_EQ(outputs[0].name, "floor over front bogie, vertical");
  EXPECT_EQ(outputs[1].name, "floor over front bogie, lateral");
  EXPECT_NEAR(outputs[0].point.x(), 9.5, 1e-9);
  for (const RideOutput& o : outputs) {
    EXPECT_EQ(o.body, "body");
    EXPECT_EQ(o.quantity, ResponseQuantity::acceleration);
  }
  const LinearSystem vertical =
      assemble(load_vehicle(test::data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
  EXPECT_EQ(default_ride_outputs(vertical).size(), 5u);  // no lateral motion, no lateral outputs
}

template <class Enum>
void round_trip(std::initializer_list<Enum> values, std::optional<Enum> (*from)(const std::string&)) {
  for (Enum v : values) {
    ASSERT_TRUE(from(to_string(v)).has_value()) << to_string(v);
    EXPECT_EQ(*from(to_string(v)), v);
  }
  EXPECT_FALSE(from("no-such-word").has_value());
}

TEST(EnumNames, RideAxis) {
  round_trip({RideAxis::longitudinal, RideAxis::lateral, RideAxis::vertical}, ride_axis_from_string);
}

TEST(EnumNames, RideOutputKind) {
  round_trip({RideOutput::Kind::point, RideOutput::Kind::element_deflection, RideOutput::Kind::element_force,
              RideOutput::Kind::wheel_rail_force},
             ride_output_kind_from_string);
}

}  // namespace
}  // namespace railmodal
