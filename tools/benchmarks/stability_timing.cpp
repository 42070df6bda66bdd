// The C++ side of compare_stability.py: the root locus of a bogie vehicle with four wheelsets
// at 1000 speeds (10–500 km/h) on one and on two threads, and its linear critical speed to a
// relative 1e-8, timed in the same run as numpy/scipy. Writes the matrices, the speeds, the
// eigenvalues at every speed and the critical speed to JSON for the script to redo and compare.
//
//   stability_timing OUT.json REPEATS   prints "locus_1_thread_s T", "locus_2_threads_s T",
//                                       "critical_speed_s T" (wall time) and the same with
//                                       "_cpu" (processor time of all threads: what a shared,
//                                       loaded machine still measures fairly), medians of
//                                       REPEATS runs
//
// The vehicle is built in code through the public API (a body, two bogies, four wheelsets on
// primary and secondary springs with their contact data, four yaw dampers with series
// stiffness), assembled over the lateral motions (vertical motions decouple from hunting in the
// linear model), and solved by solve_hunting_stability, whose contact terms come from
// contact_matrices. Until the assembly of series dampers is merged, this program adds the yaw
// dampers' stretch rows to the assembled system itself.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "model_json.hpp"
#include "railmodal/railmodal.hpp"

using namespace railmodal;
using benchmarks::matrix;

