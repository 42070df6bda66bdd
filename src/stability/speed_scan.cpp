// Unstable intervals (see speed_scan.hpp).
#include "stability/speed_scan.hpp"

#include <algorithm>
#include <limits>

#include "stability/damping_search.hpp"

namespace railmodal::stability {

namespace {

// The speed where ζ − target changes sign between grid speeds a and b (classified with the
// round-off band, so a grid value of exactly 0 is a root within round-off). The refinement
// follows ζ without the band, so that its accuracy is the bracket's, except where a grid end is
// exactly 0: an undamped root makes the least-damped ζ exactly 0 on the stable side, and without
// the band its round-off would decide the sign; there the banded ζ is followed, an exact 0
// counting as stable (> 0), and the end is known to the band's width (speed_scan.hpp).
double refine(const ZetaAt& zeta_at, double target, double a, double b, double za, double zb,
              double relative_tolerance, int* evaluations, int* own = nullptr) {
  const bool banded = za == target || zb == target;
  const auto f = [&](double zeta) {
    const double v = zeta - target;
    return banded && v == 0.0 ? std::numeric_limits<double>::min() : v;
  };
  const BracketedRoot r = bracketed_root([&](double v) { return f(zeta_at(v, !banded)); }, a, b, f(za), f(zb),
                                         relative_tolerance);
  *evaluations += r.evaluations;
  if (own) *own = r.evaluations;
  return r.x;
}

}  // namespace

std::vector<ScannedInterval> unstable_intervals(const std::vector<double>& speeds, const std::vector<double>& zeta,
                                                const ZetaAt& zeta_at, double relative_tolerance,
                                                int* evaluations) {
  const int n = static_cast<int>(speeds.size());
  std::vector<ScannedInterval> intervals;
  for (int s = 0; s < n; ++s) {
    if (zeta[s] < 0.0) {
      ScannedInterval interval;
      interval.grid_index = s;
      if (s == 0) {
        interval.from = speeds[0];
        interval.from_lowest_speed = true;
      } else {
        interval.from = refine(zeta_at, 0.0, speeds[s - 1], speeds[s], zeta[s - 1], zeta[s], relative_tolerance,
                               evaluations, &interval.from_evaluations);
      }
      while (s + 1 < n && zeta[s + 1] < 0.0) ++s;
      if (s == n - 1) {
        interval.to = speeds[n - 1];
        interval.to_highest_speed = true;
      } else {
        interval.to =
            refine(zeta_at, 0.0, speeds[s], speeds[s + 1], zeta[s], zeta[s + 1], relative_tolerance, evaluations);
      }
      intervals.push_back(interval);
      continue;
    }
    // The dip guard: a grid minimum nearer zero than its rise to the higher neighbour.
    if (s == 0 || s == n - 1 || zeta[s - 1] < 0.0 || zeta[s + 1] < 0.0) continue;
    if (!(zeta[s] <= zeta[s - 1] && zeta[s] <= zeta[s + 1])) continue;
    if (!(zeta[s] < std::max(zeta[s - 1], zeta[s + 1]) - zeta[s])) continue;
    const Minimum dip =
        dip_minimum([&](double v) { return zeta_at(v, false); }, speeds[s - 1], speeds[s + 1], relative_tolerance);
    *evaluations += dip.evaluations;
    if (!(dip.value < 0.0)) continue;
    ScannedInterval interval;
    interval.grid_index = s;
    interval.from = refine(zeta_at, 0.0, speeds[s - 1], dip.x, zeta[s - 1], dip.value, relative_tolerance, evaluations,
                           &interval.from_evaluations);
    interval.to = refine(zeta_at, 0.0, dip.x, speeds[s + 1], dip.value, zeta[s + 1], relative_tolerance, evaluations);
    intervals.push_back(interval);
  }
  return intervals;
}

}  // namespace railmodal::stability
