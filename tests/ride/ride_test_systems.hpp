// Small systems built by hand for the ride tests: a mass on its wheels' springs and dampers,
// bounce only, so its frequency response is written down directly; a car body on four springs.
#pragma once

#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/ride_simulation.hpp"
#include "test_support.hpp"

namespace railmodal::test {

/// A body of mass `mass` (its reference point at the origin) bouncing on one spring k and
/// damper c per wheel at x = each of `wheel_x`.
inline LinearSystem bouncing_mass(double mass, double k, double c, const std::vector<double>& wheel_x) {
  LinearSystem s;
  Body body;
  body.name = "body";
  body.mass = mass;
  body.inertia = {1.0, 1.0, 1.0};
  s.vehicle.bodies.push_back(body);
  s.dofs.push_back({"body.bounce", 0, Motion::bounce});
  const double n = static_cast<double>(wheel_x.size());
  s.mass = Eigen::MatrixXd::Constant(1, 1, mass);
  s.stiffness = Eigen::MatrixXd::Constant(1, 1, n * k);
  s.damping = Eigen::MatrixXd::Constant(1, 1, n * c);
  s.gravity_stiffness = Eigen::MatrixXd::Zero(1, 1);
  for (size_t i = 0; i < wheel_x.size(); ++i) {
    TrackInput input;
    input.element = static_cast<int>(i);
    input.point = {wheel_x[i], 0.0, 0.0};
    input.load_per_displacement = Eigen::MatrixXd::Zero(1, 3);
    input.load_per_velocity = Eigen::MatrixXd::Zero(1, 3);
    input.load_per_displacement(0, 2) = k;
    input.load_per_velocity(0, 2) = c;
    s.track_inputs.push_back(input);
  }
  return s;
}

/// A car body of 12 t (roll, pitch, yaw inertia 2e4, 1e5, 1e5 kg·m²) on four springs at
/// (±3, ±1, 0), vertical and lateral 5e5 N/m and 8e3 N·s/m each, with its motions `held` held:
/// its reference point at z = `reference`, its centre of gravity at z = `cg`, its floor at
/// `floor_height` (Body::floor_height; none: not given). With cg = reference = 0 neither the
/// lateral springs nor gravity couple roll to lateral motion, and the body rolls about the
/// springs' plane alone; with the CG above the springs lateral motion and roll are coupled.
inline LinearSystem body_on_four_springs(std::optional<double> floor_height = std::nullopt, double reference = 0.0,
                                         double cg = 0.0, std::vector<Motion> held = {Motion::longitudinal}) {
  Vehicle v;
  v.name = "car body on four springs";
  Body b;
  b.name = "body";
  b.mass = 12000.0;
  b.inertia = Eigen::Vector3d(2e4, 1e5, 1e5);
  b.centre_of_gravity = Eigen::Vector3d(0.0, 0.0, cg);
  b.reference_point = Eigen::Vector3d(0.0, 0.0, reference);
  b.held = std::move(held);
  b.floor_height = floor_height;
  v.bodies.push_back(b);
  SpringStage coil;
  coil.kind = "coil";
  coil.stiffness = 5e5;
  const double points[4][2] = {{3.0, 1.0}, {3.0, -1.0}, {-3.0, 1.0}, {-3.0, -1.0}};
  for (int i = 0; i < 4; ++i) {
    Element e;
    e.name = "spring" + std::to_string(i + 1);
    e.upper = "body";
    e.point = Eigen::Vector3d(points[i][0], points[i][1], 0.0);
    e.vertical_stages = e.lateral_stages = {coil};
    e.vertical_damping = e.lateral_damping = 8e3;
    v.elements.push_back(e);
  }
  return assemble(v, DofSet::all);
}

/// Its displacement per unit track level at f Hz and speed V: Σ_i (k + iωc) e^{−iω lag_i/V} /
/// (n k − ω² m + i ω n c), lag_i behind the leading wheel.
inline std::complex<double> bouncing_mass_response(double mass, double k, double c, const std::vector<double>& wheel_x,
                                                   double f, double speed) {
  const double w = 2.0 * 3.14159265358979323846 * f;
  double lead = wheel_x.front();
  for (double x : wheel_x) lead = std::max(lead, x);
  std::complex<double> sum = 0.0;
  for (double x : wheel_x) sum += std::complex<double>(k, w * c) * std::polar(1.0, -w * (lead - x) / speed);
  const double n = static_cast<double>(wheel_x.size());
  return sum / std::complex<double>(n * k - w * w * mass, w * n * c);
}

/// The body's reference point as a ride output ("body displacement", …) along `axis`.
inline RideOutput body_point(ResponseQuantity quantity, RideAxis axis = RideAxis::vertical) {
  RideOutput o;
  o.name = std::string("body ") + to_string(quantity);
  o.body = "body";
  o.axis = axis;
  o.quantity = quantity;
  return o;
}

/// A periodic sine of `cycles` wavelengths over `samples` samples of `step` m.
inline TrackGeometry sine_track(double amplitude, int cycles, int samples, double step) {
  TrackGeometry g;
  g.step = step;
  g.periodic = true;
  g.vertical_level.resize(samples);
  for (int n = 0; n < samples; ++n) g.vertical_level(n) = amplitude * std::cos(2 * kPi * cycles * n / samples);
  return g;
}

}  // namespace railmodal::test
