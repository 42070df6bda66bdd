// ARPACK (arpack-ng) back-end: the lowest eigenpairs of K φ = λ M φ for sparse M and K by
// shift-invert Lanczos (dsaupd mode 3) with a sparse LDLᵀ (or LU) factorisation of K − σM.
//
// Shift-invert turns the lowest λ, which plain Lanczos finds last, into the largest
// ν = 1/(λ − σ) of OP = (K − σM)⁻¹M (ARPACK users' guide, sec. 3.2.3), found first.
#include <arpackdef.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "railmodal/errors.hpp"
#include "solve/eigenpairs.hpp"
#include "solve/low_modes.hpp"

extern "C" {
// arpack-ng's ISO C binding. arpack.h declares it beside complex variants whose C99
// _Complex types are not C++, so the one this file calls is declared here. (dseupd's work,
// the Ritz vectors, is done below with one matrix product.)
void dsaupd_c(a_int* ido, char const* bmat, a_int n, char const* which, a_int nev, double tol, double* resid,
              a_int ncv, double* v, a_int ldv, a_int* iparam, a_int* ipntr, double* workd, double* workl,
              a_int lworkl, a_int* info);
}

namespace railmodal::solve {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// ARPACK keeps its state in Fortran SAVE variables: one run at a time per process.
std::mutex arpack_mutex;

// The automatic shift σ = −kShiftFraction · max(Kᵢᵢ/Mᵢᵢ). Every Rayleigh quotient Kᵢᵢ/Mᵢᵢ
// lies in the spectrum, so this is a small fraction of its top: far enough below zero that
// K − σM is positive definite, with pivots well above round-off, when K is singular
// (rigid-body modes), close enough that the lowest modes stay well separated in ν.
constexpr double kShiftFraction = 1e-6;
// A pivot of K − σM this small against its diagonal entry means σ is (nearly) an eigenvalue.
constexpr double kSingularPivot = 1e-12;
// LAPACK's dlamch('EpsMach'), what ARPACK means by tol = 0: the unit round-off 2⁻⁵³.
constexpr double kMachinePrecision = 0.5 * std::numeric_limits<double>::epsilon();

// (K − σM)⁻¹ by sparse LDLᵀ (Eigen's SimplicialLDLT on P A Pᵀ, P the AMD ordering), which
// also gives the inertia: by Sylvester's law the number of negative pivots is the number of
// eigenvalues below σ (M positive definite). LDLᵀ does not pivot, so a zero pivot of an
// indefinite matrix falls back to sparse LU (no inertia then). Every shift gives the same
// pattern (K − σM keeps the union of those of K and M): the ordering is computed once and
// reused for other shifts and for the count check's K − μM.
class ShiftedInverse {
 public:
  /// Factor with the ordering already chosen for `other` (another shift of the same K, M).
  void use_ordering_of(const ShiftedInverse& other) { P_ = other.P_; }
  /// False when A = K − σM is singular to working precision.
  bool factor(const SparseMatrix& A) {
    use_lu_ = false;
    negative_pivots_ = -1;
    if (P_.size() != A.rows()) {
      Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> Pinv;
      Eigen::AMDOrdering<int>()(A, Pinv);  // on the pattern of A + Aᵀ
      P_ = Pinv.inverse();
    }
    {
      SparseMatrix permuted(A.rows(), A.cols());
      permuted.selfadjointView<Eigen::Lower>() = A.selfadjointView<Eigen::Lower>().twistedBy(P_);
      ldlt_.analyzePattern(permuted);
      ldlt_.factorize(permuted);
      if (ldlt_.info() == Eigen::Success) {
        const Eigen::VectorXd& D = ldlt_.vectorD();
        int negative = 0;
        for (Eigen::Index i = 0; i < D.size(); ++i) {
          if (!std::isfinite(D(i)) || std::abs(D(i)) <= kSingularPivot * std::abs(permuted.coeff(i, i))) return false;
          if (D(i) < 0.0) ++negative;
        }
        negative_pivots_ = negative;
        work_.resize(A.rows());
        return true;
      }
    }
    use_lu_ = true;
    lu_.analyzePattern(A);
    lu_.factorize(A);
    return lu_.info() == Eigen::Success;
  }
  /// y ← (K − σM)⁻¹ y, without allocating: it runs once a Lanczos step.
  void solve_in_place(double* y) const {
    const Eigen::Index n = use_lu_ ? lu_.rows() : ldlt_.rows();
    Eigen::Map<Eigen::VectorXd> v(y, n);
    if (use_lu_) {
      work_ = lu_.solve(v);
      v = work_;
      return;
    }
    work_.noalias() = P_ * v;
    ldlt_.matrixL().solveInPlace(work_);
    work_.array() /= ldlt_.vectorD().array();
    ldlt_.matrixU().solveInPlace(work_);
    v.noalias() = P_.transpose() * work_;
  }
  /// Eigenvalues below σ, or -1 when unknown (LU).
  int negative_pivots() const { return negative_pivots_; }
  const char* name() const { return use_lu_ ? "LU" : "LDLT"; }

