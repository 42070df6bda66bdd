// What a modal solve costs, and what accuracy it buys: each benchmark reports the largest
// relative residual ‖Kφ − λMφ‖/(‖K‖‖φ‖ + |λ|‖M‖‖φ‖) and the M-orthonormality error beside
// the time. Reference results: tools/benchmarks/reference_results.txt.
#include <benchmark/benchmark.h>

#include <railmodal/railmodal.hpp>

namespace {

// A chain of `n` wagon-like bodies on springs to the track, joined by couplers: the shape of
// an articulated train, n × 5 degrees of freedom.
railmodal::Vehicle chain(int n) {
  railmodal::Vehicle v;
  v.name = "chain";
  for (int i = 0; i < n; ++i) {
    railmodal::Body b;
    b.name = "car" + std::to_string(i);
    b.mass = 20000.0 + 100.0 * i;  // slightly different cars: no exact degeneracy
    b.inertia = {3.0e4, 4.0e5, 4.0e5};
    b.centre_of_gravity = {20.0 * i, 0.0, 1.5};
    b.reference_point = {20.0 * i, 0.0, 1.0};
    v.bodies.push_back(b);
    for (double dx : {-6.0, 6.0})
      for (double y : {-1.0, 1.0}) {
        railmodal::Element e;
        e.name = "suspension";
        e.upper = b.name;
        e.point = {20.0 * i + dx, y, 1.0};
        e.vertical_stages = {{"coil", 5.0e5, 1}};
        e.lateral_stages = {{"coil", 2.0e5, 1}};
        e.longitudinal_stages = {{"coil", 2.0e5, 1}};
        v.elements.push_back(e);
      }
    if (i > 0) {
      railmodal::Element c;
      c.name = "coupler";
      c.lower = "car" + std::to_string(i - 1);
      c.upper = b.name;
      c.point = {20.0 * i - 10.0, 0.0, 1.0};
      c.vertical_stages = {{"coil", 1.0e6, 1}};
      c.lateral_stages = {{"coil", 1.0e6, 1}};
      v.elements.push_back(c);
    }
  }
  return v;
}

void report(benchmark::State& state, const railmodal::ModalResult& r) {
  state.counters["dofs"] = static_cast<double>(r.dofs.size());
  state.counters["residual"] = r.max_residual;
  state.counters["orthonormality"] = r.orthonormality_error;
}

void BM_BogieWagonSolve(benchmark::State& state) {
  const auto system = railmodal::assemble(
      railmodal::load_vehicle(std::string(RAILMODAL_DATA_DIR) + "/vehicles/resort_car.toml"),
      railmodal::DofSet::all);
  railmodal::ModalResult r;
  for (auto _ : state) {
    r = railmodal::solve_modes(system);
    benchmark::DoNotOptimize(r.modes.data());
  }
  report(state, r);
}
BENCHMARK(BM_BogieWagonSolve);

void BM_BogieWagonLoadAssembleSolve(benchmark::State& state) {
  const std::string file = std::string(RAILMODAL_DATA_DIR) + "/vehicles/resort_car.toml";
  railmodal::ModalResult r;
  for (auto _ : state) {
    r = railmodal::solve_modes(railmodal::assemble(railmodal::load_vehicle(file), railmodal::DofSet::all));
    benchmark::DoNotOptimize(r.modes.data());
  }
  report(state, r);
}
BENCHMARK(BM_BogieWagonLoadAssembleSolve);

void BM_ChainAssemble(benchmark::State& state) {
  const auto v = chain(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(railmodal::assemble(v, railmodal::DofSet::all).stiffness.data());
  state.counters["dofs"] = 5.0 * static_cast<double>(state.range(0));
}
BENCHMARK(BM_ChainAssemble)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_ChainSolve(benchmark::State& state) {
  const auto system = railmodal::assemble(chain(static_cast<int>(state.range(0))), railmodal::DofSet::all);
  railmodal::ModalResult r;
  for (auto _ : state) {
    r = railmodal::solve_modes(system);
    benchmark::DoNotOptimize(r.modes.data());
  }
  report(state, r);
}
BENCHMARK(BM_ChainSolve)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
