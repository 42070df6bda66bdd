// The C++ side of compare_sweep.py: a sweep of 10 000 speeds, timed in the same run as
// numpy/scipy. Without SCENE: every source a bogie wagon meets, the resort car with all its
// DOFs, body bounce displacement and acceleration. With SCENE (a critical-speed scene file):
// its vehicle, DOF set and sources over 10 000 speeds of its speed range, displacement and
// acceleration of each of its output DOFs (body.bounce, or DOF 0, if it names none). Writes the
// model, the sources' separable loads and load scales s(ω) to JSON for the script to redo the
// same computation, and its amplitudes and phases for the script to compare ("-": no JSON, for
// the script's later timing rounds).
//
// Timed: amplitude_curves for every source, with what it does inside before it sweeps (ΦᵀCΦ and
// the proportionality test; with discrete dampers the complex modes of the first-order form and
// their check at nine speeds), as the script times its numpy equivalent (damping_path) with its
// sweep. Not timed, on either side: assembly and the real modes (solve_modes; scipy's eigh).
//
//   sweep_timing DATA_DIR OUT.json REPEATS [SCENE]   prints "sweep_s T" (amplitudes only) and
//                                                    "sweep_with_phases_s T", medians of REPEATS,
//                                                    and the same in processor time (_cpu_s)
#include <algorithm>
#include <chrono>
#include <complex>
#include <ctime>
#include <fstream>
#include <iterator>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "model_json.hpp"
#include "railmodal/railmodal.hpp"

using namespace railmodal;

