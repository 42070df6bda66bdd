// The ride's default floor points at the car body's floor (Body::floor_height; docs/ride.md,
// "Ride scenes"): the lateral acceleration there is the reference point's plus the roll's share,
// and a body that gives no floor height has its points at the reference point, which the notes
// say once, in every report that carries notes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "railmodal/ride_simulation.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr const char* kFloorNote = "floor height not given: the default floor points lie at z = ";

SpringStage floor_test_coil(double k) {
  SpringStage s;
  s.kind = "coil";
  s.stiffness = k;
  return s;
}

// A car body on four springs at (±3, ±1, 0), vertical and lateral 5e5 N/m and 8e3 N·s/m each,
// its reference point at z = `reference`, its CG at z = `cg`. With the CG above the springs the
// lateral and roll motions are coupled (the lower sway), so the reference point moves sideways
// as the body rolls; with cg = reference = 0 the body rolls about the springs' plane alone.
LinearSystem floor_test_body(std::optional<double> floor_height, double reference, double cg) {
  Vehicle v;
  v.name = "car body";
  Body b;
  b.name = "body";
  b.mass = 12000.0;
  b.inertia = Eigen::Vector3d(2e4, 1e5, 1e5);
  b.centre_of_gravity = Eigen::Vector3d(0.0, 0.0, cg);
  b.reference_point = Eigen::Vector3d(0.0, 0.0, reference);
  b.held = {Motion::longitudinal};
  b.floor_height = floor_height;
  v.bodies.push_back(b);
  const double points[4][2] = {{3.0, 1.0}, {3.0, -1.0}, {-3.0, 1.0}, {-3.0, -1.0}};
  for (int i = 0; i < 4; ++i) {
    Element e;
    e.name = "spring" + std::to_string(i + 1);
    e.upper = "body";
    e.point = Eigen::Vector3d(points[i][0], points[i][1], 0.0);
    e.vertical_stages = e.lateral_stages = {floor_test_coil(5e5)};
    e.vertical_damping = e.lateral_damping = 8e3;
    v.elements.push_back(e);
  }
  return assemble(v, DofSet::all);
}

RideOutput floor_test_point(const std::string& name, const Eigen::Vector3d& p, RideAxis axis,
                            RideOutput::Frame frame = RideOutput::Frame::body) {
  RideOutput o;
  o.name = name;
  o.body = "body";
  o.point = p;
  o.axis = axis;
  o.quantity = ResponseQuantity::acceleration;
  o.frame = frame;
  return o;
}

const RideOutput& floor_output_named(const std::vector<RideOutput>& outputs, const std::string& name) {
  const auto found = std::find_if(outputs.begin(), outputs.end(), [&](const RideOutput& o) { return o.name == name; });
  EXPECT_NE(found, outputs.end()) << name;
  return *found;
}

int notes_with(const std::vector<std::string>& notes, const std::string& text) {
  return static_cast<int>(std::count_if(notes.begin(), notes.end(),
                                        [&](const std::string& n) { return n.find(text) != std::string::npos; }));
}

// The points lie at the floor where the body gives it, at the reference point where it does not.
TEST(DefaultFloor, PointsLieAtTheFloorHeight) {
  for (const std::optional<double> floor : {std::optional<double>(1.7), std::optional<double>()}) {
    const std::vector<RideOutput> outputs = default_ride_outputs(floor_test_body(floor, 0.5, 1.0));
    ASSERT_FALSE(outputs.empty());
    for (const RideOutput& o : outputs) EXPECT_EQ(o.point.z(), floor.value_or(0.5)) << o.name;
  }
}

// A body rolling and swaying together (its CG 1 m above the springs): at every sample of a
// time-domain run on alignment and cross-level, the default point's lateral acceleration at the
// floor, h = 1.2 m above the reference point, is the reference point's minus h·φ̈ (the vehicle
// frame's right-handed roll about x, y to the left: the floor goes right as the left side rises),
// φ̈ read independently as the difference of the vertical accelerations 1 m apart across the
// body at the reference point's height. Both lateral readings are the accelerometer's (frame =
// body), whose g·φ is the same at both heights. The three outputs are rows on the same state,
// so the identity holds to round-off: 1e-9 of the largest reading is a million times that, and
// far below the roll's share, which is checked to be a large part of the floor's reading (the
// check fails for points at the reference point's height, as before floor_height).
TEST(DefaultFloor, LateralAccelerationAtTheFloorIsTheReferencePointsPlusTheRollsShare) {
  const double floor = 1.7, reference = 0.5, h = floor - reference;
  const LinearSystem s = floor_test_body(floor, reference, 1.0);
  std::vector<RideOutput> outputs = default_ride_outputs(s);
  const Eigen::Vector3d under(floor_output_named(outputs, "floor at mid-car, lateral").point.x(), 0.0, reference);
  outputs.push_back(floor_test_point("reference point, lateral", under, RideAxis::lateral));
  outputs.push_back(floor_test_point("z̈ on the centre line", under, RideAxis::vertical));
  outputs.push_back(floor_test_point("z̈ 1 m to the left", under + Eigen::Vector3d(0, 1, 0), RideAxis::vertical));
  TrackIrregularitySpectra track;
  track.alignment = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {0.06, 2.0});
  track.cross_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, {0.06, 2.0});
  TrackSynthesisOptions synthesis;
  synthesis.length = 512.0;
  synthesis.step = 0.25;
  synthesis.seed = 3;
  RideSimulationOptions o;
  o.speed = 20.0;
  const RideSimulationResult r = simulate_ride(s, synthesise_track(track, synthesis), outputs, o);
  const auto values = [&](const std::string& name) -> const Eigen::VectorXd& {
    const auto at = std::find_if(r.outputs.begin(), r.outputs.end(), [&](const RideOutput& x) { return x.name == name; });
    return r.histories[static_cast<std::size_t>(at - r.outputs.begin())].values;
  };
  const Eigen::VectorXd& at_floor = values("floor at mid-car, lateral");
  const Eigen::VectorXd& at_reference = values("reference point, lateral");
  const Eigen::VectorXd roll = values("z̈ 1 m to the left") - values("z̈ on the centre line");
  ASSERT_GT(at_floor.size(), 1000);
  const double largest = at_floor.cwiseAbs().maxCoeff();
  EXPECT_LT((at_floor - (at_reference - h * roll)).cwiseAbs().maxCoeff(), 1e-9 * largest);
  EXPECT_GT((h * roll).cwiseAbs().maxCoeff(), 0.2 * largest);  // the roll's share matters here
  EXPECT_GT(at_reference.cwiseAbs().maxCoeff(), 0.2 * largest);  // and the reference point sways
}

