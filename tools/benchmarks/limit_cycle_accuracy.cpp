// The fold speed of the continuation of hunting limit cycles against its two accuracy settings
// (fixed Dormand–Prince steps per period, Newton tolerance), beside the ramp-down with its held
// confirmation, on the bundled nonlinear scene: the table of docs/accuracy.md, "Limit cycles by
// continuation".
//
//   limit_cycle_accuracy SCENE REPEATS   prints a Markdown table: per setting the fold speed, its
//                                        difference from the finest setting, orbits, one-period
//                                        integrations, and processor time (median and range of
//                                        REPEATS rounds, every setting once a round, interleaved)
//
// Processor time (std::clock: this program is single-threaded) rather than wall time: the
// machine is shared, and a loaded machine still measures processor time fairly.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"

using namespace railmodal;

namespace {

struct Setting {
  std::string name;
  int steps = 0;           // 0: the ramp-down
  double tolerance = 0.0;
  std::vector<double> seconds;
  double speed = 0.0;
  long flows = 0;
  std::size_t orbits = 0;
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: limit_cycle_accuracy SCENE REPEATS\n";
    return 2;
  }
  const Scene scene = load_scene(argv[1]);
  const LinearSystem system = assemble(load_vehicle(scene.vehicle_file), DofSet::lateral);
  const NonlinearHuntingOptions& hunting = *scene.nonlinear_hunting;
  const int repeats = std::max(1, std::atoi(argv[2]));
  std::vector<Setting> settings{{"ramp-down, rates 0.5 and 0.25 m/s², held to 0.05 m/s", 0, 0.0, {}, 0.0, 0, 0}};
  for (int steps : {200, 500, 1000, 2000, 4000})
    settings.push_back({"continuation", steps, 1e-9, {}, 0.0, 0, 0});
  settings.push_back({"continuation", 1000, 1e-6, {}, 0.0, 0, 0});
  settings.push_back({"continuation", 1000, 1e-11, {}, 0.0, 0, 0});
  settings.push_back({"continuation (reference)", 4000, 1e-11, {}, 0.0, 0, 0});
  for (int round = 0; round < repeats; ++round) {
    for (Setting& s : settings) {
      const double start = cpu_seconds();
      if (s.steps == 0) {
        const NonlinearHuntingResult r = solve_nonlinear_hunting(system, hunting);
        s.speed = r.critical_speed.value_or(std::nan(""));
      } else {
        LimitCycleOptions o;
        o.steps_per_period = s.steps;
        o.newton_tolerance = s.tolerance;
        const LimitCycleBranch b = continue_limit_cycles(system, hunting, o);
        s.speed = b.fold ? b.fold->speed : std::nan("");
        s.flows = b.flows;
        s.orbits = b.points.size();
      }
      s.seconds.push_back(cpu_seconds() - start);
    }
  }
  const double reference = settings.back().speed;
  std::cout << "| method | steps per period | Newton tolerance | critical speed (m/s) | difference from the "
               "reference (m/s) | orbits | one-period integrations | CPU time (s), median [range] |\n";
  std::cout << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (Setting& s : settings) {
    std::sort(s.seconds.begin(), s.seconds.end());
    char tolerance[32] = "—";
    if (s.steps) std::snprintf(tolerance, sizeof tolerance, "%.0e", s.tolerance);
    const std::string steps = s.steps ? std::to_string(s.steps) : "adaptive";
    const std::string orbits = s.steps ? std::to_string(s.orbits) : "—";
    const std::string flows = s.steps ? std::to_string(s.flows) : "—";
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %s | %s | %.6f | %.1e | %s | %s | %.2f [%.2f, %.2f] |\n", s.name.c_str(),
                  steps.c_str(), tolerance, s.speed, s.speed - reference, orbits.c_str(), flows.c_str(),
                  s.seconds[s.seconds.size() / 2], s.seconds.front(), s.seconds.back());
    std::cout << line;
  }
}
