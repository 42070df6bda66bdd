// The suspension elements a nonlinear simulation follows beyond the linear model: leaf springs
// with friction and progressive springs, each with its kinematics and its static state.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <optional>
#include <vector>

#include "railmodal/excitation.hpp"
#include "railmodal/simulation.hpp"
#include "simulate/speed_profile.hpp"

namespace railmodal::simulate {

/// One harmonic of the track's vertical displacement under an element (up positive):
/// u(t) = Re(amplitude · r · e^{i(κx(t) − lag)}), κ = ω/V the harmonic's wavenumber along the
/// track, lag = κ × the wheel's distance behind the reference (ω·delay at any speed), and
/// r = s(ω(t))/s(ω₀) how the source's amplitude follows the speed (1 at constant speed).
struct TrackHarmonic {
  std::complex<double> amplitude;  ///< at the initial speed
  double omega = 0.0;              ///< ω₀ at the initial speed, rad/s
  double lag = 0.0;                ///< rad
  double wavenumber = 0.0;         ///< κ, rad/m
  const ExcitationSource* source = nullptr;  ///< for s(ω); none: r = 1
};

struct NonlinearElement {
  int element = 0;            ///< index into Vehicle::elements
  Eigen::RowVectorXd stretch;  ///< vertical stretch (up) per DOF; compression δ = −(stretch·x − u)
  double static_load = 0.0;   ///< P0, N, compression positive
  double tangent = 0.0;       ///< c0, N/m: what the linear stiffness matrix holds for the element
  double friction = 0.0;      ///< φ; 0 when leaf friction is not simulated for it
  std::optional<LoadDeflectionCurve> curve;  ///< per spring; followed when progressive springs are
  int springs = 1;                           ///< springs in parallel on the curve
  double static_deflection = 0.0;            ///< on the curve under P0
  std::vector<TrackHarmonic> track;          ///< empty for an element between two bodies
  SpeedProfile profile;                      ///< of the run, for the track under a ramp
  bool constant_friction = false;            ///< φ·P₀ (Coulomb) instead of the book's φ·R_el
  /// A leaf with friction in series with elastic stages (the book's double and triple
  /// suspension): the leaf's own stiffness c_l (N/m, all its springs) and k_c, the series
  /// stiffness of the elastic stages. k_c = 0: the element is the leaf alone.
  double leaf_stiffness = 0.0;
  double coil_stiffness = 0.0;

  /// Whether the element is a friction leaf in series with elastic stages: one element with
  /// an internal state, the leaf's own deflection s (see nonlinear_elements.cpp).
  bool in_series() const { return coil_stiffness > 0.0; }
  /// The friction force φ·R (R the leaf's elastic reaction, compression positive; none in
  /// tension), or φ·P₀ under the constant (Coulomb) law.
  double friction_force(double reaction) const {
    return friction * (constant_friction ? static_load : std::max(reaction, 0.0));
  }
  /// Series element: the leaf's elastic reaction P₀ + c_l·s at its dynamic deflection s.
  double leaf_reaction(double s) const { return static_load + leaf_stiffness * s; }
  /// Series element: the force through the pair, P₀ + k_c(δ − s) (compression positive).
  double series_force(double delta, double s) const { return static_load + coil_stiffness * (delta - s); }
  /// Series element: the leaf's deflection while it slides into compression (direction +1)
  /// or out of it (−1) with the pair compressed by δ, or with no friction (direction 0).
  double sliding_leaf_deflection(double delta, int direction) const;

  /// Elastic reaction (N, compression positive) at the dynamic compression δ from equilibrium.
  double reaction(double delta) const {
    return curve ? springs * curve->load_at(static_deflection + delta) : static_load + tangent * delta;
  }
  /// Track displacement, velocity and acceleration under the element at time t.
  void track_motion(double t, double* u, double* du, double* ddu) const;
};

/// The elements of `system` that carry an effect named in `effects`, with the track harmonics
/// of `loads` (taken at the profile's initial speed; `load_sources[i]` made `loads[i]`, for
/// the amplitude's speed law under a ramp) under them. Throws std::invalid_argument for a
/// progressive stage in series with other stages, or for two friction stages in one element.
std::vector<NonlinearElement> nonlinear_elements(const LinearSystem& system, const std::vector<HarmonicLoad>& loads,
                                                 const NonlinearEffects& effects,
                                                 const std::vector<const ExcitationSource*>& load_sources = {},
                                                 const SpeedProfile& profile = {});

}  // namespace railmodal::simulate
