// The C++ side of compare_ride.py: the vertical frequency-domain ride of the Manchester
// benchmark coach on ORE B176 low-level track (wavelengths 3 … 100 m) at 20 speeds
// (10, 20, …, 200 km/h) over a fixed grid of about 10⁴ frequencies (0.1 … 80 Hz), the vertical
// floor acceleration over each bogie centre and at mid-car.
//
//   ride_timing OUT.json REPEATS   times solve_ride in this process, the full solve and the one
//                                  with RideOptions::rms_only in a kept workspace and the full
//                                  solve through the public solve_ride, interleaved, and prints
//                                  "ride_s T", "ride_cpu_s T", "ride_rms_s T", "ride_rms_cpu_s T",
//                                  "ride_public_s T" and "ride_public_cpu_s T" (wall and
//                                  processor time, medians of REPEATS runs each), then writes
//                                  M, C, K, the DOF labels, the bodies' reference points, the
//                                  track inputs (vertical columns and their x), the output
//                                  points, the speeds, the grid and railmodal's figures (RMS,
//                                  weighted RMS, Sperling's Wz, P95, N_MV, the modal shares, the
//                                  grid error estimate; the rms_only solve's RMS too) to
//                                  OUT.json for the script to redo and compare
//   ride_timing --model OUT.json   writes the model part of that JSON only (no solve): what the
//                                  script's reference table needs
//   ride_timing --once [--rms-only]  the whole job once, as a user's program would do it: read
//                                  the vehicle file, assemble, solve, print the table (RMS and
//                                  weighted RMS; without --rms-only Wz, P95 and N_MV too, and
//                                  the grid error estimate): what compare_ride.py times as a
//                                  whole process
//
// Everything goes through the public API but one thing: the repeated solves ride_s and
// ride_rms_s keep their large arrays in one ride::Workspace (src/ride/ride_workspace.hpp), as a
// study's worker does, so that their cost does not depend on whether glibc returns those arrays
// to the system between solves (docs/ride.md, "Performance", the ninth round); the answers are
// solve_ride's, bit for bit. ride_public_s is the public solve_ride (and Python's ride), which
// allocates those arrays at every call: what a program that solves repeatedly through
// include/ pays. Nothing here computes a response itself.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "railmodal/railmodal.hpp"
#include "ride/ride_workspace.hpp"
#include "ride_coach.hpp"

using namespace railmodal;
using benchmarks::kPi;

namespace {

// ORE B176 low level over wavelengths 3 … 100 m: the band the script uses too.
constexpr double kLongestWavelength = 100.0, kShortestWavelength = 3.0;
// 3444 log-spaced points a decade over 0.1 … 80 Hz (log10 800 = 2.903 decades) make 10⁴
// points; solve_ride adds the band edges of every speed (40) and the modes' frequencies.
constexpr int kPointsPerDecade = 3444;

struct Setup {
  LinearSystem system;
  TrackIrregularitySpectra track;
  std::vector<RideOutput> outputs;
  RideOptions options;
};

// The floor over each bogie centre and at mid-car (ride_coach.hpp).
Setup setup() {
  Setup s;
  s.system = assemble(load_vehicle(benchmarks::kCoach), DofSet::vertical);
  s.track.vertical_level = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level,
                                                   {2 * kPi / kLongestWavelength, 2 * kPi / kShortestWavelength});
  s.outputs = benchmarks::coach_floor_outputs(s.system);
  for (int k = 1; k <= 20; ++k) s.options.speeds.push_back(10.0 * k / 3.6);
  s.options.min_frequency = 0.1;
  s.options.max_frequency = 80.0;
  s.options.points_per_decade = kPointsPerDecade;
  s.options.points_per_bandwidth = 1;  // the base grid is already far finer than any bandwidth
  s.options.keep_spectra = false;      // the indices, as a speed study keeps them
  return s;
}

nlohmann::json model_json(const Setup& s) {
  return benchmarks::coach_model_json(s.system, s.outputs, kLongestWavelength, kShortestWavelength);
}