 private:
  // The ordering is P_ (applied here), not Eigen's: it is kept across factorisations.
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt_;
  Eigen::SparseLU<SparseMatrix> lu_;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P_;
  mutable Eigen::VectorXd work_;
  bool use_lu_ = false;
  int negative_pivots_ = -1;
};

struct Run {
  Eigen::VectorXd values;   // ascending
  Eigen::MatrixXd vectors;  // n × nev, M-orthonormal
  int ncv = 0, restarts = 0, operations = 0;
};

std::string dsaupd_failure(a_int info, a_int converged, int nev, int ncv, const ArpackOptions& o) {
  std::ostringstream s;
  switch (info) {
    case 1:
      s << "ARPACK did not converge: " << converged << " of " << nev << " Ritz values converged in "
        << o.max_iterations << " restarts (raise the restart limit or the subspace size, ncv = " << ncv << ")";
      break;
    case 3:
      s << "ARPACK could not apply shifts in a restart: the subspace (ncv = " << ncv << ") is too small for "
        << nev << " modes";
      break;
    case -8: s << "ARPACK: the LAPACK tridiagonal eigensolver failed"; break;
    case -9999: s << "ARPACK could not build a Lanczos factorisation (size " << converged << ")"; break;
    default: s << "ARPACK dsaupd failed with info = " << info; break;
  }
  return s.str();
}

// ARPACK's Lanczos factorisation OP V = V T + r eₖᵀ once dsaupd has converged (V: n × ncv,
// M-orthonormal, column-major in V; T tridiagonal, in workl at ipntr(5): subdiagonal in its
// first column, diagonal in its second; r in resid).
struct Lanczos {
  a_int ncv = 0;
  Eigen::VectorXd resid, V, workd, workl;
  a_int iparam[11] = {}, ipntr[11] = {};
};

// One reverse-communication request of dsaupd; false when it asks for none (done or failed).
bool serve_request(a_int ido, const SparseMatrix& M, const ShiftedInverse& op, Lanczos& l, a_int n) {
  double* x = l.workd.data() + l.ipntr[0] - 1;
  double* y = l.workd.data() + l.ipntr[1] - 1;
  // In place and without temporaries: these run two or three times a Lanczos step.
  if (ido == -1) {  // y = (K − σM)⁻¹ M x
    Eigen::Map<Eigen::VectorXd>(y, n).noalias() = M * Eigen::Map<const Eigen::VectorXd>(x, n);
    op.solve_in_place(y);
  } else if (ido == 1) {  // M x is already at ipntr(3)
    std::copy_n(l.workd.data() + l.ipntr[2] - 1, n, y);
    op.solve_in_place(y);
  } else if (ido == 2) {  // y = M x
    Eigen::Map<Eigen::VectorXd>(y, n).noalias() = M * Eigen::Map<const Eigen::VectorXd>(x, n);
  } else {
    return false;
  }
  return true;
}

// dsaupd until the nev largest ν of OP have converged.
Lanczos lanczos(const SparseMatrix& M, const ShiftedInverse& op, int nev, const ArpackOptions& o) {
  const a_int n = static_cast<a_int>(M.rows());
  Lanczos l;
  l.ncv = o.subspace_size > 0 ? o.subspace_size : std::max(2 * nev + 1, 20);
  l.ncv = std::clamp<a_int>(l.ncv, nev + 1, n);
  const a_int lworkl = l.ncv * (l.ncv + 8);
  // A fixed pseudo-random start: the same answer on every run.
  l.resid.resize(n);
  std::mt19937 random(20240601);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (a_int i = 0; i < n; ++i) l.resid(i) = uniform(random);
  l.V.resize(static_cast<Eigen::Index>(n) * l.ncv);
  l.workd.resize(3 * static_cast<Eigen::Index>(n));
  l.workl.resize(lworkl);
  // tol 0 asks for machine precision. dsaupd puts dlamch('EpsMach') in its place only on its
  // first call, in its argument, which the C binding takes by value: every later call, where
  // the convergence test is made, would see 0 again and demand error bounds of exactly 0
  // (115 solves where machine precision takes 81 on the 10⁵-DOF train).
  const double tol = o.tolerance > 0.0 ? o.tolerance : kMachinePrecision;
  l.iparam[0] = 1;                 // exact shifts
  l.iparam[2] = o.max_iterations;  // restarts allowed
  l.iparam[6] = 3;                 // mode 3: shift-invert, B = M
  a_int ido = 0, info = 1;         // info = 1: resid holds the start vector
  {
    std::lock_guard<std::mutex> lock(arpack_mutex);
    do {
      dsaupd_c(&ido, "G", n, "LM", nev, tol, l.resid.data(), l.ncv, l.V.data(), n, l.iparam, l.ipntr,
               l.workd.data(), l.workl.data(), lworkl, &info);
    } while (serve_request(ido, M, op, l, n));
  }
  if (info < 0 && info != -8 && info != -9999)
    throw std::logic_error("ARPACK dsaupd rejected its arguments: info = " + std::to_string(info));
  // Never a partial answer: fewer converged Ritz values than asked is a failure.
  if (info != 0 || l.iparam[4] < nev)
    throw NumericalError(dsaupd_failure(info == 0 ? 1 : info, l.iparam[4], nev, l.ncv, o));
  return l;
}

// The Ritz vectors, as dseupd computes them but with one matrix product. For the nev
// eigenpairs (θ, s) of T largest in |θ|, z = V s + r (eₖᵀs)/θ = OP V s / θ: dseupd's
// purification, which keeps z in the range of OP (no component a massless DOF could hide).
// dseupd gets V s by applying nev Householder reflectors to V one at a time, 0.11 s of
// reference-BLAS vector operations at 10⁵ DOFs; V · S takes 0.03 s.
Eigen::MatrixXd ritz_vectors(const Lanczos& l, int nev) {
  const a_int n = static_cast<a_int>(l.resid.size()), ncv = l.ncv;
  Eigen::MatrixXd Z(n, nev);
  const double* h = l.workl.data() + l.ipntr[4] - 1;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> tridiagonal;
  tridiagonal.computeFromTridiagonal(Eigen::Map<const Eigen::VectorXd>(h + ncv, ncv),
                                     Eigen::Map<const Eigen::VectorXd>(h + 1, ncv - 1), Eigen::ComputeEigenvectors);
  if (tridiagonal.info() != Eigen::Success)
    throw NumericalError("the eigenvalues of ARPACK's Lanczos tridiagonal matrix did not converge");
  const Eigen::VectorXd& theta = tridiagonal.eigenvalues();
  std::vector<Eigen::Index> order(ncv);
  for (Eigen::Index i = 0; i < ncv; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&theta](Eigen::Index a, Eigen::Index b) { return std::abs(theta(a)) > std::abs(theta(b)); });
  Eigen::MatrixXd S(ncv, nev);
  Eigen::VectorXd w(nev);
  for (int k = 0; k < nev; ++k) {
    S.col(k) = tridiagonal.eigenvectors().col(order[k]);
    w(k) = S(ncv - 1, k) / theta(order[k]);
  }
  Z.noalias() = Eigen::Map<const Eigen::MatrixXd>(l.V.data(), n, ncv) * S;
  Z.noalias() += l.resid * w.transpose();
  return Z;
}

