// fft-check compares only what the record holds: a mode the initial conditions leave at rest
// is "not excited", never an "ok" read off round-off, and each excited mode is checked on a
// DOF where it moves.
#include <cmath>
#include <fstream>
#include <sstream>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string data(const std::string& file) { return std::string(RAILMODAL_DATA_DIR) + "/" + file; }

// The two-axle wagon's bounce and pitch decouple exactly (a symmetric wagon: two-axle digest,
// eq. (159)); released in bounce alone, its pitch holds nothing but round-off.
TEST(FftCheck, ModeTheReleaseLeavesAtRestIsNotExcited) {
  const std::string scene_file = write_temp("bounce_release.toml", "[scene]\nname = \"bounce release\"\nvehicle = \"" +
                                                                       data("vehicles/two_axle_freight_wagon.toml") +
                                                                       R"("
dofs = "vertical"
[simulation]
duration = "20 s"
time_step = "2 ms"
[[simulation.initial]]
dof = "body.bounce"
displacement = "10 mm"
)");
  const Scene scene = load_scene(scene_file);
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  const FftCheckResult r = fft_check(scene, vehicle);
  ASSERT_EQ(r.checks.size(), 2u);
  for (const FftCheck& c : r.checks) {
    if (c.mode_name == "body bounce") {
      EXPECT_TRUE(c.excited);
      EXPECT_EQ(c.modal_amplitude_ratio, 1.0);
      ASSERT_TRUE(c.peak_hz);
      EXPECT_TRUE(c.within_resolution) << *c.peak_hz << " against " << c.modal_hz;
    } else {
      EXPECT_EQ(c.mode_name, "body pitch");
      // Exactly decoupled: the pitch coordinate stays at round-off of the bounce (1e-16 of it,
      // times the steps' accumulation), far below the 1e-6 floor.
      EXPECT_FALSE(c.excited);
      EXPECT_LT(c.modal_amplitude_ratio, 1e-10);
      EXPECT_FALSE(c.peak_hz);
    }
  }
  std::ostringstream table;  // says so instead of a peak
  write_fft_check(table, r, scene, vehicle, OutputFormat::table);
  const std::string text = table.str();
  const size_t pitch = text.find("body pitch");
  ASSERT_NE(pitch, std::string::npos) << text;
  const std::string row = text.substr(pitch, text.find('\n', pitch) - pitch);
  EXPECT_NE(row.find("not excited (modal amplitude "), std::string::npos) << row;
}

// The resort car released in body and front-bogie motions (the bundled scene): the two bogie
// pitch modes are a repeated pair (4.3107 Hz, bogies that do not couple in pitch), whose basis
// may put one mode mostly on the rear bogie, which the release leaves at rest. Every check must
// read a DOF that moves, and find the mode there within the resolution.
TEST(FftCheck, EveryModeIsCheckedWhereItMoves) {
  const Scene scene = load_scene(data("scenes/resort_car_free_response.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  ASSERT_EQ(r.checks.size(), 6u);
  for (const FftCheck& c : r.checks) {
    EXPECT_TRUE(c.excited) << c.mode_name;
    int dof = -1;
    for (size_t d = 0; d < r.history.labels.size(); ++d)
      if (r.history.labels[d] == c.dof) dof = static_cast<int>(d);
    ASSERT_GE(dof, 0) << c.dof;
    // Released by millimetres and milliradians: a DOF that moves moves by more than 1e-6 (m or
    // rad); round-off stays below 1e-12.
    EXPECT_GT(r.history.displacement.col(dof).cwiseAbs().maxCoeff(), 1e-6) << c.mode_name << " on " << c.dof;
    ASSERT_TRUE(c.peak_hz) << c.mode_name;
    EXPECT_TRUE(c.within_resolution) << c.mode_name << ": " << *c.peak_hz << " against " << c.modal_hz;
  }
}

// Issue 17 item 9: a short record of a friction scene used to pass as "ok" — the two-axle
// wagon at 75 km/h over 10 m joints (the bundled Example 3 scene) cut to 1.5 s gave peaks 16 %
// and 18 % off the modes, each "within the resolution" because its line was 0.9–1.4 Hz wide.
// A nonlinear check is held to FftCheck::kNonlinearTolerance and must resolve it: this record
// cannot, and the verdict says FAILED; the report says what was compared and within what.
TEST(FftCheck, ShortFrictionRecordFailsWithAStatedTolerance) {
  std::string text;
  {
    std::ifstream in(data("scenes/two_axle_freight_wagon_joints_friction.toml"));
    std::stringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  const auto replace = [&text](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("duration = \"3 s\"", "duration = \"1.5 s\"");
  replace("\"../vehicles/two_axle_freight_wagon.toml\"", "\"" + data("vehicles/two_axle_freight_wagon.toml") + "\"");
  const Scene scene = load_scene(write_temp("short_friction.toml", text));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  EXPECT_TRUE(r.nonlinear);
  EXPECT_FALSE(r.passed);
  for (const FftCheck& c : r.checks) {
    EXPECT_EQ(c.tolerance, FftCheck::kNonlinearTolerance);
    EXPECT_FALSE(c.passed) << c.mode_name;
    EXPECT_GT(c.resolution_hz, c.tolerance * c.modal_hz) << c.mode_name;  // why: not resolved
  }
  std::ostringstream table;
  write_fft_check(table, r, scene, load_vehicle(scene.vehicle_file), OutputFormat::table);
  EXPECT_NE(table.str().find("within 5.0 %"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("FAILED: not resolved"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("verdict: FAILED (2 of 2 checks)"), std::string::npos) << table.str();
}

// A linear release holds its line within the line's width: the verdict passes.
TEST(FftCheck, LinearReleasePassesItsVerdict) {
  const Scene scene = load_scene(data("scenes/resort_car_free_response.toml"));
  const FftCheckResult r = fft_check(scene, load_vehicle(scene.vehicle_file));
  EXPECT_FALSE(r.nonlinear);
  EXPECT_TRUE(r.passed);
  for (const FftCheck& c : r.checks) EXPECT_TRUE(c.passed) << c.mode_name;
}

}  // namespace
}  // namespace railmodal::test
