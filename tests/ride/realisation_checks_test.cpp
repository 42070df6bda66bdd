// The FFT checks: (a) the exact bin check holds to round-off for periodic realisations, at
// one and at several steps per track sample, and fails for a wrong run; (b) Welch's estimate
// of realisations falls outside its 95 % band in about 5 % of the bins.
#include <gtest/gtest.h>

#include <cmath>

#include "railmodal/ride_simulation.hpp"
#include "ride/realisation_checks.hpp"
#include "ride/ride_test_systems.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

TrackIrregularitySpectra ore_level() {
  TrackIrregularitySpectra t;
  t.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {2 * kPi / 100, 2 * kPi / 2});
  return t;
}

std::vector<RideOutput> body_outputs() {
  std::vector<RideOutput> out;
  for (ResponseQuantity q : {ResponseQuantity::displacement, ResponseQuantity::velocity, ResponseQuantity::acceleration}) {
    RideOutput o;
    o.name = to_string(q);
    o.body = "body";
    o.quantity = q;
    out.push_back(o);
  }
  return out;
}

class ExactBinCheck : public ::testing::TestWithParam<int> {};

TEST_P(ExactBinCheck, SimulatedBinsEqualTheFrequencyResponseTimesTheTrack) {
  const std::vector<double> wheels{9.35, 6.85, -6.85, -9.35};  // two bogies, 2.5 m wheelbase, 16.2 m centres
  const LinearSystem system = bouncing_mass(30000.0, 1.2e6, 4e4, wheels);
  TrackSynthesisOptions s;
  s.length = 1024.0;
  s.step = 0.5;
  s.seed = 3;
  const TrackGeometry track = synthesise_track(ore_level(), s);
  RideSimulationOptions o;
  o.speed = 40.0;
  o.time_step = 0.5 / 40.0 / GetParam();
  o.settle_time = 0.3;  // the evaluated period starts off the track's origin: ξ₀ ≠ span
  const RideSimulationResult r = simulate_ride(system, track, body_outputs(), o);
  const double error = ride::exact_bin_error(system, track, r, o);
  RecordProperty("exact_bin_error", std::to_string(error));
  // the march is exact for the interpolated track and the prediction sums its images: what
  // is left is round-off over 2048·m steps and the alias tail beyond ±16 images (< 1e-7)
  EXPECT_LT(error, 1e-6);
  // a run at another speed is not this track's response: the check sees it
  RideSimulationOptions other = o;
  other.speed = 41.0;
  other.time_step = 0.5 / 41.0 / GetParam();
  EXPECT_GT(ride::exact_bin_error(system, track, simulate_ride(system, track, body_outputs(), other), o), 1e-2);
}

INSTANTIATE_TEST_SUITE_P(StepsPerSample, ExactBinCheck, ::testing::Values(1, 3));

// Over seeds, the fraction of bins outside the 95 % chi-square band is about 0.05: with
// about 125 bins a realisation and neighbouring bins nearly independent, 20 realisations give
// 2500 bins, whose fraction has a standard error √(0.05·0.95/2500) = 0.0044 (more with the
// correlation of neighbouring bins through Hann's main lobe, up to about twice); held to
// 0.05 ± 0.025.
TEST(WelchCheck, AboutFivePercentOfBinsFallOutsideTheBand) {
  TrackSynthesisOptions s;
  s.length = 4096.0;
  s.step = 0.5;
  double outside = 0.0;
  int bins = 0;
  double bias = 0.0;
  for (int seed = 1; seed <= 20; ++seed) {
    s.seed = static_cast<std::uint64_t>(seed);
    const TrackGeometry g = synthesise_track(ore_level(), s);
    const ride::WelchCheck c = ride::welch_band_check(g.vertical_level, s.step, *ore_level().vertical_level, 512);
    outside += c.fraction_outside * c.bins;
    bins += c.bins;
    bias = c.leakage_bias;
    EXPECT_GT(c.degrees_of_freedom, 2 * 31 / 1.1);  // 31 segments, less their overlap's correlation
  }
  ASSERT_GT(bins, 1000);
  EXPECT_NEAR(outside / bins, 0.05, 0.025);
  RecordProperty("leakage_bias", std::to_string(bias));
  // ORE falls as Ω⁻⁴ above Ω_c; Hann's sidelobes fall as Ω⁻⁶ in power: the bias stays small
  // inside the band, largest next to its edges where the target steps to zero
  EXPECT_LT(bias, 1.0);
}

}  // namespace
}  // namespace railmodal::test

namespace railmodal::test {
namespace {

// (c) with the whole check: a long periodic realisation of a linear scene against solve_ride.
// The band's ends lie half-way between the realisation's lines, so the sum over lines is the
// midpoint rule of ∫S (no edge bias); what is left is the realisation's own scatter, whose
// standard deviation in the mean square is √Σ(|H_k|²P_k)² / Σ|H_k|²P_k over the lines (the
// periodogram's χ²₂ law), half that in the RMS. Held to four of those, plus 1 % for
// solve_ride's grid and the interpolation's sinc² (1e-3 at the shortest wavelength).
TEST(RideFftChecks, SimulatedRmsMatchesTheFrequencyDomainWithinTheRealisationsScatter) {
  const std::vector<double> wheels{9.35, 6.85, -6.85, -9.35};
  constexpr double kMass = 30000.0, kStiffness = 1.2e6, kDamping = 4e4, kSpeed = 40.0;
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, wheels);
  TrackSynthesisOptions s;
  s.length = 8192.0;
  s.step = 0.25;
  s.seed = 11;
  const double dOmega = 2 * kPi / s.length;
  TrackIrregularitySpectra track;
  track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level,
                                                 {(std::floor(2 * kPi / 100 / dOmega) + 0.5) * dOmega,
                                                  (std::floor(2 * kPi / 2 / dOmega) + 0.5) * dOmega});
  const TrackGeometry geometry = synthesise_track(track, s);
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = s.step / kSpeed;
  const std::vector<RideOutput> outputs = body_outputs();
  const RideSimulationResult r = simulate_ride(system, geometry, outputs, o);
  const RideFftChecks checks = check_ride_realisation(system, track, geometry, r, o);
  ASSERT_TRUE(checks.exact_bin_error);
  EXPECT_LT(*checks.exact_bin_error, 1e-6);
  ASSERT_EQ(checks.rms_difference.size(), 3u);
  double sum = 0.0, squares = 0.0;  // of the displacement's line powers
  for (int k = 1; k < 16384; ++k) {
    const double f = kSpeed * k * dOmega / (2 * kPi);
    const double p = std::norm(bouncing_mass_response(kMass, kStiffness, kDamping, wheels, f, kSpeed)) *
                     track.vertical_level->density(k * dOmega) * dOmega;
    sum += p;
    squares += p * p;
  }
  const double scatter = 0.5 * std::sqrt(squares) / sum;
  RecordProperty("displacement_rms_difference", std::to_string(checks.rms_difference[0]));
  RecordProperty("displacement_rms_scatter", std::to_string(scatter));
  EXPECT_LT(std::abs(checks.rms_difference[0]), 4.0 * scatter + 0.01);
  // the acceleration's scatter is of the same order (3–5 % over seeds 11–13, against the
  // displacement's 3.7 % standard deviation): the same bound
  EXPECT_LT(std::abs(checks.rms_difference[2]), 4.0 * scatter + 0.01);
  EXPECT_TRUE(checks.summary.passed());
}

}  // namespace
}  // namespace railmodal::test
