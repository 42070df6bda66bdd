// Small systems built by hand for the time-domain ride tests: a mass on its wheels' springs
// and dampers, bounce only, so its frequency response is written down directly.
#pragma once

#include <algorithm>
#include <complex>
#include <string>
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

/// A body of mass `body_mass` on a bogie of mass `bogie_mass`, bounce only: the body on a spring
/// `k2` and on a series damper (dashpot c with spring k in series, element "body damper"), the
/// bogie on one spring k1 and damper c1 per wheel at x = each of `wheel_x` (the track inputs).
struct BodyOnBogie {
  double body_mass = 30000.0, bogie_mass = 3000.0;
  double k2 = 1.2e6;            ///< N/m: the body's spring to the bogie
  double c = 6e4, k = 3e6;      ///< the series damper: N·s/m and N/m (k/c = 50 /s)
  double k1 = 2.4e6, c1 = 2e4;  ///< per wheel
  std::vector<double> wheel_x{9.35, 6.85, -6.85, -9.35};

  LinearSystem system() const {
    LinearSystem s;
    for (const char* name : {"body", "bogie"}) {
      Body b;
      b.name = name;
      b.mass = std::string(name) == "body" ? body_mass : bogie_mass;
      b.inertia = {1.0, 1.0, 1.0};
      s.vehicle.bodies.push_back(b);
    }
    s.dofs = {{"body.bounce", 0, Motion::bounce}, {"bogie.bounce", 1, Motion::bounce}};
    const double n = static_cast<double>(wheel_x.size());
    s.mass = Eigen::Vector2d(body_mass, bogie_mass).asDiagonal();
    s.stiffness = (Eigen::Matrix2d() << k2, -k2, -k2, k2 + n * k1).finished();
    s.damping = (Eigen::Matrix2d() << 0.0, 0.0, 0.0, n * c1).finished();
    s.gravity_stiffness = Eigen::MatrixXd::Zero(2, 2);
    for (size_t i = 0; i < wheel_x.size(); ++i) {
      Element wheel;
      wheel.name = "wheel " + std::to_string(i + 1);
      s.vehicle.elements.push_back(wheel);
      TrackInput input;
      input.element = static_cast<int>(i);
      input.point = {wheel_x[i], 0.0, 0.0};
      input.load_per_displacement = Eigen::MatrixXd::Zero(2, 3);
      input.load_per_velocity = Eigen::MatrixXd::Zero(2, 3);
      input.load_per_displacement(1, 2) = k1;
      input.load_per_velocity(1, 2) = c1;
      s.track_inputs.push_back(input);
    }
    Element damper;
    damper.name = "body damper";
    s.vehicle.elements.push_back(damper);
    s.series_dampers.push_back({static_cast<int>(wheel_x.size()), Motion::bounce,
                                (Eigen::RowVectorXd(2) << 1.0, -1.0).finished(), c, k});
    return s;
  }

  /// The body's displacement per unit track level at f Hz and speed V, the series damper as the
  /// Maxwell stiffness k_s = iωck/(k + iωc) beside k2: with D the 2 × 2 dynamic stiffness and Q
  /// the bogie's load Σ_i (k1 + iωc1) e^{−iω lag_i/V}, X = D⁻¹(0, Q).
  std::complex<double> body_response(double f, double speed) const {
    using C = std::complex<double>;
    const double w = 2.0 * 3.14159265358979323846 * f;
    const C ks = C(0.0, w * c) * k / C(k, w * c);
    double lead = wheel_x.front();
    for (double x : wheel_x) lead = std::max(lead, x);
    C load = 0.0;
    for (double x : wheel_x) load += C(k1, w * c1) * std::polar(1.0, -w * (lead - x) / speed);
    const double n = static_cast<double>(wheel_x.size());
    const C upper = k2 + ks;
    const C d11 = upper - w * w * body_mass, d22 = upper + n * C(k1, w * c1) - w * w * bogie_mass;
    return upper * load / (d11 * d22 - upper * upper);  // (D⁻¹)₁₂ = −D₁₂/det, D₁₂ = −upper
  }
};

}  // namespace railmodal::test
