// One ramp-down: the lateral equations integrated while the speed falls at a constant rate, and
// the half cycles of the first wheelset's lateral motion read off as limit-cycle amplitudes
// (docs/stability.md, "The nonlinear critical speed").
#pragma once

#include "railmodal/nonlinear_hunting.hpp"
#include "stability/lateral_equations.hpp"

namespace railmodal::stability {

/// From options.start_speed, the first wheelset displaced laterally by options.disturbance and
/// everything else at rest, to options.end_speed at `ramp_rate` (m/s²). Throws NumericalError
/// when the step size collapses or the state stops being finite (naming the speed).
RampDown ramp_down(const LateralEquations& equations, const NonlinearHuntingOptions& options, double ramp_rate);

}  // namespace railmodal::stability
