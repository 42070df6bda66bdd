// Names a root of the hunting system from what moves most in it.
#pragma once

#include <Eigen/Core>
#include <string>

#include "railmodal/linear_system.hpp"

namespace railmodal::stability {

/// The name of a root from its displacement shape weighted by √M_ii (squared entries: the
/// kinetic energy of each degree of freedom, up to the factor ω²/2 they share). The body
/// that moves most, with the most energy per unit of its mass, names it, in words with a space
/// before a trailing number ("bogie1" → "bogie 1"):
///  - a wheelset (a body of system.vehicle.wheelsets) whose lateral and yaw motions both carry
///    at least 1 % of its energy is "hunting" (in the kinematic motion the yaw carries little
///    energy: ψ = 2πy/Λ), otherwise "lateral" or "yaw";
///  - another body is named by its motions that carry at least a quarter of its energy, the
///    larger first, joined by "/": "body lateral/roll", "bogie 1 yaw".
/// A system whose DOFs have no bodies (matrices read from files) is named after the label of
/// the DOF with the most energy. A shape with no displacement (a series damper's own root
/// where nothing moves) is "series damper".
std::string root_name(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape);

}  // namespace railmodal::stability
