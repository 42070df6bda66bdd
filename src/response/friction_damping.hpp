// Leaf friction as an equivalent viscous damper, element by element (shared by the system
// with friction dampers and the element deflection curves, which need the force it carries).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <utility>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::response {

/// The viscous damper across element `element` that dissipates per cycle what its leaf-friction
/// stages do when the element stretches by `stretch` X at circular frequency ω:
/// Σ 4R·s·(X − h)/(πωX²) over the stages, R = φ × load, s the stage's share of the stretch and
/// h = R/k_c the stretch the elastic stages in series take alone while the leaf holds
/// (leaf_hold_stretch; 0 for a leaf alone). 0 without friction, for a non-positive stretch,
/// or for X ≤ h (the leaf never slips).
double equivalent_friction_damping(const LinearSystem& system, std::size_t element, double omega, double stretch);

/// The stretch h = R/k_c of element `element` that its elastic stages take alone while its
/// friction leaf holds (R = φ × load, k_c the series stiffness of the other stages): under a
/// harmonic stretch X the leaf deflects share·(X − h), and not at all for X ≤ h. 0 for an
/// element without friction or whose friction leaf is its only stage.
double leaf_hold_stretch(const LinearSystem& system, std::size_t element);

/// modal_friction_work for a motion Re(ψ e^{iωt}) whose DOFs need not move in phase (modes of a
/// cluster driven out of phase): Σ R·|δ(ψ)| with δ(ψ) complex, each stage sliding over the
/// amplitude |δ| of its own stretch. Equal to the real version for ψ = φ·e^{iθ}.
double modal_friction_work(const LinearSystem& system, const Eigen::VectorXcd& shape);

/// A friction stage of a system as modal_friction_work weighs it: its element, R = φ × load,
/// the stage's share of the element's stretch, and where the nonzero entries of the element's
/// row of element_vertical_map are in FrictionStages::entries ([begin, end)).
struct FrictionStage {
  std::size_t element = 0;
  double friction = 0.0;
  double share = 0.0;
  std::size_t begin = 0, end = 0;
};

/// Every friction stage of a system, element by element, with their rows' nonzero entries
/// (DOF, coefficient) in the rows' order.
struct FrictionStages {
  std::vector<FrictionStage> stages;
  std::vector<std::pair<int, double>> entries;
};

/// The system's friction stages: found once for many modal_friction_work calls on one system
/// (the critical speeds weigh one combination per resonance).
FrictionStages friction_stages(const LinearSystem& system);

/// modal_friction_work(system, shape) from `stages` = friction_stages(system), which the former
/// calls: each stretch summed over its row's nonzero entries only, in the row's order, so |δ| is
/// the dense row product's to the bit.
double modal_friction_work(const FrictionStages& stages, const Eigen::VectorXcd& shape);

/// Σ R·s over the friction stages of element `element` (R = φ × load, s the stage's share of the
/// element's stretch): a Coulomb force level seen across the element. 0 without friction.
/// The random ride's statistical linearisation takes its friction from here
/// (src/ride/ride_friction.cpp), so both linearisations share one friction model.
double friction_force_share(const LinearSystem& system, std::size_t element);

/// The system with a viscous damper damping[k] (N·s/m; 0, or beyond the vector: none) across
/// each element k's vertical stretch: C gains c·rowᵀrow (row = element_vertical_map.row(k)), and a
/// track element's input the damper's load per track velocity.
LinearSystem with_element_vertical_dampers(const LinearSystem& system, const std::vector<double>& damping);

}  // namespace railmodal::response
