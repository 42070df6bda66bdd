// The exact kinematics and inertia forces of one crank, connecting rod and crosshead
// (docs/driving_gear.md, "Exact forces"). The λ-series of Zhdanov (10)–(13) and the closed forms
// (33)–(43) are checks of this, not its method (tests/validation/driving_gear_validation_test.cpp).
#include <cmath>
#include <stdexcept>

#include "railmodal/driving_gear.hpp"

namespace railmodal {

namespace {
constexpr double kGravity = 9.81;  // m/s², the digest's g (Zhdanov uses 9.81 throughout)
}  // namespace

double rod_inertia_about_centre(double inertia_about_point, double mass, double distance) {
  return inertia_about_point - mass * distance * distance;
}

double rod_dynamic_defect(const GearCylinder& c) {
  return c.rod_mass * c.rod_centre_of_mass * (c.rod_length - c.rod_centre_of_mass) - c.rod_inertia;
}

CrankKinematics crank_kinematics(const GearCylinder& c, double phi, double omega) {
  const double r = c.crank_radius, L = c.rod_length;
  if (!(r > 0.0) || !(L > r))
    throw std::invalid_argument("crank kinematics: need 0 < crank_radius < rod_length (cylinder '" + c.name + "')");
  const double lambda = r / L;
  // The rod from the crosshead pin B (on the cylinder axis) to the crank pin A at height r sin φ:
  // sin β = λ sin φ. Differentiating cos β·β̇ = λω cos φ once more gives β̈ (steady ω).
  const double s = lambda * std::sin(phi), cb = std::sqrt(1.0 - s * s);
  const double beta_dot = lambda * omega * std::cos(phi) / cb;
  const double beta_ddot = (s * beta_dot * beta_dot - lambda * omega * omega * std::sin(phi)) / cb;
  CrankKinematics k;
  k.crank_angle = phi;
  k.crank_pin_x = -r * std::cos(phi);
  k.crank_pin_y = r * std::sin(phi);
  k.crosshead_x = -r * std::cos(phi) + L * cb;
  k.crosshead_velocity = r * omega * std::sin(phi) - L * s * beta_dot;
  k.crosshead_acceleration = r * omega * omega * std::cos(phi) - L * (cb * beta_dot * beta_dot + s * beta_ddot);
  k.rod_angle = std::asin(s);
  k.rod_angular_velocity = beta_dot;
  k.rod_angular_acceleration = beta_ddot;
  return k;
}

RodForces rod_forces(const GearCylinder& c, double phi, double omega) {
  const CrankKinematics k = crank_kinematics(c, phi, omega);
  const double r = c.crank_radius, L = c.rod_length, d = c.rod_centre_of_mass, m = c.rod_mass;
  const double s = std::sin(k.rod_angle), cb = std::cos(k.rod_angle);
  // Accelerations of the crank pin (centripetal), the crosshead pin (along x) and the rod's
  // centre of mass, which lies on BA at d from B, so its acceleration interpolates linearly.
  const double aAx = r * omega * omega * std::cos(phi), aAy = -r * omega * omega * std::sin(phi);
  const double aB = k.crosshead_acceleration;
  const double aGx = aB + d / L * (aAx - aB), aGy = d / L * aAy;
  // F = the crank pin's force on the rod. Rod + crosshead along x (the guide carries no x force):
  // F_x = m a_Gx + m_k a_B. Moments of the rod about B, with A − B = L(−cos β, sin β) and the rod's
  // orientation angle π − β (so its angular acceleration is −β̈):
  // L(−cos β F_y − sin β F_x) = −J_G β̈ + m d(−cos β a_Gy − sin β a_Gx).
  const double Fx = m * aGx + c.reciprocating_mass * aB;
  const double tan_beta = s / cb;
  const double Fy = -tan_beta * Fx + c.rod_inertia * k.rod_angular_acceleration / (L * cb) +
                    m * d / L * (aGy + tan_beta * aGx);
  // The guide's force on the crosshead N closes the vertical balance of rod + crosshead:
  // F_y + N = m a_Gy (the crosshead does not move vertically).
  const double N = m * aGy - Fy;
  RodForces f;
  f.crank_angle = phi;
  f.horizontal = -Fx;  // the rod's force on the pin is the reaction
  f.vertical = -Fy;
  // Z, the crosshead's force on the bars, is −N; the static weight of the crosshead group and of
  // the rod's share at B (exactly m(1 − d/L) at any rod angle: moments about A) presses down.
  f.guide = -N - (c.reciprocating_mass + m * (1.0 - d / L)) * kGravity;
  return f;
}

}  // namespace railmodal
