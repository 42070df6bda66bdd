// A body's first vertical bending mode (Body::bending): the free–free Euler–Bernoulli beam's
// first mode shape in closed form, and the mode's frequency, modal mass and damping resolved
// from whichever of its two forms the vehicle gives.
#pragma once

#include "railmodal/vehicle.hpp"

namespace railmodal::model {

/// β₁L of the free–free beam's first bending mode: the first nonzero root of
/// cos(βL)·cosh(βL) = 1, computed to full precision (4.730040745 in Blevins, "Formulas for
/// natural frequency and mode shape", 1979, Table 8-1; 4.73004074 in Timoshenko, Young and
/// Weaver, "Vibration problems in engineering", 4th ed. 1974, §5.3).
double free_free_beta1_l();

/// φ(ξ) of the free–free beam's first mode at ξ = s/L ∈ [0, 1] from one end, normalised to
/// φ(0) = φ(1) = 1: φ = ½[cosh βξ + cos βξ − σ(sinh βξ + sin βξ)], β = β₁L,
/// σ = (cosh β − cos β)/(sinh β − sin β) (Blevins Table 8-1, case "free–free").
double free_free_mode_shape(double xi);

/// The first bending frequency of a free–free uniform beam, Hz:
/// f = (β₁L)² / (2π L²) · √(EI / m') (Blevins Table 8-1).
double free_free_beam_frequency(double bending_stiffness, double mass_per_length, double length);

/// A body's bending mode as the assembly uses it (SI).
struct BendingMode {
  double omega = 0.0;          ///< ω_b = 2π f_b, rad/s
  double modal_mass = 0.0;     ///< m_b, kg, for φ = 1 at the beam's ends
  double damping_ratio = 0.0;  ///< ζ
  double length = 0.0;         ///< L, m
  double centre = 0.0;         ///< x of the beam's centre, m
  /// φ at x (vehicle frame). Throws std::invalid_argument, naming `what`, for an x beyond the
  /// beam's ends (the beam is not there: the closed form would grow as cosh).
  double shape_at(double x, const std::string& what) const;
};

/// The bending mode of `body` (which must have one), checked: exactly one of beam and mode,
/// each value positive and finite, 0 ≤ ζ < 1. Throws std::invalid_argument naming the body
/// and the rule.
BendingMode bending_mode(const Body& body);

}  // namespace railmodal::model
