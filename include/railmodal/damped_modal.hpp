// railmodal — damped (complex) modes of M q̈ + C q̇ + K q = 0.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/manchester_benchmark_coach.toml");
//     auto system = railmodal::assemble(vehicle, railmodal::DofSet::all);
//     railmodal::DampedModalResult r = railmodal::solve_damped_modes(system);
//     for (const auto& mode : r.modes)
//       if (mode.damped_frequency_hz)
//         std::cout << mode.name << "  f_d = " << *mode.damped_frequency_hz << " Hz  zeta = "
//                   << *mode.damping_ratio << "\n";
//   }
#pragma once

#include <Eigen/Core>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal {

/// How a damped mode moves. Each kind holds one or two eigenvalues λ of
/// (λ²M + λC + K)φ = 0, the motion being φ e^{λt}.
enum class DampedModeKind {
  underdamped,  ///< a complex-conjugate pair λ = −ζω ± iω√(1−ζ²), |ζ| < 1: decaying oscillation
  critical,     ///< a double real eigenvalue −ω (ζ = 1 within round-off): the fastest decay
                ///< without overshoot
  overdamped,   ///< two real eigenvalues of one sign, λ₁λ₂ = ω², |ζ| > 1: no oscillation
  divergent,    ///< two real eigenvalues of opposite signs: an undamped unstable mode (λ = ω² < 0),
                ///< which damping slows but cannot stop
  first_order,  ///< one real eigenvalue on its own: a massless degree of freedom held by a
                ///< damper, as a series damper's stroke (its relaxation, near −k/c), or,
                ///< under heavy mixing, a root left over by the matching
  rigid_body    ///< λ = 0 (a direction nothing restrains), with the rate at which its velocity
                ///< decays as the second eigenvalue
};
/// "underdamped", "critical", "overdamped", "divergent", "first-order", "rigid-body"
const char* to_string(DampedModeKind kind);
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<DampedModeKind> damped_mode_kind_from_string(const std::string& word);

struct DampedModalOptions {
  /// Options of the undamped solve the damped modes are matched to (its zero_tolerance on
  /// ω² is applied as √zero_tolerance to |λ| here).
  ModalOptions undamped;
  /// Two eigenvalues closer than this fraction of their size are one double eigenvalue
  /// (critical damping). A double eigenvalue is defective (one eigenvector): round-off ε
  /// in the state matrix splits it by about √ε ≈ 1.5e-8 relative, into a real pair or a
  /// complex pair, so the gap must be well above √ε. 1e-6 reads |ζ − 1| < 1.25e-13 as
  /// critical.
  double critical_gap = 1e-6;
  /// Returns false and explains in *why when an option is out of range.
  bool is_valid(std::string* why) const;
};

struct DampedMode {
  int index = 0;  ///< 1-based
  DampedModeKind kind = DampedModeKind::underdamped;
  /// The eigenvalues of this mode, 1/s: the pair (the one with Im λ > 0 first; the larger
  /// real part first for real pairs); one for first-order modes.
  std::vector<std::complex<double>> eigenvalues;
  /// Every eigenvalue has Re λ ≤ 0 (within 1e-11 of the largest |λ|): the motion does not grow.
  bool stable = true;
  /// |Im λ|/2π for underdamped modes (also when unstable, with ζ < 0); none otherwise.
  std::optional<double> damped_frequency_hz;
  /// ζ = −Re λ/|λ| for a complex pair, −(λ₁+λ₂)/(2√(λ₁λ₂)) for a real pair of one sign
  /// (≥ 1 when overdamped), exactly 1 when critical; none for divergent, first-order and
  /// rigid-body modes.
  std::optional<double> damping_ratio;
  /// ω/2π with ω = |λ| of a complex pair, √(λ₁λ₂) of a real pair of one sign: the
  /// frequency of the undamped oscillator with the same eigenvalues. None for divergent,
  /// first-order and rigid-body modes.
  std::optional<double> natural_frequency_hz;
  /// −max Re λ, 1/s: how fast the slowest part of the motion decays (negative: it grows).
  /// For a rigid-body mode, the decay rate of its velocity (0 when undamped).
  double decay_rate = 0.0;
  /// The undamped mode this one comes from: a 1-based index into `undamped.modes`, or 0
  /// for a first-order mode (it has no undamped counterpart).
  int undamped_mode = 0;
  /// The undamped mode's name (the mode names of README, "Mode names"), "<dof> first-order" for a massless
  /// damped degree of freedom, "series damper relaxation (<element>)" for a series damper's stroke.
  std::string name;
  /// φ over DampedModalResult::dofs for the first eigenvalue, φᴴMφ = 1 (largest entry 1 for a
  /// first-order mode), its phase chosen so that φ_uᵀMφ is real and positive for the
  /// undamped mode φ_u it comes from: with C = 0 it is the undamped shape.
  Eigen::VectorXcd shape;
  /// Largest over this mode's eigenvalues of ‖(λ²M + λC + K)φ‖ / ((|λ|²‖M‖ + |λ|‖C‖ + ‖K‖)‖φ‖).
  double residual = 0.0;
};

struct DampedModalResult {
  /// The system's degrees of freedom, then one per series damper (LinearSystem::series_dampers
  /// order): the stroke of its dashpot, "<element>.<direction> stroke", massless, body −1.
  std::vector<Dof> dofs;
  /// In ascending damped frequency (modes that do not oscillate, f_d = 0, first); among equal
  /// frequencies as the undamped modes they come from, first-order modes last.
  /// DampedMode::undamped_mode names each one's undamped mode.
  std::vector<DampedMode> modes;
  /// The undamped solve (C and the series dampers ignored) the damped modes are matched to, with
  /// its own notes (what the undamped modes leave out: the series dampers among them).
  ModalResult undamped;
  /// What these damped modes leave out or add, one sentence each: the wheel–rail contact of the
  /// wheelsets (left out), the series dampers (in, each a first-order state); empty for neither.
  std::vector<std::string> notes;
  /// Massless degrees of freedom without damping, condensed out statically.
  std::vector<std::string> condensed;
  /// Massless degrees of freedom with damping, the series dampers' strokes among them: each adds
  /// a first-order state.
  std::vector<std::string> first_order;
  bool stable = true;  ///< every mode is stable
  double max_residual = 0.0;
  /// The method, the residual check and the stages ("undamped modes", "state-space
  /// eigenvalues", "matching and shapes"); the undamped solve has its own in undamped.solver.
  AnalysisSummary summary;
};

/// Damped modes: the eigenvalues of the first-order (state-space) form of
/// M q̈ + C q̇ + K q = 0, each complex pair or real pair matched to the undamped mode it
/// comes from by the share of energy it carries. With C = 0 the frequencies are the undamped
/// ones and ζ = 0 exactly; with Rayleigh damping C = αM + βK, ζ = α/(2ω) + βω/2.
///
/// Massless degrees of freedom without damping are condensed statically as in
/// solve_modes(); a massless one with damping becomes a first-order state, and so does each
/// series damper (LinearSystem::series_dampers), through the stroke of its dashpot (the
/// undamped modes are solved without them: they carry no static force). Throws
/// NumericalError as solve_modes() does, when the damping of the massless damped degrees of
/// freedom is singular (naming them), and when a residual exceeds
/// options.undamped.max_residual; std::invalid_argument for bad options, a damping matrix
/// of the wrong size, and a series damper without a positive damping and stiffness.
DampedModalResult solve_damped_modes(const LinearSystem& system, const DampedModalOptions& options = {});

}  // namespace railmodal
