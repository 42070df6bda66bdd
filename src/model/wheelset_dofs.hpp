// Where a wheelset sits in a vehicle and in an assembled system: its body, its lateral and yaw
// degrees of freedom, the lever from its reference point to the axle, and the gyroscopic
// coefficient of its spin. One answer for the linear contact terms (wheel_rail_contact.cpp) and
// the nonlinear lateral equations (stability/lateral_equations.cpp).
#pragma once

#include <string>

#include "railmodal/linear_system.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal::model {

/// The wheelset standing on the body named `body`, or nullptr when that body is not a wheelset.
const Wheelset* wheelset_of(const Vehicle& vehicle, const std::string& body);

/// The index into vehicle.bodies of the body the wheelset on `body` hangs from: the other body of
/// the first element (in the vehicle's order: its primary suspension) joining it to a body that
/// is not a wheelset; -1 when none does (a wheelset held by the track alone). A bogie frame, or
/// a two-axle wagon's body.
int wheelset_carrier(const Vehicle& vehicle, const std::string& body);

/// A wheelset's place in an assembled system.
struct WheelsetDofs {
  int body = -1;       ///< index into vehicle.bodies
  int lateral = -1;    ///< index into system.dofs
  int yaw = -1;        ///< index into system.dofs
  double lever = 0.0;  ///< x_axle − x_ref, m: the axle's lateral displacement is y_ref + lever·ψ
};

/// Finds the wheelset's body and DOFs. Throws std::invalid_argument ("contact_matrices: wheelset
/// '<body>': …") when the body is missing, its centre of gravity (the axle centre) or reference
/// point is off the track's centre line or the axle plane (y, z ≠ 0), its lateral or yaw motion
/// is not a free DOF, or its
/// bounce, roll or pitch is free (they follow the rails in the linear model).
WheelsetDofs wheelset_dofs(const LinearSystem& system, const Wheelset& wheelset);

/// g = I_y·σ/(r0·l0): the spin angular momentum I_y·V/r0 tilted by the roll σy/l0 gives the yaw
/// moment V·g·ẏ; its partner, the lateral force −V·g·ψ̇, makes G skew-symmetric (docs/stability.md).
inline double gyroscopic_coefficient(double spin_inertia, double roll_parameter, double rolling_radius,
                                     double contact_half_spacing) {
  return spin_inertia * roll_parameter / (rolling_radius * contact_half_spacing);
}

}  // namespace railmodal::model
