// The frequency-domain ride's fast paths (issue 21 item 9): the small dense solve, the inputs
// that share an x summed before the solve, the grid points a speed does not need skipped, the
// input spectra's names in the result, and the vector sincos of the delay phases.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "ride/phase_sincos.hpp"
#include "ride/ride_transfer.hpp"
#include "ride/ride_workspace.hpp"
#include "ride_test_systems.hpp"

namespace railmodal {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

RideOutput bounce_output() {
  RideOutput o;
  o.name = "bounce";
  o.kind = RideOutput::Kind::point;
  o.body = "body";
  o.point = Eigen::Vector3d::Zero();
  o.axis = RideAxis::vertical;
  o.quantity = ResponseQuantity::displacement;
  return o;
}

TrackIrregularitySpectra white_level(double low, double high) {
  TrackIrregularitySpectra track;
  track.vertical_level = TrackSpectrum::table(TrackIrregularity::vertical_level, SpectrumAbscissa::wavenumber,
                                              {low, high}, {1e-6, 1e-6});
  return track;
}

// Against Eigen's LU on a random complex system that needs row swaps (a zero leading entry).
// ride::solve_in_place on Eigen's column-major storage, with the pivot and reciprocal buffers
// receptances gives it.
Eigen::VectorXd solve_in_place(Eigen::MatrixXcd* D, Eigen::MatrixXcd* B) {
  const int n = static_cast<int>(D->rows());
  Eigen::VectorXd pivots(n);
  std::vector<Complex> inverse(static_cast<size_t>(n));
  ride::solve_in_place(n, static_cast<int>(B->cols()), D->data(), B->data(), pivots.data(), inverse.data());
  return pivots;
}

TEST(RideSpeed, SmallSolveMatchesEigensLu) {
  std::mt19937 random(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 7, r = 3;
  Eigen::MatrixXcd D(n, n), B(n, r);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) D(i, j) = Complex(u(random), u(random)) + (i == j ? Complex(3.0, 1.0) : 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < r; ++j) B(i, j) = Complex(u(random), u(random));
  D(0, 0) = 0.0;
  const Eigen::MatrixXcd expected = Eigen::PartialPivLU<Eigen::MatrixXcd>(D).solve(B);
  Eigen::MatrixXcd a = D, y = B;
  const Eigen::VectorXd pivots = solve_in_place(&a, &y);
  // 1e-13: a diagonally dominated matrix (condition ~10), two eliminations of n = 7 in double
  // precision differ by a few ulps times the condition.
  EXPECT_LT((y - expected).norm(), 1e-13 * expected.norm());
  EXPECT_LT((D * y - B).norm(), 1e-13 * B.norm());
  EXPECT_GT(pivots.minCoeff(), 0.0);
}

// A singular matrix: a zero pivot, reported and never a NaN.
TEST(RideSpeed, SmallSolveReportsAZeroPivotWithoutNaN) {
  Eigen::MatrixXcd D(3, 3), B(3, 1);
  D << 1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 1.0, 0.0, 1.0;  // row 2 = 2 × row 1
  B << 1.0, 1.0, 1.0;
  const Eigen::VectorXd pivots = solve_in_place(&D, &B);
  EXPECT_EQ(pivots.minCoeff(), 0.0);
  EXPECT_TRUE(pivots.allFinite());
  EXPECT_GT(pivots.maxCoeff(), 0.0);
}

// A scene's ride as `railmodal ride` runs it, in `kept` (null: solve_ride's own arrays); a
// positive `per_decade` and `threads` replace the scene's grid density and thread count.
RideResult scene_ride(const std::string& file, bool rms_only, bool keep_spectra, ride::Workspace* kept,
                      int per_decade = 0, int threads = 0) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/" + file);
  const LinearSystem system = assemble(load_vehicle(scene.vehicle_file), scene.dofs);
  RideOptions options = scene.ride->options;
  options.rms_only = rms_only;
  options.keep_spectra = keep_spectra;
  if (per_decade > 0) options.points_per_decade = per_decade;
  if (threads > 0) options.threads = threads;
  const std::vector<RideOutput> outputs = scene.ride->outputs.empty() ? default_ride_outputs(system) : scene.ride->outputs;
  return ride::solve_ride(system, *scene.irregularity, outputs, options, kept);
}

