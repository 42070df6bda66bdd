// The back-ends of solve_modes: each returns eigenpairs of K φ = λ M φ; modal_solver.cpp
// turns them into classified, named, checked modes.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal::solve {

struct Eigenpairs {
  Eigen::VectorXd values;   ///< λ, ascending
  Eigen::MatrixXd vectors;  ///< n × m, M-orthonormal, over every DOF (massless ones recovered)
  std::vector<int> massless;  ///< DOFs with a zero row of M (condensed statically)
  /// The |λ| that ModalOptions::zero_tolerance is a fraction of.
  double scale = 0.0;
  /// The number of eigenvalues of (K, M) that are zero to working precision, by inertia
  /// (low_modes.hpp), or -1 when it could not be counted (ModalOptions::zero_tolerance decides).
  int rigid_count = -1;
  double zero_band = 0.0;  ///< t of eigenvalues_near_zero, 1/s²
  Eigen::VectorXd errors;  ///< a bound of each λ's rounding error, 1/s²
  SolverSummary summary;
};

/// Every eigenpair (dense_modal.cpp): massless DOFs condensed statically, a checked Cholesky
/// factorisation of M, a symmetric QR. scale = max |λ|. The DOFs' labels name them in errors.
Eigenpairs dense_eigenpairs(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const std::vector<Dof>& dofs);

/// The `count` lowest eigenpairs, extended to the end of a cluster (arpack_modal.cpp).
/// scale = max(max Kᵢᵢ/Mᵢᵢ, max |λ| found).
Eigenpairs arpack_eigenpairs(const Eigen::SparseMatrix<double>& M, const Eigen::SparseMatrix<double>& K,
                             const std::vector<std::string>& labels, int count, const ModalOptions& options);

/// Eigenvalues a ≤ b belong to one cluster (a repeated frequency): relative gap at most
/// kRepeatedGap, or both rigid-body (|λ| ≤ zero, where their differences are round-off).
bool same_eigenvalue(double a, double b, double zero);

/// The relative gap |b − a| / max(|a|, |b|) up to which two eigenvalues are one frequency.
/// Any combination of two modes split by δ is an exact mode of the model changed by δ/2 of its
/// stiffness (its residual ‖Kφ − λ̄Mφ‖ is at most (δ/2) λ̄ ‖Mφ‖), so below the precision of the
/// data the pair's own shapes, and the phases their names give, say nothing of the vehicle: a
/// value written to 4 significant digits ("1220 kN/m") is uncertain by 5e-5 to 5e-4 of itself,
/// and twins that differ by their last digit split more than a weaker coupling splits them and
/// move each on its own. 1e-4 (5e-5 in frequency): the coach on wheelsets' pairs that the car
/// body hardly couples (each bogie's wheelsets at 14.90, 16.36 and 50.55 Hz, split by 1.2e-7,
/// 4.7e-5 and 1.6e-9; the coach on track's bogie yaw at 35.35 Hz, 1.4e-8) are one frequency; the
/// pairs it couples (bogies' bounce, sway, yaw: 1.7e-3 to 9.5e-3; the closest in a bundled
/// vehicle, the coach's bogies' upper sway at 12.8 Hz, 3.7e-4) are two. The hunting branches'
/// twins are one value likewise (stability::kTwins: 1e-4 of |λ| + |μ|). The solver's rounding is far
/// below (Mode::eigenvalue_error: 4ε of the largest λ, 1e-11 of λ at 1 Hz under a 50 Hz top).
constexpr double kRepeatedGap = 1e-4;

/// One past the last index of the cluster that holds values(count − 1) (values ascending).
int cluster_end(const Eigen::VectorXd& values, int count, double zero);

/// DOFs whose row of M is exactly zero.
std::vector<int> massless_dofs(const Eigen::SparseMatrix<double>& M);

}  // namespace railmodal::solve
