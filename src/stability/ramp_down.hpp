// One ramp-down: the lateral equations integrated while the speed falls at a constant rate, and
// the half cycles of the wheelsets' lateral motion read off as limit-cycle amplitudes; and one
// held speed, the same integration at a fixed speed (docs/stability.md, "The nonlinear critical
// speed").
#pragma once

#include <Eigen/Core>
#include <limits>
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

/// A least-squares slope of ln A against the half-cycle count, per period (two half cycles), with
/// the most the peaks' errors can have moved it (ramp_down.cpp, fitted_slope, derives it).
struct Slope {
  double per_period = 0.0;
  double bound = std::numeric_limits<double>::infinity();  ///< infinite: fewer than 4 half cycles
};

/// A hold's growth rate: fitted over the second half of the hold's half cycles (the last left
/// out), and its change, the rate over the second half of that span less the rate over its first
/// half, with the sum of their bounds. A change beyond its bound is a rate still changing (a
/// settling not over), which the one fitted line absorbs without a residual.
struct HoldRate {
  Slope rate;
  double change = 0.0;
  double change_bound = std::numeric_limits<double>::infinity();
};

/// The growth rate of `peaks`' amplitudes; `sampling` is δ, the most by which a peak picked from
/// the steps is low in ln A: −ln cos(ωh/2) (sampling_error).
HoldRate hold_rate(const std::vector<LimitCyclePoint>& peaks, double sampling);

/// δ = −ln cos(ωh/2): the most by which the largest sample of a cycle of angular frequency ω
/// (rad/s), sampled at steps of at most h (s), is below its peak, in ln A; infinite when ωh ≥ π.
double sampling_error(double omega, double h);

enum class RateVerdict { survives, dies, undecided };

/// What a completed hold's rate says against −1e-4 per period: survives when the rate less its
/// bound is at or above it, dies when the rate plus its bound is below it; undecided otherwise, or
/// when the rate is still changing toward the threshold (|change| > change_bound in its
/// direction; not a growing amplitude's falling rate, which tends to a cycle's 0), or when either
/// bound is infinite.
RateVerdict rate_verdict(const HoldRate& rate);

/// Holds `speed` from `start` for `periods` periods (counted as half cycles of the wheelset
/// `watched`): survives when every half cycle after the first stays at or above half the start's
/// amplitude; stops early when one falls below it.
SpeedHold hold_speed(const LateralEquations& equations, const NonlinearHuntingOptions& options, double speed,
                     const Eigen::VectorXd& start, int watched, int periods);

}  // namespace railmodal::stability