void expect_same_bits(const RideResult& a, const RideResult& b) {
  ASSERT_EQ(a.frequencies.size(), b.frequencies.size());
  EXPECT_EQ(a.frequencies, b.frequencies);
  ASSERT_EQ(a.speeds.size(), b.speeds.size());
  EXPECT_EQ(a.grid_error_estimate, b.grid_error_estimate);
  for (size_t v = 0; v < a.speeds.size(); ++v) {
    ASSERT_EQ(a.speeds[v].outputs.size(), b.speeds[v].outputs.size());
    for (size_t o = 0; o < a.speeds[v].outputs.size(); ++o) {
      const RideOutputAtSpeed &x = a.speeds[v].outputs[o], &y = b.speeds[v].outputs[o];
      EXPECT_EQ(x.rms, y.rms);
      EXPECT_EQ(x.weighted_rms, y.weighted_rms);
      EXPECT_EQ(x.sperling_wz, y.sperling_wz);
      EXPECT_EQ(x.p95_estimate, y.p95_estimate);
      EXPECT_EQ(x.cross_term_variance, y.cross_term_variance);
      EXPECT_EQ(x.direct_variance, y.direct_variance);
      EXPECT_EQ(x.psd, y.psd);
      ASSERT_EQ(x.modes.size(), y.modes.size());
      for (size_t j = 0; j < x.modes.size(); ++j) {
        EXPECT_EQ(x.modes[j].mode, y.modes[j].mode);
        EXPECT_EQ(x.modes[j].variance, y.modes[j].variance);
      }
    }
    EXPECT_EQ(a.speeds[v].input_psd, b.speeds[v].input_psd);
  }
}

// A workspace kept across solves holds nothing a solve reads before writing it: the coach,
// then the leaf-friction wagon (another grid, other outputs, its own receptances at each
// friction pass), the coach RMS-only (no modal terms: the kept ones stay) and with its spectra,
// and the coach again, all in one workspace, give solve_ride's answers bit for bit.
TEST(RideSpeed, KeptWorkspaceGivesTheSameBits) {
  ride::Workspace kept;
  const RideResult coach = scene_ride("manchester_coach_ore_low.toml", false, false, nullptr);
  const RideResult wagon = scene_ride("two_axle_wagon_fra_class4.toml", false, true, nullptr);
  const RideResult coach_rms = scene_ride("manchester_coach_ore_low.toml", true, false, nullptr);
  const RideResult coach_psd = scene_ride("manchester_coach_ore_low.toml", false, true, nullptr);
  ASSERT_GT(coach.speeds.size(), 1u);
  ASSERT_NE(coach.frequencies.size(), wagon.frequencies.size());
  expect_same_bits(scene_ride("manchester_coach_ore_low.toml", false, false, &kept), coach);
  expect_same_bits(scene_ride("two_axle_wagon_fra_class4.toml", false, true, &kept), wagon);
  expect_same_bits(scene_ride("manchester_coach_ore_low.toml", true, false, &kept), coach_rms);
  expect_same_bits(scene_ride("manchester_coach_ore_low.toml", false, true, &kept), coach_psd);
  expect_same_bits(scene_ride("manchester_coach_ore_low.toml", false, false, &kept), coach);
}

// A kept workspace whose arrays are wider than the next grid (the same rows, fewer points: a
// kept matrix keeps its columns and the solve uses the first) and narrower again, on one and
// two threads (a workspace slot per worker): each answer is solve_ride's bit for bit.
TEST(RideSpeed, KeptWorkspaceServesAShorterGridAndALongerOneAgain) {
  for (const char* file : {"manchester_coach_ore_low.toml", "two_axle_wagon_fra_class4.toml"}) {
    ride::Workspace kept;
    const RideResult fine = scene_ride(file, false, false, nullptr, 300, 1);
    const RideResult coarse = scene_ride(file, false, false, nullptr, 60, 2);
    ASSERT_GT(fine.frequencies.size(), coarse.frequencies.size()) << file;
    expect_same_bits(scene_ride(file, false, false, &kept, 300, 1), fine);
    expect_same_bits(scene_ride(file, false, false, &kept, 60, 2), coarse);
    expect_same_bits(scene_ride(file, false, false, &kept, 300, 1), fine);
  }
}

