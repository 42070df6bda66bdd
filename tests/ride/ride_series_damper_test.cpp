// The time-domain ride with series dampers (each dashpot's stroke a state of the march): the
// steady state over a sine against the closed form with the Maxwell stiffness, the FFT checks of
// a realisation (exact bins, RMS against solve_ride), and the coach with yaw dampers, whose
// state space has the frequency domain's transfer function at every grid frequency.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "railmodal/ride.hpp"
#include "railmodal/ride_simulation.hpp"
#include "ride/ride_state_space.hpp"
#include "ride/ride_test_systems.hpp"
#include "series_damper_coach.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

using Complex = std::complex<double>;

/// A body of mass `body_mass` on a bogie of mass `bogie_mass`, bounce only: the body on a spring
/// `k2` and on a series damper (dashpot c with spring k in series, element "body damper"), the
/// bogie on one spring k1 and damper c1 per wheel at x = each of `wheel_x` (the track inputs).
struct BodyOnBogie {
  double body_mass = 30000.0, bogie_mass = 3000.0;
  double k2 = 1.2e6;            ///< N/m: the body's spring to the bogie
  double c = 6e4, k = 3e6;      ///< the series damper: N·s/m and N/m (k/c = 50 /s)
  double k1 = 2.4e6, c1 = 2e4;  ///< per wheel
  std::vector<double> wheel_x{9.35, 6.85, -6.85, -9.35};

  LinearSystem system() const {
    LinearSystem s;
    for (const char* name : {"body", "bogie"}) {
      Body b;
      b.name = name;
      b.mass = std::string(name) == "body" ? body_mass : bogie_mass;
      b.inertia = {1.0, 1.0, 1.0};
      s.vehicle.bodies.push_back(b);
    }
    s.dofs = {{"body.bounce", 0, Motion::bounce}, {"bogie.bounce", 1, Motion::bounce}};
    const double n = static_cast<double>(wheel_x.size());
    s.mass = Eigen::Vector2d(body_mass, bogie_mass).asDiagonal();
    s.stiffness = (Eigen::Matrix2d() << k2, -k2, -k2, k2 + n * k1).finished();
    s.damping = (Eigen::Matrix2d() << 0.0, 0.0, 0.0, n * c1).finished();
    s.gravity_stiffness = Eigen::MatrixXd::Zero(2, 2);
    for (size_t i = 0; i < wheel_x.size(); ++i) {
      Element wheel;
      wheel.name = "wheel " + std::to_string(i + 1);
      s.vehicle.elements.push_back(wheel);
      TrackInput input;
      input.element = static_cast<int>(i);
      input.point = {wheel_x[i], 0.0, 0.0};
      input.load_per_displacement = Eigen::MatrixXd::Zero(2, 3);
      input.load_per_velocity = Eigen::MatrixXd::Zero(2, 3);
      input.load_per_displacement(1, 2) = k1;
      input.load_per_velocity(1, 2) = c1;
      s.track_inputs.push_back(input);
    }
    Element damper;
    damper.name = "body damper";
    s.vehicle.elements.push_back(damper);
    s.series_dampers.push_back({static_cast<int>(wheel_x.size()), Motion::bounce,
                                (Eigen::RowVectorXd(2) << 1.0, -1.0).finished(), c, k});
    s.element_loads.assign(s.vehicle.elements.size(), 0.0);
    return s;
  }

  /// The body's displacement per unit track level at f Hz and speed V, the series damper as the
  /// Maxwell stiffness k_s = iωck/(k + iωc) beside k2: with D the 2 × 2 dynamic stiffness and Q
  /// the bogie's load Σ_i (k1 + iωc1) e^{−iω lag_i/V}, X = D⁻¹(0, Q).
  std::complex<double> body_response(double f, double speed) const {
    using C = std::complex<double>;
    const double w = 2.0 * 3.14159265358979323846 * f;
    const C ks = C(0.0, w * c) * k / C(k, w * c);
    double lead = wheel_x.front();
    for (double x : wheel_x) lead = std::max(lead, x);
    C load = 0.0;
    for (double x : wheel_x) load += C(k1, w * c1) * std::polar(1.0, -w * (lead - x) / speed);
    const double n = static_cast<double>(wheel_x.size());
    const C upper = k2 + ks;
    const C d11 = upper - w * w * body_mass, d22 = upper + n * C(k1, w * c1) - w * w * bogie_mass;
    return upper * load / (d11 * d22 - upper * upper);  // (D⁻¹)₁₂ = −D₁₂/det, D₁₂ = −upper
  }
};

