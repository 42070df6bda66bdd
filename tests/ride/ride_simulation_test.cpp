// simulate_ride: exact for the linearly interpolated track (a finer step changes nothing at
// the shared times), the steady state over a sine track against the closed-form response of a
// mass on its wheels with the wheelbase delay, the indices of that sine, the cross-level's
// roll, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "railmodal/ride_simulation.hpp"
#include "ride/ride_test_systems.hpp"
#include "ride/track_under_wheels.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr double kMass = 10000.0, kStiffness = 4e5, kDamping = 8e3;  // 1 Hz bounce on two wheels, ζ ≈ 0.13
const std::vector<double> kWheels{4.3, -4.3};                          // 8.6 m apart: not a whole number of steps

// Linear interpolation of a sampled cosine of `per` samples a period keeps the fundamental
// with the gain sinc²(1/per) (the triangle's transform): the input the vehicle sees.
double interpolation_gain(double per) {
  const double x = kPi / per;
  return std::pow(std::sin(x) / x, 2);
}

TEST(RideSimulation, SteadyStateOverASineIsTheClosedFormResponseWithTheWheelbaseDelay) {
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, kWheels);
  constexpr double kAmplitude = 0.002, kSpeed = 25.0;
  const TrackGeometry track = sine_track(kAmplitude, 4, 1600, 1.0 / 16);  // λ = 25 m: 1 Hz at 25 m/s
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = 1.0 / 16 / kSpeed;
  const RideSimulationResult r = simulate_ride(
      system, track, {body_point(ResponseQuantity::displacement), body_point(ResponseQuantity::acceleration)}, o);
  ASSERT_EQ(r.histories.size(), 2u);
  EXPECT_EQ(r.time.size(), 1600);  // one period
  EXPECT_TRUE(r.summary.passed());
  // the 1 Hz line of one period of each history (4 cycles: DFT bin 4), as an amplitude
  const auto line = [&](const Eigen::VectorXd& y) {
    std::complex<double> sum = 0.0;
    for (Eigen::Index n = 0; n < y.size(); ++n) sum += y(n) * std::polar(1.0, -2 * kPi * 4.0 * n / y.size());
    return 2.0 * std::abs(sum) / y.size();
  };
  const double h = std::abs(bouncing_mass_response(kMass, kStiffness, kDamping, kWheels, 1.0, kSpeed));
  const double expected = h * kAmplitude * interpolation_gain(400);
  // started on the periodic orbit: no transient. The interpolated track's images at 1600 ± 4
  // cycles a period fold onto the same bin; through the 1 Hz mass at 400 Hz they are down by
  // sinc²(1.0025) = 6e-6 times c/(ωm) = 3e-4: 1e-8 holds them.
  EXPECT_NEAR(line(r.histories[0].values) / expected, 1.0, 1e-8);
  // acceleration: ω² times; its images pass the damper as c·ω/m (2000 s⁻² at 400 Hz against
  // ω₀²|H| ≈ 50 s⁻² at 1 Hz), so they reach 6e-6 · 40 = 2.4e-4 of the line: 1e-3
  EXPECT_NEAR(line(r.histories[1].values) / (expected * std::pow(2 * kPi, 2)), 1.0, 1e-3);
  // and the RMS is the line's, the kinks' harmonics adding below 1e-4 of it
  EXPECT_NEAR(r.histories[0].rms / (expected / std::sqrt(2.0)), 1.0, 1e-4);
}

TEST(RideSimulation, ExactForTheInterpolatedTrackWhateverTheStep) {
  // A rough measured record: every step the wheels' inputs kink at different phases of
  // the grid; the march is exact for them, so a third of the step gives the same samples.
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, kWheels);
  TrackIrregularitySpectra spectra;
  spectra.vertical_level = TrackSpectrum::ore_b176(OreLevel::high, TrackIrregularity::vertical_level, {0.1, 6.0});
  TrackSynthesisOptions s;
  s.length = 300.0;
  s.step = 0.5;
  TrackGeometry track = synthesise_track(spectra, s);
  track.periodic = false;  // read as measured: from rest, over the record only
  RideSimulationOptions o;
  o.speed = 30.0;
  o.time_step = 0.5 / 30.0;
  const std::vector<RideOutput> outputs{body_point(ResponseQuantity::displacement),
                                        body_point(ResponseQuantity::velocity)};
  const RideSimulationResult coarse = simulate_ride(system, track, outputs, o);
  o.time_step /= 3.0;
  const RideSimulationResult fine = simulate_ride(system, track, outputs, o);
  ASSERT_GE(fine.time.size(), 3 * (coarse.time.size() - 1));
  for (int j = 0; j < 2; ++j) {
    double worst = 0.0;
    for (Eigen::Index k = 0; k < coarse.time.size(); ++k)
      worst = std::max(worst, std::abs(fine.histories[j].values(3 * k) - coarse.histories[j].values(k)));
    // round-off of two different sets of exponentials over 570 steps: 1e-9 of the RMS (a
    // first-order hold on the sampled inputs would differ by O(h²), about 1e-2 here)
    EXPECT_LT(worst, 1e-9 * coarse.histories[j].rms) << j;
  }
}

