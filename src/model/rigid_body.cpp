#include "model/rigid_body.hpp"

#include <Eigen/Dense>

namespace railmodal::model {
namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// The motions as columns of the six rigid-body velocities (vx vy vz ωx ωy ωz).
Eigen::Matrix<double, 6, kMotionsPerBody> motion_basis() {
  Eigen::Matrix<double, 6, kMotionsPerBody> b = Eigen::Matrix<double, 6, kMotionsPerBody>::Zero();
  b(1, 0) = 1.0;  // lateral
  b(2, 1) = 1.0;  // bounce
  b(3, 2) = 1.0;  // roll
  b(4, 3) = 1.0;  // pitch
  b(5, 4) = 1.0;  // yaw
  b(0, 5) = 1.0;  // longitudinal
  return b;
}

}  // namespace

PointMap point_map(const Body& body, const Eigen::Vector3d& point) {
  Eigen::Matrix<double, 3, 6> full;
  full.leftCols<3>().setIdentity();
  full.rightCols<3>() = -cross_matrix(point - body.reference_point);  // θ × d = −d × θ
  return full * motion_basis();
}

BodyMatrix body_mass(const Body& body) {
  const Eigen::Vector3d r = body.centre_of_gravity - body.reference_point;
  const Eigen::Matrix3d rx = cross_matrix(r);
  Eigen::Matrix<double, 6, 6> m6;
  m6.topLeftCorner<3, 3>() = body.mass * Eigen::Matrix3d::Identity();
  m6.topRightCorner<3, 3>() = -body.mass * rx;
  m6.bottomLeftCorner<3, 3>() = body.mass * rx;
  m6.bottomRightCorner<3, 3>() = Eigen::Matrix3d(body.inertia.asDiagonal()) - body.mass * rx * rx;
  const auto b = motion_basis();
  return b.transpose() * m6 * b;
}

BodyMatrix dead_load_stiffness(const Body& body, const Eigen::Vector3d& point,
                               const Eigen::Vector3d& force) {
  const Eigen::Vector3d r = point - body.reference_point;
  Eigen::Matrix<double, 6, 6> k6 = Eigen::Matrix<double, 6, 6>::Zero();
  k6.bottomRightCorner<3, 3>() = force.dot(r) * Eigen::Matrix3d::Identity() -
                                 0.5 * (force * r.transpose() + r * force.transpose());
  const auto b = motion_basis();
  return b.transpose() * k6 * b;
}

}  // namespace railmodal::model