// The same vehicle with its wheels doubled at each x (two wheels of an axle, summed into one
// group before the solve) and with one wheel of twice the spring and damper per x: one answer.
TEST(RideSpeed, WheelsAtOneXAreOneInput) {
  const double m = 30000.0, k = 1.2e6, c = 4e4;
  RideOptions options;
  options.speeds = {20.0, 40.0};
  const TrackIrregularitySpectra track = white_level(2 * kPi / 50.0, 2 * kPi / 2.0);
  const RideResult pairs = solve_ride(test::bouncing_mass(m, k, c, {4.0, 4.0, -4.0, -4.0}), track, {bounce_output()}, options);
  const RideResult single = solve_ride(test::bouncing_mass(m, 2 * k, 2 * c, {4.0, -4.0}), track, {bounce_output()}, options);
  for (size_t v = 0; v < options.speeds.size(); ++v) {
    // 1e-13: the same sums in another order (round-off of a few ulps over 10³ points).
    EXPECT_NEAR(pairs.speeds[v].outputs[0].rms, single.speeds[v].outputs[0].rms, 1e-13 * single.speeds[v].outputs[0].rms);
    EXPECT_GT(single.speeds[v].outputs[0].rms, 0.0);
  }
}

// Wheels at one x and wheels a millimetre apart (not grouped: their delays differ) against the
// closed form on the grid, and the PSD exactly zero where the track has no density (the points
// a speed skips).
TEST(RideSpeed, PsdMatchesTheClosedFormAndIsZeroOutsideTheBand) {
  const double m = 30000.0, k = 1.2e6, c = 4e4, V = 30.0;
  const std::vector<double> wheels = {5.0, 5.0, 4.999, -5.0};
  RideOptions options;
  options.speeds = {V};
  const double low = 2 * kPi / 50.0, high = 2 * kPi / 1.0;
  const RideResult r = solve_ride(test::bouncing_mass(m, k, c, wheels), white_level(low, high), {bounce_output()}, options);
  const RideAtSpeed& at = r.speeds[0];
  int inside = 0, outside = 0;
  for (Eigen::Index i = 0; i < r.frequencies.size(); ++i) {
    const double f = r.frequencies(i), g = at.input_psd[0](i);
    if (g == 0.0) {
      EXPECT_EQ(at.outputs[0].psd(i), 0.0) << f;
      ++outside;
      continue;
    }
    ++inside;
    const double expected = std::norm(test::bouncing_mass_response(m, k, c, wheels, f, V)) * g;
    // 1e-10: the closed form and the solve differ by round-off amplified by the resonance's
    // 1/ζ and the phases ωτ of up to ~10² rad.
    EXPECT_NEAR(at.outputs[0].psd(i), expected, 1e-10 * expected + 1e-30) << f;
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(RideSpeed, ResultNamesTheInputSpectraInInputPsdOrder) {
  RideOptions options;
  options.speeds = {20.0};
  const TrackIrregularitySpectra track = white_level(2 * kPi / 50.0, 2 * kPi / 2.0);
  const RideResult r = solve_ride(test::bouncing_mass(3e4, 1e6, 3e4, {3.0, -3.0}), track, {bounce_output()}, options);
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0], track.vertical_level->name());
  EXPECT_EQ(r.speeds[0].input_psd.size(), r.inputs.size());
}

