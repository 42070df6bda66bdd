// The motion of a body-fixed point from the degrees of freedom: rigid-body kinematics,
// u = u_ref + θ × (point − reference), per DOF of that body, and on a body with a bending mode
// the mode's vertical displacement φ(x)·q_b (model/body_bending.hpp).
#include "model/point_motion.hpp"

#include <stdexcept>

#include "model/body_bending.hpp"
#include "model/rigid_body.hpp"

namespace railmodal::model {

Eigen::MatrixXd point_displacement_map(const LinearSystem& system, int body, const Eigen::Vector3d& point) {
  if (body < 0 || body >= static_cast<int>(system.vehicle.bodies.size()))
    throw std::invalid_argument("point_displacement_map: no body " + std::to_string(body));
  const Body& b = system.vehicle.bodies[body];
  const PointMap G = point_map(b, point);
  Eigen::MatrixXd map = Eigen::MatrixXd::Zero(3, system.size());
  for (int d = 0; d < system.size(); ++d) {
    if (system.dofs[d].body != body) continue;
    if (system.dofs[d].motion == Motion::bending)
      map(2, d) = bending_mode(b).shape_at(point.x(), "a point on body '" + b.name + "'");
    else
      map.col(d) = G.col(static_cast<int>(system.dofs[d].motion));
  }
  return map;
}

int body_index(const LinearSystem& system, const std::string& name) {
  const auto& bodies = system.vehicle.bodies;
  for (size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name == name) return static_cast<int>(b);
  return -1;
}

}  // namespace railmodal::model
