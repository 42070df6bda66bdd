// The time-domain run's options as a scene leaves them to the library: the default step (fine
// enough for the digital weightings), the note on a coarse one, the averaging window carried
// into the result the report reads, and the contact half spacing that turns cross-level into
// roll.
#include <gtest/gtest.h>

#include <cmath>

#include "railmodal/ride_simulation.hpp"
#include "ride/ride_test_systems.hpp"
#include "test_support.hpp"

// Its own namespace: in a unity batch beside ride_simulation_test.cpp, whose helpers share names.
namespace railmodal::test::run_options {
namespace {

constexpr double kMass = 10000.0, kStiffness = 4e5, kDamping = 8e3;  // 1 Hz bounce, ζ ≈ 0.13 on two wheels

RideOutput body_acceleration() {
  RideOutput o;
  o.name = "body acceleration";
  o.body = "body";
  o.quantity = ResponseQuantity::acceleration;
  return o;
}

// `samples` samples `step` m apart of a periodic cosine of `cycles` periods in the given slot.
TrackGeometry cosine_track(Eigen::VectorXd TrackGeometry::*slot, int cycles, int samples, double step) {
  TrackGeometry g;
  g.step = step;
  g.periodic = true;
  (g.*slot).resize(samples);
  for (int n = 0; n < samples; ++n) (g.*slot)(n) = 0.001 * std::cos(2 * kPi * cycles * n / samples);
  return g;
}

bool has_note(const RideSimulationResult& r, const std::string& part) {
  for (const std::string& note : r.notes)
    if (note.find(part) != std::string::npos) return true;
  return false;
}

TEST(RideRunOptions, TheDefaultStepIsAWholeFractionOfTheTrackStepAtMostOneMillisecond) {
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, {4.3, -4.3});
  RideSimulationOptions o;
  o.speed = 25.0;
  ASSERT_EQ(o.time_step, 0.0);  // the default
  // Δx/V = 0.0625/25 = 2.5 ms: three steps of 0.833 ms each
  const TrackGeometry track = cosine_track(&TrackGeometry::vertical_level, 40, 1600, 1.0 / 16);
  const RideSimulationResult r = simulate_ride(system, track, {body_acceleration()}, o);
  EXPECT_NEAR(r.time_step, 2.5e-3 / 3.0, 1e-15);
  EXPECT_FALSE(has_note(r, "sampling at"));
  // Δx/V = 0.01/25 = 0.4 ms, already below 1 ms: the default is the track's own step
  const TrackGeometry fine = cosine_track(&TrackGeometry::vertical_level, 40, 10000, 0.01);
  EXPECT_NEAR(simulate_ride(system, fine, {body_acceleration()}, o).time_step, 4e-4, 1e-15);
}

TEST(RideRunOptions, ACoarseStepIsNotedWithTheWeightingsError) {
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, {4.3, -4.3});
  RideSimulationOptions o;
  o.speed = 25.0;
  o.time_step = 2.5e-3;  // 400 Hz: 3.5·(16/400)² = 0.56 % at 16 Hz
  const TrackGeometry track = cosine_track(&TrackGeometry::vertical_level, 40, 1600, 1.0 / 16);
  const RideSimulationResult r = simulate_ride(system, track, {body_acceleration()}, o);
  EXPECT_TRUE(has_note(r, "sampling at 400 Hz: the digital weightings are off by about 0.56 % at 16 Hz")) << [&] {
    std::string all;
    for (const std::string& n : r.notes) all += n + "\n";
    return all;
  }();
}

TEST(RideRunOptions, TheWindowIsTheResultsAndSizesTheWindowValues) {
  const LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, {0.0});
  RideSimulationOptions o;
  o.speed = 25.0;
  o.window = 4.0;
  // 1000 m at 25 m/s: 40 s, ten windows of 4 s (eight of the default 5 s)
  const TrackGeometry track = cosine_track(&TrackGeometry::vertical_level, 200, 16000, 1.0 / 16);
  const RideSimulationResult r = simulate_ride(system, track, {body_acceleration()}, o);
  EXPECT_EQ(r.window, 4.0);
  EXPECT_EQ(r.histories[0].window_rms.size(), 10);
}

TEST(RideRunOptions, TheContactHalfSpacingScalesTheRollOfCrossLevel) {
  // One wheel 0.75 m left of the centre line: it rises by Δz·0.75/(2b), so doubling b halves
  // every output of this linear system (to round-off).
  LinearSystem system = bouncing_mass(kMass, kStiffness, kDamping, {0.0});
  system.track_inputs[0].point.y() = 0.75;
  const TrackGeometry track = cosine_track(&TrackGeometry::cross_level, 40, 1600, 1.0 / 16);
  RideSimulationOptions o;
  o.speed = 25.0;
  o.contact_half_spacing = 0.75;
  const double narrow = simulate_ride(system, track, {body_acceleration()}, o).histories[0].rms;
  o.contact_half_spacing = 1.5;
  const double wide = simulate_ride(system, track, {body_acceleration()}, o).histories[0].rms;
  ASSERT_GT(narrow, 0.0);
  EXPECT_NEAR(wide / narrow, 0.5, 1e-12);
}

}  // namespace
}  // namespace railmodal::test::run_options
