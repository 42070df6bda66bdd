// The accuracy-against-time rows of docs/accuracy.md, "Ride: frequency grid" and "Ride: modal
// truncation": the Manchester coach (vertical) on ORE B176 low-level track, the RMS floor
// accelerations against the grid's density and against the modes kept, each with its time.
// Also the figure of 20 speeds × 10⁴ frequencies. Prints Markdown tables.
//   build/tools/benchmarks/ride_accuracy
#include <ctime>
#include <cmath>
#include <cstdio>
#include <railmodal/railmodal.hpp>

namespace {

using namespace railmodal;
constexpr double kPi = 3.14159265358979323846;

struct Run {
  RideResult result;
  double seconds = 0.0;
};

// CPU time of the call (the machine these tables were measured on is shared: wall time there
// is several times the CPU time and varies from run to run).
Run run(const LinearSystem& s, const TrackIrregularitySpectra& t, const std::vector<RideOutput>& o, const RideOptions& opt) {
  const std::clock_t start = std::clock();
  Run r{solve_ride(s, t, o, opt), 0.0};
  r.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  return r;
}

// The largest relative difference of any output's RMS at any speed.
double worst(const RideResult& a, const RideResult& reference) {
  double e = 0.0;
  for (size_t v = 0; v < a.speeds.size(); ++v)
    for (size_t o = 0; o < a.outputs.size(); ++o) {
      const double ref = reference.speeds[v].outputs[o].rms;
      if (ref > 0.0) e = std::max(e, std::abs(a.speeds[v].outputs[o].rms - ref) / ref);
    }
  return e;
}

}  // namespace

int main() {
  const LinearSystem s =
      assemble(load_vehicle(RAILMODAL_DATA_DIR "/vehicles/manchester_benchmark_coach.toml"), DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level =
      TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {2 * kPi / 100, 2 * kPi / 1});
  const std::vector<RideOutput> outputs = default_ride_outputs(s);
  RideOptions base;
  base.speeds = {100 / 3.6, 150 / 3.6, 200 / 3.6};
  base.keep_spectra = false;

  RideOptions fine = base;
  fine.points_per_decade = 2000;
  fine.points_per_bandwidth = 256;
  const Run reference = run(s, track, outputs, fine);
  std::printf("### Grid: RMS floor acceleration against points (reference: 2000 a decade, 256 a bandwidth, %ld points)\n\n",
              static_cast<long>(reference.result.frequencies.size()));
  std::printf("| points a decade | points a bandwidth | grid points | largest relative RMS error | grid_error_estimate | CPU time, ms |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|\n");
  for (int ppd : {10, 30, 100}) {
    for (int ppb : {1, 2, 4, 8, 16, 32}) {
      RideOptions o = base;
      o.points_per_decade = ppd;
      o.points_per_bandwidth = ppb;
      const Run r = run(s, track, outputs, o);
      std::printf("| %d | %d | %ld | %.2e | %.2e | %.2f |\n", ppd, ppb, static_cast<long>(r.result.frequencies.size()),
                  worst(r.result, reference.result), r.result.grid_error_estimate, 1e3 * r.seconds);
    }
  }

  const Run direct = run(s, track, outputs, base);
  std::printf("\n### Modal truncation: RMS floor acceleration against modes kept (default grid; direct solve %.2f ms of CPU)\n\n",
              1e3 * direct.seconds);
  std::printf("| modes | highest kept, Hz | largest relative RMS error | CPU time, ms |\n|---:|---:|---:|---:|\n");
  for (int n = 1; n <= s.size(); ++n) {
    RideOptions o = base;
    o.modes = n;
    const Run r = run(s, track, outputs, o);
    const double highest = n <= static_cast<int>(r.result.modes.size()) ? r.result.modes[n - 1].frequency_hz : 0.0;
    std::printf("| %d | %.2f | %.2e | %.2f |\n", n, highest, worst(r.result, direct.result), 1e3 * r.seconds);
  }

  // The figure: 20 speeds × 10⁴ frequencies (a log grid of 3000 a decade over 0.1–200 Hz).
  RideOptions big = base;
  big.speeds.clear();
  for (int k = 0; k < 20; ++k) big.speeds.push_back((50 + 10 * k) / 3.6);
  big.min_frequency = 0.1;
  big.max_frequency = 200.0;
  big.points_per_decade = 3030;
  const Run b = run(s, track, outputs, big);
  std::printf("\n20 speeds × %ld frequencies, %zu outputs: %.1f ms of CPU (stages, wall:",
              static_cast<long>(b.result.frequencies.size()), outputs.size(), 1e3 * b.seconds);
  for (const StageTiming& t : b.result.summary.stages) std::printf(" %s %.1f ms", t.stage.c_str(), 1e3 * t.seconds);
  std::printf(" )\n");
  return 0;
}
