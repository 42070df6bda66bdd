// railmodal — natural modes of an assembled vehicle.
//
//   #include <railmodal/railmodal.hpp>
//   auto vehicle = railmodal::load_vehicle("data/vehicles/fette_car.toml");
//   auto system = railmodal::assemble(vehicle, railmodal::DofSet::all);
//   railmodal::ModalResult result = railmodal::solve_modes(system);
//   for (const auto& mode : result.modes)
//     std::cout << mode.name << "  " << mode.frequency_hz << " Hz  " << mode.period_s << " s\n";
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal {

/// What kind of motion an eigenvalue λ = ω² describes.
enum class ModeKind {
  oscillatory,  ///< λ > 0: oscillates at ω = √λ
  rigid_body,   ///< λ = 0 within the tolerance: a direction nothing restrains
  unstable      ///< λ < 0: diverges as e^{σt}, σ = √−λ (e.g. CG too high for the springs)
};
const char* to_string(ModeKind kind);

struct ModalOptions {
  /// |λ| below this fraction of the largest |λ| counts as zero (rigid-body mode). The dense
  /// solver's eigenvalues carry an absolute error of order n·ε·|λ|max (ε = 2.2e-16), so a true
  /// zero lands far below 1e-13·|λ|max, while a soft spring beside a link 1e12 times stiffer
  /// (|λ| ≈ 1e-12·|λ|max) is still told from zero: a looser default would call it rigid.
  double zero_tolerance = 1e-13;
  /// Reject if the relative residual of any mode exceeds this (a solver failure).
  double max_residual = 1e-8;
  /// Returns false and explains in *why when an option is out of range.
  bool is_valid(std::string* why) const;
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
  std::string name;            ///< e.g. "body bounce", "body lower sway", "bogies pitch, antiphase";
                               ///< without bodies, the DOF with most kinetic energy ("dof3")
  Eigen::VectorXd shape;       ///< mass-normalised: φᵀMφ = 1, over LinearSystem::dofs
  Eigen::VectorXd kinetic_energy_share;  ///< per DOF, sums to 1 (φᵢ (Mφ)ᵢ)
  std::optional<CentreOfOscillation> centre;  ///< for pitch and roll modes
  /// Another mode has the same eigenvalue (relative gap below 1e-8): only the subspace the
  /// two span is determined, not this shape on its own (symmetric bogies, for instance).
  bool repeated = false;
  double residual = 0.0;  ///< ‖Kφ − λMφ‖ / (‖K‖‖φ‖ + |λ|‖M‖‖φ‖)
};

struct ModalResult {
  std::vector<Dof> dofs;
  std::vector<Mode> modes;
  /// Massless DOFs that were condensed out statically (their shape entries are recovered).
  std::vector<std::string> condensed;
  double max_residual = 0.0;
  double orthonormality_error = 0.0;  ///< max |ΦᵀMΦ − I|
};

/// Solve K φ = λ M φ densely. Massless degrees of freedom (zero row of M) are condensed out
/// statically, the way the book eliminates the massless leaf-spring end and the bogie roll;
/// one that nothing restrains is a NumericalError naming it. M is then factorised by
/// Cholesky and checked (Eigen 3.4 does not report a failed factorisation of the
/// generalised solver); a mass matrix that is not positive definite is a NumericalError
/// naming the degree of freedom where the factorisation broke down.
ModalResult solve_modes(const LinearSystem& system, const ModalOptions& options = {});

}  // namespace railmodal
