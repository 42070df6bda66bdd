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

/// Eigenvalues a ≤ b belong to one cluster (a repeated frequency): relative gap at most 1e-8,
/// or both rigid-body (|λ| ≤ zero, where their differences are round-off).
bool same_eigenvalue(double a, double b, double zero);

/// One past the last index of the cluster that holds values(count − 1) (values ascending).
int cluster_end(const Eigen::VectorXd& values, int count, double zero);

/// DOFs whose row of M is exactly zero.
std::vector<int> massless_dofs(const Eigen::SparseMatrix<double>& M);

}  // namespace railmodal::solve
