// solve_modes: picks a back-end (dense or ARPACK), then classifies, names and checks the
// eigenpairs it returns the same way for both.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "model/analysis_limits.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/modal.hpp"
#include "require_valid.hpp"
#include "shortest_text.hpp"
#include "solve/eigenpairs.hpp"
#include "solve/low_modes.hpp"
#include "solve/modal_solver.hpp"
#include "solve/mode_naming.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

const char* to_string(ModeKind kind) {
  switch (kind) {
    case ModeKind::oscillatory: return "oscillatory";
    case ModeKind::rigid_body: return "rigid-body";
    case ModeKind::unstable: return "unstable";
  }
  return "?";
}

std::optional<ModeKind> mode_kind_from_string(const std::string& word) {
  for (ModeKind k : {ModeKind::oscillatory, ModeKind::rigid_body, ModeKind::unstable})
    if (word == to_string(k)) return k;
  return std::nullopt;
}

const char* to_string(ModalSolver solver) {
  switch (solver) {
    case ModalSolver::dense: return "dense";
    case ModalSolver::arpack: return "arpack";
    case ModalSolver::automatic: return "auto";
  }
  return "?";
}

std::optional<ModalSolver> modal_solver_from_string(const std::string& word) {
  for (ModalSolver s : {ModalSolver::dense, ModalSolver::arpack, ModalSolver::automatic})
    if (word == to_string(s)) return s;
  return std::nullopt;
}

bool ArpackOptions::is_valid(std::string* why) const {
  if (!std::isnan(shift) && !std::isfinite(shift))
    return invalid(why, "arpack.shift must be finite (or NaN for automatic)");
  if (!(tolerance >= 0.0 && tolerance < 1.0)) return invalid(why, "arpack.tolerance must satisfy 0 <= tolerance < 1");
  if (subspace_size < 0) return invalid(why, "arpack.subspace_size must be 0 (automatic) or positive");
  if (max_iterations < 1) return invalid(why, "arpack.max_iterations must be at least 1");
  return true;
}

bool ModalOptions::is_valid(std::string* why) const {
  if (!(zero_tolerance > 0.0 && zero_tolerance < 1e-2))
    return invalid(why, "zero_tolerance must satisfy 0 < zero_tolerance < 1e-2");
  if (!(max_residual > 0.0)) return invalid(why, "max_residual must be positive");
  if (mode_count < 0) return invalid(why, "mode_count must be 0 (all, or ARPACK's default) or positive");
  return arpack.is_valid(why);
}

ModalSolver choose_solver(ModalSolver requested, int dofs, int mode_count) {
  if (requested != ModalSolver::automatic) return requested;
  // ARPACK finds a small part of a large spectrum; half of it or more is the dense solver's job.
  const int wanted = mode_count > 0 ? mode_count : kArpackDefaultModes;
  return dofs > kArpackAboveDofs && 2 * wanted < dofs ? ModalSolver::arpack : ModalSolver::dense;
}