int once(bool rms_only) {
  Setup s = setup();
  s.options.rms_only = rms_only;
  const RideResult r = solve_ride(s.system, s.track, s.outputs, s.options);
  std::cout << "km/h";
  for (const RideOutput& o : r.outputs)
    std::cout << "\t" << o.name << " RMS\tweighted" << (rms_only ? "" : "\tWz\tP95\tN_MV");
  std::cout << "\n";
  for (const RideAtSpeed& at : r.speeds) {
    std::cout << at.speed * 3.6;
    for (size_t o = 0; o < at.outputs.size(); ++o) {
      const RideOutputAtSpeed& out = at.outputs[o];
      std::cout << "\t" << out.rms << "\t" << out.weighted_rms.value_or(0.0);
      if (!rms_only)
        std::cout << "\t" << out.sperling_wz.value_or(0.0) << "\t" << out.p95_estimate.value_or(0.0) << "\t"
                  << (o < at.comfort.size() ? at.comfort[o].nmv_estimate : 0.0);
    }
    std::cout << "\n";
  }
  if (!rms_only) std::cout << "grid error estimate " << r.grid_error_estimate << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "--once")
    return once(argc == 3 && std::string(argv[2]) == "--rms-only");
  if (argc == 3 && std::string(argv[1]) == "--model") {
    std::ofstream(argv[2]) << model_json(setup()).dump();
    return 0;
  }
  if (argc != 3) {
    std::cerr << "usage: ride_timing OUT.json REPEATS | ride_timing --model OUT.json | ride_timing --once [--rms-only]\n";
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[2]));
  const Setup s = setup();
  RideOptions rms_only = s.options;
  rms_only.rms_only = true;
  RideResult r, q, public_r;
  benchmarks::Stopwatch ride, ride_rms, ride_public;
  ride::Workspace workspace;  // one for both: the rms_only solve leaves the modal terms' arrays alone
  for (int k = 0; k < repeats; ++k) {  // interleaved: all three see the same load
    ride.time([&] { r = ride::solve_ride(s.system, s.track, s.outputs, s.options, &workspace); });
    ride_rms.time([&] { q = ride::solve_ride(s.system, s.track, s.outputs, rms_only, &workspace); });
    ride_public.time([&] { public_r = solve_ride(s.system, s.track, s.outputs, s.options); });
  }
  std::cout << "ride_s " << ride.median_wall() << "\nride_cpu_s " << ride.median_cpu() << "\nride_rms_s "
            << ride_rms.median_wall() << "\nride_rms_cpu_s " << ride_rms.median_cpu() << "\nride_public_s "
            << ride_public.median_wall() << "\nride_public_cpu_s " << ride_public.median_cpu() << "\n";
  for (size_t v = 0; v < r.speeds.size(); ++v)  // the kept workspace changes no answer
    for (size_t o = 0; o < r.speeds[v].outputs.size(); ++o)
      if (r.speeds[v].outputs[o].rms != public_r.speeds[v].outputs[o].rms ||
          r.speeds[v].outputs[o].weighted_rms != public_r.speeds[v].outputs[o].weighted_rms) {
        std::cerr << "ride_timing: the kept workspace's solve differs from solve_ride's\n";
        return 1;
      }
  std::cerr << "ride_timing: " << s.system.size() << " DOFs, " << s.system.track_inputs.size() << " track inputs, "
            << r.frequencies.size() << " frequencies, " << r.speeds.size() << " speeds, " << r.outputs.size()
            << " outputs; grid error estimate " << r.grid_error_estimate << "\n";

  nlohmann::json j = model_json(s);
  j["frequencies"] = std::vector<double>(r.frequencies.data(), r.frequencies.data() + r.frequencies.size());
  j["grid_error_estimate"] = r.grid_error_estimate;
  for (size_t v = 0; v < r.speeds.size(); ++v) {
    const RideAtSpeed& at = r.speeds[v];
    nlohmann::json rms = nlohmann::json::array(), weighted = nlohmann::json::array(), wz = nlohmann::json::array(),
                   p95 = nlohmann::json::array(), nmv = nlohmann::json::array(), modal = nlohmann::json::array(),
                   cross = nlohmann::json::array(), only_rms = nlohmann::json::array(),
                   only_weighted = nlohmann::json::array();
    for (size_t o = 0; o < at.outputs.size(); ++o) {
      const RideOutputAtSpeed& out = at.outputs[o];
      rms.push_back(out.rms);
      weighted.push_back(out.weighted_rms.value_or(-1.0));
      wz.push_back(out.sperling_wz.value_or(-1.0));
      p95.push_back(out.p95_estimate.value_or(-1.0));
      nmv.push_back(o < at.comfort.size() ? at.comfort[o].nmv_estimate : -1.0);
      std::vector<double> shares(r.modes.size(), 0.0);  // by mode, lowest first
      for (const ModalContribution& c : out.modes) shares[c.mode] = c.variance;
      modal.push_back(shares);
      cross.push_back(out.cross_term_variance);
      only_rms.push_back(q.speeds[v].outputs[o].rms);
      only_weighted.push_back(q.speeds[v].outputs[o].weighted_rms.value_or(-1.0));
    }
    j["speeds"].push_back(at.speed);
    j["rms"].push_back(rms);
    j["weighted_rms"].push_back(weighted);
    j["sperling_wz"].push_back(wz);
    j["p95"].push_back(p95);
    j["nmv"].push_back(nmv);
    j["modal_variance"].push_back(modal);
    j["cross_term_variance"].push_back(cross);
    j["rms_only_rms"].push_back(only_rms);
    j["rms_only_weighted_rms"].push_back(only_weighted);
  }
  std::ofstream(argv[1]) << j.dump();
  return 0;
}
