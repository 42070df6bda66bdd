// Complex modes of the first-order form (see the header).
#include "response/state_space_modes.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numeric>
#include <vector>

namespace railmodal::response {
namespace {

// The uncoupled blocks of the system: DOFs that no entry of M, K or C joins are in different
// blocks (a symmetric wagon's vertical and lateral motions). Each block's modes are found on
// their own, so a load on one block gives exactly zero in another, as the direct solve does;
// one eigensolution of the whole would leave round-off (1e-16) across the blocks.
std::vector<std::vector<int>> blocks(const LinearSystem& s) {
  const int n = s.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (s.mass(i, j) != 0.0 || s.stiffness(i, j) != 0.0 || s.damping(i, j) != 0.0 || s.mass(j, i) != 0.0 ||
          s.stiffness(j, i) != 0.0 || s.damping(j, i) != 0.0)
        parent[root(i)] = root(j);
  std::vector<std::vector<int>> out;
  std::vector<int> index(n, -1);
  for (int i = 0; i < n; ++i) {
    const int r = root(i);
    if (index[r] < 0) index[r] = static_cast<int>(out.size()), out.emplace_back();
    out[index[r]].push_back(i);
  }
  return out;
}

}  // namespace

std::optional<StateSpaceModes> state_space_modes(const LinearSystem& system, bool allow_undamped) {
  const int n = system.size();
  if (n == 0) return std::nullopt;
  StateSpaceModes out;
  out.undamped.assign(2 * n, false);
  out.roots = Eigen::VectorXcd::Zero(2 * n);
  out.shapes = Eigen::MatrixXcd::Zero(n, 2 * n);
  out.projection = Eigen::MatrixXcd::Zero(2 * n, n);
  int column = 0;
  for (const std::vector<int>& dofs : blocks(system)) {
    const int m = static_cast<int>(dofs.size());
    Eigen::MatrixXd M(m, m), K(m, m), C(m, m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) {
        M(a, b) = system.mass(dofs[a], dofs[b]);
        K(a, b) = system.stiffness(dofs[a], dofs[b]);
        C(a, b) = system.damping(dofs[a], dofs[b]);
      }
    const Eigen::LLT<Eigen::MatrixXd> mass(M);
    if (mass.info() != Eigen::Success || mass.matrixL().toDenseMatrix().diagonal().minCoeff() <= 0.0) return std::nullopt;
    const Eigen::MatrixXd mass_inverse = mass.solve(Eigen::MatrixXd::Identity(m, m));
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * m, 2 * m);
    A.topRightCorner(m, m).setIdentity();
    A.bottomLeftCorner(m, m) = -mass_inverse * K;
    A.bottomRightCorner(m, m) = -mass_inverse * C;
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(A);
    if (solver.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXcd roots = solver.eigenvalues();
    for (Eigen::Index r = 0; r < roots.size(); ++r) {
      if (roots(r).real() < -1e-9 * std::abs(roots(r))) continue;  // strictly damped
      if (!allow_undamped || !(std::abs(roots(r).real()) <= 1e-9 * std::abs(roots(r))) || roots(r) == 0.0)
        return std::nullopt;  // rigid-body or unstable, or undamped where not allowed
      out.undamped[column + r] = true;
    }
    const Eigen::MatrixXcd V = solver.eigenvectors();
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(V);
    if (!(lu.rcond() >= 1e-10)) return std::nullopt;
    const Eigen::MatrixXcd projection = lu.inverse().rightCols(m) * mass_inverse.cast<std::complex<double>>();
    for (int r = 0; r < 2 * m; ++r, ++column) {
      out.roots(column) = roots(r);
      for (int a = 0; a < m; ++a) {
        out.shapes(dofs[a], column) = V(a, r);
        out.projection(column, dofs[a]) = projection(r, a);
      }
    }
  }
  return out;
}

}  // namespace railmodal::response