// The series damper matters here: at 1 Hz ωc/k = 0.13, so the Maxwell stiffness differs from the
// plain damper's iωc by 13 % (and the march would be 13 % off had it left the spring out).
TEST(RideSeriesDamper, SteadyStateOverASineIsTheMaxwellResponse) {
  const BodyOnBogie vehicle;
  const LinearSystem system = vehicle.system();
  ASSERT_EQ(system.series_dampers.size(), 1u);
  constexpr double kAmplitude = 0.002, kSpeed = 25.0;
  const TrackGeometry track = sine_track(kAmplitude, 4, 1600, 1.0 / 16);  // λ = 25 m: 1 Hz at 25 m/s
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = 1.0 / 16 / kSpeed;
  const RideSimulationResult r = simulate_ride(system, track, {body_point(ResponseQuantity::displacement)}, o);
  ASSERT_EQ(r.histories.size(), 1u);
  EXPECT_TRUE(r.summary.passed());
  std::complex<double> sum = 0.0;  // the 1 Hz line of one period (4 cycles: bin 4), as an amplitude
  const Eigen::VectorXd& y = r.histories[0].values;
  for (Eigen::Index n = 0; n < y.size(); ++n) sum += y(n) * std::polar(1.0, -2 * kPi * 4.0 * n / y.size());
  const double x = kPi / 400;  // the interpolated cosine's gain sinc²(1/400), 400 samples a period
  const double expected = std::abs(vehicle.body_response(1.0, kSpeed)) * kAmplitude * std::pow(std::sin(x) / x, 2);
  // started on the periodic orbit: no transient. The images at 1600 ± 4 cycles a period (400 Hz)
  // reach the body through the bogie (c1·ω/(m2·ω²) ≈ 1e-2) and the body's springs
  // ((k2 + k)/(m1·ω²) ≈ 2e-5) after sinc² ≈ 6e-6: about 1e-12 of the line; 1e-8 is round-off's.
  EXPECT_NEAR(2.0 * std::abs(sum) / y.size() / expected, 1.0, 1e-8);
}

TrackIrregularitySpectra centred_ore(TrackIrregularity kind, double length) {
  // the band's ends half-way between the realisation's lines (midpoint rule of ∫S, no edge bias)
  const double dOmega = 2 * kPi / length;
  TrackIrregularitySpectra t;
  const TrackSpectrum s = TrackSpectrum::ore_b176(OreLevel::low, kind,
                                                  {(std::floor(2 * kPi / 100 / dOmega) + 0.5) * dOmega,
                                                   (std::floor(2 * kPi / 2 / dOmega) + 0.5) * dOmega});
  (kind == TrackIrregularity::alignment ? t.alignment : t.vertical_level) = s;
  return t;
}

// (a) and (c) of the FFT checks with a series damper, as RideFftChecks.* does for the mass on
// its wheels (realisation_checks_test.cpp): the realisation's RMS scatters about solve_ride's by
// √Σ(|H_k|²P_k)²/(2Σ|H_k|²P_k) (one standard deviation; the lines' powers from the closed form),
// held to four of those plus 1 % for solve_ride's grid and the interpolation.
TEST(RideSeriesDamper, RealisationChecksHold) {
  const BodyOnBogie vehicle;
  const LinearSystem system = vehicle.system();
  constexpr double kSpeed = 40.0;
  TrackSynthesisOptions s;
  s.length = 8192.0;
  s.step = 0.25;
  s.seed = 11;
  const TrackIrregularitySpectra track = centred_ore(TrackIrregularity::vertical_level, s.length);
  const TrackGeometry geometry = synthesise_track(track, s);
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = s.step / kSpeed;
  const std::vector<RideOutput> outputs{body_point(ResponseQuantity::displacement),
                                        body_point(ResponseQuantity::acceleration)};
  const RideSimulationResult r = simulate_ride(system, geometry, outputs, o);
  const RideFftChecks checks = check_ride_realisation(system, track, geometry, r, o);
  ASSERT_TRUE(checks.exact_bin_error);
  // the march is exact for the interpolated track: round-off over 32768 steps and the alias
  // tail beyond ±16 images (< 1e-7), as ExactBinCheck
  EXPECT_LT(*checks.exact_bin_error, 1e-6);
  ASSERT_EQ(checks.rms_difference.size(), 2u);
  const double dOmega = 2 * kPi / s.length;
  double sum = 0.0, squares = 0.0;
  for (int k = 1; k < 16384; ++k) {
    const double f = kSpeed * k * dOmega / (2 * kPi);
    const double p = std::norm(vehicle.body_response(f, kSpeed)) * track.vertical_level->density(k * dOmega) * dOmega;
    sum += p;
    squares += p * p;
  }
  const double scatter = 0.5 * std::sqrt(squares) / sum;
  RecordProperty("displacement_rms_difference", std::to_string(checks.rms_difference[0]));
  RecordProperty("acceleration_rms_difference", std::to_string(checks.rms_difference[1]));
  RecordProperty("displacement_rms_scatter", std::to_string(scatter));
  EXPECT_LT(std::abs(checks.rms_difference[0]), 4.0 * scatter + 0.01);
  EXPECT_LT(std::abs(checks.rms_difference[1]), 4.0 * scatter + 0.01);
}

