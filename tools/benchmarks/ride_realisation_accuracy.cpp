// Accuracy against time of a ride realisation (docs/accuracy.md, "Ride: realisation length
// and step"): the scatter of the simulated RMS over seeds against the realisation's length, and
// the change of the weighted RMS with the track step, with the wall time of each run.
//
//   build/tools/benchmarks/ride_realisation_accuracy
#include <cmath>
#include <ctime>
#include <cstdio>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "railmodal/ride_simulation.hpp"

using namespace railmodal;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpeed = 160.0 / 3.6;

std::vector<RideOutput> floor_points() {
  std::vector<RideOutput> out;
  for (double x : {0.0, 9.5}) {
    RideOutput o;
    o.name = x == 0.0 ? "mid-car" : "over front bogie";
    o.body = "body";
    o.point = {x, 0.0, 0.0};
    out.push_back(o);
  }
  return out;
}

struct Run {
  double rms = 0.0, weighted = 0.0, seconds = 0.0;
};

Run run(const LinearSystem& system, const TrackIrregularitySpectra& track, double length, double step,
        std::uint64_t seed) {
  const std::clock_t start = std::clock();  // CPU time: the machine may be shared
  TrackSynthesisOptions s;
  s.length = length;
  s.step = step;
  s.seed = seed;
  const TrackGeometry g = synthesise_track(track, s);
  RideSimulationOptions o;
  o.speed = kSpeed;
  o.time_step = step / kSpeed;
  const RideSimulationResult r = simulate_ride(system, g, floor_points(), o);
  Run out;
  out.rms = r.histories[0].rms;
  out.weighted = *r.histories[0].weighted_rms;
  out.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace

int main() {
  const LinearSystem system = assemble(load_vehicle(RAILMODAL_DATA_DIR "/vehicles/manchester_benchmark_coach.toml"),
                                       DofSet::vertical);
  TrackIrregularitySpectra track;
  track.vertical_level =
      TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {2 * kPi / 100, 2 * kPi / 2});
  constexpr int kSeeds = 16;
  std::printf("| length (m) | duration (s) | mean RMS (m/s²) | scatter of RMS | mean Wb RMS (m/s²) | scatter of Wb RMS | "
              "CPU per run (ms) |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  for (double length : {512.0, 2048.0, 8192.0, 32768.0}) {
    double sum = 0.0, squares = 0.0, wsum = 0.0, wsquares = 0.0, seconds = 0.0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      const Run r = run(system, track, length, 0.25, static_cast<std::uint64_t>(seed));
      sum += r.rms;
      squares += r.rms * r.rms;
      wsum += r.weighted;
      wsquares += r.weighted * r.weighted;
      seconds += r.seconds;
    }
    const double mean = sum / kSeeds, wmean = wsum / kSeeds;
    const double scatter = std::sqrt(std::max(0.0, squares / kSeeds - mean * mean) * kSeeds / (kSeeds - 1)) / mean;
    const double wscatter = std::sqrt(std::max(0.0, wsquares / kSeeds - wmean * wmean) * kSeeds / (kSeeds - 1)) / wmean;
    std::printf("| %.0f | %.1f | %.4f | %.3f | %.4f | %.3f | %.1f |\n", length, length / kSpeed, mean, scatter, wmean,
                wscatter, 1e3 * seconds / kSeeds);
  }
  std::printf("\n| track step (m) | time step (ms) | Wb RMS (m/s²), seed 1, 4096 m | change from 0.0625 m | "
              "CPU per run (ms) |\n|---:|---:|---:|---:|---:|\n");
  const Run finest = run(system, track, 4096.0, 0.0625, 1);
  for (double step : {1.0, 0.5, 0.25, 0.125, 0.0625}) {
    const Run r = run(system, track, 4096.0, step, 1);
    std::printf("| %.4g | %.3f | %.5f | %.2e | %.1f |\n", step, 1e3 * step / kSpeed, r.weighted,
                r.weighted / finest.weighted - 1.0, 1e3 * r.seconds);
  }
}