// Rayleigh–Ritz: (ZᵀKZ) y = λ (ZᵀMZ) y; φ = Z y is M-orthonormal.
void rayleigh_ritz(const SparseMatrix& M, const SparseMatrix& K, const Eigen::MatrixXd& Z, Run& run) {
  Eigen::MatrixXd A, B;
  {
    const Eigen::MatrixXd KZ = K * Z;  // one n × nev product at a time
    A.noalias() = Z.transpose() * KZ;
  }
  {
    const Eigen::MatrixXd MZ = M * Z;
    B.noalias() = Z.transpose() * MZ;
  }
  A = 0.5 * (A + A.transpose()).eval();
  B = 0.5 * (B + B.transpose()).eval();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rr(A, B);
  if (rr.info() != Eigen::Success)
    throw NumericalError("the Ritz vectors ARPACK returned are not independent in the mass metric");
  run.values = rr.eigenvalues();
  run.vectors.noalias() = Z * rr.eigenvectors();
}

// One ARPACK run for the nev eigenvalues nearest σ, then a Rayleigh–Ritz step in the
// subspace they span: λ from the projected K and M, not from σ + 1/ν, whose error grows as
// the largest ν (a rigid-body mode near σ) dwarfs the others.
Run run_arpack(const SparseMatrix& M, const SparseMatrix& K, const ShiftedInverse& op, int nev,
               const ArpackOptions& o) {
  Run run;
  Eigen::MatrixXd Z;
  {  // the Lanczos basis (n·ncv) is not needed once Z is formed
    const Lanczos l = lanczos(M, op, nev, o);
    Z = ritz_vectors(l, nev);
    run.ncv = l.ncv;
    run.restarts = l.iparam[2];
    run.operations = l.iparam[8];
  }
  rayleigh_ritz(M, K, Z, run);
  return run;
}

