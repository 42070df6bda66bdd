// The first-order system of hunting stability and its eigen-solve at one speed.
//
// Why a real nonsymmetric solver on the state matrix: K_c is not symmetric and C_c/V + V·G is
// neither symmetric nor proportional, so no symmetric reduction applies. Eigen::EigenSolver
// (Hessenberg reduction and real Schur form, Golub & Van Loan §7.5) returns complex roots in
// exact conjugate pairs, which the tracking uses to pair the two halves of a mode. The state
// mixes metres, radians, m/s and newtons, and at low speed the creep damping C_c/V makes some
// entries orders of magnitude larger than others: the matrix is balanced first
// (solve/balance.hpp), exactly, by powers of two.
#include "stability/first_order_system.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

#include "railmodal/errors.hpp"
#include "shortest_text.hpp"
#include "solve/balance.hpp"

namespace railmodal::stability {

namespace {

using cd = std::complex<double>;

void require_square(const Eigen::MatrixXd& A, int n, const char* what) {
  if (A.rows() != n || A.cols() != n)
    throw std::invalid_argument(std::string("hunting stability: ") + what + " is " + std::to_string(A.rows()) + " x " +
                                std::to_string(A.cols()) + ", the system has " + std::to_string(n) +
                                " degrees of freedom");
  if (!A.allFinite()) throw NumericalError(std::string("hunting stability: ") + what + " contains NaN or infinity");
}

// Cholesky M = LLᵀ column by column, so that a pivot that is not positive names its DOF
// (Eigen's LLT reports only that it failed).
Eigen::MatrixXd cholesky_factor(const LinearSystem& system) {
  const Eigen::MatrixXd& M = system.mass;
  const int n = system.size();
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    double pivot = M(j, j) - L.row(j).head(j).squaredNorm();
    // A pivot at round-off of the diagonal is a mass the other DOFs already account for.
    if (!(pivot > 1e-12 * std::abs(M(j, j))) || !std::isfinite(pivot))
      throw NumericalError("hunting stability: the mass matrix is singular at degree of freedom '" +
                           system.dofs[j].label + "' (pivot " + shortest_text(pivot, 3) +
                           "): every motion of a wheelset, bogie or body needs mass or inertia");
    L(j, j) = std::sqrt(pivot);
    for (int i = j + 1; i < n; ++i) L(i, j) = (M(i, j) - L.row(i).head(j).dot(L.row(j).head(j))) / L(j, j);
  }
  return L;
}

}  // namespace

FirstOrderSystem::FirstOrderSystem(const LinearSystem& system, const ContactMatrices& contact) {
  const int n = system.size();
  if (static_cast<int>(system.dofs.size()) != n || n == 0)
    throw std::invalid_argument("hunting stability: the system has no degrees of freedom");
  require_square(system.mass, n, "the mass matrix");
  require_square(system.stiffness, n, "the stiffness matrix");
  const Eigen::MatrixXd C = system.damping.size() == 0 ? Eigen::MatrixXd::Zero(n, n) : system.damping;
  require_square(C, n, "the damping matrix");
  require_square(contact.creep_damping, n, "the creep damping matrix");
  require_square(contact.gyroscopic, n, "the gyroscopic matrix");
  require_square(contact.stiffness, n, "the contact stiffness matrix");

  const Eigen::MatrixXd L = cholesky_factor(system);
  const auto llt = [&L](const Eigen::MatrixXd& B) {
    // No right-hand sides (a vehicle without series dampers): Eigen's triangular solve would bind
    // a reference to the empty matrix's null data, which UBSan rightly reports.
    if (B.cols() == 0) return Eigen::MatrixXd(B.rows(), 0);
    Eigen::MatrixXd X = L.triangularView<Eigen::Lower>().solve(B);
    L.transpose().triangularView<Eigen::Upper>().solveInPlace(X);
    return X;
  };
  stiffness_ = llt(system.stiffness + contact.stiffness);
  damping_ = llt(C);
  creep_damping_ = llt(contact.creep_damping);
  gyroscopic_ = llt(contact.gyroscopic);

  const int m = static_cast<int>(system.series_dampers.size());
  Eigen::MatrixXd S(m, n);
  series_stretch_.resize(m, n);
  series_stiffness_.resize(m);
  for (int j = 0; j < m; ++j) {
    const SeriesDamperRow& row = system.series_dampers[j];
    if (row.stretch.size() != n)
      throw std::invalid_argument("hunting stability: series damper " + std::to_string(j + 1) + " has " +
                                  std::to_string(row.stretch.size()) + " stretch entries, the system has " +
                                  std::to_string(n) + " degrees of freedom");
    if (!(row.damping > 0.0 && row.stiffness > 0.0 && std::isfinite(row.damping) && std::isfinite(row.stiffness)))
      throw std::invalid_argument("hunting stability: series damper " + std::to_string(j + 1) +
                                  " needs a positive, finite damping and stiffness");
    S.row(j) = row.stretch;
    series_stretch_.row(j) = row.stiffness * row.stretch;
    series_stiffness_(j) = row.stiffness / row.damping;
  }
  series_force_ = llt(S.transpose());
  mass_weights_ = system.mass.diagonal().cwiseSqrt();
}

Eigen::MatrixXd FirstOrderSystem::state_matrix(double speed) const {
  const int n = dofs(), m = static_cast<int>(series_stiffness_.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(states(), states());
  A.block(0, n, n, n).setIdentity();
  A.block(n, 0, n, n) = -stiffness_;
  A.block(n, n, n, n) = -(damping_ + creep_damping_ / speed + speed * gyroscopic_);
  if (m > 0) {
    A.block(n, 2 * n, n, m) = -series_force_;
    A.block(2 * n, n, m, n) = series_stretch_;
    A.block(2 * n, 2 * n, m, m).diagonal() = -series_stiffness_;
  }
  return A;
}

SpeedRoots solve_at_speed(const FirstOrderSystem& system, double speed, bool vectors) {
  Eigen::MatrixXd A = system.state_matrix(speed);
  const Eigen::VectorXd scaling = solve::balance(A);
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(A, vectors);
  if (eig.info() != Eigen::Success || !eig.eigenvalues().allFinite())
    throw NumericalError("hunting stability: the eigensolver did not converge at " + shortest_text(speed, 6) + " m/s");
  SpeedRoots roots;
  roots.speed = speed;
  roots.values = eig.eigenvalues();
  if (!vectors) return roots;

  const Eigen::MatrixXcd X = eig.eigenvectors();
  const Eigen::MatrixXcd R = A.cast<cd>() * X - X * roots.values.asDiagonal();
  const double norm_A = A.norm();
  for (int k = 0; k < X.cols(); ++k)
    if (norm_A > 0.0) roots.residual = std::max(roots.residual, R.col(k).norm() / (norm_A * X.col(k).norm()));

  const int n = system.dofs();
  roots.shapes = (system.mass_weights().cwiseProduct(scaling.head(n))).cast<cd>().asDiagonal() * X.topRows(n);
  for (int k = 0; k < X.cols(); ++k) {
    const double norm = roots.shapes.col(k).norm();
    if (norm > 0.0) roots.shapes.col(k) /= norm;
  }
  return roots;
}

}  // namespace railmodal::stability
