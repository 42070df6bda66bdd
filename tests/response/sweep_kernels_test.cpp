// The sweep's block arithmetic (response/sweep_kernels): the branch-free atan2 against libm,
// the phase wrap over its whole input range, the input's argument, the sweep's curves sharing
// one speed grid, outputs swept together giving the same bits as each alone, a study's curves
// without their phases, and the curve scans (the largest, the local maxima) against one pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "response/critical_speed_study.hpp"
#include "response/curve_peaks.hpp"
#include "response/sweep_kernels.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// One unit in the last place of π (2⁻⁵¹): the spacing of doubles in [2, 4), where atan2 of the
// left half-plane lands. The kernel promises 2 of them.
const double kUlpOfPi = std::ldexp(1.0, -51);

TEST(SweepKernels, FastAtan2AgreesWithLibmToTwoUlpOfPiInEveryQuadrant) {
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> angle(-kPi, kPi), exponent(-30.0, 30.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double r = std::pow(10.0, exponent(random)), a = angle(random);
    const double x = r * std::cos(a), y = r * std::sin(a);
    worst = std::max(worst, std::abs(response::fast_atan2(y, x) - std::atan2(y, x)));
  }
  // The reduction's seams (t = 0.66, |y| = |x|) and the axes, where a select changes branch.
  for (double t : {0.0, 0.66, std::nextafter(0.66, 1.0), 1.0, 1e-300, 1e300})
    for (double sx : {1.0, -1.0})
      for (double sy : {1.0, -1.0}) {
        if (sy * t != 0.0)  // −0: libm gives −π on the negative axis, the kernel +π (checked below)
          worst = std::max(worst, std::abs(response::fast_atan2(sy * t, sx) - std::atan2(sy * t, sx)));
        worst = std::max(worst, std::abs(response::fast_atan2(sy, sx * t) - std::atan2(sy, sx * t)));
      }
  EXPECT_LE(worst, 2.0 * kUlpOfPi);
  // Small angles to their own precision, not just to π's: a phase of 1e-20 rad is not 0.
  double worst_relative = 0.0;
  for (double e = -20.0; e <= -1.0; e += 0.01) {
    const double t = std::pow(10.0, e);
    worst_relative = std::max(worst_relative, std::abs(response::fast_atan2(t, 1.0) / std::atan2(t, 1.0) - 1.0));
  }
  EXPECT_LE(worst_relative, 4.0 * std::numeric_limits<double>::epsilon());
  std::cout << "fast_atan2: largest difference from libm " << worst / kUlpOfPi << " ulp of pi\n";
  EXPECT_DOUBLE_EQ(response::fast_atan2(0.0, -1.0), kPi);
  EXPECT_DOUBLE_EQ(response::fast_atan2(-0.0, -1.0), kPi);  // −0 counts as +0: the same phase
  EXPECT_DOUBLE_EQ(response::fast_atan2(-1.0, 0.0), -kPi / 2);
  EXPECT_TRUE(std::isnan(response::fast_atan2(0.0, 0.0)));  // no response: no phase
}

// The loop form (the vectorised one) gives what the scalar form gives, NaN included.
TEST(SweepKernels, ArgumentsOfABlockAreTheScalarOnes) {
  std::vector<double> re, im;
  for (int i = 0; i < 37; ++i) {  // not a multiple of any vector width: the tail loop too
    re.push_back(std::cos(0.3 * i) * (i % 5 == 0 ? 0.0 : 1.0 + i));
    im.push_back(std::sin(0.3 * i) * (i % 5 == 0 ? 0.0 : 1.0 + i));
  }
  std::vector<double> out(re.size());
  response::arguments(re.data(), im.data(), static_cast<int>(re.size()), out.data());
  for (size_t i = 0; i < re.size(); ++i) {
    if (i % 5 == 0) {
      EXPECT_TRUE(std::isnan(out[i])) << i;
    } else {
      EXPECT_EQ(out[i], response::fast_atan2(im[i], re[i])) << i;
    }
  }
}

