// Small systems built by hand for the time-domain ride tests: a mass on its wheels' springs
// and dampers, bounce only, so its frequency response is written down directly.
#pragma once

#include <cmath>
#include <complex>
#include <string>
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
