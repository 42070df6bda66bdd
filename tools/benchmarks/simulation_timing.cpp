// The C++ side of compare_lsim.py: one million steps of the linear simulation of the
// Manchester coach (the bundled bogie vehicle with most DOFs, 15, and the only one with
// dampers), timed in the same run as scipy.signal.lsim. Writes the model, the load harmonics
// and the initial state to JSON for the script to build the same state-space system, and the
// response (displacement then velocity, each (steps+1) × n column-major float64) for it to
// compare.
//
//   simulation_timing DATA_DIR OUT.json OUT.f64 REPEATS [STEPS]
//     prints "simulate_s T", "simulate_cpu_s T" (medians of REPEATS runs: wall and CPU time)
//     and "steps N"; OUT.f64 "-" writes no response (the script's later timing rounds)
#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "model_json.hpp"
#include "railmodal/railmodal.hpp"

using namespace railmodal;

using benchmarks::matrix;

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) {
    std::cerr << "usage: simulation_timing DATA_DIR OUT.json OUT.f64 REPEATS [STEPS]\n";
    return 2;
  }
  const std::string data = argv[1];
  const int repeats = std::max(1, std::atoi(argv[4]));
  const int steps = argc == 6 ? std::max(1, std::atoi(argv[5])) : 1000000;
  const LinearSystem sys = assemble(load_vehicle(data + "/vehicles/manchester_benchmark_coach.toml"), DofSet::all);

  // Staggered joints of 25 m rails at 30 m/s (108 km/h): 6 harmonics at 1.2 … 7.2 Hz, through
  // the primary springs and dampers; and the body released from 10 mm above its equilibrium.
  RailJoints joints;
  joints.rail_length = 25.0;
  joints.staggered = true;
  joints.dip_depth = 0.005;
  joints.harmonics = 6;
  const auto source = make_source(joints);
  SimulationOptions options;
  options.speed = 30.0;
  options.time_step = 1e-3;  // 1 ms: 7 steps per period of the bogies' yaw (35 Hz)
  options.duration = steps * options.time_step;
  options.initial = {{"body.bounce", 0.01, 0.0}};

  TimeHistory history;
  std::vector<double> times, cpu_times;
  for (int r = 0; r < repeats; ++r) {
    history = TimeHistory();  // free the last run's output first, as the script's lsim does
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    history = simulate_linear(sys, {source.get()}, options);
    cpu_times.push_back(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  std::sort(cpu_times.begin(), cpu_times.end());
  std::cout << "simulate_s " << times[times.size() / 2] << "\nsimulate_cpu_s " << cpu_times[cpu_times.size() / 2]
            << "\nsteps " << history.time.size() - 1 << "\n";

  nlohmann::json j;
  j["vehicle"] = sys.vehicle.name;
  j["labels"] = history.labels;
  j["mass"] = matrix(sys.mass);
  j["stiffness"] = matrix(sys.stiffness);
  j["damping"] = matrix(sys.damping);
  j["time_step"] = options.time_step;
  j["steps"] = history.time.size() - 1;
  j["harmonics"] = nlohmann::json::array();  // F(t) = Σ Re(Q_k e^{iω_k t})
  for (int k = 1; k <= source->harmonic_count(); ++k) {
    const HarmonicLoad load = source->load(sys, options.speed, k);
    const Eigen::VectorXcd Q = generalized_load(sys, load);
    std::vector<double> re(Q.size()), im(Q.size());
    for (int i = 0; i < Q.size(); ++i) re[i] = Q(i).real(), im[i] = Q(i).imag();
    j["harmonics"].push_back({{"frequency_hz", load.frequency_hz},
                              {"re", re}, {"im", im}});
  }
  std::vector<double> x0(sys.size(), 0.0), v0(sys.size(), 0.0);
  for (const auto& ic : options.initial) {
    x0[sys.index_of(ic.dof)] = ic.displacement;
    v0[sys.index_of(ic.dof)] = ic.velocity;
  }
  j["initial_displacement"] = x0;
  j["initial_velocity"] = v0;
  std::ofstream(argv[2]) << j.dump();

  if (std::string(argv[3]) == "-") return 0;
  std::ofstream out(argv[3], std::ios::binary);
  for (const Eigen::MatrixXd* m : {&history.displacement, &history.velocity})
    out.write(reinterpret_cast<const char*>(m->data()), static_cast<std::streamsize>(m->size() * sizeof(double)));
  if (!out) {
    std::cerr << argv[3] << ": error: cannot write\n";
    return 5;
  }
  return 0;
}
