// Dense generalised symmetric eigen-analysis K φ = λ M φ with static condensation of
// massless degrees of freedom and a checked Cholesky factorisation of M: every eigenpair.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "railmodal/errors.hpp"
#include "railmodal/modal.hpp"
#include "shortest_text.hpp"
#include "solve/eigenpairs.hpp"
#include "solve/low_modes.hpp"

namespace railmodal::solve {

namespace {

Eigen::MatrixXd take(const Eigen::MatrixXd& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) out(i, j) = A(rows[i], cols[j]);
  return out;
}

// Cholesky M = L Lᵀ that names the degree of freedom where it breaks down, so that a
// mass matrix that is not positive definite is a clear error and never garbage. Eigen's LLT
// does the work; when it reports a failure, or a pivot is at round-off level, the
// factorisation is repeated column by column to find the degree of freedom.
// `dofs[kept[j]]` is row j of M (its label is only read for the message).
Eigen::MatrixXd checked_cholesky(const Eigen::MatrixXd& M, const std::vector<Dof>& dofs, const std::vector<int>& kept) {
  const double tiny = 64.0 * std::numeric_limits<double>::epsilon() * M.diagonal().cwiseAbs().maxCoeff();
  Eigen::LLT<Eigen::MatrixXd> llt(M);
  if (llt.info() == Eigen::Success) {
    Eigen::MatrixXd L = llt.matrixL();
    if ((L.diagonal().array().square() > tiny).all()) return L;
  }
  const int n = static_cast<int>(M.rows());
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    double pivot = M(j, j) - L.row(j).head(j).squaredNorm();
    // Round-off in a positive definite matrix leaves pivots of order ε·scale at worst.
    if (!(pivot > tiny))
      throw NumericalError("the mass matrix is not positive definite at degree of freedom '" + dofs[kept[j]].label +
                           "' (pivot " + shortest_text(pivot, 3) + "): its inertia is zero or depends on the others");
    L(j, j) = std::sqrt(pivot);
    for (int i = j + 1; i < n; ++i)
      L(i, j) = (M(i, j) - L.row(i).head(j).dot(L.row(j).head(j))) / L(j, j);
  }
  return L;  // every pivot passed after all (LLT was at the round-off edge)
}

}  // namespace

namespace {

// The direct solve gives every λ to an absolute error of about ε·λmax, which leaves the low
// modes of a system with a huge stiffness or mass contrast (a soft spring beside a nearly
// rigid link: λmax/λ ≈ 1e13) with only a few correct digits. The modes below the geometric
// mean of the spectrum are solved again in the subspace they span with ZᵀKZ and ZᵀMZ formed
// in double-double (refine_low_modes): their error is then about ε times the largest of them.
// Spectra narrower than 1e8 (every wagon) are left as they are. Returns how many were refined.
int refine_low_end(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double zero, Eigen::VectorXd* lambda,
                   Eigen::MatrixXd* phi) {
  const double top = lambda->cwiseAbs().maxCoeff();
  if (!needs_refinement(*lambda, top, zero)) return 0;
  double lowest = top;
  for (Eigen::Index k = 0; k < lambda->size(); ++k)
    if (std::abs((*lambda)(k)) > zero) lowest = std::min(lowest, std::abs((*lambda)(k)));
  const double crossover = std::sqrt(lowest * top);
  int window = 0;
  while (window < lambda->size() && std::abs((*lambda)(window)) < crossover) ++window;
  refine_low_modes(K, M, window, lambda, phi);
  return window;
}

// The bound of each λ's rounding error: 4ε times the largest |λ| of the problem it was solved in
// (the refined window, or the whole spectrum).
Eigen::VectorXd rounding_bounds(const Eigen::VectorXd& lambda, int refined) {
  Eigen::VectorXd bound = Eigen::VectorXd::Constant(lambda.size(), rounding_bound(lambda.cwiseAbs().maxCoeff()));
  if (refined > 0) bound.head(refined).setConstant(rounding_bound(lambda.head(refined).cwiseAbs().maxCoeff()));
  return bound;
}

}  // namespace

