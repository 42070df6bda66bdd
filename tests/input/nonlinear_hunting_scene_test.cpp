// Nonlinear-hunting scenes: [nonlinear_hunting] loads with its units, only the effects whose
// tables the file gives are simulated, and bad values name file, line and key.
#include <gtest/gtest.h>

#include <algorithm>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kHuntingScene = R"([scene]
name = "hunting scene"
vehicle = "hunting_wheelset.toml"
[nonlinear_hunting]
start_speed = "270 km/h"
end_speed = "180 km/h"
ramp_rate = "50 cm/s^2"
disturbance = "-5 mm"
tolerance = "0.18 km/h"
hold_periods = 200
hold_margin = "2 m/s"
extinction_amplitude = "0.2 mm"
amplitude_bound = "5 cm"
[nonlinear_hunting.creep_saturation]
law = "shen_hedrick_elkins"
friction_coefficient = 0.3
wheel_load = "60 kN"
contact_angle = "0.05 rad"
[nonlinear_hunting.flange_contact]
clearance = "9 mm"
stiffness = "20 MN/m"
)";

std::string write_hunting_scene(const std::string& text) {
  write_temp("hunting_wheelset.toml", "[vehicle]\nname = \"w\"\n");  // only its path is read with the scene
  return write_temp("hunting_scene.toml", text);
}

std::string hunting_scene_text_with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) ADD_FAILURE() << "not in the scene: " << from;
  else text.replace(at, from.size(), to);
  return text;
}

bool names_effect(const NonlinearHuntingOptions& o, NonlinearEffect e) {
  return std::find(o.effects.begin(), o.effects.end(), e) != o.effects.end();
}

// Replaces `from` by `to` and expects an InputError holding every part.
void expect_hunting_error(const std::string& from, const std::string& to, const std::vector<std::string>& parts) {
  try {
    load_scene(write_hunting_scene(hunting_scene_text_with(kHuntingScene, from, to)));
    FAIL() << "no error for " << to;
  } catch (const InputError& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(NonlinearHuntingScene, EveryKeyLoadsInSI) {
  const Scene s = load_scene(write_hunting_scene(kHuntingScene));
  ASSERT_TRUE(s.nonlinear_hunting);
  const NonlinearHuntingOptions& o = *s.nonlinear_hunting;
  EXPECT_DOUBLE_EQ(o.start_speed, 75.0);
  EXPECT_DOUBLE_EQ(o.end_speed, 50.0);
  EXPECT_DOUBLE_EQ(o.ramp_rate, 0.5);
  EXPECT_DOUBLE_EQ(o.disturbance, -0.005);  // either side: the sign is the side it starts on
  EXPECT_DOUBLE_EQ(o.tolerance, 0.05);
  EXPECT_EQ(o.hold_periods, 200);
  EXPECT_DOUBLE_EQ(o.hold_margin, 2.0);
  EXPECT_DOUBLE_EQ(o.extinction_amplitude, 2e-4);
  EXPECT_DOUBLE_EQ(o.amplitude_bound, 0.05);
  EXPECT_DOUBLE_EQ(o.friction_coefficient, 0.3);
  ASSERT_TRUE(o.wheel_load);
  EXPECT_DOUBLE_EQ(*o.wheel_load, 60e3);
  EXPECT_DOUBLE_EQ(o.contact_angle, 0.05);
  EXPECT_DOUBLE_EQ(o.flange_clearance, 0.009);
  EXPECT_DOUBLE_EQ(o.flange_stiffness, 2e7);
  EXPECT_TRUE(names_effect(o, NonlinearEffect::creep_saturation));
  EXPECT_TRUE(names_effect(o, NonlinearEffect::flange_contact));
  EXPECT_EQ(o.effects.size(), 2u);
  // A hunting scene needs no [speed] range and no sources.
  EXPECT_TRUE(s.sources.empty());
  EXPECT_FALSE(s.simulation);
}

TEST(NonlinearHuntingScene, OnlyTheNamedEffectsAreSimulated) {
  const std::string cut = "[nonlinear_hunting.flange_contact]\nclearance = \"9 mm\"\nstiffness = \"20 MN/m\"\n";
  const Scene saturation = load_scene(write_hunting_scene(hunting_scene_text_with(kHuntingScene, cut, "")));
  ASSERT_TRUE(saturation.nonlinear_hunting);
  EXPECT_TRUE(names_effect(*saturation.nonlinear_hunting, NonlinearEffect::creep_saturation));
  EXPECT_FALSE(names_effect(*saturation.nonlinear_hunting, NonlinearEffect::flange_contact));

  const auto at = kHuntingScene.find("[nonlinear_hunting.creep_saturation]");
  const Scene linear = load_scene(write_hunting_scene(kHuntingScene.substr(0, at)));
  ASSERT_TRUE(linear.nonlinear_hunting);
  EXPECT_TRUE(linear.nonlinear_hunting->effects.empty());  // Kalker's linear law, no flange
  // Defaults the file leaves: the library's.
  const NonlinearHuntingOptions defaults;
  EXPECT_EQ(linear.nonlinear_hunting->friction_coefficient, defaults.friction_coefficient);
  EXPECT_FALSE(linear.nonlinear_hunting->wheel_load);
}

TEST(NonlinearHuntingScene, BadValuesNameTheKey) {
  expect_hunting_error("law = \"shen_hedrick_elkins\"", "law = \"polach\"",
                       {"hunting_scene.toml:", "nonlinear_hunting.creep_saturation.law", "polach", "shen_hedrick_elkins"});
  expect_hunting_error("end_speed = \"180 km/h\"", "end_speed = \"300 km/h\"",
                       {"hunting_scene.toml:6:", "nonlinear_hunting.end_speed", "below start_speed"});
  expect_hunting_error("disturbance = \"-5 mm\"", "disturbance = 0", {"nonlinear_hunting.disturbance", "not be zero"});
  expect_hunting_error("ramp_rate = \"50 cm/s^2\"", "ramp_rate = \"50 cm/s\"", {"nonlinear_hunting.ramp_rate"});
  expect_hunting_error("friction_coefficient = 0.3", "friction_coefficient = 3",
                       {"nonlinear_hunting.creep_saturation.friction_coefficient", "below 2"});
  expect_hunting_error("friction_coefficient = 0.3", "", {"nonlinear_hunting.creep_saturation", "friction_coefficient"});
  expect_hunting_error("stiffness = \"20 MN/m\"", "stiffness = \"20 MN\"", {"nonlinear_hunting.flange_contact.stiffness"});
  expect_hunting_error("clearance = \"9 mm\"", "clearance = \"-9 mm\"", {"nonlinear_hunting.flange_contact.clearance"});
  expect_hunting_error("hold_periods = 200", "hold_periods = 5", {"nonlinear_hunting.hold_periods", "from 10"});
  expect_hunting_error("amplitude_bound = \"5 cm\"", "amplitude_bound = \"0.1 mm\"",
                       {"nonlinear_hunting.amplitude_bound", "above extinction_amplitude"});
  expect_hunting_error("contact_angle = \"0.05 rad\"", "contact_angle = \"70 deg\"",
                       {"nonlinear_hunting.creep_saturation.contact_angle", "below 1 rad"});
  // A misspelt effect is an unknown key, never an effect silently left out.
  expect_hunting_error("[nonlinear_hunting.flange_contact]", "[nonlinear_hunting.flange]",
                       {"nonlinear_hunting.flange", "unknown key"});
  expect_hunting_error("start_speed = \"270 km/h\"\n", "", {"nonlinear_hunting", "start_speed"});
}

}  // namespace
}  // namespace railmodal::test
