// railmodal — the hunting limit cycles by numerical continuation: the periodic orbits of the
// nonlinear lateral equations (the right-hand side solve_nonlinear_hunting ramps through, here at
// fixed speeds) found by shooting and followed in speed by pseudo-arclength continuation from the
// Hopf point, the unstable branch of a subcritical bifurcation included, its fold (the nonlinear
// critical speed) refined, each orbit's stability from its Floquet multipliers
// (docs/stability.md, "Continuation of the limit cycles").
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/wheelset_on_springs_nonlinear_hunting.toml");
//     railmodal::LinearSystem system =
//         railmodal::assemble(railmodal::load_vehicle(scene.vehicle_file), railmodal::DofSet::lateral);
//     railmodal::LimitCycleBranch b = railmodal::continue_limit_cycles(system, *scene.nonlinear_hunting);
//     std::cout << to_string(b.kind) << ", " << b.points.size() << " orbits\n";
//     if (b.fold) std::cout << "fold (nonlinear critical speed) at " << b.fold->speed * 3.6 << " km/h\n";
//   }
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/nonlinear_hunting.hpp"
#include "railmodal/summary.hpp"

namespace railmodal {

struct LimitCycleOptions {
  /// m: the watched wheelset's amplitude of the first orbit at the Hopf point (the second has
  /// twice it), > 0 and < max_amplitude.
  double start_amplitude = 1e-4;
  /// m: the continuation stops once the amplitude passes this; > start_amplitude.
  double max_amplitude = 0.02;
  int max_points = 300;  ///< orbits at most (the refined fold not counted), ≥ 3
  /// Fixed Dormand–Prince steps per period of the shooting (docs/stability.md gives the fold
  /// speed against it: 1000 moves it by under 1e-3 m/s from 4000 on the bundled scene), ≥ 50.
  int steps_per_period = 1000;
  /// The Newton residual (closure of the orbit, in metres of the watched wheelset's amplitude
  /// per metre of it, and the phase and step conditions) that counts as converged, > 0.
  double newton_tolerance = 1e-9;
  /// The arclength step's units: the amplitude in amplitude_unit (m) and the speed in
  /// speed_unit (m/s); the first step 0.1, at most max_step, at least 1e-4.
  double amplitude_unit = 1e-3;
  double speed_unit = 1.0;
  double max_step = 1.0;
  /// Called with the fraction done (0…1) after each orbit of the branch, and 1 when it ends:
  /// an estimate from the orbits against max_points and the amplitude against max_amplitude
  /// (a branch that leaves the speed range ends sooner). From the calling thread; none: not
  /// called. `railmodal hunting --continuation` shows it on a terminal.
  std::function<void(double)> progress;
  bool is_valid(std::string* why) const;
};

/// How the branch leaves the Hopf point.
enum class LimitCycleBranchKind {
  subcritical,    ///< towards lower speeds: unstable orbits below the linear critical speed
  supercritical,  ///< towards higher speeds: stable orbits above it
  no_hopf_point,  ///< the centred running does not lose stability in the speed range: no branch
  undetermined,   ///< the corrector failed before the branch's direction was seen (see `failure`)
  /// Every orbit sits at the Hopf speed whatever its amplitude (to 1e-8 of it): a linear law (no
  /// effect simulated), whose orbits are the neutral mode at any size; stability is then moot
  /// (a second multiplier is 1).
  neutral
};
const char* to_string(LimitCycleBranchKind kind);
std::optional<LimitCycleBranchKind> limit_cycle_branch_kind_from_string(const std::string& word);

/// Why the continuation stopped.
enum class ContinuationEnd {
  amplitude_reached,   ///< the amplitude passed LimitCycleOptions::max_amplitude
  speed_range_left,    ///< the speed left [end_speed, start_speed] of the NonlinearHuntingOptions
  point_limit,         ///< max_points orbits
  newton_failed,       ///< the corrector did not converge even with the smallest step: see `failure`
  no_hopf_point        ///< nothing to continue
};
const char* to_string(ContinuationEnd end);
std::optional<ContinuationEnd> continuation_end_from_string(const std::string& word);

/// One periodic orbit of the branch.
struct LimitCycleBranchPoint {
  double speed = 0.0;      ///< m/s
  double amplitude = 0.0;  ///< m: the watched wheelset's largest |y| of the axle centre over the orbit
  double period = 0.0;     ///< s
  bool stable = false;     ///< every Floquet multiplier but the trivial one inside the unit circle
  double largest_multiplier = 0.0;  ///< the largest |μ| but the trivial one
  double residual = 0.0;            ///< the Newton residual at the point (≤ newton_tolerance)
};

struct LimitCycleBranch {
  LimitCycleBranchKind kind = LimitCycleBranchKind::no_hopf_point;
  /// m/s: where the equilibrium loses stability (the linear critical speed of the nonlinear
  /// equations' own linearisation; with contact_angle 0 that of solve_hunting_stability).
  std::optional<double> hopf_speed;
  double hopf_frequency = 0.0;  ///< Hz: the frequency of the orbit born there
  int watched_wheelset = 0;     ///< index into Vehicle::wheelsets: the wheelset largest in the Hopf mode
  std::vector<LimitCycleBranchPoint> points;  ///< from the Hopf point along the branch
  /// The refined turning points of the speed, in branch order: every turn, including wiggles of
  /// the branch across which its stability does not change.
  std::vector<LimitCycleBranchPoint> folds;
  /// The fold of a subcritical branch whose speed is the nonlinear critical speed: of the turns
  /// where the unstable cycles meet stable ones (the largest Floquet |μ| crosses 1 across the
  /// turn), the one at the lowest speed. None for a supercritical branch, when the branch ended
  /// before such a turn, or when its only turns keep the stability on both sides.
  std::optional<LimitCycleBranchPoint> fold;
  ContinuationEnd end = ContinuationEnd::no_hopf_point;
  std::string failure;  ///< with newton_failed: where the corrector failed and how far it got
  long flows = 0;       ///< one-period integrations spent (the cost)
  AnalysisSummary summary;
};

/// The branch of hunting limit cycles of `system` (an assembly of the lateral motions,
/// DofSet::lateral, of a vehicle with wheelsets) with the effects and laws of `hunting` (its
/// speeds end_speed..start_speed are the range searched and continued; its ramp and hold
/// settings are not used). Throws std::invalid_argument for bad options or a vehicle without
/// wheelsets. No Hopf point in the range, a supercritical branch, or a corrector that fails are
/// results (`kind`, `end`, `failure`), never exceptions; every point returned converged.
LimitCycleBranch continue_limit_cycles(const LinearSystem& system, const NonlinearHuntingOptions& hunting,
                                       const LimitCycleOptions& options = {});

}  // namespace railmodal
