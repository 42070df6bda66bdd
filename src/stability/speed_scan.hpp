// The unstable speed intervals, from the least-damped ζ on the grid refined between grid speeds.
#pragma once

#include <functional>
#include <vector>

namespace railmodal::stability {

/// The least-damped ζ at a speed, with the round-off band (raw = false: what classifies a speed
/// as stable or not) or without it (raw = true: what the refinement follows).
using ZetaAt = std::function<double(double speed, bool raw)>;

/// One unstable interval: ζ < 0 between `from` and `to`.
struct ScannedInterval {
  double from = 0.0, to = 0.0;
  bool from_lowest_speed = false, to_highest_speed = false;
  int from_evaluations = 0;  ///< evaluations of ζ(V) the refinement of `from` took
  int grid_index = 0;        ///< a grid speed in the interval (or, for a dip, the nearest)
};

/// Every unstable interval, in order of speed. `zeta[s]` is the least-damped ζ at `speeds[s]`,
/// `zeta_at` evaluates it anywhere. Each end between two grid speeds is refined by Brent's
/// method to `relative_tolerance`. A narrow interval can lie between two stable grid speeds:
/// at every interior grid minimum of ζ that is not below zero but is closer to zero than the
/// rise to its higher neighbour (a dip the grid may have cut off), ζ is minimised by golden
/// section over the two grid steps around it, and a negative minimum opens an interval whose
/// two ends are refined.
std::vector<ScannedInterval> unstable_intervals(const std::vector<double>& speeds, const std::vector<double>& zeta,
                                                const ZetaAt& zeta_at, double relative_tolerance,
                                                int* evaluations);

}  // namespace railmodal::stability
