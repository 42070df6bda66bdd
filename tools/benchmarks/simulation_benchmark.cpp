// What the linear simulation costs per step: the exact state transition of a bogie vehicle
// with all its DOFs, forced by rail joints (several load harmonics) and released from a
// displaced position, or in free decay. Reference results:
// tools/benchmarks/simulation_reference_results.txt; against scipy.signal.lsim:
// compare_lsim.py.
#include <benchmark/benchmark.h>

#include <railmodal/railmodal.hpp>

namespace {

using namespace railmodal;

LinearSystem vehicle(const char* file) {
  return assemble(load_vehicle(std::string(RAILMODAL_DATA_DIR) + "/vehicles/" + file), DofSet::all);
}

// Staggered joints of 25 m rails at 30 m/s, 6 harmonics (1.2 … 7.2 Hz); 1 ms steps.
std::unique_ptr<ExcitationSource> joints(int harmonics) {
  RailJoints j;
  j.rail_length = 25.0;
  j.staggered = true;
  j.dip_depth = 0.005;
  j.harmonics = harmonics;
  return make_source(j);
}

void run(benchmark::State& state, const LinearSystem& sys, const std::vector<const ExcitationSource*>& sources) {
  SimulationOptions o;
  o.speed = 30.0;
  o.time_step = 1e-3;
  o.duration = static_cast<double>(state.range(0)) * o.time_step;
  o.initial = {{"body.bounce", 0.01, 0.0}};
  for (auto _ : state) {
    TimeHistory h = simulate_linear(sys, sources, o);
    benchmark::DoNotOptimize(h.displacement.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));  // steps: items_per_second = steps/s
  state.counters["dofs"] = sys.size();
}

// The Manchester coach (15 DOFs, dampers) over joints: the case of compare_lsim.py.
void BM_SimulateCoachOverJoints(benchmark::State& state) {
  const LinearSystem sys = vehicle("manchester_benchmark_coach.toml");
  const auto source = joints(static_cast<int>(state.range(1)));
  run(state, sys, {source.get()});
  state.counters["harmonics"] = static_cast<double>(state.range(1));
}
BENCHMARK(BM_SimulateCoachOverJoints)
    ->Args({10000, 6})
    ->Args({1000000, 6})
    ->Args({1000000, 1})
    ->Args({1000000, 30})
    ->Unit(benchmark::kMillisecond);

// Free decay: no load harmonics, the transition matrix alone.
void BM_SimulateCoachFreeDecay(benchmark::State& state) {
  run(state, vehicle("manchester_benchmark_coach.toml"), {});
}
BENCHMARK(BM_SimulateCoachFreeDecay)->Arg(1000000)->Unit(benchmark::kMillisecond);

// The resort car (11 DOFs, no dampers) in free decay.
void BM_SimulateResortCarFreeDecay(benchmark::State& state) { run(state, vehicle("resort_car.toml"), {}); }
BENCHMARK(BM_SimulateResortCarFreeDecay)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
