// The frame of a point's lateral acceleration (RideOutput::Frame): an accelerometer fixed to a
// rolling body reads ÿ + g·φ (EN 12299, ISO 2631-1: transducers on the floor, along the body's
// axes), the track's frame ÿ alone; the same in the frequency and the time domain.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "railmodal/ride_simulation.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr double kFrameTestGravity = 9.81;  // Vehicle::gravity's default, which the body frame uses

SpringStage frame_test_coil(double k) {
  SpringStage s;
  s.kind = "coil";
  s.stiffness = k;
  return s;
}

// A body that rolls alone: four springs at (±3, ±1, 0), vertical and lateral 5e5 N/m and 8e3
// N·s/m each, its centre of gravity at their height, so neither the lateral springs nor gravity
// couple roll to lateral motion. Cross-level rolls the rails about the rail top, r0 below the
// springs' plane, and moves them sideways by −θ(z + r0): zero with z = 0 and r0 = 0 (no wheelsets),
// so cross-level excites roll and nothing else. Roll: 4k·1² = 2e6 N·m/rad on 2e4 kg·m², 1.59 Hz,
// ζ = 4c/(2√(K I)) = 0.08.
LinearSystem rolling_body(std::vector<Motion> held = {Motion::longitudinal}) {
  Vehicle v;
  v.name = "rolling body";
  Body b;
  b.name = "body";
  b.mass = 12000.0;
  b.inertia = Eigen::Vector3d(2e4, 1e5, 1e5);
  b.held = held;
  v.bodies.push_back(b);
  const double points[4][2] = {{3.0, 1.0}, {3.0, -1.0}, {-3.0, 1.0}, {-3.0, -1.0}};
  for (int i = 0; i < 4; ++i) {
    Element e;
    e.name = "spring" + std::to_string(i + 1);
    e.upper = "body";
    e.point = Eigen::Vector3d(points[i][0], points[i][1], 0.0);
    e.vertical_stages = e.lateral_stages = {frame_test_coil(5e5)};
    e.vertical_damping = e.lateral_damping = 8e3;
    v.elements.push_back(e);
  }
  return assemble(v, DofSet::all);
}

RideOutput frame_test_point(const std::string& name, const Eigen::Vector3d& p, RideAxis axis, ResponseQuantity q,
                            RideOutput::Frame frame) {
  RideOutput o;
  o.name = name;
  o.body = "body";
  o.point = p;
  o.axis = axis;
  o.quantity = q;
  o.frame = frame;
  return o;
}

TrackIrregularitySpectra cross_level_only(double low, double high) {
  TrackIrregularitySpectra t;
  t.cross_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, {low, high});
  return t;
}