// RideOptions::rms_only: the same RMS and weighted RMS bit for bit (the same sums over the same
// points; only the other indices' work is skipped), and none of the other indices.
TEST(RideSpeed, RmsOnlyGivesTheFullSolvesRmsAndNothingElse) {
  RideOutput floor = bounce_output();
  floor.quantity = ResponseQuantity::acceleration;
  RideOptions full;
  full.speeds = {20.0, 40.0};
  RideOptions only = full;
  only.rms_only = true;
  const LinearSystem system = test::bouncing_mass(3e4, 1e6, 3e4, {4.0, -4.0});
  const TrackIrregularitySpectra track = white_level(2 * kPi / 50.0, 2 * kPi / 2.0);
  const RideResult a = solve_ride(system, track, {floor}, full), b = solve_ride(system, track, {floor}, only);
  ASSERT_EQ(b.speeds.size(), a.speeds.size());
  for (size_t v = 0; v < a.speeds.size(); ++v) {
    const RideOutputAtSpeed &x = a.speeds[v].outputs[0], &y = b.speeds[v].outputs[0];
    EXPECT_GT(x.rms, 0.0);
    EXPECT_EQ(y.rms, x.rms);
    ASSERT_TRUE(x.weighted_rms && y.weighted_rms);
    EXPECT_EQ(*y.weighted_rms, *x.weighted_rms);
    EXPECT_TRUE(x.p95_estimate && x.sperling_wz && !x.modes.empty() && !a.speeds[v].comfort.empty());
    EXPECT_FALSE(y.p95_estimate || y.sperling_wz);
    EXPECT_TRUE(y.modes.empty());
    EXPECT_TRUE(b.speeds[v].comfort.empty());
    EXPECT_DOUBLE_EQ(y.cross_term_variance, y.rms * y.rms);  // σ² with no shares (4 ulps: the square root's round-off)
    EXPECT_EQ(y.psd.size(), x.psd.size());                    // keep_spectra still keeps the PSD
    EXPECT_EQ(y.psd, x.psd);
  }
  EXPECT_GT(a.grid_error_estimate, 0.0);
  EXPECT_EQ(b.grid_error_estimate, 0.0);
  for (const Check& c : b.summary.checks) EXPECT_EQ(c.name.find("grid error"), std::string::npos) << c.name;
  bool said = false;
  for (const std::string& n : b.notes) said = said || n.rfind("rms_only", 0) == 0;
  EXPECT_TRUE(said);
  EXPECT_TRUE(b.rms_only);  // the reports and the Python binding read this mark
  EXPECT_FALSE(a.rms_only);
}

// The vector sincos against the C library's over the phases the ride forms (up to ~10⁴ rad: 80 Hz
// and a 20 m delay at 10 km/h is 3500 rad), up to its reduction's limit, at the multiples of
// π/2 where the reduction cancels most, and beyond the limit and at non-finite arguments (the
// C library's own answer). Bound: phase_sincos is within 1.4·2⁻⁵³ of the exact value (measured
// against long double over 10⁷ arguments), std::sin within half an ulp of its value (≤ 2⁻⁵⁴
// for |value| ≤ 1), so the two differ by at most 2⁻⁵² (one ulp of 1).
TEST(RideSpeed, PhaseSincosMatchesTheCLibrary) {
  std::mt19937_64 random(9);
  std::vector<double> x;
  for (double range : {1.0, 100.0, 1e4, ride::kPhaseSincosLimit}) {
    std::uniform_real_distribution<double> u(-range, range);
    for (int i = 0; i < 20000; ++i) x.push_back(u(random));
  }
  for (int q = -2000; q <= 2000; ++q) {
    const double near = q * (kPi / 2);
    x.insert(x.end(), {near, std::nextafter(near, 1e9), std::nextafter(near, -1e9)});
  }
  x.insert(x.end(), {0.0, -0.0, 1e-300, ride::kPhaseSincosLimit, -ride::kPhaseSincosLimit, 3e6, -1e15, 1e300});
  std::vector<double> s(x.size()), c(x.size());
  ride::phase_sincos(x.data(), s.data(), c.data(), x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_LE(std::abs(s[i] - std::sin(x[i])), 0x1p-52) << x[i];
    EXPECT_LE(std::abs(c[i] - std::cos(x[i])), 0x1p-52) << x[i];
    if (std::abs(x[i]) > ride::kPhaseSincosLimit) {  // the C library's answer itself
      EXPECT_EQ(s[i], std::sin(x[i])) << x[i];
      EXPECT_EQ(c[i], std::cos(x[i])) << x[i];
    }
  }
  const double odd[] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()};
  double so[2], co[2];
  ride::phase_sincos(odd, so, co, 2);
  EXPECT_TRUE(std::isnan(so[0]) && std::isnan(co[0]) && std::isnan(so[1]) && std::isnan(co[1]));
}

}  // namespace
}  // namespace railmodal