// Rolling alone about a known centre, the springs' plane (CG and reference point in it, so
// nothing couples roll to sway): in the frequency domain the track-frame lateral acceleration
// at the floor is −h·φ̈ alone, its PSD h² times φ̈'s (the vertical acceleration 1 m off the
// centre line) at every frequency, to round-off (1e-9 relative), and the reference point's is
// zero to round-off.
TEST(DefaultFloor, RollAboutTheReferencePointGivesTheFloorHTimesTheRollAcceleration) {
  const double h = 1.3;
  const LinearSystem s = floor_test_body(h, 0.0, 0.0);
  RideOutput floor = floor_output_named(default_ride_outputs(s), "floor at mid-car, lateral");
  floor.frame = RideOutput::Frame::track;
  const Eigen::Vector3d centre(floor.point.x(), 0.0, 0.0);
  const std::vector<RideOutput> outputs{
      floor, floor_test_point("reference point", centre, RideAxis::lateral, RideOutput::Frame::track),
      floor_test_point("φ̈ · 1 m", centre + Eigen::Vector3d(0, 1, 0), RideAxis::vertical)};
  TrackIrregularitySpectra track;
  track.cross_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, {0.06, 2.0});
  RideOptions options;
  options.speeds = {20.0};
  const RideResult r = solve_ride(s, track, outputs, options);
  const RideAtSpeed& at = r.speeds[0];
  int checked = 0;
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double roll = at.outputs[2].psd(k);
    if (!(roll > 0.0)) continue;  // outside the band
    EXPECT_NEAR(at.outputs[0].psd(k), h * h * roll, 1e-9 * h * h * roll) << r.frequencies(k);
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_LT(at.outputs[1].rms, 1e-9 * at.outputs[0].rms);
}

// The note: once when any default point is used on a body without its floor height, naming the
// height; none with the floor given or with only points the scene names; in solve_ride and
// simulate_ride alike, and once in each report format that carries notes (CSV carries none).
TEST(DefaultFloor, TheNoteSaysOnceWhereThePointsAreWithoutAFloorHeight) {
  TrackIrregularitySpectra track;
  track.cross_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, {0.06, 2.0});
  RideOptions options;
  options.speeds = {20.0, 30.0};
  const LinearSystem without = floor_test_body(std::nullopt, 0.5, 1.0);
  const RideResult r = solve_ride(without, track, default_ride_outputs(without), options);
  ASSERT_EQ(notes_with(r.notes, kFloorNote), 1);
  EXPECT_EQ(notes_with(r.notes, std::string(kFloorNote) + "0.5 m, the reference point of 'body'"), 1);
  EXPECT_EQ(notes_with(r.notes, "give `floor_height`"), 1);
  // Two of the default points, as docs/python.md's example takes them: still the defaults.
  const std::vector<RideOutput> defaults = default_ride_outputs(without);
  const std::vector<RideOutput> two(defaults.begin(), defaults.begin() + 2);
  EXPECT_EQ(notes_with(solve_ride(without, track, two, options).notes, kFloorNote), 1);
  // Points the scene names, even at the same height: no note.
  const std::vector<RideOutput> own{floor_test_point("seat", Eigen::Vector3d(0, 0, 0.5), RideAxis::lateral)};
  EXPECT_EQ(notes_with(solve_ride(without, track, own, options).notes, kFloorNote), 0);
  // The floor given: no note.
  const LinearSystem with = floor_test_body(1.7, 0.5, 1.0);
  EXPECT_EQ(notes_with(solve_ride(with, track, default_ride_outputs(with), options).notes, kFloorNote), 0);
  // The time domain says the same.
  TrackSynthesisOptions synthesis;
  synthesis.length = 256.0;
  synthesis.step = 0.25;
  RideSimulationOptions o;
  o.speed = 20.0;
  const TrackGeometry geometry = synthesise_track(track, synthesis);
  EXPECT_EQ(notes_with(simulate_ride(without, geometry, two, o).notes, kFloorNote), 1);
  EXPECT_EQ(notes_with(simulate_ride(with, geometry, default_ride_outputs(with), o).notes, kFloorNote), 0);
  // Each report with notes writes it once.
  for (OutputFormat format : {OutputFormat::table, OutputFormat::markdown, OutputFormat::html, OutputFormat::json}) {
    std::ostringstream out;
    write_ride(out, r, format);
    const std::string text = out.str();
    const std::size_t first = text.find(kFloorNote);
    EXPECT_NE(first, std::string::npos) << to_string(format);
    EXPECT_EQ(text.find(kFloorNote, first + 1), std::string::npos) << to_string(format);
  }
}

}  // namespace
}  // namespace railmodal::test