namespace {

constexpr double kRollingRadius = 0.46, kHalfSpacing = 0.75, kConicity = 0.15, kCreep = 1.0e7;
constexpr double kWheelsetMass = 1813.0, kSpinInertia = 140.0;

Body body(const std::string& name, double mass, Eigen::Vector3d inertia, Eigen::Vector3d cg) {
  Body b;
  b.name = name;
  b.mass = mass;
  b.inertia = inertia;
  b.centre_of_gravity = cg;
  b.reference_point = cg;
  return b;
}

Element element(const std::string& name, const std::string& lower, const std::string& upper, Eigen::Vector3d point,
                double vertical, double lateral, double longitudinal, double lateral_damping) {
  Element e;
  e.name = name;
  e.lower = lower;
  e.upper = upper;
  e.point = point;
  e.vertical_stages = {{"coil", vertical, 1}};
  e.lateral_stages = {{"coil", lateral, 1}};
  e.longitudinal_stages = {{"coil", longitudinal, 1}};
  e.lateral_damping = lateral_damping;
  return e;
}

// Dimensions and masses after the Manchester benchmark coach (Iwnicki, The Manchester
// Benchmarks for Rail Vehicle Simulation, 1999): bogie centres ±9.5 m, wheelbase 2.56 m. Heights
// from the axle plane (a wheelset's centre must lie in it, wheelset_dofs.cpp): the rail-top
// heights less the rolling radius, so that every lever is what it was.
Vehicle bogie_vehicle() {
  Vehicle v;
  v.name = "bogie vehicle with four wheelsets";
  v.bodies.push_back(body("body", 32000.0, {56800.0, 1.97e6, 1.97e6}, {0.0, 0.0, 1.8 - kRollingRadius}));
  int wheelset = 0;
  for (int g = 0; g < 2; ++g) {
    const double xg = g == 0 ? 9.5 : -9.5;
    const std::string bogie = "bogie" + std::to_string(g + 1);
    v.bodies.push_back(body(bogie, 2615.0, {1722.0, 1476.0, 3067.0}, {xg, 0.0, 0.6 - kRollingRadius}));
    v.elements.push_back(element("secondary", bogie, "body", {xg, 1.0, 0.8 - kRollingRadius}, 4.3e5, 1.6e5, 1.6e5, 3.3e4));
    v.elements.push_back(element("secondary", bogie, "body", {xg, -1.0, 0.8 - kRollingRadius}, 4.3e5, 1.6e5, 1.6e5, 0.0));
    for (double dx : {1.28, -1.28}) {
      const std::string name = "wheelset" + std::to_string(++wheelset);
      Body w = body(name, kWheelsetMass, {1120.0, 112.0, 1120.0}, {xg + dx, 0.0, 0.0});
      w.held = {Motion::bounce, Motion::roll, Motion::pitch};
      v.bodies.push_back(w);
      Wheelset ws;
      ws.body = name;
      ws.spin_inertia = kSpinInertia;
      ws.contact.rolling_radius = kRollingRadius;
      ws.contact.contact_half_spacing = kHalfSpacing;
      ws.contact.conicity = kConicity;
      ws.contact.creep = CreepCoefficients{kCreep, kCreep, 0.0, 0.0};
      v.wheelsets.push_back(ws);
      for (double y : {1.0, -1.0})
        v.elements.push_back(element("primary", name, bogie, {xg + dx, y, 0.0}, 1.22e6, 4.0e6, 4.0e6, 0.0));
    }
  }
  return v;
}

// The yaw dampers: longitudinal, between body and bogie at y = ±1.3 m; the stretch of a point
// at y from yaw ψ is −y·ψ.
void add_yaw_dampers(LinearSystem& s) {
  for (int g = 1; g <= 2; ++g)
    for (double y : {1.3, -1.3}) {
      SeriesDamperRow row;
      row.direction = Motion::longitudinal;
      row.stretch = Eigen::RowVectorXd::Zero(s.size());
      row.stretch(s.index_of("body.yaw")) = -y;
      row.stretch(s.index_of("bogie" + std::to_string(g) + ".yaw")) = y;
      row.damping = 4.0e5;
      row.stiffness = 5.0e6;
      s.series_dampers.push_back(row);
    }
}

double median(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

struct Times {
  std::vector<double> wall, cpu;
};

template <class F>
void time(Times& t, const F& f) {
  const std::clock_t cpu = std::clock();
  const auto start = std::chrono::steady_clock::now();
  f();
  t.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  t.cpu.push_back(static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: stability_timing OUT.json REPEATS\n";
    return 2;
  }
  const int repeats = std::max(1, std::atoi(argv[2]));
  LinearSystem system = assemble(bogie_vehicle(), DofSet::lateral);
  add_yaw_dampers(system);

  HuntingOptions locus;
  locus.min_speed = 10.0 / 3.6;
  locus.max_speed = 500.0 / 3.6;
  locus.speed_count = 1000;
  // The critical speed alone: a coarse grid of 10 speeds brackets it (and every interval the
  // dip guard can find), Brent refines it to 1e-8.
  HuntingOptions critical = locus;
  critical.speed_count = 10;
  critical.threads = 2;

  HuntingResult one, two, quick;
  Times t1, t2, tc;
  for (int r = 0; r < repeats; ++r) {  // alternating, so that all three see the same machine
    locus.threads = 1;
    time(t1, [&] { one = solve_hunting_stability(system, locus); });
    locus.threads = 2;
    time(t2, [&] { two = solve_hunting_stability(system, locus); });
    time(tc, [&] { quick = solve_hunting_stability(system, critical); });
  }
  for (size_t b = 0; b < one.branches.size(); ++b)
    if (one.branches[b].eigenvalues != two.branches[b].eigenvalues) {
      std::cerr << "stability_timing: one and two threads differ on branch " << one.branches[b].name << "\n";
      return 1;
    }
  if (!one.critical || !quick.critical) {
    std::cerr << "stability_timing: no critical speed in range (" << to_string(one.verdict) << ")\n";
    return 1;
  }
  std::cout << "locus_1_thread_s " << median(t1.wall) << "\nlocus_1_thread_cpu_s " << median(t1.cpu) << "\n";
  std::cout << "locus_2_threads_s " << median(t2.wall) << "\nlocus_2_threads_cpu_s " << median(t2.cpu) << "\n";
  std::cout << "critical_speed_s " << median(tc.wall) << "\ncritical_speed_cpu_s " << median(tc.cpu) << "\n";
  std::cerr << "stability_timing: " << system.size() << " DOFs, " << system.series_dampers.size() << " series dampers, "
            << one.branches.size() << " branches; critical speed " << one.critical->speed * 3.6 << " km/h ("
            << one.critical->branch << ", " << one.critical->frequency_hz << " Hz, Klingel "
            << one.critical->klingel_frequency_hz << " Hz), coarse grid " << quick.critical->speed * 3.6 << " km/h in "
            << quick.critical->evaluations << " evaluations\n";
  std::cerr << "  " << one.summary.brief() << "\n";
  for (const Check& check : one.summary.checks) std::cerr << "  " << check.name << ": " << check.value << "\n";
  for (const HuntingBranch& b : one.branches)
    std::cerr << "  " << b.name << (b.veers ? " (veers)" : "") << ": ζ " << b.damping_ratio.front() << " → "
              << b.damping_ratio.back() << "\n";

  const ContactMatrices c = contact_matrices(system);
  nlohmann::json j;
  j["mass"] = matrix(system.mass);
  j["damping"] = matrix(system.damping);
  j["stiffness"] = matrix(system.stiffness);
  j["creep_damping"] = matrix(c.creep_damping);
  j["gyroscopic"] = matrix(c.gyroscopic);
  j["contact_stiffness"] = matrix(c.stiffness);
  j["series"] = nlohmann::json::array();
  for (const SeriesDamperRow& row : system.series_dampers)
    j["series"].push_back(
        {{"stretch", std::vector<double>(row.stretch.data(), row.stretch.data() + row.stretch.size())},
         {"damping", row.damping},
         {"stiffness", row.stiffness}});
  j["speeds"] = one.speeds;
  // The least-damped ζ at each speed, over the branches (what the script recomputes from all
  // roots: here the least-damped root is always an oscillatory one).
  std::vector<double> zeta(one.speeds.size(), 1.0);
  for (const HuntingBranch& b : one.branches)
    for (size_t s = 0; s < zeta.size(); ++s) zeta[s] = std::min(zeta[s], b.damping_ratio[s]);
  j["least_damped_zeta"] = zeta;
  j["critical_speed"] = one.critical->speed;
  j["critical_bracket"] = {quick.speeds.front(), quick.speeds.back()};
  j["relative_tolerance"] = locus.relative_tolerance;
  std::ofstream(argv[1]) << j.dump();
  return 0;
}
