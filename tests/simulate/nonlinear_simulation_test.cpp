// The nonlinear path: only the named effects are built, the curve of a progressive spring,
// and what it refuses (with a message that says why).
#include <cmath>
#include <string>

#include "simulate/nonlinear_elements.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string scene_file(const std::string& name) { return std::string(RAILMODAL_DATA_DIR) + "/scenes/" + name; }

// The loads of a scene's sources, as the simulation builds them.
std::vector<HarmonicLoad> source_loads(const Scene& s, const LinearSystem& sys) {
  std::vector<HarmonicLoad> loads;
  for (const auto& source : s.sources)
    for (int k = 1; k <= source->harmonic_count(); ++k) loads.push_back(source->load(sys, s.simulation->speed, k));
  return loads;
}

// A scene builds exactly the nonlinear elements its effects name: the two-axle wagon's four
// leaf springs carry friction only under "leaf_friction"; it has no load–deflection curves,
// so "progressive_springs" builds nothing, and nothing named builds nothing.
TEST(NonlinearElements, OnlyTheNamedEffectsAreBuilt) {
  const Scene s = load_scene(scene_file("two_axle_freight_wagon_joints_friction.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  const LinearSystem sys = scene_system(s, v);
  const auto loads = source_loads(s, sys);

  const auto friction = simulate::nonlinear_elements(sys, loads, NonlinearEffects{true, false});
  ASSERT_EQ(friction.size(), 4u);
  for (const auto& e : friction) {
    EXPECT_GT(e.friction, 0.0);
    EXPECT_FALSE(e.curve);
    EXPECT_EQ(e.track.size(), loads.size());  // every harmonic of the joints under every wheel
  }
  EXPECT_TRUE(simulate::nonlinear_elements(sys, loads, NonlinearEffects{false, true}).empty());
  EXPECT_TRUE(simulate::nonlinear_elements(sys, loads, NonlinearEffects{}).empty());
}

// The Khanin spring's curve is followed only under "progressive_springs"; its friction-free
// coil builds no friction even when "leaf_friction" is named.
TEST(NonlinearElements, CurvesOnlyUnderProgressiveSprings) {
  const Scene s = load_scene(scene_file("khanin_spring_free_oscillation.toml"));
  const LinearSystem sys = scene_system(s, load_vehicle(s.vehicle_file));
  const auto both = simulate::nonlinear_elements(sys, {}, NonlinearEffects{true, true});
  ASSERT_EQ(both.size(), 1u);
  EXPECT_TRUE(both[0].curve);
  EXPECT_EQ(both[0].friction, 0.0);
  EXPECT_TRUE(simulate::nonlinear_elements(sys, {}, NonlinearEffects{true, false}).empty());
}

// With every nonlinearity left out, the nonlinear integrator and the linear path solve the
// same equations. Free motion: the linear path is exact, so they agree to the integrator's
// tolerance (1e-10 relative per step, a few hundred steps: 1e-8 of the 25 mm release).
// Forced: the linear path samples the load (first-order hold, O(Δt²)), so the difference is
// its error and falls by 4 when its step is halved.
TEST(NonlinearSimulation, NothingNamedMatchesTheLinearPath) {
  const Scene s = load_scene(scene_file("two_axle_freight_wagon_joints_friction.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  const LinearSystem sys = scene_system(s, v);
  SimulationOptions o;
  o.speed = s.simulation->speed;
  o.duration = 1.0;
  o.time_step = 2e-3;
  o.initial = s.simulation->initial;
  const TimeHistory free_linear = simulate_linear(sys, {}, o);
  const TimeHistory free_nonlinear = simulate_nonlinear(sys, {}, o, NonlinearEffects{});
  EXPECT_TRUE(free_nonlinear.events.empty());
  EXPECT_GT(free_nonlinear.steps_taken, 0);
  EXPECT_LT((free_linear.displacement - free_nonlinear.displacement).cwiseAbs().maxCoeff(), 1e-8 * 0.025);

  std::vector<const ExcitationSource*> sources;
  for (const auto& source : s.sources) sources.push_back(source.get());
  const TimeHistory reference = simulate_nonlinear(sys, sources, o, NonlinearEffects{});
  const TimeHistory coarse = simulate_linear(sys, sources, o);
  o.time_step = 1e-3;
  const TimeHistory fine = simulate_linear(sys, sources, o);
  double coarse_error = 0.0, fine_error = 0.0;
  for (int i = 0; i < reference.time.size(); ++i) {
    coarse_error = std::max(coarse_error, (coarse.displacement.row(i) - reference.displacement.row(i)).cwiseAbs().maxCoeff());
    fine_error = std::max(fine_error, (fine.displacement.row(2 * i) - reference.displacement.row(i)).cwiseAbs().maxCoeff());
  }
  EXPECT_NEAR(coarse_error / fine_error, 4.0, 0.6);  // second order; ±15 % for the higher-order terms
}

// The scene's choice decides the path: leaf_friction named → events; dropped → none.
TEST(NonlinearSimulation, SceneEffectsChooseThePath) {
  Scene s = load_scene(scene_file("leaf_spring_drop_test.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  EXPECT_TRUE(scene_effects(s).leaf_friction);
  EXPECT_FALSE(scene_effects(s).progressive_springs);
  EXPECT_FALSE(simulate_scene(s, v).events.empty());
  s.simulation->effects.clear();
  EXPECT_FALSE(scene_effects(s).any());
  const TimeHistory h = simulate_scene(s, v);
  EXPECT_TRUE(h.events.empty());
  // Undamped and frictionless: it swings back to the full 39 mm (exact linear path).
  EXPECT_NEAR(h.displacement.col(0).maxCoeff(), 0.039, 1e-9);
}

// A Khanin-type curve: 260 kg/cm to the kink at 70 mm, 356 kg/cm beyond (Example 10).
TEST(LoadDeflectionCurve, PiecewiseLinearWithKink) {
  LoadDeflectionCurve c;
  c.deflection = {0.0, 0.070, 0.170};
  c.load = {0.0, 260 * 7.0 * kKgf, (260 * 7.0 + 356 * 10.0) * kKgf};
  EXPECT_NEAR(c.load_at(0.035), 260 * 3.5 * kKgf, 1e-9);
  EXPECT_NEAR(c.load_at(0.120), (260 * 7.0 + 356 * 5.0) * kKgf, 1e-9);
  EXPECT_NEAR(c.load_at(0.200), (260 * 7.0 + 356 * 13.0) * kKgf, 1e-9);  // the last segment continues
  EXPECT_NEAR(c.deflection_at(c.load_at(0.120)), 0.120, 1e-15);
  // At the kink the stiffer segment above it carries the load (the linear models then use the
  // stiffness the first dynamic compression meets).
  EXPECT_NEAR(c.stiffness_at(260 * 7.0 * kKgf), 356 * kKgfPerCm, 1e-9);
  EXPECT_NEAR(c.stiffness_at(100 * kKgf), 260 * kKgfPerCm, 1e-9);
}

// What the nonlinear path refuses, with the reason.
TEST(NonlinearSimulation, RefusesWhatItCannotModel) {
  const std::string vehicle = write_temp("series.toml", R"([vehicle]
name = "leaf on coil"
[[body]]
name = "load"
weight = "751 kgf"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "leaf over coil"
upper = "load"
point = ["0 m", "0 m", "0 m"]
load = "751 kgf"
vertical = [{ kind = "leaf", static_deflection = "145 mm", relative_friction = 0.06 },
            { kind = "coil", stiffness = "500 kgf/cm" }]
)");
  const LinearSystem sys = assemble(load_vehicle(vehicle), DofSet::vertical);
  SimulationOptions o;
  o.duration = 0.1;
  o.time_step = 1e-3;
  try {
    simulate_nonlinear(sys, {}, o, NonlinearEffects{true, false});
    FAIL() << "a friction stage in series was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("in series with other stages"), std::string::npos) << e.what();
  }
  o.event_tolerance = 0.0;
  EXPECT_THROW(simulate_nonlinear(sys, {}, o, NonlinearEffects{}), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::test
