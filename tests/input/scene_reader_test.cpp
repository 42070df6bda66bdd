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

// The [simulation] table: effects, tolerances and initial conditions; bad ones named.
const std::string kSimulation = R"(
[simulation]
speed = "75 km/h"
duration = "2 s"
time_step = "1 ms"
effects = ["leaf_friction", "viscous_dampers"]
tolerance = 1e-9
event_tolerance = "1e-10 s"
[[simulation.initial]]
dof = "body.bounce"
displacement = "-25 mm"
)";

TEST(SceneReader, Simulation) {
  const Scene s = load_scene(write_scene(kScene + kSimulation));
  ASSERT_TRUE(s.simulation);
  EXPECT_NEAR(s.simulation->speed, 75 / 3.6, 1e-12);
  EXPECT_EQ(s.simulation->effects, (std::vector<std::string>{"leaf_friction", "viscous_dampers"}));
  EXPECT_TRUE(scene_effects(s).leaf_friction);
  EXPECT_FALSE(scene_effects(s).progressive_springs);
  EXPECT_EQ(s.simulation->tolerance, 1e-9);
  EXPECT_EQ(s.simulation->event_tolerance, 1e-10);
  ASSERT_EQ(s.simulation->initial.size(), 1u);
  EXPECT_NEAR(s.simulation->initial[0].displacement, -0.025, 1e-15);
}