// Pure roll φ about the springs' plane: a point h above it moves sideways by −hφ (the vehicle
// frame's right-handed roll about x, y to the left: the top goes right as the left side rises),
// so ÿ = −hφ̈ = hω²φ; the accelerometer's axis tilts with the body, its left end up, and reads
// the upward specific force's component g·φ besides: (g + hω²)φ. Below the axis (h < 0) the two
// oppose, |g − |h|ω²|, and a point g/ω² below it reads nothing (a pendulum's passenger). The
// ratio of PSDs is that squared at every grid frequency; 1e-9 of (g + |h|ω²)² allows round-off
// (the lateral motion is zero to round-off: nothing couples it to roll).
TEST(RideFrame, AccelerometerOnARollingBodyReadsGravityPlusTheRollsAcceleration) {
  const LinearSystem s = rolling_body();
  const double above = 0.6, below = -0.3;
  const std::vector<RideOutput> outputs{
      frame_test_point("roll", Eigen::Vector3d(0, 1, 0), RideAxis::vertical, ResponseQuantity::displacement,
                       RideOutput::Frame::body),
      frame_test_point("above, body", Eigen::Vector3d(0, 0, above), RideAxis::lateral, ResponseQuantity::acceleration,
                       RideOutput::Frame::body),
      frame_test_point("below, body", Eigen::Vector3d(0, 0, below), RideAxis::lateral, ResponseQuantity::acceleration,
                       RideOutput::Frame::body),
      frame_test_point("above, track", Eigen::Vector3d(0, 0, above), RideAxis::lateral,
                       ResponseQuantity::acceleration, RideOutput::Frame::track)};
  RideOptions options;
  options.speeds = {20.0};  // the band 0.06 … 2 rad/m: 0.19 … 6.4 Hz
  const RideResult r = solve_ride(s, cross_level_only(0.06, 2.0), outputs, options);
  const RideAtSpeed& at = r.speeds[0];
  int checked = 0;
  double deepest = INFINITY;  // the "below" reading over g²φ² near its node
  const double node = std::sqrt(kFrameTestGravity / -below) / (2 * kPi);
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double roll = at.outputs[0].psd(k);
    if (!(roll > 0.0)) continue;  // outside the band
    const double w2 = std::pow(2 * kPi * r.frequencies(k), 2);
    for (const auto& [o, h, g] : {std::tuple{1, above, kFrameTestGravity}, std::tuple{2, below, kFrameTestGravity}, std::tuple{3, above, 0.0}}) {
      const double expected = std::pow(g + h * w2, 2), scale = std::pow(g + std::abs(h) * w2, 2);
      EXPECT_NEAR(at.outputs[o].psd(k) / roll, expected, 1e-9 * scale) << r.outputs[o].name << " at " << r.frequencies(k);
    }
    if (std::abs(r.frequencies(k) / node - 1.0) < 0.05) deepest = std::min(deepest, at.outputs[2].psd(k) / roll / (kFrameTestGravity * kFrameTestGravity));
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_LT(deepest, 0.02);  // within 5 % of 0.91 Hz the reading falls below 14 % of gφ
  // The note says which frame each kind of output is in.
  int frame_notes = 0;
  for (const std::string& n : r.notes)
    frame_notes += n.find("frame = body") != std::string::npos || n.find("frame = track") != std::string::npos;
  EXPECT_EQ(frame_notes, 2);
}

// The track frame is the inertial acceleration as before: a lateral acceleration's PSD is ω⁴
// times the lateral displacement's (1e-12: round-off of ω⁴), and a vertical acceleration reads
// the same bits in both frames (no gravity term: the vertical axis' tilt is of second order).
TEST(RideFrame, TrackFrameIsTheInertialAccelerationAndVerticalIsTheSameInBoth) {
  const LinearSystem s = rolling_body();
  const Eigen::Vector3d p(2.0, 0.5, 0.8);
  const std::vector<RideOutput> outputs{
      frame_test_point("y", p, RideAxis::lateral, ResponseQuantity::displacement, RideOutput::Frame::track),
      frame_test_point("ÿ", p, RideAxis::lateral, ResponseQuantity::acceleration, RideOutput::Frame::track),
      frame_test_point("z̈ body", p, RideAxis::vertical, ResponseQuantity::acceleration, RideOutput::Frame::body),
      frame_test_point("z̈ track", p, RideAxis::vertical, ResponseQuantity::acceleration, RideOutput::Frame::track)};
  RideOptions options;
  options.speeds = {20.0};
  const RideResult r = solve_ride(s, cross_level_only(0.06, 2.0), outputs, options);
  const RideAtSpeed& at = r.speeds[0];
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double w4 = std::pow(2 * kPi * r.frequencies(k), 4);
    EXPECT_NEAR(at.outputs[1].psd(k), w4 * at.outputs[0].psd(k), 1e-12 * w4 * at.outputs[0].psd(k));
    EXPECT_EQ(at.outputs[2].psd(k), at.outputs[3].psd(k));
  }
  EXPECT_EQ(at.outputs[2].rms, at.outputs[3].rms);
  EXPECT_EQ(at.outputs[2].weighted_rms, at.outputs[3].weighted_rms);
}