TEST(RideSimulation, IndicesOfASineAreItsWeightedLevel) {
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, {0.0});
  constexpr double kSpeed = 25.0;
  // 5 Hz: λ = 5 m; 1000 m long, 40 s at 25 m/s: 8 windows of 5 s
  const TrackGeometry track = sine_track(0.001, 200, 16000, 1.0 / 16);
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = 1.0 / 16 / kSpeed / 2;  // 800 Hz sampling
  const RideSimulationResult r = simulate_ride(system, track, {body_point(ResponseQuantity::acceleration)}, o);
  const RideHistory& a = r.histories[0];
  ASSERT_TRUE(a.weighted_rms && a.p95 && a.sperling_wz);
  // the digital Wb at 5 Hz and 800 Hz sampling is within 2e-3 of the analog (docs/ride.md)
  EXPECT_NEAR(*a.weighted_rms / (en12299_wb().magnitude(5.0) * a.rms), 1.0, 2e-3);
  ASSERT_EQ(a.window_rms.size(), 8);
  for (Eigen::Index w = 0; w < a.window_rms.size(); ++w) EXPECT_NEAR(a.window_rms(w) / *a.weighted_rms, 1.0, 1e-9);
  EXPECT_NEAR(*a.p95 / *a.weighted_rms, 1.0, 1e-9);
  EXPECT_NEAR(a.continuous_comfort(a.continuous_comfort.size() - 1) / *a.weighted_rms, 1.0, 1e-9);
  EXPECT_NEAR(*a.sperling_wz, sperling_wz_harmonic(a.rms * std::sqrt(2.0), 5.0, SperlingDirection::vertical), 3e-3);
  ASSERT_EQ(r.comfort.size(), 1u);
  EXPECT_NEAR(r.comfort[0].nmv_estimate, 6.0 * *a.p95, 1e-12);
  EXPECT_EQ(r.comfort[0].missing_axes.size(), 2u);  // longitudinal and lateral
  bool noted = false;
  for (const std::string& note : r.notes) noted = noted || note.find("fewer than the 60") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(RideSimulation, CrossLevelRollsTheTrackUnderEachWheelByItsLateralPosition) {
  LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, {0.0, 0.0});
  system.track_inputs[0].point.y() = 0.75;   // left
  system.track_inputs[1].point.y() = -0.75;  // right
  TrackGeometry g;
  g.step = 1.0;
  g.cross_level = Eigen::VectorXd::Constant(4, 0.01);  // left rail 10 mm above the right
  const ride::TrackUnderWheels track(system, g, ride::cross_level_directions(system, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(track.cross_level(0).z(), 0.75 / 1.5);  // b: standard gauge's 0.75 m
  EXPECT_DOUBLE_EQ(track.displacement_of(0, 1.5).z(), 0.005);
  EXPECT_DOUBLE_EQ(track.displacement_of(1, 1.5).z(), -0.005);
}

TEST(RideSimulation, RefusesWhatItCannotRun) {
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, kWheels);
  const TrackGeometry track = sine_track(0.001, 4, 1600, 1.0 / 16);
  RideSimulationOptions o;
  o.speed = 25.0;
  o.time_step = 0.01;  // longer than Δx/V = 2.5 ms
  const std::vector<RideOutput> out{body_point(ResponseQuantity::displacement)};
  EXPECT_THROW(simulate_ride(system, track, out, o), std::invalid_argument);
  o.time_step = 0.001;  // (nonlinear effects are simulated now: tests/ride/ride_friction_time_test.cpp)
  RideOutput nobody = out[0];
  nobody.body = "frame";
  EXPECT_THROW(simulate_ride(system, track, {nobody}, o), std::invalid_argument);
  TrackGeometry short_record = track;
  short_record.periodic = false;
  short_record.vertical_level.conservativeResize(100);  // 6.2 m: shorter than the 8.6 m wheelbase
  EXPECT_THROW(simulate_ride(system, short_record, out, o), std::invalid_argument);
  RideSimulationOptions bad = o;
  bad.speed = -1.0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("speed"), std::string::npos);
}

}  // namespace
}  // namespace railmodal::test