double spectrum_scale(const SparseMatrix& M, const SparseMatrix& K) {
  const Eigen::VectorXd m = M.diagonal(), k = K.diagonal();
  double scale = 0.0;
  for (int i = 0; i < m.size(); ++i)
    if (m(i) > 0.0) scale = std::max(scale, std::abs(k(i)) / m(i));
  return scale > 0.0 ? scale : 1.0;  // K = 0: every mode is rigid; any negative σ will do
}

std::string shift_text(double sigma) {
  std::ostringstream s;
  s << sigma;
  return s.str();
}

// A massless DOF needs a restraint: its row of K − σM is then its row of K.
void check_massless_restrained(const SparseMatrix& K, const std::vector<int>& massless,
                               const std::vector<std::string>& labels) {
  if (massless.empty()) return;
  std::vector<bool> stiff(K.rows(), false);
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.value() != 0.0) stiff[it.row()] = true;
  for (int s : massless)
    if (!stiff[s])
      throw NumericalError("degree of freedom '" + labels[s] +
                           "' has neither mass nor a restraint; give it inertia or hold it");
}

// The search for the lowest modes above the shift σ: ARPACK runs, each asking for a few more
// modes than wanted, until the modes kept end where a cluster of repeated eigenvalues ends and
// their count agrees with the inertia of K − μM.
class ModeSearch {
 public:
  ModeSearch(const SparseMatrix& M, const SparseMatrix& K, const ModalOptions& options, int wanted, int most)
      : M_(M),
        K_(K),
        options_(options),
        o_(options.arpack),
        wanted_(wanted),
        most_(most),
        automatic_shift_(std::isnan(o_.shift)),
        scale_(spectrum_scale(M, K)),
        sigma_(automatic_shift_ ? -kShiftFraction * scale_ : o_.shift),
        zero_band_(zero_band(K, M)),
        extra_(std::max(2, wanted / 10)) {}  // a few more than asked, so that a cluster cut at N shows where it ends

  Eigenpairs solve(Eigenpairs result) {
    for (int attempt = 0;; ++attempt) {
      if (!factored_) factor_at_shift();
      if (automatic_shift_ && attempt == 0) adapt_shift();
      const int nev = std::min(wanted_ + extra_, most_);
      Run run = run_arpack(M_, K_, op_, nev, o_);
      record(run, nev, result.summary);
      if (automatic_shift_ && missed_unstable(run.values)) {
        if (attempt >= 12) throw NumericalError("ARPACK: could not place the shift below the unstable modes");
        move_below(run.values);
        continue;
      }
      Eigen::VectorXd values = std::move(run.values);
      Eigen::MatrixXd vectors = std::move(run.vectors);
      if (!automatic_shift_) drop_below_shift(values, vectors);
      const int available = static_cast<int>(values.size());
      if (available <= wanted_ && nev < most_) {  // one more than N shows whether a cluster goes on
        extra_ *= 2;
        continue;
      }
      if (available < wanted_)
        throw NumericalError("ARPACK: only " + std::to_string(available) + " modes lie above the shift σ = " +
                             shift_text(sigma_) + " 1/s², not " + std::to_string(wanted_));
      result.scale = std::max(scale_, values.cwiseAbs().maxCoeff());
      const int end = cluster_end(values, wanted_, options_.zero_tolerance * result.scale);
      result.summary.count_checked = false;
      if (end < available && op_.negative_pivots() >= 0 && !count_agrees(values, end, result.summary)) continue;
      if (end == available && nev == most_ && op_.negative_pivots() >= 0)
        check_cluster_is_whole(values, end, result.scale);
      if (end < available || nev == most_) {
        values.conservativeResize(end);
        vectors.conservativeResize(Eigen::NoChange, end);
        result.values = std::move(values);
        result.vectors = std::move(vectors);
        finish_low_end(result);
        return result;
      }
      extra_ *= 2;  // the cluster reaches the last Ritz value found: look further
    }
  }