namespace solve {

bool same_eigenvalue(double a, double b, double zero) {
  if (std::abs(a) <= zero && std::abs(b) <= zero) return true;  // both rigid-body: λ = 0 twice
  return std::abs(b - a) <= 1e-8 * std::max({std::abs(a), std::abs(b), zero});
}

int cluster_end(const Eigen::VectorXd& values, int count, double zero) {
  int end = count;
  while (end < values.size() && same_eigenvalue(values(end - 1), values(end), zero)) ++end;
  return end;
}

std::vector<int> massless_dofs(const Eigen::SparseMatrix<double>& M) {
  std::vector<bool> has_mass(M.rows(), false);
  for (int j = 0; j < M.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
      if (it.value() != 0.0) has_mass[it.row()] = true;
  std::vector<int> out;
  for (int i = 0; i < M.rows(); ++i)
    if (!has_mass[i]) out.push_back(i);
  return out;
}

}  // namespace solve

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

// Names a mode from its shape and whether it is repeated: writes its name and centre of
// oscillation (ModeNamer::describe).
using Describe =
    std::function<void(const Eigen::VectorXd&, bool, std::string*, std::optional<CentreOfOscillation>*)>;

void check_options(const ModalOptions& options) { require_valid(options, "ModalOptions: "); }

// Which of the eigenvalues `lambda` are rigid-body modes: the Eigenpairs::rigid_count of
// smallest |λ| when the inertia counted them (a soft spring beside a stiff link, λ tiny against
// λmax but K positive definite, is then oscillatory), else those with |λ| ≤ zero.
std::vector<bool> rigid_body_modes(const Eigen::VectorXd& lambda, const solve::Eigenpairs& pairs, double zero) {
  const int m = static_cast<int>(lambda.size());
  std::vector<bool> rigid(m, false);
  if (pairs.rigid_count < 0) {
    for (int k = 0; k < m; ++k) rigid[k] = std::abs(lambda(k)) <= zero;
    return rigid;
  }
  if (pairs.rigid_count == 0) return rigid;  // most vehicles: nothing to sort
  std::vector<int> by_size(m);
  for (int k = 0; k < m; ++k) by_size[k] = k;
  std::stable_sort(by_size.begin(), by_size.end(),
                   [&lambda](int a, int b) { return std::abs(lambda(a)) < std::abs(lambda(b)); });
  for (int k = 0; k < std::min(m, pairs.rigid_count); ++k) rigid[by_size[k]] = true;
  return rigid;
}

// The largest bound of the relative rounding error of λ over the modes that are not rigid.
double relative_error_bound(const std::vector<Mode>& modes) {
  double worst = 0.0;
  for (const Mode& m : modes)
    if (m.kind != ModeKind::rigid_body) worst = std::max(worst, m.eigenvalue_error / std::abs(m.eigenvalue));
  return worst;
}

// The summary of a result make_result() wrote: its method, checks and stage times. The checks
// (the back-end's, then these) are written into `kept`, the checks of a result kept from an
// earlier solve (solve_modes_into), so that their names' storage serves again.
void summarise(ModalResult* result, const ModalOptions& options, std::vector<StageTiming> stages,
               std::vector<Check> kept = {}) {
  SolverSummary& s = result->solver;
  s.analysis = "undamped modes";
  s.method = s.solver == ModalSolver::dense
                 ? "dense: static condensation of massless DOFs, Cholesky of M, symmetric QR (Eigen)"
                 : "ARPACK shift-invert Lanczos on (K − σM)⁻¹M, " + s.factorisation + " of K − σM";
  const size_t given = s.checks.size();
  kept.resize(given + (s.count_checked ? 4 : 3));  // the back-end's and those below: one allocation at most
  for (size_t i = 0; i < given; ++i) kept[i] = s.checks[i];
  size_t next = given;
  const auto check = [&](const char* name, double value, double limit, bool passed) {
    Check& c = kept[next++];
    c.name = name;
    c.value = value;
    c.limit = limit;
    c.passed = passed;
  };
  check("max relative residual", result->max_residual, options.max_residual, true);
  check("M-orthonormality error max|ΦᵀMΦ − I|", result->orthonormality_error, std::numeric_limits<double>::infinity(),
        true);
  // Rounding, not the solver's convergence: the residual cannot see it (issue 18 item 9).
  const double bound = relative_error_bound(result->modes);
  check("max relative rounding error bound of λ", bound, kEigenvalueAccuracy, bound <= kEigenvalueAccuracy);
  if (s.count_checked) {
    const double found = static_cast<double>(result->modes.size());
    check("eigenvalues below the last mode by the inertia of K − μM", found, found, true);
  }
  s.checks = std::move(kept);
  s.stages = std::move(stages);
}

// A mode that is not oscillatory says so after the name of its shape.
void add_kind_to_name(Mode* mode) {
  if (mode->kind == ModeKind::unstable) mode->name += " (unstable)";
  if (mode->kind == ModeKind::rigid_body) mode->name += " (rigid-body)";
}

// Classifies, names and checks the first `keep` eigenpairs into `into` (all but its notes);
// without `describe` the modes are left unnamed (ModeNaming::deferred).
// Every member is written: a result kept from another solve (solve_modes_into) ends as a
// fresh one would, its modes' shapes and names in the storage it had. Matrix: dense or sparse.
template <class Matrix>
void make_result(const std::vector<Dof>& dofs, const Matrix& M, const Matrix& K, const solve::Eigenpairs& pairs,
                 int keep, const ModalOptions& options, const Describe& describe, ModalResult* into) {
  ModalResult& result = *into;
  result.dofs = dofs;
  result.solver = pairs.summary;
  result.condensed.clear();
  for (int s : pairs.massless) result.condensed.push_back(dofs[s].label);
  result.max_residual = 0.0;
  const Eigen::VectorXd lambda = pairs.values.head(keep);
  const Eigen::MatrixXd phi = pairs.vectors.leftCols(keep);
  const double zero = options.zero_tolerance * pairs.scale;
  const std::vector<bool> rigid = rigid_body_modes(lambda, pairs, zero);
  const double norm_K = K.norm(), norm_M = M.norm();
  const Eigen::MatrixXd K_phi = K * phi, M_phi = M * phi;
  std::vector<bool> repeated(keep, false);
  result.modes.resize(keep);
  for (int k = 0; k + 1 < keep; ++k)
    if (solve::same_eigenvalue(lambda(k), lambda(k + 1), zero)) repeated[k] = repeated[k + 1] = true;
  for (int k = 0; k < keep; ++k) {
    Mode& mode = result.modes[k];
    mode.index = k + 1;
    mode.eigenvalue = lambda(k);
    mode.eigenvalue_error = pairs.errors.size() > k ? pairs.errors(k) : 0.0;
    mode.shape = phi.col(k);
    mode.omega_rad_s = mode.frequency_hz = mode.period_s = mode.divergence_rate = 0.0;  // as a new Mode's
    if (rigid[k]) {
      mode.kind = ModeKind::rigid_body;
    } else if (lambda(k) < 0.0) {
      mode.kind = ModeKind::unstable;
      mode.divergence_rate = std::sqrt(-lambda(k));
    } else {
      mode.kind = ModeKind::oscillatory;
      mode.omega_rad_s = std::sqrt(lambda(k));
      mode.frequency_hz = mode.omega_rad_s / kTwoPi;
      mode.period_s = kTwoPi / mode.omega_rad_s;
    }
    mode.kinetic_energy_share = mode.shape.cwiseProduct(M_phi.col(k));
    const double denom = (norm_K + std::abs(lambda(k)) * norm_M) * mode.shape.norm();
    mode.residual = denom > 0.0 ? (K_phi.col(k) - lambda(k) * M_phi.col(k)).norm() / denom : 0.0;
    result.max_residual = std::max(result.max_residual, mode.residual);
    mode.repeated = repeated[k];
    if (describe) {
      describe(mode.shape, mode.repeated, &mode.name, &mode.centre);
      add_kind_to_name(&mode);
    } else {  // named later, if at all (ModeNaming::deferred)
      mode.name.clear();
      mode.centre.reset();
    }
  }
  // Orthonormality over the kept coordinates (the condensed ones carry no mass).
  const Eigen::MatrixXd G = phi.transpose() * M_phi;
  result.orthonormality_error = (G - Eigen::MatrixXd::Identity(keep, keep)).cwiseAbs().maxCoeff();
  if (!(result.max_residual <= options.max_residual))
    throw NumericalError("eigen-solution residual " + shortest_text(result.max_residual, 3) + " exceeds the limit " +
                         shortest_text(options.max_residual, 3));
}

std::vector<std::string> labels_of(const std::vector<Dof>& dofs) {
  std::vector<std::string> labels;
  for (const auto& d : dofs) labels.push_back(d.label);
  return labels;
}

// How many of the dense solver's eigenpairs to keep: all, or N and the rest of its cluster.
int dense_keep(const solve::Eigenpairs& pairs, const ModalOptions& options) {
  const int m = static_cast<int>(pairs.values.size());
  if (options.mode_count == 0 || options.mode_count >= m) return m;
  return solve::cluster_end(pairs.values, options.mode_count, options.zero_tolerance * pairs.scale);
}

bool all_finite(const Eigen::SparseMatrix<double>& A) {
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (!std::isfinite(it.value())) return false;
  return true;
}

}  // namespace

