// Small-displacement kinematics of a rigid body whose degrees of freedom are the six
// motions (lateral, bounce, roll, pitch, yaw, longitudinal) of a reference point; the
// longitudinal one is a degree of freedom only where the body frees it (see Motion).
#pragma once

#include <Eigen/Core>

#include "railmodal/vehicle.hpp"

namespace railmodal::model {

// The six rigid motions: lateral, bounce, roll, pitch, yaw, longitudinal, in the order of Motion.
// Motion::bending, after them, is no motion of the reference point: a body that has a bending
// mode gets one coordinate more, after every body's six (model/assembly.cpp, Layout), so that
// the rigid blocks, and everything of a vehicle without bending, stay as they were.
constexpr int kMotionsPerBody = 6;
using BodyVector = Eigen::Matrix<double, kMotionsPerBody, 1>;
using BodyMatrix = Eigen::Matrix<double, kMotionsPerBody, kMotionsPerBody>;
using PointMap = Eigen::Matrix<double, 3, kMotionsPerBody>;

/// Displacement (x, y, z) of the body-fixed point `point` per unit of each motion:
/// u = u_ref + θ × (point − reference).
PointMap point_map(const Body& body, const Eigen::Vector3d& point);

/// Mass matrix of the body about its reference point: translation of the CG through the
/// lever CG − reference adds m·l² to roll and pitch and couples lateral with roll (the m3·d0
/// of the book's lateral model, bogie-wagons-natural digest §2.9).
BodyMatrix body_mass(const Body& body);

/// Second-order potential of a dead load `force` at `point` (gravity, static spring load):
/// K = (F·r) I − ½(F rᵀ + r Fᵀ) on the rotations, r = point − reference. A weight W at a
/// height l above the reference gives −W·l in roll and pitch, the −8Pl of eq. (156a).
BodyMatrix dead_load_stiffness(const Body& body, const Eigen::Vector3d& point,
                               const Eigen::Vector3d& force);

}  // namespace railmodal::model
