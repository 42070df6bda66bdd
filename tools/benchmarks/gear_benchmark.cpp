// What the driving gear and its balancing cost (issue 22, item 7): one revolution in 1° steps
// (the exact forces of every cylinder, the wheel loads, harmonics), each vertical sizing rule
// (a whole balancing with no trade-off table), and the trade-off table of eleven fractions.
// Run: build/tools/benchmarks/gear_benchmark (Google Benchmark; figures in docs/driving_gear.md).
#include <benchmark/benchmark.h>

#include "railmodal/railmodal.hpp"

namespace {

const railmodal::DrivingGear& su() {
  static const railmodal::DrivingGear gear = railmodal::load_driving_gear(RAILMODAL_DATA_DIR "/locomotives/su.toml");
  return gear;
}

void revolution_in_1_degree_steps(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(railmodal::solve_driving_gear(su(), su().design_speed));
}
BENCHMARK(revolution_in_1_degree_steps)->Unit(benchmark::kMillisecond);

void balance_by_rule(benchmark::State& state) {
  railmodal::BalanceOptions options;
  options.rule = static_cast<railmodal::VerticalRule>(state.range(0));
  options.allowed_alpha = 0.3;
  options.trade_off_fractions.clear();
  state.SetLabel(railmodal::to_string(options.rule));
  for (auto _ : state) benchmark::DoNotOptimize(railmodal::balance_driving_gear(su(), su().design_speed, options));
}
BENCHMARK(balance_by_rule)
    ->Arg(static_cast<int>(railmodal::VerticalRule::least_squares))
    ->Arg(static_cast<int>(railmodal::VerticalRule::minimax))
    ->Arg(static_cast<int>(railmodal::VerticalRule::book))
    ->Unit(benchmark::kMillisecond);

void trade_off_table(benchmark::State& state) {
  railmodal::BalanceOptions options;  // the book's rule, eleven fractions
  for (auto _ : state) benchmark::DoNotOptimize(railmodal::balance_driving_gear(su(), su().design_speed, options));
}
BENCHMARK(trade_off_table)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
