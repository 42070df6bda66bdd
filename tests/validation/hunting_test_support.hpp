// Test support for the hunting validation: vehicles with wheelsets built in code, and the
// eigenvalues of M q̈ + (C + C_c/V + V·G) q̇ + (K + K_c) q = 0 formed here, with Eigen's general
// EigenSolver, independently of the library's stability solver.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "railmodal/railmodal.hpp"

namespace railmodal::test {

/// One wheelset's data. Representative of a passenger-coach wheelset (r0, l0 as the Manchester
/// benchmark coach's, 0.46 m and 0.75 m); the creep coefficients are of the size f = G·a·b·C
/// (CreepCoefficients) gives for semi-axes of ~6 mm, a wheel load of ~50 kN.
struct WheelsetData {
  std::string name = "wheelset";
  double x = 0.0;               // m, axle position
  double mass = 1500.0;         // kg
  double roll_inertia = 700.0;  // kg·m²
  double yaw_inertia = 800.0;   // kg·m²
  double spin_inertia = 100.0;  // kg·m²
  double r0 = 0.46;             // m
  double l0 = 0.75;             // m
  double conicity = 0.15;
  std::optional<double> epsilon;  // none: the knife-edge default
  std::optional<double> sigma;
  CreepCoefficients creep{1.0e7, 0.9e7, 1.0e4, 100.0};
};

/// The wheelset as a Body with its bounce, roll and pitch held, and its Wheelset entry.
inline void add_wheelset(Vehicle& v, const WheelsetData& d) {
  Body b;
  b.name = d.name;
  b.mass = d.mass;
  b.inertia = {d.roll_inertia, d.yaw_inertia, d.yaw_inertia};
  b.centre_of_gravity = {d.x, 0.0, 0.0};
  b.reference_point = {d.x, 0.0, 0.0};
  b.held = {Motion::bounce, Motion::roll, Motion::pitch};
  v.bodies.push_back(b);
  Wheelset w;
  w.body = d.name;
  w.spin_inertia = d.spin_inertia;
  w.contact.rolling_radius = d.r0;
  w.contact.contact_half_spacing = d.l0;
  w.contact.conicity = d.conicity;
  w.contact.contact_angle_parameter = d.epsilon;
  w.contact.roll_parameter = d.sigma;
  w.contact.creep = d.creep;
  v.wheelsets.push_back(w);
}

/// A spring between `upper` and `lower` ("" = the fixed frame, the ground) at `point`.
inline Element spring(const std::string& name, const std::string& upper, const std::string& lower,
                      const Eigen::Vector3d& point, double longitudinal, double lateral, double vertical = 0.0) {
  Element e;
  e.name = name;
  e.upper = upper;
  e.lower = lower;
  e.point = point;
  if (longitudinal > 0.0) e.longitudinal_stages = {{"coil", longitudinal, 1}};
  if (lateral > 0.0) e.lateral_stages = {{"coil", lateral, 1}};
  if (vertical > 0.0) e.vertical_stages = {{"coil", vertical, 1}};
  return e;
}

/// Lateral stiffness `lateral` and yaw stiffness `yaw` from the wheelset to a fixed frame: two
/// springs at y = ±b, each lateral/2, longitudinal yaw/(2b²) (yaw stiffness 2·k_x·b²).
inline void add_springs_to_ground(Vehicle& v, const WheelsetData& d, double lateral, double yaw, double b = 1.0) {
  for (double y : {-b, b})
    v.elements.push_back(
        spring(d.name + (y > 0 ? ".left" : ".right"), d.name, "", {d.x, y, 0.0}, yaw / (2.0 * b * b), lateral / 2.0));
}

/// One wheelset held to a fixed frame by lateral and yaw springs (none where both are zero): with
/// the defaults, the wheelset on springs of data/vehicles/wheelset_on_springs.toml (k_y = 1 MN/m,
/// k_ψ = 2 MN·m/rad), whose linear critical speed hunting_validation_test.cpp finds by
/// Routh–Hurwitz. The hunting, nonlinear-hunting and lateral-ride tests share it.
inline Vehicle wheelset_on_springs(const WheelsetData& d = {}, double k_y = 1.0e6, double k_psi = 2.0e6) {
  Vehicle v;
  v.name = "wheelset on springs";
  add_wheelset(v, d);
  if (k_y > 0.0 || k_psi > 0.0) add_springs_to_ground(v, d, k_y, k_psi);
  return v;
}

/// The system with its contact terms at one speed.
struct HuntingModel {
  LinearSystem system;
  ContactMatrices contact;
};

inline HuntingModel hunting_model(const Vehicle& v, std::optional<double> conicity = std::nullopt) {
  HuntingModel m{assemble(v, DofSet::lateral), {}};
  m.contact = contact_matrices(m.system, conicity);
  return m;
}

/// The first-order matrix A of ẋ = A x, x = (q, q̇), at speed V.
inline Eigen::MatrixXd first_order(const HuntingModel& m, double speed) {
  const int n = m.system.size();
  const Eigen::MatrixXd c = m.system.damping + m.contact.creep_damping / speed + speed * m.contact.gyroscopic;
  const Eigen::MatrixXd k = m.system.stiffness + m.contact.stiffness;
  const Eigen::MatrixXd minv = m.system.mass.inverse();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
  a.bottomLeftCorner(n, n) = -minv * k;
  a.bottomRightCorner(n, n) = -minv * c;
  return a;
}

inline Eigen::VectorXcd eigenvalues(const HuntingModel& m, double speed) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(first_order(m, speed), false);
  return solver.eigenvalues();
}