ModalResult solve_modes(const LinearSystem& system, const ModalOptions& options) {
  ModalResult result;
  solve::solve_modes_into(system, options, &result);
  return result;
}

void solve::name_mode(const ModeNamer& namer, Mode* mode) {
  namer.describe(mode->shape, mode->repeated, &mode->name, &mode->centre);
  add_kind_to_name(mode);
}

void solve::solve_modes_into(const LinearSystem& system, const ModalOptions& options, ModalResult* into,
                             ModeNaming naming) {
  check_options(options);
  const int n = system.size();
  if (n == 0) throw std::invalid_argument("the system has no degrees of freedom");
  const Eigen::MatrixXd& M = system.mass;
  const Eigen::MatrixXd& K = system.stiffness;
  if (!M.allFinite() || !K.allFinite())
    throw NumericalError("the mass or stiffness matrix contains NaN or infinity");
  // What the names need of the system, once for all modes (when they are named now).
  std::optional<solve::ModeNamer> namer;
  Describe describe;
  if (naming == ModeNaming::now) {
    namer.emplace(system);
    describe = [&namer](const Eigen::VectorXd& shape, bool repeated, std::string* name,
                        std::optional<CentreOfOscillation>* centre) { namer->describe(shape, repeated, name, centre); };
  }
  std::vector<Check> kept_checks = std::move(into->solver.checks);  // rewritten by summarise
  AnalysisSummary timing;
  StageClock clock(&timing);
  if (choose_solver(options.solver, n, options.mode_count) == ModalSolver::dense) {
    const solve::Eigenpairs pairs = solve::dense_eigenpairs(M, K, system.dofs);
    clock.lap("eigensolve");
    make_result(system.dofs, M, K, pairs, dense_keep(pairs, options), options, describe, into);
  } else {
    const Eigen::SparseMatrix<double> Ms = M.sparseView(), Ks = K.sparseView();
    const solve::Eigenpairs pairs = solve::arpack_eigenpairs(Ms, Ks, labels_of(system.dofs), options.mode_count, options);
    clock.lap("eigensolve");
    make_result(system.dofs, Ms, Ks, pairs, static_cast<int>(pairs.values.size()), options, describe, into);
  }
  clock.lap("classify and check");
  summarise(into, options, std::move(timing.stages), std::move(kept_checks));
  into->notes = model::undamped_mode_notes(system);
}

