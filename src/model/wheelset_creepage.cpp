// The creepages of a wheelset's two wheels and the linear creep law. docs/stability.md derives
// each term from first principles; the classical treatments are Wickens, Fundamentals of Rail
// Vehicle Dynamics (2003), and Knothe and Stichel, Rail Vehicle Dynamics (2017).
#include "model/wheelset_creepage.hpp"

namespace railmodal::model {

WheelsetCreepages wheelset_creepages(const WheelsetGeometry& g, const WheelsetState& s) {
  const double r0 = g.rolling_radius;
  const double l0 = g.contact_half_spacing;
  // Left wheel: its rolling radius r0 + λy turns at the axle's V/r0, so its contact point moves
  // back by Vλy/r0 relative to the rail; yaw rate moves the left wheel back by l0·ψ̇.
  const double longitudinal_left = -(g.conicity * s.lateral / r0 + l0 * s.yaw_rate / s.speed);
  // Both wheels slide sideways with the axle, plus the roll rate φ̇ = σẏ/l0 carrying the contact
  // (r0 below the axle) to the left; the wheel rolls along its own heading, ψ off the track's.
  const double lateral = (1.0 + g.roll_parameter * r0 / l0) * s.lateral_rate / s.speed - s.yaw;
  // The spin V/r0 about the axle has a component along each contact normal equal to the angle
  // between normal and the axle's perpendicular: δ_left − φ on the left (sign −), δ_right + φ on
  // the right (sign +); their changes with y are both −(ε − σ)y/l0 · V/r0. The yaw rate adds ψ̇.
  const double spin = s.yaw_rate / s.speed - (g.contact_angle_parameter - g.roll_parameter) * s.lateral / (r0 * l0);
  WheelsetCreepages c;
  c.left = {longitudinal_left, lateral, spin};
  c.right = {-longitudinal_left, lateral, spin};
  return c;
}

WheelContactForces linear_creep_forces(const CreepCoefficients& f, const WheelCreepage& x) {
  return {-f.f11 * x.longitudinal, -f.f22 * x.lateral - f.f23 * x.spin, f.f23 * x.lateral - f.f33 * x.spin};
}

WheelsetLoad wheelset_load(const WheelsetGeometry& g, const WheelContactForces& left, const WheelContactForces& right) {
  const double l0 = g.contact_half_spacing;
  // The lateral generalised force is κ·ΣFy, the transpose of the creepage map (ξy carries κ·ẏ/V):
  // by virtual work a displacement δy moves the contact points, r0 below an axle that rolls by
  // σ·δy/l0, through κ·δy. Seen as forces: ΣFy at the rail head has the roll moment r0·ΣFy about
  // the axle, which the rails take as a normal-load difference r0·ΣFy/l0; the normals, inclined
  // by ±δ0, add δ0·r0·ΣFy/l0 laterally, and for cones δ0 = σ. With ΣFy alone the lateral creep
  // would take 2f22κẏ²/V from the motion where the creepages dissipate 2f22κ²ẏ²/V
  // (docs/stability.md, "The equations of motion").
  // The moment about z of a force (Fx, Fy) at (0, ±l0): x·Fy − y·Fx = ∓l0·Fx.
  const double kappa = 1.0 + g.roll_parameter * g.rolling_radius / l0;
  return {kappa * (left.lateral + right.lateral),
          -l0 * left.longitudinal + l0 * right.longitudinal + left.spin_moment + right.spin_moment};
}

}  // namespace railmodal::model
