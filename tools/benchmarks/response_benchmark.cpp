// Cost of the harmonic response: one direct solve against modal superposition per speed,
// and a whole critical-speed study of a bundled scene. Accuracy beside these times is in
// docs/accuracy.md (tools/update_accuracy.sh).
#include <benchmark/benchmark.h>

#include "railmodal/railmodal.hpp"

using namespace railmodal;

namespace {

struct Case {
  LinearSystem system;
  ModalResult modes;
  Eigen::VectorXcd load;
  double frequency_hz;
};

Case coach_case() {
  Case c;
  c.system = assemble(load_vehicle(std::string(RAILMODAL_DATA_DIR) + "/vehicles/manchester_benchmark_coach.toml"),
                      DofSet::all);
  c.modes = solve_modes(c.system);
  RailJoints j;
  j.rail_length = 25.0;
  j.dip_depth = 0.005;
  j.staggered = true;
  const HarmonicLoad load = make_source(j)->load(c.system, 30.0, 1);
  c.load = generalized_load(c.system, load);
  c.frequency_hz = load.frequency_hz;
  return c;
}

void BM_DirectResponse(benchmark::State& state) {
  const Case c = coach_case();
  for (auto _ : state) benchmark::DoNotOptimize(harmonic_response(c.system, c.modes, c.load, c.frequency_hz));
  state.counters["dofs"] = c.system.size();
}
BENCHMARK(BM_DirectResponse);

void BM_ModalResponse(benchmark::State& state) {
  const Case c = coach_case();
  const int modes = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(modal_harmonic_response(c.system, c.modes, c.load, c.frequency_hz, modes));
  state.counters["dofs"] = c.system.size();
}
BENCHMARK(BM_ModalResponse)->Arg(4)->Arg(15);

void BM_CriticalSpeedStudy(benchmark::State& state) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/resort_car_10m_rails.toml");
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  for (auto _ : state) benchmark::DoNotOptimize(study_critical_speeds(scene, vehicle));
}
BENCHMARK(BM_CriticalSpeedStudy)->Unit(benchmark::kMillisecond);

// 10 000 speeds of rail joints (6 harmonics) on the resort car, all DOFs: the fast modal
// sweep (tools/benchmarks/compare_sweep.py runs all sources against numpy/scipy).
void BM_SpeedSweep10k(benchmark::State& state) {
  const LinearSystem sys =
      assemble(load_vehicle(std::string(RAILMODAL_DATA_DIR) + "/vehicles/resort_car.toml"), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 12.5;
  j.dip_depth = 0.005;
  j.dip_length = 1.0;
  j.staggered = true;
  j.harmonics = 6;
  const auto source = make_source(j);
  std::vector<double> grid(10000);
  for (size_t i = 0; i < grid.size(); ++i) grid[i] = 1.0 + 59.0 * i / (grid.size() - 1);
  const SpeedGrid speeds(grid);  // made once: the curves share it
  const std::vector<OutputRequest> outputs = {{sys.index_of("body.bounce"), ResponseQuantity::acceleration}};
  for (auto _ : state) benchmark::DoNotOptimize(amplitude_curves(sys, modes, *source, 0, outputs, speeds));
}
BENCHMARK(BM_SpeedSweep10k)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
