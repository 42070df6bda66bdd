// Hard cases of the time-domain ride: an undamped vehicle on periodic track, a floating one
// (no periodic steady state), a stiff wheel mode far above the sampling rate, a single spike in a measured
// record, and a synthesis at the very edges of the band the sampling holds.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "railmodal/ride_simulation.hpp"
#include "ride/ride_test_systems.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

RideOutput displacement() {
  RideOutput o;
  o.name = "body displacement";
  o.body = "body";
  o.quantity = ResponseQuantity::displacement;
  return o;
}

TrackGeometry cosine_track(int samples, double step, bool periodic) {
  TrackGeometry g;
  g.step = step;
  g.periodic = periodic;
  g.vertical_level.resize(samples);
  for (int n = 0; n < samples; ++n) g.vertical_level(n) = 0.001 * std::cos(2 * kPi * 3 * n / samples);
  return g;
}

TEST(RideRealisationHardCases, UndampedVehicleOffResonanceHasItsPeriodicOrbit) {
  // 1.59 Hz undamped under a 0.3 Hz track line: I − Φ^{Nm} is regular, the run starts on the
  // forced periodic motion, amplitude k/(k − ω²m) times the interpolated line
  const LinearSystem system = bouncing_mass(1000.0, 1e5, 0.0, {0.0});
  RideSimulationOptions o;
  o.speed = 20.0;
  o.time_step = 0.5 / 20.0;
  const RideSimulationResult r = simulate_ride(system, cosine_track(400, 0.5, true), {displacement()}, o);
  const Eigen::VectorXd& x = r.histories[0].values;
  std::complex<double> sum = 0.0;
  for (Eigen::Index n = 0; n < x.size(); ++n) sum += x(n) * std::polar(1.0, -2 * kPi * 3.0 * n / x.size());
  const double w = 2 * kPi * 0.3, gain = std::pow(std::sin(kPi * 3 / 400.0) / (kPi * 3 / 400.0), 2);
  // the line's images at 400 ± 3 cycles reach the mass at 60 Hz attenuated by (1.59/60)² and
  // sinc²: below 1e-6
  EXPECT_NEAR(2.0 * std::abs(sum) / x.size() / (0.001 * gain * 1e5 / (1e5 - w * w * 1000.0)), 1.0, 1e-6);
}

TEST(RideRealisationHardCases, AFloatingBodyHasNoPeriodicOrbitAndStartsFromRest) {
  // on a damper alone the body's position is free (Φ has the eigenvalue 1): no fixed point
  const LinearSystem system = bouncing_mass(1000.0, 0.0, 1e4, {0.0});
  RideSimulationOptions o;
  o.speed = 20.0;
  o.time_step = 0.5 / 20.0;
  const RideSimulationResult r = simulate_ride(system, cosine_track(400, 0.5, true), {displacement()}, o);
  EXPECT_TRUE(r.histories[0].values.allFinite());
  bool noted = false;
  for (const std::string& note : r.notes) noted = noted || note.find("started from rest") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(RideRealisationHardCases, StiffModeFarAboveTheSamplingStaysBoundedAndQuasiStatic) {
  // 1 kg on 1e10 N/m (16 kHz) sampled at 40 Hz: the exact transition does not blow up; the
  // mass follows the track quasi-statically ((f/f_n)² ≈ 1e-9 of 1 mm) but for the ringing each
  // kink of the interpolated track starts, V·Δslope/ω ≈ 20·4.5e-6/1e5 ≈ 1e-9 m, lightly damped
  // (e^{−1.25} a step): 1e-8 m
  const LinearSystem system = bouncing_mass(1.0, 1e10, 100.0, {0.0});
  RideSimulationOptions o;
  o.speed = 20.0;
  o.time_step = 0.5 / 20.0;
  const TrackGeometry track = cosine_track(400, 0.5, true);
  const RideSimulationResult r = simulate_ride(system, track, {displacement()}, o);
  const Eigen::VectorXd& x = r.histories[0].values;
  ASSERT_EQ(x.size(), 400);
  for (Eigen::Index n = 0; n < x.size(); ++n) EXPECT_NEAR(x(n), track.vertical_level(n), 1e-8);
}

TEST(RideRealisationHardCases, ASingleSpikeInAMeasuredRecordGivesAFiniteDecayingResponse) {
  const LinearSystem system = bouncing_mass(10000.0, 4e5, 8e3, {0.0});
  TrackGeometry g;
  g.step = 0.25;
  g.vertical_level = Eigen::VectorXd::Zero(4000);
  g.vertical_level(100) = 0.05;  // a 50 mm spike
  RideSimulationOptions o;
  o.speed = 25.0;
  o.time_step = 0.01;
  const RideSimulationResult r = simulate_ride(system, g, {displacement()}, o);
  const Eigen::VectorXd& x = r.histories[0].values;
  EXPECT_TRUE(x.allFinite());
  EXPECT_GT(x.cwiseAbs().maxCoeff(), 1e-4);
  // 1 Hz, ζ = 0.063: after the 36 s record the motion has decayed by e^{−ζω t} ≈ 1e-6
  EXPECT_LT(std::abs(x(x.size() - 1)), 1e-5 * x.cwiseAbs().maxCoeff());
}

TEST(RideRealisationHardCases, SynthesisAtTheEdgesOfTheRepresentableBand) {
  TrackSynthesisOptions s;
  s.length = 100.0;
  s.step = 0.5;
  TrackIrregularitySpectra t;
  // exactly [2π/L, π/Δx]: both ends allowed
  t.vertical_level =
      TrackSpectrum::ore_b176(OreLevel::high, TrackIrregularity::vertical_level, {2 * kPi / 100.0, kPi / 0.5});
  const TrackGeometry g = synthesise_track(t, s);
  EXPECT_EQ(g.vertical_level.size(), 200);
  EXPECT_TRUE(g.vertical_level.allFinite());
  EXPECT_GT(g.vertical_level.norm(), 0.0);
}

}  // namespace
}  // namespace railmodal::test
