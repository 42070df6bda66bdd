// What an amplitude spectrum costs, and what accuracy it buys: each benchmark of a spectrum
// reports, beside the time, the worst frequency error (bins of fs/N) and relative amplitude
// error of the interpolated peak of an off-bin test tone (0.37 bin off). Reference results:
// tools/benchmarks/spectrum_reference_results.txt; against numpy.fft: compare_fft.py.
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <algorithm>
#include <cmath>

#include <railmodal/spectrum.hpp>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFs = 1000.0;

// A unit tone 0.37 bin off bin 1000, under a weaker tone and a static offset.
Eigen::VectorXd test_signal(Eigen::Index n, double* f) {
  *f = 1000.37 * kFs / static_cast<double>(n);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / kFs;
    x(i) = 0.5 + std::sin(2 * kPi * *f * t) + 0.1 * std::sin(2 * kPi * 3.3 * *f * t);
  }
  return x;
}

railmodal::SpectrumOptions options_of(const benchmark::State& state) {
  railmodal::SpectrumOptions o;
  o.window = static_cast<railmodal::Window>(state.range(1));
  return o;
}

void report(benchmark::State& state, const railmodal::Spectrum& s, double f) {
  const auto peaks = railmodal::find_peaks(s);
  double frequency_error = 1e9, amplitude_error = 1e9;  // of the peak nearest the tone
  for (const auto& p : peaks)
    if (std::abs(p.frequency - f) / s.resolution < frequency_error) {
      frequency_error = std::abs(p.frequency - f) / s.resolution;
      amplitude_error = std::abs(p.amplitude - 1.0);
    }
  state.counters["samples"] = static_cast<double>(s.signal_length);
  state.counters["f_err_bins"] = frequency_error;
  state.counters["amp_err"] = amplitude_error;
  state.SetLabel(railmodal::to_string(s.window));
}

// Plan once, transform many times: the way SpectrumAnalyzer is meant to be used.
void BM_AmplitudeSpectrumReusedPlan(benchmark::State& state) {
  double f = 0.0;
  const Eigen::VectorXd x = test_signal(state.range(0), &f);
  railmodal::SpectrumAnalyzer analyzer(x.size(), options_of(state));
  railmodal::Spectrum s;
  for (auto _ : state) {
    analyzer.compute(x, kFs, &s);
    benchmark::DoNotOptimize(s.amplitude.data());
  }
  report(state, s, f);
}
BENCHMARK(BM_AmplitudeSpectrumReusedPlan)
    ->ArgsProduct({{1 << 16, 1 << 20}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);

// A fresh plan and a fresh result every time: amplitude_spectrum().
void BM_AmplitudeSpectrumNewPlan(benchmark::State& state) {
  double f = 0.0;
  const Eigen::VectorXd x = test_signal(state.range(0), &f);
  railmodal::Spectrum s;
  for (auto _ : state) {
    s = railmodal::amplitude_spectrum(x, kFs, options_of(state));
    benchmark::DoNotOptimize(s.amplitude.data());
  }
  report(state, s, f);
}
BENCHMARK(BM_AmplitudeSpectrumNewPlan)->ArgsProduct({{1 << 20}, {1}})->Unit(benchmark::kMillisecond);

// The bare r2c transform under the analyzer, planned by estimate (what railmodal uses: the
// same plan every run) and by measure (FFTW times candidates: possibly faster, but two runs
// may pick different algorithms and differ in the last bits). No accuracy counters: the
// transform alone is exact to round-off either way.
void BM_FftwR2c(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  const unsigned flags = state.range(1) ? FFTW_MEASURE : FFTW_ESTIMATE;
  double* in = fftw_alloc_real(static_cast<size_t>(n));
  fftw_complex* out = fftw_alloc_complex(static_cast<size_t>(n / 2 + 1));
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in, out, flags);  // measure overwrites `in`
  double f = 0.0;
  const Eigen::VectorXd x = test_signal(n, &f);
  std::copy(x.data(), x.data() + n, in);
  for (auto _ : state) {
    fftw_execute(plan);
    benchmark::DoNotOptimize(out);
  }
  fftw_destroy_plan(plan);
  fftw_free(in);
  fftw_free(out);
  state.SetLabel(state.range(1) ? "FFTW_MEASURE" : "FFTW_ESTIMATE");
}
BENCHMARK(BM_FftwR2c)->ArgsProduct({{1 << 20}, {0, 1}})->Unit(benchmark::kMillisecond);

// Peaks of a 2^20-sample spectrum (2^19 + 1 bins).
void BM_FindPeaks(benchmark::State& state) {
  double f = 0.0;
  const Eigen::VectorXd x = test_signal(state.range(0), &f);
  const railmodal::Spectrum s = railmodal::amplitude_spectrum(x, kFs);
  for (auto _ : state) benchmark::DoNotOptimize(railmodal::find_peaks(s).data());
  report(state, s, f);
}
BENCHMARK(BM_FindPeaks)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