// arg x ∈ [−π, π] and arg input ∈ [−π, 2π] (π added for a negative load scale), plus up to 180°
// for an acceleration: the difference spans [−540°, 540°], and each wraps into (−180°, 180°]
// to the same angle modulo 360°.
TEST(SweepKernels, PhasesWrapTheWholeRangeIntoOneTurn) {
  std::vector<double> x, input, flags;
  for (double a : {-kPi, -2.0, 0.0, 1.0, kPi})
    for (double b : {-kPi, -1.0, 0.0, kPi, 5.0, 2.0 * kPi}) x.push_back(a), input.push_back(b), flags.push_back(0.0);
  x.push_back(1.0), input.push_back(std::nan("")), flags.push_back(0.0);  // no input: phase 0
  x.push_back(1.0), input.push_back(0.0), flags.push_back(1.0);           // unbounded: phase 0
  for (double offset : {0.0, 90.0, 180.0}) {
    std::vector<double> out(x.size());
    response::phases_deg(x.data(), input.data(), flags.data(), offset, static_cast<int>(x.size()), out.data());
    for (size_t i = 0; i + 2 < x.size(); ++i) {
      const double raw = (x[i] - input[i]) * 180.0 / kPi + offset;
      EXPECT_GT(out[i], -180.0) << raw;
      EXPECT_LE(out[i], 180.0) << raw;
      const double turns = (raw - out[i]) / 360.0;
      EXPECT_NEAR(turns, std::round(turns), 1e-12) << raw;  // whole turns taken off, to round-off
    }
    EXPECT_EQ(out[x.size() - 2], 0.0);
    EXPECT_EQ(out[x.size() - 1], 0.0);
  }
}

// A sweep's curves share its grid (one copy per sweep, not per curve); a vector converts.
TEST(SweepKernels, CurvesOfOneSweepShareTheirSpeedGrid) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 12.5;
  const auto source = make_source(j);
  const int bounce = sys.index_of("body.bounce");
  const SpeedGrid grid(std::vector<double>{10.0, 20.0, 30.0});
  const auto curves = amplitude_curves(sys, modes, *source, 0,
                                       {{bounce, ResponseQuantity::displacement}, {bounce, ResponseQuantity::acceleration}},
                                       grid);
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(&curves[0].speeds.values(), &grid.values());
  EXPECT_EQ(&curves[1].speeds.values(), &grid.values());
  const auto from_vector =
      amplitude_curves(sys, modes, *source, 0, {{bounce, ResponseQuantity::displacement}}, std::vector<double>{10.0, 20.0, 30.0});
  EXPECT_EQ(from_vector[0].speeds, grid);
  EXPECT_EQ(from_vector[0].amplitudes, curves[0].amplitudes);
}

// The input's argument per speed: the reference where s > 0, turned by π where s < 0 (a real
// scale's sign), NaN (no phase) where s = 0; the block and one speed at a time agree.
TEST(SweepKernels, InputArgumentFollowsTheSignOfTheLoadScale) {
  const std::vector<double> scale = {2.0, -0.5, 0.0, 1e-300, -1e-300};
  std::vector<double> out(scale.size());
  response::input_arguments(scale.data(), 0.25, static_cast<int>(scale.size()), out.data());
  EXPECT_EQ(out[0], 0.25);
  EXPECT_EQ(out[1], 0.25 + kPi);
  EXPECT_TRUE(std::isnan(out[2]));
  EXPECT_EQ(out[3], 0.25);
  EXPECT_EQ(out[4], 0.25 + kPi);
  double one = 0.0;
  response::input_arguments(&scale[1], 0.25, 1, &one);
  EXPECT_EQ(one, out[1]);
  // A reference of −0 gives +0, as reference + 0 did before the block form.
  response::input_arguments(&scale[0], -0.0, 1, &one);
  EXPECT_FALSE(std::signbit(one));
}

