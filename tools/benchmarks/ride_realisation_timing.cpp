// The C++ side of compare_ride_realisation.py (issue 21, item 9, the time domain): a realisation
// of 2²⁰ samples of ORE B176 low-level vertical track (wavelengths 1 … 100 m, every 0.05 m:
// 52.4 km) synthesised by inverse FFT, the vertical Manchester benchmark coach run over it at
// 180 km/h (one step of 1 ms a track sample: 2²⁰ steps, 17.5 minutes of running) and the
// EN 12299 and Sperling weightings of the vertical floor acceleration over each bogie centre and
// at mid-car, with their 5 s windows, P95, Cc(t) and N_MV.
//
//   ride_realisation_timing OUT_DIR REPEATS   times synthesise_track + simulate_ride in this
//                                             process ("realisation_s", "simulation_s" and their
//                                             "_cpu_s", medians of REPEATS runs), then writes
//                                             OUT_DIR/track.f64 (the profile, little-endian
//                                             doubles) and OUT_DIR/model.json (M, C, K, the track
//                                             inputs, the output points, the run and railmodal's
//                                             figures) for the script to redo and compare
//   ride_realisation_timing --once            the whole job once, as a user's program would do
//                                             it (read the vehicle, assemble, synthesise,
//                                             simulate, print the indices)
//   ride_realisation_timing --track-csv OUT.csv LENGTH STEP SEED
//                                             writes a synthesised ORE B176 low-level track (all
//                                             three components, 1 … 100 m) as a geometry CSV in
//                                             mm: how data/track/ore_low_synthesised.csv was made
//
// Everything goes through the public API; nothing here computes a response itself.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "railmodal/railmodal.hpp"
#include "ride_coach.hpp"

using namespace railmodal;
using benchmarks::kPi;