Eigenpairs dense_eigenpairs(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const std::vector<Dof>& dofs) {
  const int n = static_cast<int>(M.rows());
  Eigenpairs result;
  result.summary.solver = ModalSolver::dense;

  // Massless DOFs: an exactly zero row of M. They are condensed statically, as the book
  // eliminates the massless leaf-spring end (eq. 192e) and the bogie roll (eq. 252c).
  std::vector<int> kept, massless;
  kept.reserve(n);
  for (int i = 0; i < n; ++i) (M.row(i).cwiseAbs().maxCoeff() == 0.0 ? massless : kept).push_back(i);
  if (kept.empty()) throw NumericalError("every degree of freedom is massless");
  // Without massless DOFs the reduced matrices are K and M themselves (no copies).
  Eigen::MatrixXd condensed_K, recover;  // φ_massless = recover · φ_kept
  if (!massless.empty()) {
    condensed_K = take(K, kept, kept);
    const Eigen::MatrixXd Kss = take(K, massless, massless);
    const Eigen::MatrixXd Ksm = take(K, massless, kept);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Kss);
    lu.setThreshold(1e-12);
    if (!lu.isInvertible()) {
      // Name a massless DOF with no stiffness of its own.
      std::string name = dofs[massless[0]].label;
      for (int s : massless)
        if (K.row(s).cwiseAbs().maxCoeff() == 0.0) { name = dofs[s].label; break; }
      throw NumericalError("degree of freedom '" + name +
                           "' has neither mass nor a restraint; give it inertia or hold it");
    }
    recover = -lu.solve(Ksm);
    condensed_K += take(K, kept, massless) * recover;
  }
  result.massless = massless;
  const Eigen::MatrixXd kept_M = massless.empty() ? Eigen::MatrixXd() : take(M, kept, kept);
  const Eigen::MatrixXd& Kr = massless.empty() ? K : condensed_K;
  const Eigen::MatrixXd& Mr = massless.empty() ? M : kept_M;

  // K φ = λ M φ  →  (L⁻¹ K L⁻ᵀ) y = λ y,  φ = L⁻ᵀ y: φ is M-normalised when y is unit.
  const Eigen::MatrixXd L = checked_cholesky(Mr, dofs, kept);
  const auto lower = L.triangularView<Eigen::Lower>();
  Eigen::MatrixXd A = lower.solve(Kr);
  A = lower.solve(A.transpose()).transpose();
  A = 0.5 * (A + A.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  if (eig.info() != Eigen::Success) throw NumericalError("the symmetric eigensolver did not converge");
  result.values = eig.eigenvalues();  // ascending
  Eigen::MatrixXd phi_kept = L.transpose().triangularView<Eigen::Upper>().solve(eig.eigenvectors());
  // Rigid-body modes are counted by the inertia of K ∓ tM, not read off the computed λ.
  result.zero_band = zero_band(Kr, Mr);
  result.rigid_count = eigenvalues_near_zero(Kr, Mr, result.zero_band);
  const int refined = refine_low_end(Kr, Mr, result.zero_band, &result.values, &phi_kept);
  result.errors = rounding_bounds(result.values, refined);

  const int m = static_cast<int>(kept.size());
  if (massless.empty()) {
    result.vectors = std::move(phi_kept);  // every DOF kept, in order
  } else {
    result.vectors = Eigen::MatrixXd::Zero(n, m);
    for (int i = 0; i < m; ++i) result.vectors.row(kept[i]) = phi_kept.row(i);
    const Eigen::MatrixXd rec = recover * phi_kept;
    for (size_t s = 0; s < massless.size(); ++s) result.vectors.row(massless[s]) = rec.row(static_cast<int>(s));
  }
  result.scale = result.values.cwiseAbs().maxCoeff();
  return result;
}

}  // namespace railmodal::solve