// The time domain reads the same g·φ: the simulated history of a periodic realisation equals
// H·X in every bin (check (a), the state space's H with g·φ in its output row: 1e-6, as in
// realisation_checks_test), and its RMS matches the frequency domain's (check (c)) within 15 %:
// the realisation's scatter, about 4 % in the RMS for this 1.6 Hz roll over 410 s (the
// displacement's 3.7 % of realisation_checks_test, a similar narrow band), times four, and the
// grid's 1 %. The bound discriminates: the track frame's RMS differs from the body frame's by
// more than 30 % here (a point 0.1 m above the roll axis: hω² is 1 m/s² per rad at the roll
// against g's 9.81), checked too.
TEST(RideFrame, TimeDomainReadsTheSameGravityTermAsTheFrequencyDomain) {
  const LinearSystem s = rolling_body();
  constexpr double kSpeed = 20.0;
  TrackSynthesisOptions synthesis;
  synthesis.length = 8192.0;
  synthesis.step = 0.25;
  synthesis.seed = 5;
  // The band's ends half-way between the realisation's lines (no edge bias in the sum over lines).
  const double dOmega = 2 * kPi / synthesis.length;
  const TrackIrregularitySpectra track =
      cross_level_only((std::floor(0.06 / dOmega) + 0.5) * dOmega, (std::floor(2.0 / dOmega) + 0.5) * dOmega);
  const TrackGeometry geometry = synthesise_track(track, synthesis);
  const Eigen::Vector3d p(0.0, 0.0, 0.1);
  const std::vector<RideOutput> body{
      frame_test_point("body", p, RideAxis::lateral, ResponseQuantity::acceleration, RideOutput::Frame::body)};
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = synthesis.step / kSpeed;
  const RideSimulationResult simulated = simulate_ride(s, geometry, body, o);
  const RideFftChecks checks = check_ride_realisation(s, track, geometry, simulated, o);
  ASSERT_TRUE(checks.exact_bin_error);
  EXPECT_LT(*checks.exact_bin_error, 1e-6);
  ASSERT_EQ(checks.rms_difference.size(), 1u);
  RecordProperty("body_frame_rms_difference", std::to_string(checks.rms_difference[0]));
  EXPECT_LT(std::abs(checks.rms_difference[0]), 0.15);
  RideOptions options;
  options.speeds = {kSpeed};
  std::vector<RideOutput> both = body;
  both.push_back(frame_test_point("track", p, RideAxis::lateral, ResponseQuantity::acceleration,
                                  RideOutput::Frame::track));
  const RideResult r = solve_ride(s, track, both, options);
  EXPECT_GT(r.speeds[0].outputs[0].rms / r.speeds[0].outputs[1].rms, 1.3);
  bool noted = false;
  for (const std::string& n : simulated.notes) noted = noted || n.find("frame = body") != std::string::npos;
  EXPECT_TRUE(noted);
}

// An output that only the accelerometer's gravity term moves is answered, not refused as zero.
// With its longitudinal motion held, the body's point at its centre reads ẍ = 0 in the track
// frame (refused: nothing moves it), but an accelerometer there, fixed to the pitching body,
// reads −g·θ. Vertical level pitches the body (the springs at x = ±3 m meet it 6 m/V apart), and
// θ is the longitudinal displacement of a point 1 m above the centre (x = z·θ for a rotation θ
// about y), so the reading's PSD is g² times that point's at every frequency (1e-12: round-off
// of the products; the two rows are the same row scaled by −g).
TEST(RideFrame, OutputOnlyGravityMovesIsNotRefusedAsZero) {
  const LinearSystem s = rolling_body();
  TrackIrregularitySpectra t;
  t.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.06, 2.0});
  RideOptions options;
  options.speeds = {20.0};
  const RideOutput centre = frame_test_point("ẍ body", Eigen::Vector3d(0, 0, 0), RideAxis::longitudinal,
                                            ResponseQuantity::acceleration, RideOutput::Frame::body);
  const RideOutput pitch = frame_test_point("x 1 m up", Eigen::Vector3d(0, 0, 1), RideAxis::longitudinal,
                                           ResponseQuantity::displacement, RideOutput::Frame::track);
  const RideResult r = solve_ride(s, t, {centre, pitch}, options);
  const RideAtSpeed& at = r.speeds[0];
  int checked = 0;
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) {
    const double theta = at.outputs[1].psd(k);
    if (!(theta > 0.0)) continue;
    const double g2 = kFrameTestGravity * kFrameTestGravity;
    EXPECT_NEAR(at.outputs[0].psd(k), g2 * theta, 1e-12 * g2 * theta) << r.frequencies(k);
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(at.outputs[0].rms, 0.0);
  // The same point read in the track's frame has nothing to move it: refused, naming the output.
  RideOutput inertial = centre;
  inertial.frame = RideOutput::Frame::track;
  try {
    solve_ride(s, t, {inertial}, options);
    ADD_FAILURE() << "a track-frame ẍ of a body held longitudinally was answered";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'ẍ body': no degree of freedom of this model moves it"), std::string::npos)
        << e.what();
  }
}

