// The branch of periodic orbits born at a Hopf point of the equilibrium x = 0, followed by
// pseudo-arclength continuation in the parameter, its folds located and refined
// (docs/stability.md, "Continuation of the limit cycles"). Generic: any OrbitProblem.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stability/periodic_orbits.hpp"

namespace railmodal::stability {

struct HopfPoint {
  double parameter = 0.0;
  double frequency = 0.0;  ///< ω, rad/s: the imaginary part of the crossing eigenvalue
  Eigen::VectorXcd vector;  ///< its eigenvector
};

/// The first parameter in [low, high], scanning upward on `scan_points` points and bisecting to
/// 1e-12 relative, where the rightmost eigenvalue of the Jacobian of `field` at x = 0 (central
/// differences, step 1e-10 in every state) crosses into the right half-plane with a nonzero
/// imaginary part. None when it does not cross there.
std::optional<HopfPoint> find_hopf(const VectorField& field, int states, double low, double high,
                                   int scan_points = 60);

struct ContinuationSettings {
  double start_amplitude = 1e-4;  ///< amplitude·x0 of the first orbit (the second has twice it)
  double max_amplitude = 0.02;    ///< stop once amplitude·x0 passes this
  double parameter_low = 0.0, parameter_high = 0.0;  ///< stop once the parameter leaves this range
  int max_points = 200;
  /// Pseudo-arclength steps, in the norm of (amplitude/amplitude_scale, parameter/parameter_scale).
  double initial_step = 0.1, min_step = 1e-4, max_step = 1.0;
  /// Called after each orbit with the fraction done (continuation_progress), 1 once the branch
  /// ends however it ends; from the calling thread. None: not called.
  std::function<void(double)> progress;
};

/// The fraction of a continuation done after `orbits` orbits, the last of amplitude·x0
/// `amplitude`: the larger of the orbits against max_points and the amplitude against
/// max_amplitude, the two limits one of which ends a branch that neither fails nor leaves the
/// parameter range; below 1. An estimate, not a promise: a branch may end early at the range.
double continuation_progress(const ContinuationSettings& settings, std::size_t orbits, double amplitude);

enum class BranchEnd { amplitude_reached, parameter_range_left, point_limit, newton_failed };

struct OrbitBranch {
  std::vector<Orbit> orbits;  ///< in the order continued, from the Hopf point
  std::vector<Orbit> folds;   ///< refined turning points of the parameter, in branch order
  /// For each fold, the index in `orbits` of the orbit at which the parameter turned (the extreme
  /// one of the three the fold was refined between).
  std::vector<std::size_t> fold_orbits;
  BranchEnd end = BranchEnd::point_limit;
  std::string failure;  ///< with newton_failed: where and how far it got
  long flows = 0;       ///< one-period integrations spent
};

/// From the Hopf point: the orbit x0 = Re(v·e^{iθ}) at amplitude·x0 = start_amplitude (θ from the
/// phase condition), period 2π/ω, then at twice it (both natural-parameter solves in the
/// amplitude), then pseudo-arclength along the secant. A step whose Newton fails is halved; below
/// min_step the branch ends with newton_failed (never a point that did not converge). A change of
/// sign of the parameter's increment is a fold: refined by golden-section search for the extremum of p against
/// amplitude·x0 with fixed-amplitude solves.
/// Whether the parameter turns at orbit m of a branch: the increments into and out of it have opposite
/// signs (m ≥ 1 and m + 1 < parameters.size(); false otherwise).
bool turns_at(const std::vector<double>& parameters, std::size_t m);

/// The turning point of the parameter at which a branch's stable and unstable orbits meet, at the
/// lowest parameter: the index m of the extreme orbit of the lowest turn (turns_at) whose
/// neighbours m − 1 and m + 1 differ in `stable` (largest Floquet |μ| below 1 on one side, above
/// on the other: a multiplier crossed 1, which at a fold is the exchange of stability). A turn with
/// the same stability on both sides is a wiggle of one branch (another multiplier passing 1 and
/// back, or a step artefact), not where the cycles cease to exist; none when no turn exchanges
/// stability. For a subcritical Hopf branch this fold's parameter is the nonlinear critical speed.
std::optional<std::size_t> lowest_exchange_turn(const std::vector<double>& parameters, const std::vector<bool>& stable);

OrbitBranch continue_from_hopf(const OrbitProblem& problem, const HopfPoint& hopf,
                               const ContinuationSettings& settings);

}  // namespace railmodal::stability