// The coach with yaw dampers, lateral, on the alignment: the march's state space (strokes
// included) has, at every frequency of solve_ride's grid, the transfer function the frequency
// domain forms with the Maxwell stiffness: |H|² = PSD / input PSD there. Both are exact
// solutions of one linear system of ~20 unknowns, conditioned by the damping (ζ ≥ a few %):
// 1e-8 of the largest |H|² leaves orders of headroom over their round-off.
TEST(RideSeriesDamper, CoachWithYawDampersHasTheFrequencyDomainsTransferFunction) {
  const LinearSystem coach = assemble(coach_with_yaw_dampers(), DofSet::lateral);
  ASSERT_FALSE(coach.series_dampers.empty());
  const TrackIrregularitySpectra track = centred_ore(TrackIrregularity::alignment, 8192.0);
  const std::vector<RideOutput> outputs{body_point(ResponseQuantity::displacement, RideAxis::lateral),
                                        body_point(ResponseQuantity::acceleration, RideAxis::lateral)};
  constexpr double kSpeed = 40.0;
  RideOptions options;
  options.speeds = {kSpeed};
  const RideResult freq = solve_ride(coach, track, outputs, options);

  const ride::RideStateSpace model = ride::ride_state_space(coach);
  EXPECT_EQ(model.strokes, static_cast<int>(coach.series_dampers.size()));
  const std::vector<ride::OutputRow> rows = ride::output_rows(coach, model, outputs);
  double lead = -INFINITY;
  for (const TrackInput& t : coach.track_inputs) lead = std::max(lead, t.point.x());
  const Eigen::MatrixXcd I = Eigen::MatrixXcd::Identity(model.states(), model.states());
  for (size_t o = 0; o < outputs.size(); ++o) {
    const Eigen::VectorXd& psd = freq.speeds[0].outputs[o].psd;
    const Eigen::VectorXd& input = freq.speeds[0].input_psd[0];
    double largest = 0.0, worst = 0.0;
    for (Eigen::Index j = 0; j < freq.frequencies.size(); ++j) {
      if (!(input(j) > 0.0)) continue;  // outside the spectrum's band
      const double omega = 2 * kPi * freq.frequencies(j);
      Eigen::VectorXcd w = Eigen::VectorXcd::Zero(model.B.cols());  // ŵ: the alignment at each input
      for (size_t i = 0; i < coach.track_inputs.size(); ++i)
        w(3 * static_cast<Eigen::Index>(i) + 1) =
            std::polar(1.0, -omega * (lead - coach.track_inputs[i].point.x()) / kSpeed);
      const Eigen::VectorXcd state =
          (Complex(0.0, omega) * I - model.A.cast<Complex>()).partialPivLu().solve(model.B.cast<Complex>() * w);
      const Complex h = (rows[o].Ls.cast<Complex>() * state)(0) + (rows[o].Lw.cast<Complex>() * w)(0) +
                        Complex(0.0, omega) * (rows[o].Ld.cast<Complex>() * w)(0);
      const double frequency_domain = psd(j) / input(j);
      largest = std::max(largest, frequency_domain);
      worst = std::max(worst, std::abs(std::norm(h) - frequency_domain));
    }
    ASSERT_GT(largest, 0.0) << outputs[o].name;
    EXPECT_LT(worst, 1e-8 * largest) << outputs[o].name;
  }

  // and the march runs (formerly refused) and is exact for its state space: check (a)
  TrackSynthesisOptions s;
  s.length = 1024.0;
  s.step = 0.5;
  s.seed = 3;
  const TrackGeometry geometry = synthesise_track(track, s);
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = s.step / kSpeed;
  const RideSimulationResult r = simulate_ride(coach, geometry, outputs, o);
  const RideFftChecks checks = check_ride_realisation(coach, track, geometry, r, o);
  ASSERT_TRUE(checks.exact_bin_error);
  EXPECT_LT(*checks.exact_bin_error, 1e-6);
}

// What stays refused says so: a series damper on an element standing on the track (the track
// would move one end of its spring), and with nonlinear effects (the nonlinear simulation holds
// M, C and K only).
TEST(RideSeriesDamper, WhatStaysRefusedIsNamed) {
  const BodyOnBogie vehicle;
  LinearSystem on_track = vehicle.system();
  on_track.series_dampers[0].element = 0;  // "wheel 1", a track input
  const TrackGeometry track = sine_track(0.001, 4, 1600, 1.0 / 16);
  RideSimulationOptions o;
  o.speed = 25.0;
  o.time_step = 1.0 / 16 / 25.0;
  try {
    simulate_ride(on_track, track, {body_point(ResponseQuantity::displacement)}, o);
    FAIL() << "a series damper on the track was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ride simulation: element 'wheel 1' stands on the track with a series damper"),
              std::string::npos)
        << e.what();
  }
  o.effects.leaf_friction = true;
  try {
    simulate_ride(vehicle.system(), track, {body_point(ResponseQuantity::displacement)}, o);
    FAIL() << "nonlinear effects with a series damper were taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the ride with nonlinear effects: element 'body damper' has a series damper"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace railmodal::test
