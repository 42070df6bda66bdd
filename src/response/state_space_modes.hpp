// Complex modes of the first-order form, for sweeping a system whose damping is not
// proportional (discrete dampers) without a dense solve per speed.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "railmodal/linear_system.hpp"

namespace railmodal::response {

/// With z = [x; ẋ], M ẍ + C ẋ + K x = Q e^{iωt} is ż = A z + [0; M⁻¹Q] e^{iωt}, and with
/// A = V Λ V⁻¹ the steady response is X(ω) = Σ_r V(x, r) (V⁻¹[0; M⁻¹Q])_r / (iω − λ_r):
/// a load is projected on the 2n roots once, and each speed costs O(n). Found block by block
/// over the uncoupled parts of the system, so that shapes and projections are exactly zero
/// across them (as the direct solve's are).
struct StateSpaceModes {
  Eigen::VectorXcd roots;       ///< λ_r, 2n of them
  Eigen::MatrixXcd shapes;      ///< the displacement rows of V (n × 2n)
  Eigen::MatrixXcd projection;  ///< the last n columns of V⁻¹ times M⁻¹ (2n × n): Q ↦ participations
  /// Root r is on the imaginary axis (|Re λ_r| ≤ 1e-9|λ_r|, λ_r ≠ 0): one of the pair of an
  /// undamped mode, only with `allow_undamped`. Its share of the expansion is the undamped
  /// mode's modal term φφᵀQ/(λ − ω²) in exact arithmetic, which the sweep adds instead, with
  /// the modal path's resonance flags and round-off rules.
  std::vector<bool> undamped;
};

/// The expansion, or nothing where it would not be trustworthy: a massless or otherwise
/// singular mass matrix, a root that is not strictly damped (a rigid-body or unstable mode, or
/// an undamped one unless `allow_undamped`: its resonance is unbounded, which the direct solve
/// or the caller's modal term reports), or an eigenvector matrix so ill-conditioned
/// (near-critical damping: a nearly defective pair) that V⁻¹ would amplify round-off
/// (reciprocal condition below 1e-10).
std::optional<StateSpaceModes> state_space_modes(const LinearSystem& system, bool allow_undamped = false);

}  // namespace railmodal::response