ModalResult solve_modes(const SparseSystem& system, const ModalOptions& options) {
  check_options(options);
  const int n = system.size();
  if (n == 0) throw std::invalid_argument("the system has no degrees of freedom");
  if (system.mass.rows() != n || system.stiffness.rows() != n || system.mass.cols() != n || system.stiffness.cols() != n)
    throw std::invalid_argument("SparseSystem: mass and stiffness must be n × n for n DOFs");
  AnalysisSummary timing;
  StageClock clock(&timing);
  if (choose_solver(options.solver, n, options.mode_count) == ModalSolver::dense) {
    ModalOptions dense = options;
    dense.solver = ModalSolver::dense;
    const LinearSystem densified = to_linear_system(system);
    clock.lap("densify");
    ModalResult result = solve_modes(densified, dense);
    result.solver.stages.insert(result.solver.stages.begin(), timing.stages.front());
    return result;
  }
  if (!all_finite(system.mass) || !all_finite(system.stiffness))
    throw NumericalError("the mass or stiffness matrix contains NaN or infinity");
  // Without bodies a mode is named after the DOF with the most kinetic energy φᵢ (Mφ)ᵢ.
  const Describe describe = [&system](const Eigen::VectorXd& shape, bool, std::string* name,
                                      std::optional<CentreOfOscillation>* centre) {
    Eigen::Index lead = 0;
    shape.cwiseProduct(system.mass * shape).maxCoeff(&lead);
    *name = system.dofs[lead].label;
    centre->reset();
  };
  const solve::Eigenpairs pairs =
      solve::arpack_eigenpairs(system.mass, system.stiffness, labels_of(system.dofs), options.mode_count, options);
  clock.lap("eigensolve");
  ModalResult result;
  make_result(system.dofs, system.mass, system.stiffness, pairs, static_cast<int>(pairs.values.size()), options,
              describe, &result);
  clock.lap("classify and check");
  summarise(&result, options, std::move(timing.stages));
  return result;
}

}  // namespace railmodal
