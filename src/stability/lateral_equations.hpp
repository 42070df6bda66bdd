// The lateral equations of motion of a vehicle on its wheelsets with nonlinear contact, as a
// first-order system for a time integrator: x = (q, q̇, F) with F the series dampers' forces,
//   M q̈ = −C q̇ − K q − Σ stretchᵀ F + Q_contact(q, q̇, V),   Ḟ = k·(stretch·q̇ − F/c).
// With the linear creep law and no flange, Q_contact = −(C_c/V + V·G) q̇ − K_c q exactly: the
// linear hunting model (docs/stability.md, "The nonlinear critical speed").
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "model/wheelset_creepage.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/nonlinear_hunting.hpp"
#include "railmodal/wheel_rail.hpp"

namespace railmodal::stability {

/// One wheelset as the contact forces see it.
struct WheelsetContact {
  int lateral = -1;    ///< DOF index of the body's lateral motion
  int yaw = -1;        ///< DOF index of its yaw
  double lever = 0.0;  ///< m: the axle centre's lateral displacement is q[lateral] + lever·q[yaw]
  model::WheelsetGeometry geometry;
  CreepCoefficients creep;
  double axle_load = 0.0;       ///< W, N: the gravitational stiffness W·ε/l0
  double gyroscopic = 0.0;      ///< g = I_y·σ/(r0·l0), kg: the gyroscopic coupling per unit speed
  double friction_limit = 0.0;  ///< μN per wheel, N
};

class LateralEquations {
 public:
  /// Throws std::invalid_argument as contact_matrices does.
  LateralEquations(const LinearSystem& system, const NonlinearHuntingOptions& options);

  int size() const { return 2 * dofs_ + static_cast<int>(dampers_.size()); }
  int dofs() const { return dofs_; }
  const std::vector<WheelsetContact>& wheelsets() const { return wheelsets_; }
  const ContactMatrices& linear_contact() const { return linear_; }

  /// ẋ at speed V.
  void derivative(double speed, const Eigen::VectorXd& x, Eigen::VectorXd* dx) const;
  /// The contact forces over the DOFs at speed V: creep, gravitational stiffness, gyroscopic, flange.
  Eigen::VectorXd contact_forces(double speed, const Eigen::VectorXd& q, const Eigen::VectorXd& rate) const;
  /// The first wheelset's axle-centre lateral displacement, m.
  double leading_lateral(const Eigen::VectorXd& x) const;

 private:
  model::WheelContactForces creep_forces(const WheelsetContact& w, const model::WheelCreepage& c) const;

  int dofs_ = 0;
  Eigen::MatrixXd damping_, stiffness_;
  Eigen::LLT<Eigen::MatrixXd> mass_;
  std::vector<SeriesDamperRow> dampers_;
  std::vector<WheelsetContact> wheelsets_;
  ContactMatrices linear_;
  bool saturation_ = false, flange_ = false;
  double contact_angle_ = 0.0;  ///< δ0, rad: the centred wheelset's spin is ∓δ0/r0
  double flange_clearance_ = 0.0, flange_stiffness_ = 0.0;
};

}  // namespace railmodal::stability
