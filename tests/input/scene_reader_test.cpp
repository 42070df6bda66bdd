// Scene files: good scenes load; bad ones name file, line, column and key.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kScene = R"([scene]
name = "test scene"
vehicle = "scene_wagon.toml"
dofs = "vertical"
[speed]
min = "10 km/h"
max = "100 km/h"
step = "1 km/h"
[[source]]
kind = "rail_joints"
rail_length = "12.5 m"
dip_depth = "5 mm"
[[output]]
dof = "body.bounce"
quantity = "acceleration"
)";

std::string write_scene(const std::string& text) {
  write_temp("scene_wagon.toml", R"([vehicle]
name = "w"
template = "two-axle"
[body]
weight = "20000 kgf"
cg_height = "100 cm"
radius_of_gyration = { roll = "110 cm", pitch = "260 cm" }
[suspension]
wheelbase = "400 cm"
spring_spacing = "200 cm"
spring = { kind = "coil", stiffness = "1000 kgf/cm" }
)");
  return write_temp("scene.toml", text);
}

void expect_error(const std::string& from, const std::string& to, const std::vector<std::string>& parts) {
  std::string text = kScene;
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    load_scene(write_scene(text));
    FAIL() << "no error for " << to;
  } catch (const InputError& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(SceneReader, GoodSceneLoads) {
  const Scene s = load_scene(write_scene(kScene));
  EXPECT_EQ(s.name, "test scene");
  EXPECT_EQ(s.dofs, DofSet::vertical);
  EXPECT_NEAR(s.min_speed, 10 / 3.6, 1e-12);
  EXPECT_NEAR(s.max_speed, 100 / 3.6, 1e-12);
  ASSERT_EQ(s.sources.size(), 1u);
  EXPECT_EQ(s.sources[0]->kind(), "rail_joints");
  EXPECT_EQ(s.sources[0]->wavelength(), 12.5);
  ASSERT_EQ(s.outputs.size(), 1u);
  EXPECT_EQ(s.outputs[0].quantity, ResponseQuantity::acceleration);
  EXPECT_NE(s.vehicle_file.find("scene_wagon.toml"), std::string::npos);
}

// Only the named sources are built: a scene with one source has one.
TEST(SceneReader, BuildsOnlyTheNamedSources) {
  const Scene s = load_scene(write_scene(kScene));
  EXPECT_EQ(s.sources.size(), 1u);
}

TEST(SceneReader, Errors) {
  expect_error("dip_depth = \"5 mm\"", "dip_depth = \"5 kgf\"", {"scene.toml:12:13", "key 'source[0].dip_depth'"});
  expect_error("kind = \"rail_joints\"", "kind = \"rail_jionts\"", {"key 'source[0].kind'", "unknown source"});
  expect_error("max = \"100 km/h\"", "max = \"5 km/h\"", {"key 'speed.max'", "above min"});
  expect_error("dof = \"body.bounce\"", "dof = \"body.bounce\"\nunits = \"mm\"", {"output[0].units"});
  expect_error("vehicle = \"scene_wagon.toml\"", "vehicle = \"missing.toml\"", {"key 'scene.vehicle'", "no such file"});
  expect_error("rail_length = \"12.5 m\"", "rail_length = \"12.5 m\"\ndip_length = \"20 m\"",
               {"key 'source[0].dip_length'", "cannot exceed"});
  expect_error("quantity = \"acceleration\"", "quantity = \"jerk\"", {"output[0].quantity"});
}

TEST(SceneReader, FrictionModel) {
  const Scene s = load_scene(write_scene(kScene + "[friction]\nmodel = \"equivalent_viscous\"\nreference_amplitude = \"5 mm\"\n"));
  EXPECT_NEAR(s.friction_reference_amplitude, 0.005, 1e-15);
  EXPECT_EQ(load_scene(write_scene(kScene)).friction_reference_amplitude, 0.0);
  expect_error("quantity = \"acceleration\"", "quantity = \"acceleration\"\n[friction]\nmodel = \"viscous\"",
               {"key 'friction.model'"});
  expect_error("quantity = \"acceleration\"", "quantity = \"acceleration\"\n[friction]\nmodel = \"equivalent_viscous\"",
               {"key 'friction.reference_amplitude'", "missing"});
}

// An output the vehicle does not have is an input error naming the scene.
TEST(SceneReader, UnknownOutputDofIsReported) {
  std::string text = kScene;
  text.replace(text.find("body.bounce"), 11, "body.sway");
  const Scene s = load_scene(write_scene(text));
  EXPECT_THROW(study_critical_speeds(s, load_vehicle(s.vehicle_file)), InputError);
}

}  // namespace
}  // namespace railmodal::test
