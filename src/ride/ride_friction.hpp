// Leaf friction in random ride: statistical linearisation (docs/ride.md, "Friction in random
// ride").
#pragma once

#include <functional>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::ride {

/// A leaf-friction element: its index and the friction force level F = Σ R·s across it
/// (response::friction_force_share: R = φ × static load, s the leaf's share of the stretch).
struct FrictionElement {
  int element = 0;
  double force = 0.0;  ///< N
};

/// The elements of the system with leaf friction (empty without).
std::vector<FrictionElement> friction_elements(const LinearSystem& system);

/// c = F·√(2/π)/σ_v: the viscous damping that best replaces (least mean square error) a
/// Coulomb force F·sgn(v) when v is Gaussian, zero-mean, of RMS σ_v: c = E[v·F sgn v]/E[v²]
/// = F·E|v|/σ_v² with E|v| = σ_v√(2/π). σ_v below 1e-9 m/s counts as 1e-9 (the leaf holds).
double gaussian_friction_damping(double force, double velocity_rms);

struct FrictionLinearisation {
  std::vector<double> damping;  ///< per vehicle element, N·s/m (0 for elements without friction)
  int passes = 0;               ///< solves of the linear system it took
  bool converged = false;
  /// The last pass's largest |log(c·σ_v(c)/(F√(2/π)))|: the relative mismatch of each damper
  /// and the one its own σ_v asks for.
  double change = 0.0;
};

/// Iterates c_k = F_k√(2/π)/σ_k(c) to consistency, σ_k(c) the RMS stretch rate across friction
/// element k that `velocity_rms` returns for the dampings c (per vehicle element; non-finite
/// when the response is unbounded), by secant steps on log c. Starts from σ = 0.01 m/s and stops
/// when every c matches the one its σ_v asks for within `tolerance` (relative) or after
/// `max_passes` passes; `damping` is that of the last solve.
FrictionLinearisation linearise_friction(const LinearSystem& system, const std::vector<FrictionElement>& elements,
                                         double tolerance, int max_passes,
                                         const std::function<std::vector<double>(const std::vector<double>&)>& velocity_rms);

}  // namespace railmodal::ride