// A body that cannot roll (roll held) reads ÿ in the body frame: there is no tilt for gravity to
// act along. The answer is the track frame's to the bit (the same row), and a note says that the
// tilted-axis reading asked for is not what the model can give, naming the output and the body,
// in the frequency and the time domain alike. Alignment moves the body sideways.
TEST(RideFrame, BodyFrameOnABodyThatCannotRollReadsTheInertialAccelerationAndSaysSo) {
  const LinearSystem s = rolling_body({Motion::longitudinal, Motion::roll});
  TrackIrregularitySpectra t;
  t.alignment = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {0.06, 2.0});
  const Eigen::Vector3d p(1.0, 0.5, 0.8);
  const std::vector<RideOutput> outputs{
      frame_test_point("ÿ body", p, RideAxis::lateral, ResponseQuantity::acceleration, RideOutput::Frame::body),
      frame_test_point("ÿ track", p, RideAxis::lateral, ResponseQuantity::acceleration, RideOutput::Frame::track)};
  RideOptions options;
  options.speeds = {20.0};
  const RideResult r = solve_ride(s, t, outputs, options);
  const RideAtSpeed& at = r.speeds[0];
  EXPECT_GT(at.outputs[0].rms, 0.0);
  for (Eigen::Index k = 0; k < r.frequencies.size(); ++k) EXPECT_EQ(at.outputs[0].psd(k), at.outputs[1].psd(k));
  EXPECT_EQ(at.outputs[0].rms, at.outputs[1].rms);
  const auto untilted_notes = [](const std::vector<std::string>& notes) {
    int n = 0;
    for (const std::string& note : notes)
      n += note.find("output 'ÿ body' asks for frame = body, but body 'body' has no roll freedom") != std::string::npos &&
           note.find("reads ÿ alone, with no g·φ term") != std::string::npos;
    return n;
  };
  EXPECT_EQ(untilted_notes(r.notes), 1);
  // The rolling body gets no such note.
  EXPECT_EQ(untilted_notes(solve_ride(rolling_body(), t, outputs, options).notes), 0);
  TrackSynthesisOptions synthesis;
  synthesis.length = 512.0;
  synthesis.step = 0.25;
  synthesis.seed = 3;
  RideSimulationOptions o;
  o.speed = 20.0;
  o.time_step = synthesis.step / o.speed;
  const RideSimulationResult simulated = simulate_ride(s, synthesise_track(t, synthesis), {outputs[0]}, o);
  EXPECT_EQ(untilted_notes(simulated.notes), 1);
}

TEST(EnumNames, RideOutputFrame) {
  for (RideOutput::Frame f : {RideOutput::Frame::body, RideOutput::Frame::track})
    EXPECT_EQ(ride_frame_from_string(to_string(f)), f);
  EXPECT_FALSE(ride_frame_from_string("inertial").has_value());
  EXPECT_EQ(RideOutput().frame, RideOutput::Frame::body);  // the standard's measurement by default
}

}  // namespace
}  // namespace railmodal::test