 private:
  // Rigid-body modes counted by the inertia of K ∓ tM; beside stiff links (found λ tiny against
  // max Kᵢᵢ/Mᵢᵢ) the modes found solved again in double-double, since the Rayleigh–Ritz step's
  // ZᵀKZ in double carries an error of ε·‖K‖ (low_modes.hpp). The rounding bound: rounding_bound
  // of the largest |λ| of the problem the modes were last solved in.
  void finish_low_end(Eigenpairs& result) const {
    result.zero_band = zero_band_;
    result.rigid_count = eigenvalues_near_zero(K_, M_, result.zero_band);
    double top = result.scale;
    if (needs_refinement(result.values, result.scale, result.zero_band)) {
      refine_low_modes(K_, M_, static_cast<int>(result.values.size()), &result.values, &result.vectors);
      top = result.values.cwiseAbs().maxCoeff();
    }
    result.errors = Eigen::VectorXd::Constant(result.values.size(), rounding_bound(top));
  }

  // The automatic σ = −1e-6·max Kᵢᵢ/Mᵢᵢ can lie far below the lowest eigenvalues (a 1e5-DOF
  // chain: λ₁ = 1e-9, σ = −2e-6), where every ν = 1/(λ − σ) ≈ 1/|σ| and Lanczos hardly tells
  // them apart (200 solves for 5 modes, 1500 at 1e6 DOFs). Inverse iteration with the factors
  // at hand weights each mode by 1/(λ − σ): after two steps from the vector of ones (smooth,
  // so mostly low modes) its Rayleigh quotient ρ lies between λ₁ and |σ| (about √(λ₁|σ|) for a
  // chain). While ρ is well above zero (no rigid-body mode, whose ρ falls inside the zero band)
  // and below |σ|/10, σ moves up to −ρ: a few moves bring it to the scale of λ₁. A σ already
  // near the lowest eigenvalues (every wagon) stays where it is.
  void adapt_shift() {
    for (int move = 0; move < 8; ++move) {
      const double rho = rayleigh_estimate();
      if (!(rho > zero_band_ && rho < 0.1 * -sigma_)) return;
      sigma_ = -rho;
      factored_ = false;
      factor_at_shift();
    }
  }

  // ρ of two inverse-iteration steps x ← (K − σM)⁻¹Mx from x = 1.
  double rayleigh_estimate() const {
    Eigen::VectorXd x = Eigen::VectorXd::Ones(M_.rows());
    for (int step = 0; step < 2; ++step) {
      Eigen::VectorXd y = M_ * x;
      op_.solve_in_place(y.data());
      const double norm = y.norm();
      if (!(norm > 0.0) || !std::isfinite(norm)) return 0.0;
      x = y / norm;
    }
    const double mass = x.dot(M_ * x);
    return mass > 0.0 ? x.dot(K_ * x) / mass : 0.0;
  }

  // σ an eigenvalue to working precision: an automatic σ moves, a given one is an error.
  void factor_at_shift() {
    for (int move = 0; !op_.factor(K_ - sigma_ * M_); ++move) {
      if (!automatic_shift_ || move == 8)
        throw NumericalError("K − σM is singular at σ = " + shift_text(sigma_) +
                             " 1/s² (σ is an eigenvalue); choose another shift");
      sigma_ *= 1.7;
    }
    factored_ = true;
  }

  void record(const Run& run, int nev, SolverSummary& summary) const {
    summary.runs += 1;
    summary.solver = ModalSolver::arpack;
    summary.shift = sigma_;
    summary.factorisation = op_.name();
    summary.requested = nev;
    summary.subspace_size = run.ncv;
    summary.restarts = run.restarts;
    summary.operator_applications += run.operations;
  }

  // Unstable modes below σ that were missed: the inertia counts more eigenvalues below σ than
  // were found.
  bool missed_unstable(const Eigen::VectorXd& values) const {
    return op_.negative_pivots() > static_cast<int>((values.array() < sigma_).count());
  }

