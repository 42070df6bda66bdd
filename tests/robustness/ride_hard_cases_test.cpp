// Hard numerical cases of the frequency-domain ride: what must stay finite, NaN-free and
// honest at the edges (no spectrum in the band, a peak far lighter than the grid's floor, links
// a million times stiffer than the suspension, a very slow train).
#include <gtest/gtest.h>

#include <cmath>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal {
namespace {

using test::kPi;

Vehicle wagon(double k, double c, double stiff_link = 0.0) {
  Vehicle v;
  v.name = "hard";
  Body b;
  b.name = "body";
  b.mass = 10000.0;
  b.inertia = Eigen::Vector3d(1e4, 5e4, 5e4);
  v.bodies.push_back(b);
  Body f = b;
  f.name = "frame";
  f.mass = 500.0;
  f.inertia = Eigen::Vector3d(50, 200, 200);
  v.bodies.push_back(f);
  for (double x : {3.0, -3.0}) {
    Element e;
    e.name = "primary" + std::to_string(x);
    e.upper = "frame";
    e.point = Eigen::Vector3d(x, 0, 0);
    SpringStage s;
    s.stiffness = stiff_link > 0.0 ? stiff_link : 4 * k;
    e.vertical_stages = {s};
    e.vertical_damping = c;
    v.elements.push_back(e);
    Element top = e;
    top.name = "secondary" + std::to_string(x);
    top.lower = "frame";
    top.upper = "body";
    top.vertical_stages[0].stiffness = k;
    v.elements.push_back(top);
  }
  return v;
}

RideOutput floor_acc() {
  RideOutput o;
  o.name = "floor";
  o.body = "body";
  o.point = Eigen::Vector3d(2, 0, 0);
  return o;
}

void expect_finite(const RideResult& r) {
  for (const RideAtSpeed& at : r.speeds)
    for (const RideOutputAtSpeed& o : at.outputs) {
      EXPECT_TRUE(std::isfinite(o.rms));
      EXPECT_TRUE(std::isfinite(o.cross_term_variance));
      EXPECT_TRUE(!o.weighted_rms || std::isfinite(*o.weighted_rms));
      EXPECT_TRUE(!o.p95_estimate || std::isfinite(*o.p95_estimate));
      for (Eigen::Index k = 0; k < o.psd.size(); ++k) EXPECT_TRUE(std::isfinite(o.psd(k)));
    }
  EXPECT_TRUE(std::isfinite(r.grid_error_estimate));
}

// The track's band maps above the grid at this speed: every figure would be a silent zero, so
// it is refused, naming the speed, the band and the grid (issue 21 review).
TEST(RideHardCases, SpectrumOutsideTheGridIsRefused) {
  const LinearSystem s = assemble(wagon(4e5, 1e4), DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {10.0, 20.0});
  RideOptions options;
  options.speeds = {100.0};  // 10 rad/m at 100 m/s is 159 Hz, above the 80-Hz grid
  try {
    solve_ride(s, track, {floor_acc()}, options);
    ADD_FAILURE() << "a band wholly outside the grid was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at 360 km/h the vertical_level band"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("wholly outside the grid 0.1 … 80 Hz"), std::string::npos) << e.what();
  }
}

// ζ = 1e-7, far below the grid's refinement floor (1e-4): still finite and bounded (damped),
// with the grid error estimate telling the reader the peak is not resolved.
TEST(RideHardCases, NearlyUndampedPeakStaysFiniteAndSaysSo) {
  const LinearSystem s = assemble(wagon(4e5, 1e-2), DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.05, 3.0});
  RideOptions options;
  options.speeds = {30.0};
  const RideResult r = solve_ride(s, track, {floor_acc()}, options);
  expect_finite(r);
  EXPECT_FALSE(r.speeds[0].outputs[0].unbounded);
  EXPECT_GT(r.grid_error_estimate, 1e-2);
}

// Primary links 1e6 times stiffer than the secondary springs: the dynamic stiffness is badly
// scaled but not singular; the floor's RMS agrees with rigid links (the frame riding the track)
// to the links' own flexibility.
TEST(RideHardCases, StiffLinksBesideSoftSprings) {
  TrackIrregularitySpectra track;
  track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.05, 3.0});
  RideOptions options;
  options.speeds = {30.0};
  options.max_frequency = 20.0;  // well below the links' 1e4-Hz modes
  const RideResult stiff = solve_ride(assemble(wagon(4e5, 1e4, 1e12), DofSet::vertical), track, {floor_acc()}, options);
  const RideResult stiffer = solve_ride(assemble(wagon(4e5, 1e4, 1e14), DofSet::vertical), track, {floor_acc()}, options);
  expect_finite(stiff);
  // The links' flexibility changes the floor by ~k/k_link = 4e-7 of its motion.
  EXPECT_NEAR(stiff.speeds[0].outputs[0].rms, stiffer.speeds[0].outputs[0].rms, 1e-5 * stiffer.speeds[0].outputs[0].rms);
}

// A walking-pace train (1 m/s): the band maps to 8 mHz … 0.48 Hz, mostly below the grid's
// 0.1 Hz, and the axles' delays are seconds long. Finite, and at most the track's own level (the
// body follows the track there).
TEST(RideHardCases, VerySlowTrain) {
  const LinearSystem s = assemble(wagon(4e5, 1e4), DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.05, 3.0});
  RideOptions options;
  options.speeds = {1.0};
  RideOutput d = floor_acc();
  d.quantity = ResponseQuantity::displacement;
  const RideResult r = solve_ride(s, track, {d}, options);
  expect_finite(r);
  EXPECT_GT(r.speeds[0].outputs[0].rms, 0.0);
  EXPECT_LE(r.speeds[0].outputs[0].rms, track.vertical_level->rms());
}

}  // namespace
}  // namespace railmodal
