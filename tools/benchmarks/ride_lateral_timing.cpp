// The lateral ride with creep (issue 21 item 9, "lateral ride with creep, state the figure";
// docs/ride.md, "Lateral ride through the creep forces", compute time): solve_ride on the
// Manchester benchmark coach on its four wheelsets (all DOFs, the linear creep contact at each
// speed) under ORE B176 low-level alignment, wavelengths 1 … 100 m, at 100, 125, …, 200 km/h;
// the lateral floor acceleration over each bogie centre and at mid-car. Times solve_ride (its
// processor time, medians of the repeats) and writes what compare_ride_lateral.py needs to redo
// the run with numpy: M, C, K, the contact matrices K_c, C_c, G, the wheelsets' lateral DOFs,
// axle positions and roll shares ρ, the output points, the grid and railmodal's RMS values.
//
//   ride_lateral_timing [--repeats N] [--json PATH]   time, and write the model
//   ride_lateral_timing --once                        one run (whole-process timing)
#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model_json.hpp"
#include "railmodal/railmodal.hpp"

using namespace railmodal;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLongest = 100.0, kShortest = 1.0;  // m: the bundled scene's band

struct Setup {
  LinearSystem system;
  TrackIrregularitySpectra track;
  std::vector<RideOutput> outputs;
  RideOptions options;
};

Setup setup() {
  Setup s;
  s.system = assemble(load_vehicle(RAILMODAL_DATA_DIR "/vehicles/manchester_benchmark_coach_wheelsets.toml"),
                      DofSet::all);
  s.track.alignment =
      TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, {2 * kPi / kLongest, 2 * kPi / kShortest});
  const Body& car = *std::max_element(s.system.vehicle.bodies.begin(), s.system.vehicle.bodies.end(),
                                      [](const Body& a, const Body& b) { return a.mass < b.mass; });
  const char* names[] = {"floor over front bogie, lateral", "floor at mid-car, lateral", "floor over rear bogie, lateral"};
  const double xs[] = {9.5, 0.0, -9.5};  // the bogie centres, 19 m apart (the vehicle file)
  for (int i = 0; i < 3; ++i) {
    RideOutput o;
    o.name = names[i];
    o.body = car.name;
    o.point = {xs[i], 0.0, car.reference_point.z()};
    o.axis = RideAxis::lateral;
    o.quantity = ResponseQuantity::acceleration;
    s.outputs.push_back(o);
  }
  for (double kmh = 100.0; kmh <= 200.0; kmh += 25.0) s.options.speeds.push_back(kmh / 3.6);
  s.options.keep_spectra = false;
  return s;
}

int dof_of(const LinearSystem& s, const std::string& body, Motion motion) {
  for (size_t d = 0; d < s.dofs.size(); ++d)
    if (s.vehicle.bodies[s.dofs[d].body].name == body && s.dofs[d].motion == motion) return static_cast<int>(d);
  return -1;
}

nlohmann::json model_json(const Setup& s, const RideResult& r) {
  using benchmarks::matrix;
  const ContactMatrices c = contact_matrices(s.system);
  nlohmann::json j;
  j["mass"] = matrix(s.system.mass);
  j["damping"] = matrix(s.system.damping);
  j["stiffness"] = matrix(s.system.stiffness);
  j["contact_stiffness"] = matrix(c.stiffness);
  j["creep_damping"] = matrix(c.creep_damping);
  j["gyroscopic"] = matrix(c.gyroscopic);
  for (const Dof& d : s.system.dofs) j["dofs"].push_back({{"label", d.label}, {"body", s.system.vehicle.bodies[d.body].name}});
  for (const Body& b : s.system.vehicle.bodies)
    j["reference_points"][b.name] = {b.reference_point.x(), b.reference_point.y(), b.reference_point.z()};
  for (size_t i = 0; i < s.system.vehicle.wheelsets.size(); ++i) {
    const Wheelset& w = s.system.vehicle.wheelsets[i];
    const ResolvedContact& rc = c.wheelsets[i];
    const double kappa = 1.0 + rc.roll_parameter * rc.rolling_radius / rc.contact_half_spacing;
    for (const Body& b : s.system.vehicle.bodies)
      if (b.name == w.body)
        j["wheelsets"].push_back({{"lateral", dof_of(s.system, w.body, Motion::lateral)},
                                  {"x", b.centre_of_gravity.x()},
                                  {"rho", (kappa - 1.0) / kappa}});
  }
  for (const RideOutput& o : s.outputs)
    j["outputs"].push_back({{"name", o.name},
                            {"body", o.body},
                            {"point", {o.point.x(), o.point.y(), o.point.z()}},
                            {"frame", to_string(o.frame)}});
  j["gravity"] = s.system.vehicle.gravity;
  j["band"] = {2 * kPi / kLongest, 2 * kPi / kShortest};
  j["speeds"] = s.options.speeds;
  j["grid"] = std::vector<double>(r.frequencies.data(), r.frequencies.data() + r.frequencies.size());
  for (const RideAtSpeed& at : r.speeds) {
    std::vector<double> rms;
    for (const RideOutputAtSpeed& o : at.outputs) rms.push_back(o.rms);
    j["rms"].push_back(rms);
  }
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 11;
  std::string json_path;
  bool once = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeats" && i + 1 < argc) repeats = std::stoi(argv[++i]);
    else if (a == "--json" && i + 1 < argc) json_path = argv[++i];
    else if (a == "--once") once = true;
    else {
      std::cerr << "usage: ride_lateral_timing [--repeats N] [--json PATH] | --once\n";
      return 2;
    }
  }
  const Setup s = setup();
  if (once) {
    const RideResult r = solve_ride(s.system, s.track, s.outputs, s.options);
    for (const RideAtSpeed& at : r.speeds) {
      std::cout << at.speed * 3.6;
      for (const RideOutputAtSpeed& o : at.outputs) std::cout << "\t" << o.rms;
      std::cout << "\n";
    }
    return 0;
  }
  std::vector<double> cpu;
  RideResult r;
  for (int k = 0; k < repeats; ++k) {
    const std::clock_t c0 = std::clock();
    r = solve_ride(s.system, s.track, s.outputs, s.options);
    cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  std::sort(cpu.begin(), cpu.end());
  nlohmann::json j = model_json(s, r);
  j["cpu_seconds"] = cpu;
  std::cout << "solve_ride, lateral ride with creep: " << r.frequencies.size() << " frequencies x "
            << s.options.speeds.size() << " speeds, " << s.system.size() << " DOFs; processor time median "
            << cpu[cpu.size() / 2] << " s (range " << cpu.front() << " .. " << cpu.back() << ")\n";
  if (!json_path.empty()) std::ofstream(json_path) << j.dump();
  return 0;
}