// Speeds are checked and their order found in one pass: a falling grid is swept too (its
// resonances found without bisection), and a speed that is not positive and finite refused.
TEST(SweepKernels, SpeedScanFindsOrderAndRefusesBadSpeeds) {
  const std::vector<double> rising = {1.0, 2.0, 2.0, 3.0};
  EXPECT_TRUE(response::scan_speeds(rising.data(), 4).valid);
  EXPECT_TRUE(response::scan_speeds(rising.data(), 4).ascending);
  const std::vector<double> falling = {3.0, 2.0, 4.0};
  EXPECT_FALSE(response::scan_speeds(falling.data(), 3).ascending);
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    const std::vector<double> v = {1.0, bad, 2.0};
    EXPECT_FALSE(response::scan_speeds(v.data(), 3).valid) << bad;
  }
}

// The curve scans against the single passes they replace (a running largest from `floor`,
// strictly greater taking over; the first point with a[j] >= a[j - 1] and a[j] > a[j + 1]), on
// curves of every length around the 32-point blocks, with ties, ±0, NaN and plateaus.
TEST(SweepKernels, CurveScansFindWhatOnePassFinds) {
  std::mt19937_64 random(20261127);
  std::uniform_int_distribution<int> pick(0, 9);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {0.0, -0.0, 1.0, 2.0, 2.0, 3.0, nan, -1.0, 0.5, 3.0};
  int found_largest = 0, found_maximum = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const size_t n = static_cast<size_t>(trial % 100);
    std::vector<double> a(n);
    for (double& x : a) x = values[static_cast<size_t>(pick(random))];
    for (const double floor : {0.0, -2.0}) {
      double largest = floor;
      size_t at = n;
      for (size_t j = 0; j < n; ++j)
        if (a[j] > largest) largest = a[j], at = j;
      const response::LargestPoint got = response::largest_above(a.data(), n, floor);
      ASSERT_EQ(got.at, at) << "trial " << trial;
      if (at < n) {
        ++found_largest;
        EXPECT_EQ(std::signbit(got.value), std::signbit(largest)) << "trial " << trial;
        EXPECT_EQ(got.value, largest) << "trial " << trial;
      }
    }
    for (size_t from = 1; from < n; from += 7) {
      size_t first = n - 1;
      for (size_t j = from; j + 1 < n; ++j)
        if (a[j] >= a[j - 1] && a[j] > a[j + 1]) {
          first = j;
          break;
        }
      const size_t got = response::next_local_maximum(a.data(), from, n);
      ASSERT_EQ(got, first) << "trial " << trial << " from " << from;
      // skip_to_local_maximum passes no maximum: the first is at or after where it stops.
      EXPECT_LE(response::skip_to_local_maximum(a.data(), from, n), first) << "trial " << trial;
      if (first + 1 < n) ++found_maximum;
    }
  }
  // Both kinds of answer were met often: not a comparison of empty results.
  EXPECT_GT(found_largest, 1000);
  EXPECT_GT(found_maximum, 1000);
}

// Sweeps `outputs` together and each output alone: every amplitude, flag and phase the same
// bits. Together the outputs share the blocks' work arrays, the DOFs' sums and the input's
// arguments; any difference would be one output's work leaking into another's.
void expect_outputs_together_as_alone(const LinearSystem& sys, const ModalResult& modes,
                                      const ExcitationSource& source, const std::vector<double>& speeds,
                                      const std::string& method) {
  std::vector<OutputRequest> outputs;
  for (int d = 0; d < sys.size(); ++d)
    for (ResponseQuantity q : {ResponseQuantity::displacement, ResponseQuantity::acceleration})
      outputs.push_back({d, q});
  AnalysisSummary summary;
  const auto together = amplitude_curves(sys, modes, source, 0, outputs, speeds, 0.0, &summary);
  EXPECT_NE(summary.method.find(method), std::string::npos) << summary.method;
  double largest = 0.0;
  for (size_t o = 0; o < outputs.size(); ++o) {
    const auto alone = amplitude_curves(sys, modes, source, 0, {outputs[o]}, speeds);
    EXPECT_EQ(alone[0].amplitudes, together[o].amplitudes) << together[o].output;
    EXPECT_EQ(alone[0].unbounded, together[o].unbounded) << together[o].output;
    EXPECT_EQ(alone[0].phases_deg, together[o].phases_deg) << together[o].output;
    largest = std::max(largest, *std::max_element(together[o].amplitudes.begin(), together[o].amplitudes.end()));
  }
  EXPECT_GT(largest, 0.0) << method;  // the source reaches the outputs: not a comparison of zeros
}

