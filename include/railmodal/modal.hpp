// railmodal — natural modes of an assembled vehicle.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/fette_car.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::all);
//     railmodal::ModalResult result = railmodal::solve_modes(system);
//     for (const auto& mode : result.modes)
//       std::cout << mode.name << "  " << mode.frequency_hz << " Hz  " << mode.period_s << " s\n";
//
//     // The 20 lowest modes of a 10 000-DOF train of wagons with ARPACK:
//     railmodal::ModalOptions options;
//     options.solver = railmodal::ModalSolver::arpack;
//     options.mode_count = 20;
//     std::string why;
//     if (!options.is_valid(&why)) return 1;
//     auto train = railmodal::wagon_train(2000);
//     railmodal::ModalResult lowest = railmodal::solve_modes(train, options);
//     std::cout << lowest.modes.size() << " modes by " << railmodal::to_string(lowest.solver.solver) << "\n";
//   }
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/sparse_system.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

/// What kind of motion an eigenvalue λ = ω² describes.
enum class ModeKind {
  oscillatory,  ///< λ > 0: oscillates at ω = √λ
  rigid_body,   ///< λ = 0 within the tolerance: a direction nothing restrains
  unstable      ///< λ < 0: diverges as e^{σt}, σ = √−λ (e.g. CG too high for the springs)
};
const char* to_string(ModeKind kind);  ///< "oscillatory", "rigid-body", "unstable"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<ModeKind> mode_kind_from_string(const std::string& word);

/// Which eigensolver back-end computes the modes (docs/solvers.md).
enum class ModalSolver {
  dense,      ///< every mode, O(n³): Cholesky of M and a symmetric QR (Eigen)
  arpack,     ///< the lowest modes of a sparse model: ARPACK shift-invert Lanczos (arpack-ng)
  automatic   ///< dense up to kArpackAboveDofs degrees of freedom, ARPACK above
};
const char* to_string(ModalSolver solver);  ///< "dense", "arpack", "auto"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<ModalSolver> modal_solver_from_string(const std::string& word);

/// ModalSolver::automatic chooses ARPACK for models with more degrees of freedom than this
/// (at 500 DOFs the dense solver takes about 0.1 s and 10 MB; it grows as n³ and n²).
constexpr int kArpackAboveDofs = 500;
/// Modes ARPACK computes when ModalOptions::mode_count is 0.
constexpr int kArpackDefaultModes = 20;

/// ARPACK's shift-invert mode (dsaupd mode 3): Lanczos on (K − σM)⁻¹M, whose largest
/// eigenvalues ν = 1/(λ − σ) are the λ nearest σ.
struct ArpackOptions {
  /// σ, 1/s². NaN (default): automatic, σ = −1e-6 · max(Kᵢᵢ/Mᵢᵢ), just below zero so that
  /// K − σM is positive definite with rigid-body modes and a singular K, and lowered further
  /// while the inertia of K − σM shows unstable modes (λ < σ) that were not found. A given σ
  /// returns the lowest modes above σ (λ ≥ σ).
  double shift = std::numeric_limits<double>::quiet_NaN();
  /// ARPACK's relative accuracy of the Ritz values; 0 means machine precision.
  double tolerance = 0.0;
  /// Lanczos basis size ncv; 0 means max(2·nev + 1, 20), at most n.
  int subspace_size = 0;
  /// Implicit restarts before giving up (a NumericalError).
  int max_iterations = 1000;
  bool is_valid(std::string* why) const;
};

struct ModalOptions {
  /// Rigid-body modes are counted by the inertia of K ∓ tM (the eigenvalues within t of zero,
  /// t = 8·m·ε·max Σⱼ|Kᵢⱼ|/Mᵢᵢ with m the most nonzeros in a row of K: what storing K in double
  /// can move an eigenvalue by), so a soft spring beside a link 1e15 times stiffer is told from
  /// zero. Only where that count fails (a factorisation breaks down) does |λ| below this
  /// fraction of the largest |λ| count as zero. It also bounds the gap under which two rigid-body
  /// eigenvalues are one repeated zero. ARPACK, which does not see the top of the spectrum, uses
  /// max(Kᵢᵢ/Mᵢᵢ) (a lower bound) in place of the largest |λ|.
  double zero_tolerance = 1e-13;
  /// Reject if the relative residual of any mode exceeds this (a solver failure).
  double max_residual = 1e-8;
  ModalSolver solver = ModalSolver::automatic;
  /// The N lowest modes, extended to the end of a cluster of equal eigenvalues (relative gap
  /// 1e-8) so that a repeated frequency always comes with its whole invariant subspace.
  /// 0: every mode (dense), kArpackDefaultModes (ARPACK).
  int mode_count = 0;
  ArpackOptions arpack;
  /// Returns false and explains in *why when an option is out of range.
  bool is_valid(std::string* why) const;
};

/// The back-end `requested` means for a model of `dofs` DOFs and ModalOptions::mode_count:
/// automatic is ARPACK when dofs > kArpackAboveDofs and the modes wanted (mode_count, or
/// kArpackDefaultModes when 0) are fewer than half the DOFs, else dense.
ModalSolver choose_solver(ModalSolver requested, int dofs, int mode_count);

/// SolverSummary fails its rounding check when a mode's eigenvalue_error exceeds this fraction
/// of |λ| (a frequency with fewer than about 6 correct digits).
constexpr double kEigenvalueAccuracy = 1e-6;