namespace {

constexpr double kLongestWavelength = 100.0, kShortestWavelength = 1.0;  // m
constexpr double kSpeed = 50.0;                                          // m/s: 180 km/h
constexpr double kStep = 0.05;                                           // m: 1 ms at 180 km/h
constexpr int kSamples = 1 << 20;
constexpr std::uint64_t kSeed = 2021;

TrackSpectrum ore_low(TrackIrregularity component) {
  return TrackSpectrum::ore_b176(OreLevel::low, component, {2 * kPi / kLongestWavelength, 2 * kPi / kShortestWavelength});
}

struct Setup {
  LinearSystem system;
  TrackIrregularitySpectra track;
  TrackSynthesisOptions synthesis;
  RideSimulationOptions run;
  std::vector<RideOutput> outputs;
};

// The floor over each bogie centre and at mid-car, vertical acceleration (ride_coach.hpp).
Setup setup() {
  Setup s;
  s.system = assemble(load_vehicle(benchmarks::kCoach), DofSet::vertical);
  s.track.vertical_level = ore_low(TrackIrregularity::vertical_level);
  s.synthesis.length = kSamples * kStep;
  s.synthesis.step = kStep;
  s.synthesis.seed = kSeed;
  s.run.speed = kSpeed;
  s.run.time_step = kStep / kSpeed;
  s.outputs = benchmarks::coach_floor_outputs(s.system);
  return s;
}

nlohmann::json model_json(const Setup& s, const RideSimulationResult& r) {
  nlohmann::json j = benchmarks::coach_model_json(s.system, s.outputs, kLongestWavelength, kShortestWavelength);
  j["speed"] = kSpeed;
  j["step"] = kStep;
  j["time_step"] = r.time_step;
  j["samples"] = kSamples;
  for (const RideHistory& h : r.histories) {
    j["rms"].push_back(h.rms);
    j["weighted_rms"].push_back(h.weighted_rms.value_or(-1.0));
    j["sperling_wz"].push_back(h.sperling_wz.value_or(-1.0));
    j["p95"].push_back(h.p95.value_or(-1.0));
    j["first_values"].push_back(std::vector<double>(h.values.data(), h.values.data() + 2000));
  }
  return j;
}

int once() {
  const Setup s = setup();
  const TrackGeometry track = synthesise_track(s.track, s.synthesis);
  const RideSimulationResult r = simulate_ride(s.system, track, s.outputs, s.run);
  for (std::size_t i = 0; i < r.outputs.size(); ++i)
    std::cout << r.outputs[i].name << "\tRMS " << r.histories[i].rms << "\tWb RMS "
              << r.histories[i].weighted_rms.value_or(0.0) << "\tP95 " << r.histories[i].p95.value_or(0.0) << "\n";
  return 0;
}

// A geometry CSV in mm of all three components, with a header saying where it came from.
int track_csv(const std::string& path, double length, double step, std::uint64_t seed) {
  TrackIrregularitySpectra spectra;
  spectra.vertical_level = ore_low(TrackIrregularity::vertical_level);
  spectra.alignment = ore_low(TrackIrregularity::alignment);
  spectra.cross_level = ore_low(TrackIrregularity::cross_level);
  TrackSynthesisOptions o;
  o.length = length;
  o.step = step;
  o.seed = seed;
  const TrackGeometry g = synthesise_track(spectra, o);
  std::ofstream out(path);
  out << "# Not measured: synthesised by railmodal (tools/benchmarks/ride_realisation_timing --track-csv "
      << path.substr(path.find_last_of('/') + 1) << " " << length << " " << step << " " << seed << "),\n"
      << "# ORE B176 low level, vertical level, alignment and cross-level, wavelengths 1 ... 100 m, seed " << seed
      << ",\n# as a stand-in for a recording car's file (no public measured record is at hand): one whole\n"
      << "# period of " << length << " m, read as measured (the run starts from rest and ends with the file).\n"
      << "distance [m],vertical_level [mm],alignment [mm],cross_level [mm]\n";
  char row[128];
  for (Eigen::Index n = 0; n < g.vertical_level.size(); ++n) {
    std::snprintf(row, sizeof row, "%.2f,%.3f,%.3f,%.3f\n", static_cast<double>(n) * step, 1e3 * g.vertical_level[n],
                  1e3 * g.alignment[n], 1e3 * g.cross_level[n]);
    out << row;
  }
  return out ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--once") return once();
  if (argc == 6 && std::string(argv[1]) == "--track-csv")
    return track_csv(argv[2], std::atof(argv[3]), std::atof(argv[4]), std::strtoull(argv[5], nullptr, 10));
  if (argc != 3) {
    std::cerr << "usage: ride_realisation_timing OUT_DIR REPEATS | --once | --track-csv OUT.csv LENGTH STEP SEED\n";
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[2]));
  const Setup s = setup();
  TrackGeometry track;
  RideSimulationResult r;
  benchmarks::Stopwatch synthesis, simulation;
  for (int k = 0; k < repeats; ++k) {
    synthesis.time([&] { track = synthesise_track(s.track, s.synthesis); });
    simulation.time([&] { r = simulate_ride(s.system, track, s.outputs, s.run); });
  }
  std::cout << "realisation_s " << synthesis.median_wall() << "\nrealisation_cpu_s " << synthesis.median_cpu()
            << "\nsimulation_s " << simulation.median_wall() << "\nsimulation_cpu_s " << simulation.median_cpu()
            << "\n";
  std::cerr << "ride_realisation_timing: " << s.system.size() << " DOFs, " << s.system.track_inputs.size()
            << " track inputs, " << track.vertical_level.size() << " samples, " << r.time.size() << " steps of "
            << r.time_step << " s\n";
  const std::string dir = argv[1];
  std::ofstream(dir + "/track.f64", std::ios::binary)
      .write(reinterpret_cast<const char*>(track.vertical_level.data()),
             static_cast<std::streamsize>(sizeof(double) * track.vertical_level.size()));
  std::ofstream(dir + "/model.json") << model_json(s, r).dump();
  return 0;
}
