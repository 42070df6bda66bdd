// What ride_timing.cpp (frequency domain) and ride_realisation_timing.cpp (time domain) share:
// the vertical Manchester benchmark coach, its three floor points, the model as JSON for the
// numpy/scipy script that redoes the run, and the timing of a call (wall and processor time,
// medians of the repeats).
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model_json.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::benchmarks {

constexpr double kPi = 3.14159265358979323846;

inline const char* const kCoach = RAILMODAL_DATA_DIR "/vehicles/manchester_benchmark_coach.toml";

/// The vertical floor acceleration over the front bogie centre, at mid-car and over the rear
/// bogie centre, at the car body's reference height: the car body is the heaviest body, the
/// bogies are the bodies named "bogie…".
inline std::vector<RideOutput> coach_floor_outputs(const LinearSystem& system) {
  const std::vector<Body>& bodies = system.vehicle.bodies;
  const Body& car =
      *std::max_element(bodies.begin(), bodies.end(), [](const Body& a, const Body& b) { return a.mass < b.mass; });
  std::vector<double> xs;
  for (const Body& b : bodies)
    if (b.name.rfind("bogie", 0) == 0) xs.push_back(b.reference_point.x());
  std::sort(xs.begin(), xs.end(), std::greater<double>());  // front first
  xs.insert(xs.begin() + 1, car.centre_of_gravity.x());     // front bogie, mid-car, rear bogie
  const char* names[] = {"floor over front bogie", "floor at mid-car", "floor over rear bogie"};
  std::vector<RideOutput> outputs;
  for (std::size_t i = 0; i < xs.size() && i < 3; ++i) {
    RideOutput o;
    o.name = std::string(names[i]) + ", vertical";
    o.body = car.name;
    o.point = {xs[i], 0.0, car.reference_point.z()};
    o.axis = RideAxis::vertical;
    o.quantity = ResponseQuantity::acceleration;
    outputs.push_back(o);
  }
  return outputs;
}

/// M, C, K, the DOF labels and bodies, the bodies' reference points, the track inputs (their
/// vertical columns and x), the output points and the track band [rad/m] of wavelengths
/// `longest` … `shortest` [m]: what the script needs to redo the run.
inline nlohmann::json coach_model_json(const LinearSystem& system, const std::vector<RideOutput>& outputs,
                                       double longest, double shortest) {
  nlohmann::json j;
  j["mass"] = matrix(system.mass);
  j["damping"] = matrix(system.damping);
  j["stiffness"] = matrix(system.stiffness);
  for (const Dof& d : system.dofs) j["dofs"].push_back({{"label", d.label}, {"body", system.vehicle.bodies[d.body].name}});
  for (const Body& b : system.vehicle.bodies)
    j["reference_points"][b.name] = {b.reference_point.x(), b.reference_point.y(), b.reference_point.z()};
  for (const TrackInput& in : system.track_inputs) {
    const Eigen::VectorXd d = in.load_per_displacement.col(2), v = in.load_per_velocity.col(2);
    j["inputs"].push_back({{"x", in.point.x()},
                           {"load_per_displacement", std::vector<double>(d.data(), d.data() + d.size())},
                           {"load_per_velocity", std::vector<double>(v.data(), v.data() + v.size())}});
  }
  for (const RideOutput& o : outputs)
    j["outputs"].push_back({{"name", o.name}, {"body", o.body}, {"point", {o.point.x(), o.point.y(), o.point.z()}}});
  j["band"] = {2 * kPi / longest, 2 * kPi / shortest};
  return j;
}

/// The wall and processor times of each call of time(); their medians.
class Stopwatch {
 public:
  template <typename Call>
  void time(Call call) {
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    call();
    wall_.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpu_.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  double median_wall() const { return median(wall_); }
  double median_cpu() const { return median(cpu_); }

 private:
  static double median(std::vector<double> t) {
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  }
  std::vector<double> wall_, cpu_;
};

}  // namespace railmodal::benchmarks