using benchmarks::matrix;
using benchmarks::complex_vector;

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::cerr << "usage: sweep_timing DATA_DIR OUT.json REPEATS [SCENE]\n";
    return 2;
  }
  const std::string data = argv[1];
  const int repeats = std::max(1, std::atoi(argv[3]));
  const std::optional<Scene> scene = argc == 5 ? std::optional<Scene>(load_scene(argv[4])) : std::nullopt;
  const LinearSystem sys = scene ? assemble(load_vehicle(scene->vehicle_file), scene->dofs)
                                 : assemble(load_vehicle(data + "/vehicles/resort_car.toml"), DofSet::all);
  const ModalResult modes = solve_modes(sys);

  // All the sources a bogie wagon meets: joints (short dips, staggered, 6 harmonics),
  // eccentricity, flats (6 harmonics), hunting (none of it reaches this car: its bogies are
  // held laterally, so its load is zero — still evaluated).
  RailJoints joints;
  joints.rail_length = 12.5;
  joints.staggered = true;
  joints.dip_depth = 0.005;
  joints.dip_length = 1.0;
  joints.harmonics = 6;
  WheelEccentricity eccentricity;
  eccentricity.wheel_diameter = 1.05;
  eccentricity.eccentricity = 0.0015;
  WheelFlat flat;
  flat.wheel_diameter = 1.05;
  flat.depth = 0.001;
  flat.length = 0.1;
  flat.harmonics = 6;
  Hunting hunting;
  hunting.conicity = 0.05;
  hunting.rolling_circle_spacing = 1.58;
  hunting.rolling_radius = 0.525;
  hunting.amplitude = 0.005;
  std::vector<std::shared_ptr<const ExcitationSource>> sources = {make_source(joints), make_source(eccentricity),
                                                                   make_source(flat), make_source(hunting)};
  if (scene) sources = scene->sources;
  // The report's outputs: displacement and acceleration of each output DOF, first as
  // amplitudes only (what the script's first rows compute), then with the phases of harmonic 1.
  std::vector<int> output_dofs;
  if (scene)
    for (const SceneOutput& o : scene->outputs)  // each DOF once: both quantities are swept anyway
      if (std::find(output_dofs.begin(), output_dofs.end(), sys.index_of(o.dof)) == output_dofs.end())
        output_dofs.push_back(sys.index_of(o.dof));
  if (output_dofs.empty()) output_dofs.push_back(std::max(0, sys.index_of("body.bounce")));
  std::vector<OutputRequest> with_phases;
  for (int d : output_dofs)
    with_phases.insert(with_phases.end(), {{d, ResponseQuantity::displacement}, {d, ResponseQuantity::acceleration}});
  std::vector<OutputRequest> amplitudes_only = with_phases;
  for (OutputRequest& o : amplitudes_only) o.phase = false;
  // 3.6–216 km/h, or the scene's range (from one step above 0, where a sweep starts).
  const double low = scene ? std::max(scene->min_speed, scene->speed_step) : 1.0;
  const double high = scene ? scene->max_speed : 60.0;
  std::vector<double> speeds(10000);
  for (size_t i = 0; i < speeds.size(); ++i) speeds[i] = low + (high - low) * i / (speeds.size() - 1);
  const SpeedGrid grid(speeds);  // one grid for every source's curves, as the report shares it

  auto sweep = [&](const std::vector<OutputRequest>& outputs) {
    std::vector<AmplitudeCurve> curves;
    for (size_t s = 0; s < sources.size(); ++s) {
      auto c = amplitude_curves(sys, modes, *sources[s], static_cast<int>(s), outputs, grid);
      curves.insert(curves.end(), std::make_move_iterator(c.begin()), std::make_move_iterator(c.end()));
    }
    return curves;
  };
  // The two configurations alternate, so that both see the same machine; each frees its
  // curves outside the timing.
  std::vector<AmplitudeCurve> curves, amplitudes;
  std::vector<double> times, times_with_phases, cpu, cpu_with_phases;
  // Processor time as well as wall time: on a shared, loaded machine the process waits for a
  // core between its time slices, which the wall clock counts and the processor time does not.
  auto cpu_now = [] { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; };
  for (int r = 0; r < repeats; ++r) {
    amplitudes.clear();
    auto start = std::chrono::steady_clock::now();
    double cpu_start = cpu_now();
    amplitudes = sweep(amplitudes_only);
    cpu.push_back(cpu_now() - cpu_start);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    curves.clear();
    start = std::chrono::steady_clock::now();
    cpu_start = cpu_now();
    curves = sweep(with_phases);
    cpu_with_phases.push_back(cpu_now() - cpu_start);
    times_with_phases.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  // The script compares the curves with phases; those without must hold the same amplitudes.
  for (size_t c = 0; c < curves.size(); ++c)
    if (amplitudes[c].amplitudes != curves[c].amplitudes || amplitudes[c].unbounded != curves[c].unbounded ||
        !amplitudes[c].phases_deg.empty()) {
      std::cerr << "sweep_timing: the amplitude-only curve " << c << " differs from the one with phases\n";
      return 1;
    }
  auto median = [](std::vector<double> t) {
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  };
  std::cout << "sweep_s " << median(times) << "\n";
  std::cout << "sweep_with_phases_s " << median(times_with_phases) << "\n";
  std::cout << "sweep_cpu_s " << median(cpu) << "\n";
  std::cout << "sweep_with_phases_cpu_s " << median(cpu_with_phases) << "\n";

  nlohmann::json j;
  j["mass"] = matrix(sys.mass);
  j["stiffness"] = matrix(sys.stiffness);
  j["damping"] = matrix(sys.damping);
  j["speeds"] = speeds;
  j["output_dofs"] = output_dofs;
  j["labels"] = nlohmann::json::array();
  for (int d : output_dofs) j["labels"].push_back(sys.dofs[d].label);
  j["scene"] = scene ? scene->name : std::string("resort car, all sources (built in)");
  j["sources"] = nlohmann::json::array();
  for (const auto& source : sources) {
    nlohmann::json h = nlohmann::json::array();
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      const SeparableLoad p = source->separable_load(sys, k);
      // Q(ω) = s(ω)(Q_K + iωQ_C): s at every speed of the grid (1 for a fixed profile, (ω/ω_ref)²
      // for an unbalance), computed here once so that the script need not re-derive each kind.
      std::vector<double> omega(speeds.size()), scale(speeds.size());
      for (size_t i = 0; i < speeds.size(); ++i) omega[i] = 2.0 * 3.14159265358979323846 * source->frequency_hz(speeds[i], k);
      source->load_scales(omega.data(), static_cast<int>(omega.size()), p.reference_omega, scale.data());
      h.push_back({{"harmonic", k}, {"stiffness_part", complex_vector(p.stiffness_part)},
                   {"damping_part", complex_vector(p.damping_part)}, {"load_scale", scale}});
    }
    const std::complex<double> reference = phase_reference(sys, *source);
    j["sources"].push_back({{"kind", source->kind()},
                            {"wavelength", source->wavelength()},
                            {"harmonics", h},
                            {"phase_reference", {{"re", reference.real()}, {"im", reference.imag()}}}});
  }
  j["amplitudes"] = nlohmann::json::array();
  for (const auto& c : curves)
    j["amplitudes"].push_back({{"quantity", to_string(c.quantity)},
                               {"values", c.amplitudes},
                               {"phases_deg", c.phases_deg},
                               {"unbounded", std::vector<bool>(c.unbounded)}});
  if (std::string(argv[2]) != "-") std::ofstream(argv[2]) << j.dump();
  return 0;
}
