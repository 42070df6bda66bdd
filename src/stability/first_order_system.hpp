// The first-order form of a vehicle on its wheelsets at speed V, and its eigenvalues.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/wheel_rail.hpp"

namespace railmodal::stability {

/// ż = A(V) z for z = (q, q̇, F), F the forces of the series dampers:
///   A(V) = [[0, I, 0], [−M⁻¹(K + K_c), −M⁻¹(C + C_c/V + V·G), −M⁻¹Sᵀ], [0, k·S, −k/c]]
/// with S the dampers' stretch rows. M is factored once (Cholesky) and every speed-independent
/// product with M⁻¹ is formed once, so a speed costs only the sum of three matrices.
class FirstOrderSystem {
 public:
  /// Throws NumericalError naming the degree of freedom where M is not positive definite, and
  /// std::invalid_argument for matrices of the wrong size or a series damper without a
  /// positive damping and stiffness.
  FirstOrderSystem(const LinearSystem& system, const ContactMatrices& contact);
  int dofs() const { return static_cast<int>(stiffness_.rows()); }
  int states() const { return 2 * dofs() + static_cast<int>(series_stiffness_.size()); }
  Eigen::MatrixXd state_matrix(double speed) const;
  /// √M_ii: the weights that make a displacement shape's squared entries kinetic energies.
  const Eigen::VectorXd& mass_weights() const { return mass_weights_; }

 private:
  Eigen::MatrixXd stiffness_;         // M⁻¹(K + K_c)
  Eigen::MatrixXd damping_;           // M⁻¹C
  Eigen::MatrixXd creep_damping_;     // M⁻¹C_c
  Eigen::MatrixXd gyroscopic_;        // M⁻¹G
  Eigen::MatrixXd series_force_;      // M⁻¹Sᵀ, n × m
  Eigen::MatrixXd series_stretch_;    // k·S, m × n
  Eigen::VectorXd series_stiffness_;  // k/c, m
  Eigen::VectorXd mass_weights_;
};

/// The roots of A(V) at one speed.
struct SpeedRoots {
  double speed = 0.0;
  Eigen::VectorXcd values;  ///< 1/s; complex ones in conjugate pairs, +Im first
  /// n × states: each root's displacement part, weighted by √M_ii and scaled to unit norm (a
  /// column of zeros where the root moves no mass). Empty when vectors were not asked for.
  Eigen::MatrixXcd shapes;
  /// Largest ‖Âx − λx‖/(‖Â‖‖x‖) over the roots, Â the balanced matrix (0 without vectors).
  double residual = 0.0;
};

/// Eigenvalues (and, with `vectors`, shapes) of A(V) by Hessenberg QR of the balanced matrix
/// (Eigen::EigenSolver). Throws NumericalError naming the speed when the solver fails.
SpeedRoots solve_at_speed(const FirstOrderSystem& system, double speed, bool vectors);

}  // namespace railmodal::stability
