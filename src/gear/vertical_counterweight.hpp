// Sizing one driving wheel's vertical counterweight against the vertical force it carries.
#pragma once

#include <functional>

#include "railmodal/balance.hpp"

namespace railmodal::gear {

/// A counterweight's vertical force a·sin θ + b·cos θ, θ the wheel's crank angle: amplitude
/// √(a² + b²) (= q·ω²·r) at angle atan2(b, a) ahead of the crank (a = Q cos γ, b = Q sin γ).
struct SineForce {
  double a = 0.0;
  double b = 0.0;
};

/// The counterweight force that opposes `upward` (N, the wheel's upward force as a function of the
/// wheel's crank angle θ) by `rule`, judged on `steps` equal steps of θ.
SineForce size_vertical_counterweight(const std::function<double(double)>& upward, VerticalRule rule, int steps);

/// max over the steps of |upward(θ) + a sin θ + b cos θ|.
double largest_residual(const std::function<double(double)>& upward, const SineForce& force, int steps);

}  // namespace railmodal::gear