  // The nev found are the nearest σ, within r of it, so the missed ones lie below σ − r.
  void move_below(const Eigen::VectorXd& values) {
    const double r = (values.array() - sigma_).abs().maxCoeff();
    sigma_ = std::min(10.0 * sigma_, sigma_ - 2.0 * r);
    factored_ = false;
  }

  // The modes to answer from: every one found for an automatic σ (the search put σ below all
  // that were missed), those above a given σ.
  void drop_below_shift(Eigen::VectorXd& values, Eigen::MatrixXd& vectors) const {
    const int below_sigma = static_cast<int>((values.array() < sigma_).count());  // ascending: the first ones
    values = Eigen::VectorXd(values.tail(values.size() - below_sigma));
    vectors = Eigen::MatrixXd(vectors.rightCols(vectors.cols() - below_sigma));
  }

  // Eigenvalues of (K, M) below μ, by the negative pivots of K − μM less those below a given
  // σ; none where the factorisation does not count them.
  std::optional<int> eigenvalues_below(double mu) const {
    const int skipped = automatic_shift_ ? 0 : op_.negative_pivots();
    ShiftedInverse check;
    check.use_ordering_of(op_);
    if (!check.factor(K_ - mu * M_) || check.negative_pivots() < 0) return std::nullopt;
    return check.negative_pivots() - skipped;
  }

  // The count check: by Sylvester's law, K − μM with μ between the last mode kept and the
  // next one found has as many negative pivots as there are eigenvalues below μ. More than
  // were found means Lanczos skipped one (a copy of a repeated frequency, say): false, to look
  // again with a larger subspace; a failure rather than an answer with a part of a cluster.
  bool count_agrees(const Eigen::VectorXd& values, int end, SolverSummary& summary) {
    const double mu = 0.5 * (values(end - 1) + values(end));
    const std::optional<int> exist = eigenvalues_below(mu);
    if (!exist) return true;
    if (*exist > end) {
      if (++missed_runs_ == 3)
        throw NumericalError("ARPACK found " + std::to_string(end) + " eigenvalues below " + shift_text(mu) +
                             " 1/s² but the inertia of K − μM counts " + std::to_string(*exist));
      extra_ = std::max(2 * extra_, *exist - wanted_ + 3);
      return false;
    }
    summary.count_checked = true;
    return true;
  }

  // The cluster reaches the last mode ARPACK can give: does it go on past it?
  void check_cluster_is_whole(const Eigen::VectorXd& values, int end, double scale) const {
    const double top = values(end - 1);
    const double mu = top + 0.5e-8 * std::max(std::abs(top), options_.zero_tolerance * scale);
    const std::optional<int> exist = eigenvalues_below(mu);
    if (exist && *exist > end)
      throw NumericalError("the repeated eigenvalue " + shift_text(top) + " 1/s² has more copies than the " +
                           std::to_string(most_) + " modes ARPACK can compute here; use the dense solver");
  }

  const SparseMatrix& M_;
  const SparseMatrix& K_;
  const ModalOptions& options_;
  const ArpackOptions& o_;
  const int wanted_, most_;
  const bool automatic_shift_;
  const double scale_;
  double sigma_;
  const double zero_band_;
  int extra_;
  int missed_runs_ = 0;
  ShiftedInverse op_;
  bool factored_ = false;
};

}  // namespace

Eigenpairs arpack_eigenpairs(const SparseMatrix& M, const SparseMatrix& K, const std::vector<std::string>& labels,
                             int count, const ModalOptions& options) {
  const int n = static_cast<int>(M.rows());
  const std::vector<int> massless = massless_dofs(M);
  check_massless_restrained(K, massless, labels);
  // Shift-invert sees only the eigenvalues of the DOFs with mass (the massless ones have
  // infinite λ, ν = 0), and ARPACK finds at most n − 1 of n.
  const int most = n - static_cast<int>(massless.size()) - 1;
  if (most < 1) throw std::invalid_argument("ARPACK needs at least two degrees of freedom with mass");
  if (count > most)
    throw std::invalid_argument("ARPACK computes at most " + std::to_string(most) + " modes of this model (" +
                                std::to_string(n) + " DOFs" +
                                (massless.empty() ? std::string() : ", " + std::to_string(massless.size()) + " massless") +
                                "), not " + std::to_string(count) + "; the dense solver gives them all");
  const int wanted = count > 0 ? count : std::min(kArpackDefaultModes, most);
  Eigenpairs result;
  result.massless = massless;
  return ModeSearch(M, K, options, wanted, most).solve(std::move(result));
}

}  // namespace railmodal::solve
