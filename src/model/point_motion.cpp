// The motion of a body-fixed point from the degrees of freedom: rigid-body kinematics,
// u = u_ref + θ × (point − reference), per DOF of that body.
#include "model/point_motion.hpp"

#include <stdexcept>

#include "model/rigid_body.hpp"

namespace railmodal::model {

Eigen::MatrixXd point_displacement_map(const LinearSystem& system, int body, const Eigen::Vector3d& point) {
  if (body < 0 || body >= static_cast<int>(system.vehicle.bodies.size()))
    throw std::invalid_argument("point_displacement_map: no body " + std::to_string(body));
  const PointMap G = point_map(system.vehicle.bodies[body], point);
  Eigen::MatrixXd map = Eigen::MatrixXd::Zero(3, system.size());
  for (int d = 0; d < system.size(); ++d)
    if (system.dofs[d].body == body) map.col(d) = G.col(static_cast<int>(system.dofs[d].motion));
  return map;
}

}  // namespace railmodal::model
