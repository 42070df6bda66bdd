// Names a root of the hunting system from what moves most in it.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::stability {

/// A body that two or more wheelsets hang from: each wheelset belongs to the body the first
/// element joining it to a body that is not a wheelset joins it to (its primary suspension, in
/// a vehicle file's order).
struct WheelsetBogie {
  int body = -1;               ///< index into vehicle.bodies
  std::vector<int> wheelsets;  ///< their bodies, in the vehicle's order
  /// m: the root mean square of their axles' x (centres of gravity) about its mean,
  /// √(Σ(x_i − x̄)²/N): a, half the wheelbase, for two axles; √(2/3)·a for three at −a, 0, a.
  /// What a rigid bogie's kinematic wavelength needs (hunting_analysis.cpp).
  double axle_spread = 0.0;
};

/// Every body carrying two or more wheelsets, in the order of the vehicle's bodies: a bogie, or
/// a two-axle (three-axle) wagon's body, to which a rigid bogie's kinematics apply alike.
std::vector<WheelsetBogie> wheelset_carriers(const Vehicle& vehicle);

/// The bogies, for the naming: wheelset_carriers, empty unless there are two or more (a two-axle
/// wagon's body, carrying its two, is not a bogie: it is the vehicle).
std::vector<WheelsetBogie> wheelset_bogies(const Vehicle& vehicle);

/// A root that does not oscillate: real, or a pair whose Im λ is under 1 % of |λ| (ζ > 0.99995,
/// a decay of e^−600 a cycle). One rule for the tracking (such a step's MAC says nothing: next
/// to where two real roots meet the eigenvector is nearly defective), the naming and the
/// reports (shown as "real", left out of the CSV).
inline bool overdamped_root(std::complex<double> value) { return std::abs(value.imag()) <= 0.01 * std::abs(value); }

/// The name of a root from its displacement shape weighted by √M_ii (squared entries: the
/// kinetic energy of each degree of freedom, up to the factor ω²/2 they share). The body
/// that moves most, with the most energy per unit of its mass, names it, its name as written:
///  - an oscillating root (`oscillatory`, the caller's judgement: for a branch, Im λ > 1 % of
///    |λ| at the lowest speed) of a wheelset (a body of system.vehicle.wheelsets) whose lateral
///    and yaw motions both carry at least 1 % of its energy is "hunting" (in the kinematic
///    motion the yaw carries little energy: ψ = 2πy/Λ); a real root never is;
///  - otherwise the body's motions that carry at least a quarter of its energy, the larger
///    first, joined by "/": "body lateral/roll", "bogie1 yaw";
///  - when twin bodies (the same name but for a trailing number: bogie1, bogie2) do the same
///    and move at least half as much per unit mass, their names joined by "+" and the phase of
///    the leading motion: "bogie1+bogie2 yaw, in phase", "ws1+ws2 hunting, antiphase" (twins
///    grouped as the undamped modes' names group them, src/solve/mode_naming.cpp);
///  - on a bogie vehicle (wheelset_bogies), hunting wheelsets are named by their bogies when
///    the wheelsets of the leading bogie move together (their lateral motions within 90° of
///    each other and within a factor 2 in amplitude): "bogie1+bogie2 hunting, in phase", each
///    bogie whose wheelsets move together with at least half the leading bogie's energy per
///    unit mass, so that no wheelset of a bogie is left out by a threshold on its own.
/// A system whose DOFs have no bodies (matrices read from files) is named after the label of
/// the DOF with the most energy. A shape with no displacement (a series damper's own root,
/// λ = −k/c, where nothing moves) is "series damper relaxation".
std::string root_name(const LinearSystem& system, const Eigen::VectorXcd& weighted_shape, bool oscillatory = true);

}  // namespace railmodal::stability