TEST(SceneReader, SimulationErrors) {
  auto expect_simulation_error = [](const std::string& from, const std::string& to, const std::vector<std::string>& parts) {
    std::string text = kSimulation;
    text.replace(text.find(from), from.size(), to);
    try {
      load_scene(write_scene(kScene + text));
      FAIL() << "no error for " << to;
    } catch (const InputError& e) {
      for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expect_simulation_error("\"viscous_dampers\"", "\"coulomb_friction\"", {"key 'simulation.effects'", "unknown effect 'coulomb_friction'"});
  expect_simulation_error("\"viscous_dampers\"", "\"leaf_friction\"", {"key 'simulation.effects'", "twice"});
  expect_simulation_error("tolerance = 1e-9", "tolerance = 0.5", {"key 'simulation.tolerance'", "below 1e-2"});
  expect_simulation_error("tolerance = 1e-9", "tolerance = -1e-9", {"key 'simulation.tolerance'"});
  expect_simulation_error("\"1e-10 s\"", "\"1e-10 mm\"", {"key 'simulation.event_tolerance'", "expected a time"});
  // ε·2 s = 4.4e-16 s: 1e-30 s would hang the event search (issue 18, item 2).
  expect_simulation_error("\"1e-10 s\"", "\"1e-30 s\"",
                          {"key 'simulation.event_tolerance'", "finer than double precision", "at least 4.4e-16 s"});
  expect_simulation_error("speed = \"75 km/h\"\n", "", {"key 'simulation.speed'", "missing"});
  expect_simulation_error("time_step = \"1 ms\"", "time_step = \"3 s\"", {"key 'simulation.time_step'", "longer than the duration"});
  expect_simulation_error("speed = \"75 km/h\"", "speed = \"75 km/h\"\nfinal_speed = \"100 kgf\"",
                          {"key 'simulation.final_speed'", "expected a speed"});
  std::string ramp_text = kSimulation;
  const std::string speed_line = "speed = \"75 km/h\"";
  ramp_text.replace(ramp_text.find(speed_line), speed_line.size(), speed_line + "\nfinal_speed = \"100 km/h\"");
  const Scene ramp = load_scene(write_scene(kScene + ramp_text));
  EXPECT_NEAR(ramp.simulation->final_speed, 100 / 3.6, 1e-12);
}

// An output the vehicle does not have is an input error naming the scene.
TEST(SceneReader, UnknownOutputDofIsReported) {
  std::string text = kScene;
  text.replace(text.find("body.bounce"), 11, "body.sway");
  const Scene s = load_scene(write_scene(text));
  EXPECT_THROW(study_critical_speeds(s, load_vehicle(s.vehicle_file)), InputError);
}

// A name only the assembled vehicle can check (a DOF, a body, the number of wheelsets) is
// refused at its key, line and column, listing what there is (issue 18, items 11 and 15).
void expect_misfit(const std::string& scene_text, const std::string& where, const std::vector<std::string>& parts) {
  const Scene s = load_scene(write_scene(scene_text));
  try {
    check_scene_fits(s, assemble(load_vehicle(s.vehicle_file), s.dofs));
    FAIL() << "no error for " << where;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.toml:" + where + ": error: "), std::string::npos) << e.what();
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(SceneReader, NamesTheVehicleLacksAreRefusedAtTheirKey) {
  const Scene good = load_scene(write_scene(kScene + kSimulation));
  EXPECT_NO_THROW(check_scene_fits(good, assemble(load_vehicle(good.vehicle_file), good.dofs)));
  std::string output = kScene;
  output.replace(output.find("dof = \"body.bounce\""), 19, "dof = \"body.sway\"");
  expect_misfit(output, "14:7",
                {"key 'output[0].dof': 'body.sway' is not a degree of freedom", "(body.bounce, body.pitch)"});
  std::string outputs = kSimulation;
  outputs.replace(outputs.find("time_step = \"1 ms\""), 18,
                  "time_step = \"1 ms\"\noutputs = [\"body.bounce\", \"nope\"]");
  expect_misfit(kScene + outputs, "21:27", {"key 'simulation.outputs': 'nope' is not a degree of freedom"});
  std::string initial = kSimulation;
  initial.replace(initial.find("dof = \"body.bounce\""), 19, "dof = \"body.sway\"");
  expect_misfit(kScene + initial, "25:7", {"key 'simulation.initial[0].dof': 'body.sway'"});
  const std::string eccentric =
      "[[source]]\nkind = \"wheel_eccentricity\"\nwheel_diameter = \"950 mm\"\n"
      "eccentricity = \"1 mm\"\nphases = [\"0 deg\"]\n";
  expect_misfit(kScene + eccentric, "20:10", {"key 'source[1].phases': 1 phases given for 2 wheelsets"});
  const std::string unbalance =
      "[[source]]\nkind = \"unbalance\"\nbody = \"frame\"\nwheel_diameter = \"950 mm\"\n"
      "[[source.rotating]]\npoint = [\"0 m\", \"0 m\", \"0 m\"]\nmass = \"10 kg\"\nradius = \"1 m\"\n";
  expect_misfit(kScene + unbalance, "18:8", {"key 'source[1].body': the vehicle has no body 'frame'"});
}

// A vehicle path the system cannot follow is the scene's error, with the system's reason,
// not an exception of std::filesystem (issue 18, item 12).
TEST(SceneReader, UnreachableVehiclePathIsAnInputError) {
  const std::filesystem::path folder = std::filesystem::path(write_scene(kScene)).parent_path();
  std::filesystem::remove(folder / "loop_a");
  std::filesystem::remove(folder / "loop_b");
  std::filesystem::create_symlink("loop_b", folder / "loop_a");
  std::filesystem::create_symlink("loop_a", folder / "loop_b");
  expect_error("vehicle = \"scene_wagon.toml\"", "vehicle = \"loop_a/wagon.toml\"",
               {"scene.toml:3:11: error: key 'scene.vehicle': cannot reach the file", "loop_a/wagon.toml: "});
  std::string long_name;
  for (int i = 0; i < 2500; ++i) long_name += "a/";
  expect_error("vehicle = \"scene_wagon.toml\"", "vehicle = \"" + long_name + "wagon.toml\"",
               {"scene.toml:3:11: error: key 'scene.vehicle': cannot reach the file"});
}

}  // namespace
}  // namespace railmodal::test
