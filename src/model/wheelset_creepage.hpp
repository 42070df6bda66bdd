// The creepage kinematics of a wheelset on straight track and the linear creep law: what
// the linear contact matrices are built from, and what a nonlinear analysis can call on any
// state with a saturated creep law instead (docs/stability.md, "The equations of motion").
//
// Frame: x forward, y to the left, z up; yaw ψ positive anticlockwise seen from above; the
// left wheel is the one at y = +l0. The state is that of the axle centre.
#pragma once

#include "railmodal/vehicle.hpp"

namespace railmodal::model {

/// The linearised contact geometry of a wheelset (docs/stability.md defines each parameter).
struct WheelsetGeometry {
  double rolling_radius = 0.0;           ///< r0, m
  double contact_half_spacing = 0.0;     ///< l0, m
  double conicity = 0.0;                 ///< λ: r_left − r_right = 2λy
  double contact_angle_parameter = 0.0;  ///< ε: δ_left − δ_right = 2εy/l0 (against the track plane)
  double roll_parameter = 0.0;           ///< σ: the wheelset's roll φ = σy/l0 (left side up)
};

/// Lateral displacement and yaw of the axle centre and their rates, at forward speed `speed`.
struct WheelsetState {
  double lateral = 0.0;       ///< y, m
  double yaw = 0.0;           ///< ψ, rad
  double lateral_rate = 0.0;  ///< ẏ, m/s
  double yaw_rate = 0.0;      ///< ψ̇, rad/s
  double speed = 0.0;         ///< V, m/s, > 0
};

/// The creepages of one wheel: the slip velocity of the wheel's material at the contact
/// relative to the rail, over V, in the contact plane; spin about the contact normal pointing
/// into the wheel. Counted from the centred wheelset rolling straight (whose equal and opposite
/// spin ∓δ0/r0 gives equal and opposite lateral forces that cancel; a saturating law must add
/// it back).
struct WheelCreepage {
  double longitudinal = 0.0;  ///< ξx
  double lateral = 0.0;       ///< ξy
  double spin = 0.0;          ///< ξsp, 1/m
};

struct WheelsetCreepages {
  WheelCreepage left;   ///< the wheel at y = +l0
  WheelCreepage right;  ///< the wheel at y = −l0
};

/// The creepages of both wheels, linear in the state:
///   ξx = ∓(λy/r0 + l0ψ̇/V)  (upper sign left: the larger rolling radius lags the rail),
///   ξy = (1 + σ·r0/l0)·ẏ/V − ψ  (the roll rate σẏ/l0 swings the contact r0 below the axle),
///   ξsp = ψ̇/V − (ε − σ)·y/(r0·l0)  (yaw rate, and the rolling spin V/r0 tilted by the change
///   of contact angle the roll does not cancel).
WheelsetCreepages wheelset_creepages(const WheelsetGeometry& geometry, const WheelsetState& state);

/// The tangential contact forces on one wheel, in the contact plane, of a creep law.
struct WheelContactForces {
  double longitudinal = 0.0;  ///< Fx, N
  double lateral = 0.0;       ///< Fy, N
  double spin_moment = 0.0;   ///< Mz about the contact normal, N·m
};

/// Kalker's linear law with the signs of CreepCoefficients: Fx = −f11ξx, Fy = −f22ξy − f23ξsp,
/// Mz = f23ξy − f33ξsp.
WheelContactForces linear_creep_forces(const CreepCoefficients& creep, const WheelCreepage& creepage);

/// What the two wheels' forces do to the wheelset: the generalised lateral force κ·(Fy,left +
/// Fy,right), κ = 1 + σ·r0/l0 (the transpose of the creepage map: the contact points move κ·δy
/// when the axle moves δy and rolls σ·δy/l0), and the yaw moment about the axle centre (a
/// longitudinal force Fx at y = ±l0 turns it by ∓l0·Fx).
struct WheelsetLoad {
  double lateral = 0.0;  ///< N
  double yaw = 0.0;      ///< N·m
};
WheelsetLoad wheelset_load(const WheelsetGeometry& geometry, const WheelContactForces& left,
                           const WheelContactForces& right);

}  // namespace railmodal::model
