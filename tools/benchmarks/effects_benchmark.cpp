// What an effect costs, and that an effect a scene does not name costs nothing.
//
// The loaded two-axle wagon over 10 m joints at its critical speed, 3 s at 1 ms:
//   plain          — its springs given without friction data, no effects named;
//   unnamed        — the bundled wagon, whose leaf springs carry relative_friction, no effects
//                    named: the same system is built (checked: M, C, K bit for bit), so the
//                    time is the same;
//   leaf_friction  — the same wagon with leaf_friction named: the nonlinear path.
// And the Manchester coach (all DOFs, its dampers) free response, 10 s at 1 ms: dampers
// unnamed (C = 0) against viscous_dampers named.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "railmodal/railmodal.hpp"

namespace {

namespace fs = std::filesystem;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "railmodal_effects_benchmark";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

// The bundled friction scene with the given effects, on the bundled wagon or on a copy whose
// springs have no friction data.
railmodal::Scene two_axle_scene(bool plain_vehicle, const std::string& effects) {
  const std::string data = RAILMODAL_DATA_DIR;
  std::string vehicle = read(data + "/vehicles/two_axle_freight_wagon.toml");
  if (plain_vehicle) vehicle = std::regex_replace(vehicle, std::regex(", relative_friction = [0-9.]+"), "");
  const std::string vehicle_file = temp(plain_vehicle ? "plain.toml" : "bundled.toml", vehicle);
  std::string scene = read(data + "/scenes/two_axle_freight_wagon_joints_friction.toml");
  scene = std::regex_replace(scene, std::regex("effects = \\[[^\\]]*\\]"), "effects = [" + effects + "]");
  scene = std::regex_replace(scene, std::regex("time_step = \"2 ms\""), "time_step = \"1 ms\"");
  scene = std::regex_replace(scene, std::regex("vehicle = \"[^\"]*\""), "vehicle = \"" + vehicle_file + "\"");
  return railmodal::load_scene(temp(std::string(plain_vehicle ? "plain" : "bundled") + "_scene.toml", scene));
}

void run(benchmark::State& state, const railmodal::Scene& scene) {
  const railmodal::Vehicle vehicle = railmodal::load_vehicle(scene.vehicle_file);
  for (auto _ : state) {
    railmodal::TimeHistory h = railmodal::simulate_scene(scene, vehicle);
    benchmark::DoNotOptimize(h.displacement.data());
  }
  const railmodal::TimeHistory h = railmodal::simulate_scene(scene, vehicle);
  state.counters["dofs"] = static_cast<double>(h.labels.size());
  state.counters["events"] = static_cast<double>(h.events.size());
  state.counters["rk_steps"] = h.steps_taken;
}

void BM_TwoAxlePlainVehicle(benchmark::State& state) { run(state, two_axle_scene(true, "")); }
void BM_TwoAxleFrictionUnnamed(benchmark::State& state) {
  // The claim behind the comparison: the unnamed friction data leave the system untouched.
  const auto a = two_axle_scene(true, ""), b = two_axle_scene(false, "");
  const auto sa = railmodal::scene_system(a, railmodal::load_vehicle(a.vehicle_file));
  const auto sb = railmodal::scene_system(b, railmodal::load_vehicle(b.vehicle_file));
  if (sa.mass != sb.mass || sa.stiffness != sb.stiffness || sa.damping != sb.damping)
    throw std::logic_error("unnamed friction changed the assembled system");
  run(state, b);
}
void BM_TwoAxleFrictionNamed(benchmark::State& state) { run(state, two_axle_scene(false, "\"leaf_friction\"")); }

railmodal::Scene coach_scene(const std::string& effects) {
  const std::string data = RAILMODAL_DATA_DIR;
  const std::string scene = "[scene]\nname = \"coach free response\"\nvehicle = \"" + data +
                            "/vehicles/manchester_benchmark_coach.toml\"\ndofs = \"all\"\n[simulation]\n"
                            "duration = \"10 s\"\ntime_step = \"1 ms\"\neffects = [" +
                            effects + "]\n[[simulation.initial]]\ndof = \"body.bounce\"\ndisplacement = \"20 mm\"\n";
  return railmodal::load_scene(temp("coach_" + std::to_string(effects.size()) + ".toml", scene));
}
void BM_CoachDampersUnnamed(benchmark::State& state) { run(state, coach_scene("")); }
void BM_CoachDampersNamed(benchmark::State& state) { run(state, coach_scene("\"viscous_dampers\"")); }

}  // namespace

BENCHMARK(BM_TwoAxlePlainVehicle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TwoAxleFrictionUnnamed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TwoAxleFrictionNamed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoachDampersUnnamed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoachDampersNamed)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