TEST(SweepKernels, OutputsSweptTogetherGiveTheSameBitsAsEachAlone) {
  // The modal path: the resort car over rail joints (6 harmonics), every vertical DOF.
  const LinearSystem car = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  RailJoints joints;
  joints.rail_length = 12.5;
  joints.dip_depth = 0.005;  // the default profile has no dip, and so no load
  joints.dip_length = 1.0;
  joints.harmonics = 6;
  std::vector<double> speeds;
  for (double v = 1.0; v <= 60.0; v += 0.11) speeds.push_back(v);  // 537 speeds: three blocks
  expect_outputs_together_as_alone(car, solve_modes(car), *make_source(joints), speeds, "modal superposition");
  // The complex modes with an undamped mode's modal terms: the steam-locomotive frame.
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/steam_locomotive_unbalance.toml");
  const LinearSystem frame = assemble(load_vehicle(scene.vehicle_file), scene.dofs);
  speeds.clear();
  for (double v = 2.0; v <= 30.0; v += 0.05) speeds.push_back(v);
  expect_outputs_together_as_alone(frame, solve_modes(frame), *scene.sources.front(), speeds, "complex modes");
}

// A design study's variant sweeps its curves without phases (CurvePhases::left_out): every
// curve's phases are empty, and everything else of the study is the same bits as with them
// (the phases are written beside the amplitudes, never into them). Over the bundled scenes
// whose sweeps take the modal path (resort car) and the complex modes (steam locomotive).
TEST(SweepKernels, AStudyWithoutPhasesHasTheSameCurvesAndPeaksBitForBit) {
  for (const char* name : {"resort_car_10m_rails.toml", "steam_locomotive_unbalance.toml"}) {
    const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/" + name);
    const Vehicle vehicle = load_vehicle(scene.vehicle_file);
    const auto assembled = [&] { return assemble(vehicle, scene.dofs); };
    CriticalSpeedStudy with, without;
    response::study_critical_speeds_into(scene, assembled, &with);
    response::study_critical_speeds_into(scene, assembled, &without, {},
                                         {response::ResonanceDetail::full, response::CurvePhases::left_out});
    ASSERT_EQ(with.curves.size(), without.curves.size()) << name;
    ASSERT_FALSE(with.curves.empty()) << name;
    for (size_t c = 0; c < with.curves.size(); ++c) {
      EXPECT_EQ(with.curves[c].phases_deg.size(), with.curves[c].amplitudes.size()) << name;
      EXPECT_TRUE(without.curves[c].phases_deg.empty()) << name;
      EXPECT_EQ(with.curves[c].amplitudes, without.curves[c].amplitudes) << name;
      EXPECT_EQ(with.curves[c].unbounded, without.curves[c].unbounded) << name;
      EXPECT_EQ(with.curves[c].speeds, without.curves[c].speeds) << name;
    }
    ASSERT_EQ(with.peaks.size(), without.peaks.size()) << name;
    for (size_t p = 0; p < with.peaks.size(); ++p) {
      EXPECT_EQ(with.peaks[p].curve, without.peaks[p].curve) << name;
      EXPECT_EQ(with.peaks[p].peak.speed, without.peaks[p].peak.speed) << name;
      EXPECT_EQ(with.peaks[p].peak.amplitude, without.peaks[p].peak.amplitude) << name;
    }
    ASSERT_EQ(with.critical_speeds.size(), without.critical_speeds.size()) << name;
    for (size_t r = 0; r < with.critical_speeds.size(); ++r)
      EXPECT_EQ(with.critical_speeds[r].speed, without.critical_speeds[r].speed) << name;
  }
}

}  // namespace
}  // namespace railmodal::test