/// How the modes were computed. As every analysis summary: the method, the checks (relative
/// residual against ModalOptions::max_residual, M-orthonormality, and for ARPACK the inertia
/// count) and the wall time of the stages ("eigensolve", "classify and check"; "densify"
/// first when a sparse model goes to the dense solver).
struct SolverSummary : AnalysisSummary {
  ModalSolver solver = ModalSolver::dense;  ///< the back-end used (never automatic)
  // ARPACK only:
  double shift = 0.0;          ///< σ of the last run
  std::string factorisation;   ///< "LDLT" or "LU" of K − σM
  int requested = 0;           ///< nev of the last run (N plus a few to see past a cluster)
  int subspace_size = 0;       ///< ncv
  int restarts = 0;            ///< ARPACK's implicit restarts (iparam(3))
  int operator_applications = 0;  ///< solves with K − σM (iparam(9))
  int runs = 0;                ///< ARPACK runs (more than 1 when a cluster or σ needed another)
  /// The inertia of K − μM (μ just above the last mode) confirmed that no eigenvalue below
  /// it was missed; false when K − σM needed LU (no inertia) or every mode was asked for.
  bool count_checked = false;
};

/// The centre of oscillation of a rotation mode: the line of the body that does not move.
struct CentreOfOscillation {
  std::string body;
  /// "pitch": x of the point on the body's reference level with no vertical motion;
  /// "roll": height z of the point above the reference point with no lateral motion.
  std::string about;
  double position = 0.0;  ///< m, vehicle frame (x for pitch, z for roll)
  bool at_infinity = false;  ///< pure translation: no finite centre
};

struct Mode {
  int index = 0;  ///< 1-based, ascending frequency (unstable modes first, then rigid-body)
  ModeKind kind = ModeKind::oscillatory;
  double eigenvalue = 0.0;     ///< λ = ω², 1/s²
  double omega_rad_s = 0.0;    ///< ω for oscillatory modes, else 0
  double frequency_hz = 0.0;   ///< ω/2π for oscillatory modes, else 0
  double period_s = 0.0;       ///< 2π/ω for oscillatory modes, else 0 (infinite period)
  double divergence_rate = 0.0;  ///< σ = √−λ, 1/s, for unstable modes, else 0
  std::string name;              ///< e.g. "body bounce", "body lower sway", "bogies bounce, antiphase",
                                 ///< "bogies pitch (repeated)" (README, "Mode names"); without
                                 ///< bodies, the DOF with most kinetic energy ("dof3")
  Eigen::VectorXd shape;       ///< mass-normalised: φᵀMφ = 1, over LinearSystem::dofs
  Eigen::VectorXd kinetic_energy_share;  ///< per DOF, sums to 1 (φᵢ (Mφ)ᵢ)
  std::optional<CentreOfOscillation> centre;  ///< for pitch, roll and sway modes; none when repeated
  /// Another mode has the same eigenvalue (relative gap below 1e-8): only the subspace the
  /// two span is determined, not this shape on its own (symmetric bogies, for instance).
  bool repeated = false;
  double residual = 0.0;  ///< ‖Kφ − λMφ‖ / (‖K‖‖φ‖ + |λ|‖M‖‖φ‖)
  /// A bound of |λ − λexact| from rounding, 1/s²: 4ε times the largest |λ| of the problem the
  /// mode was solved in (the whole spectrum, or the low modes solved again in double-double
  /// beside stiff links; docs/accuracy.md). The residual does not show this error.
  double eigenvalue_error = 0.0;
};

struct ModalResult {
  std::vector<Dof> dofs;
  std::vector<Mode> modes;
  /// Massless DOFs that were condensed out statically (their shape entries are recovered).
  std::vector<std::string> condensed;
  double max_residual = 0.0;
  double orthonormality_error = 0.0;  ///< max |ΦᵀMΦ − I|
  SolverSummary solver;
  /// What these modes leave out of the vehicle, one sentence each, written by every format: on
  /// wheelsets, the wheel–rail contact terms; the series dampers (they carry no static force).
  /// Empty for a vehicle without wheelsets or series dampers.
  std::vector<std::string> notes;
};

/// Solve K φ = λ M φ densely. Massless degrees of freedom (zero row of M) are condensed out
/// statically, the way the book eliminates the massless leaf-spring end and the bogie roll;
/// one that nothing restrains is a NumericalError naming it. M is then factorised by
/// Cholesky and checked (Eigen 3.4 does not report a failed factorisation of the
/// generalised solver); a mass matrix that is not positive definite is a NumericalError
/// naming the degree of freedom where the factorisation broke down.
///
/// options.solver picks the back-end; with ARPACK the matrices are copied to sparse form.
/// Throws std::invalid_argument for invalid options or a mode count ARPACK cannot give
/// (N must be below the number of DOFs with mass), NumericalError for the failures above and
/// for ARPACK not converging (fewer converged Ritz values than asked: never a partial answer).
ModalResult solve_modes(const LinearSystem& system, const ModalOptions& options = {});

/// The same for a sparse model (bodies unknown: modes named after the DOF with the most
/// kinetic energy). ARPACK works on the sparse matrices directly; the dense solver on a
/// dense copy.
ModalResult solve_modes(const SparseSystem& system, const ModalOptions& options = {});

}  // namespace railmodal
