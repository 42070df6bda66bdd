// Small systems built by hand for the time-domain ride tests: a mass on its wheels' springs
// and dampers, bounce only, so its frequency response is written down directly.
#pragma once

#include <complex>
#include <vector>

#include "railmodal/linear_system.hpp"

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

}  // namespace railmodal::test
