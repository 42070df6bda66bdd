// Leaf friction as an equivalent viscous damper, element by element (shared by the system
// with friction dampers and the element deflection curves, which need the force it carries).
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "railmodal/linear_system.hpp"

namespace railmodal::response {

/// The viscous damper across element `element` that dissipates per cycle what its leaf-friction
/// stages do when the element stretches by `stretch` at circular frequency ω:
/// Σ 4R·s/(πωX) over the stages, R = φ × load, s the stage's share of the stretch. 0 without
/// friction or for a non-positive stretch.
double equivalent_friction_damping(const LinearSystem& system, std::size_t element, double omega, double stretch);

/// modal_friction_work for a motion Re(ψ e^{iωt}) whose DOFs need not move in phase (modes of a
/// cluster driven out of phase): Σ R·|δ(ψ)| with δ(ψ) complex, each stage sliding over the
/// amplitude |δ| of its own stretch. Equal to the real version for ψ = φ·e^{iθ}.
double modal_friction_work(const LinearSystem& system, const Eigen::VectorXcd& shape);

}  // namespace railmodal::response