/// The largest real part of the eigenvalues, 1/s.
inline double max_real_part(const HuntingModel& m, double speed) { return eigenvalues(m, speed).real().maxCoeff(); }

/// The oscillatory eigenvalue (Im > 0) of smallest modulus: the kinematic (hunting) root at low
/// speed, where the others are either real (creep-damped) or of the suspension's frequencies.
inline std::complex<double> slowest_oscillatory_root(const HuntingModel& m, double speed) {
  std::complex<double> best(0.0, 0.0);
  double best_modulus = std::numeric_limits<double>::infinity();
  for (const auto& l : eigenvalues(m, speed))
    if (l.imag() > 1e-9 * std::abs(l) && std::abs(l) < best_modulus) {
      best = l;
      best_modulus = std::abs(l);
    }
  return best;
}

/// The root of a function that is negative at `stable` and positive at `unstable`, by
/// bisection to a relative width of 1e-13.
inline double bisect(const std::function<double(double)>& f, double stable, double unstable) {
  double lo = stable, hi = unstable;
  for (int i = 0; i < 200 && std::abs(hi - lo) > 1e-13 * std::abs(hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// ---------------------------------------------------------------------------------------------
// The characteristic polynomial of one wheelset, derived by hand from the equations of motion
// (docs/stability.md), not from the assembled matrices. With the lateral spring k_y and the yaw
// spring k_ψ to a fixed frame, κ = 1 + σ·r0/l0 and g = I_y·σ/(r0·l0), the equations are (the
// lateral creepage is κẏ/V − ψ and, its transpose, the generalised lateral force κ·ΣFy)
//
//   m ÿ + (2f22κ²/V) ẏ + (2f23κ/V − gV) ψ̇ + (k_y + Wε/l0 − 2f23κ(ε−σ)/(r0 l0)) y − 2f22κ ψ = 0
//   I ψ̈ + ((2f11 l0² + 2f33)/V) ψ̇ + (gV − 2f23κ/V) ẏ + (2f11 λ l0/r0 − 2f33(ε−σ)/(r0 l0)) y
//       + (k_ψ + 2f23) ψ = 0
//
// With y, ψ ∝ e^{st} and the names
//   a = 2f22κ²/V,  p = k_y + Wε/l0 − 2f23κ(ε−σ)/(r0 l0),  e = gV − 2f23κ/V,
//   c = (2f11 l0² + 2f33)/V,  q = k_ψ + 2f23,  h = gV − 2f23κ/V,  b = 2f11λl0/r0 − 2f33(ε−σ)/(r0 l0),
// the determinant (m s² + a s + p)(I s² + c s + q) − (−e s − 2f22κ)(h s + b) is
//   a4 s⁴ + a3 s³ + a2 s² + a1 s + a0 with
//   a4 = m I,  a3 = m c + a I,  a2 = m q + a c + p I + e h,  a1 = a q + c p + e b + 2f22κ h,
//   a0 = p q + 2f22κ b.
// Routh–Hurwitz for a quartic: stable iff every a_i > 0 and H = a3 a2 a1 − a4 a1² − a3² a0 > 0;
// the critical speed is where H changes sign (the others staying positive there).
struct Quartic {
  double a4, a3, a2, a1, a0;
  double hurwitz() const { return a3 * a2 * a1 - a4 * a1 * a1 - a3 * a3 * a0; }
  bool coefficients_positive() const { return a4 > 0 && a3 > 0 && a2 > 0 && a1 > 0 && a0 > 0; }
};

inline Quartic wheelset_quartic(const WheelsetData& d, double weight, double k_y, double k_psi, double speed) {
  const double eps = d.epsilon.value_or(d.conicity), sig = d.sigma.value_or(d.conicity);
  const double r0 = d.r0, l0 = d.l0, v = speed;
  const auto& f = d.creep;
  const double kappa = 1.0 + sig * r0 / l0, g = d.spin_inertia * sig / (r0 * l0);
  const double a = 2 * f.f22 * kappa * kappa / v,
               p = k_y + weight * eps / l0 - 2 * f.f23 * kappa * (eps - sig) / (r0 * l0);
  const double e = g * v - 2 * f.f23 * kappa / v, c = (2 * f.f11 * l0 * l0 + 2 * f.f33) / v, q = k_psi + 2 * f.f23;
  const double h = g * v - 2 * f.f23 * kappa / v;
  const double b = 2 * f.f11 * d.conicity * l0 / r0 - 2 * f.f33 * (eps - sig) / (r0 * l0);
  const double m = d.mass, i = d.yaw_inertia;
  return {m * i, m * c + a * i, m * q + a * c + p * i + e * h, a * q + c * p + e * b + 2 * f.f22 * kappa * h,
          p * q + 2 * f.f22 * kappa * b};
}

// The speed at which a Routh–Hurwitz determinant crosses zero, by bisection in [lo, hi].
inline double routh_critical_speed(const WheelsetData& d, double weight, double k_y, double k_psi, double lo,
                                   double hi) {
  return bisect([&](double v) { return -wheelset_quartic(d, weight, k_y, k_psi, v).hurwitz(); }, lo, hi);
}

}  // namespace railmodal::test
