// One ramp-down: the lateral equations integrated while the speed falls at a constant rate, and
// the half cycles of the wheelsets' lateral motion read off as limit-cycle amplitudes; and one
// held speed, the same integration at a fixed speed (docs/stability.md, "The nonlinear critical
// speed").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "railmodal/nonlinear_hunting.hpp"
#include "stability/lateral_equations.hpp"

namespace railmodal::stability {

/// The state at each half cycle's peak of the watched wheelset during a ramp, aligned with
/// RampDown::curve: where a held speed starts from.
struct BranchStates {
  std::vector<Eigen::VectorXd> states;
  std::size_t branch_end = 0;  ///< index of the branch end in RampDown::curve (limit_cycle_dies_out)
};

/// From options.start_speed, every wheelset displaced laterally by options.disturbance and
/// everything else at rest, to options.end_speed at `ramp_rate` (m/s²); stops early when the
/// amplitude passes options.amplitude_bound. Throws NumericalError when the step size collapses or
/// the state stops being finite (naming the speed).
RampDown ramp_down(const LateralEquations& equations, const NonlinearHuntingOptions& options, double ramp_rate,
                   BranchStates* branch = nullptr);

/// Whether the last whole half cycle of `curve` (the one before the unfinished last) fell by more
/// than a cycle on its branch does in a half cycle (0.5 %): the oscillation was collapsing there.
bool collapsing_at_end(const std::vector<LimitCyclePoint>& curve);

/// Holds `speed` from `start` for `periods` periods (counted as half cycles of the wheelset
/// `watched`): survives when every half cycle after the first stays at or above half the start's
/// amplitude; stops early when one falls below it.
SpeedHold hold_speed(const LateralEquations& equations, const NonlinearHuntingOptions& options, double speed,
                     const Eigen::VectorXd& start, int watched, int periods);

}  // namespace railmodal::stability
