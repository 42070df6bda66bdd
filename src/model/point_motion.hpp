// The motion of a body-fixed point in terms of the assembled degrees of freedom: the one map
// that point outputs (ride), point forces and anything else that looks at a point go through,
// so that a body's flexible modes (when it has them) reach all of them at once.
#pragma once

#include <Eigen/Core>
#include <string>

#include "railmodal/linear_system.hpp"

namespace railmodal::model {

/// 3 × n: the displacement (longitudinal, lateral, vertical; m) of `point` (vehicle frame, m)
/// on body `body` per unit of each of the system's degrees of freedom. Columns of DOFs of
/// other bodies are zero. The body's bending DOF ("<body>.bending", Body::bending) moves the
/// point vertically by the mode shape φ(x) (1 at the beam's ends). Throws
/// std::invalid_argument for a body index out of range, or a point beyond the ends of the
/// body's bending beam.
Eigen::MatrixXd point_displacement_map(const LinearSystem& system, int body, const Eigen::Vector3d& point);

/// The index in system.vehicle.bodies of the body named `name`; −1 when there is none (the
/// track, an element's empty lower end).
int body_index(const LinearSystem& system, const std::string& name);

}  // namespace railmodal::model
