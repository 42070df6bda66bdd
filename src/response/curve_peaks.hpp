// The peaks of a curve over speed, found one way for every caller: the local maxima of a grid
// of amplitudes (the critical-speed study's peak refinement and a study's permissible
// deflection check, rule 2) and the largest response of a critical-speed study's curve (a
// design variant's peak summary, and the comparison report's peak table that writes it).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "railmodal/critical_speed.hpp"
#include "response/sweep_kernels.hpp"

namespace railmodal::response {

/// The first local maximum of a[0, n) from i on (a[i] ≥ a[i − 1] and a[i] > a[i + 1]; 0 < i),
/// or n − 1 if there is none: a tight loop of its own over the amplitudes, each read once (few
/// points are maxima, and a caller's loop would reread the curve's size around its calls).
/// Walk a curve's maxima with `for (i = next_local_maximum(a, 1, n); i + 1 < n; i =
/// next_local_maximum(a, i + 1, n))`, which also ends at once for n < 3.
inline size_t next_local_maximum(const double* a, size_t i, size_t n) {
  if (i + 1 >= n) return n - 1;
  // Past the blocks with no maximum (a vectorised test), then point by point: the same
  // comparisons, the same first maximum.
  i = skip_to_local_maximum(a, i, n);
  if (i + 1 >= n) return n - 1;
  double before = a[i - 1], at = a[i];
  for (; i + 1 < n; ++i) {
    const double after = a[i + 1];
    if (at >= before && at > after) return i;
    before = at;
    at = after;
  }
  return n - 1;
}

/// The largest response of a critical-speed study's curve: its largest bounded amplitude on
/// the grid and at its refined peaks (CriticalSpeedStudy::peaks), where it is, and whether the
/// grid met an undamped resonance. amplitude and speed stay 0 when no point is above 0.
struct LargestResponse {
  double amplitude = 0.0;  ///< the curve's unit
  double speed = 0.0;      ///< m/s
  bool unbounded = false;  ///< some grid point is unbounded: the curve has no finite peak
};

/// The LargestResponse of study.curves[k]. Its grid's largest: an unbounded point holds 0
/// (AmplitudeCurve::amplitudes), which never beats the running largest (≥ 0), so the
/// amplitudes are scanned without the flags (bits, slow to read one by one), and the flags only
/// searched for whether any is set. Ties keep the first: the lowest speed on the grid, and the
/// grid's point over a refined peak of the same amplitude.
inline LargestResponse largest_response(const CriticalSpeedStudy& study, size_t k) {
  const AmplitudeCurve& curve = study.curves[k];
  const std::vector<double>& speeds = curve.speeds.values();
  const std::vector<double>& a = curve.amplitudes;
  LargestResponse p;
  // One pass's running largest, strictly greater taking over (response::largest_above).
  const LargestPoint largest = largest_above(a.data(), speeds.size(), p.amplitude);
  if (largest.at < speeds.size()) p.amplitude = largest.value, p.speed = speeds[largest.at];
  p.unbounded = std::find(curve.unbounded.begin(), curve.unbounded.end(), true) != curve.unbounded.end();
  for (const auto& refined : study.peaks)
    if (refined.curve == static_cast<int>(k) && refined.peak.amplitude > p.amplitude)
      p.amplitude = refined.peak.amplitude, p.speed = refined.peak.speed;
  return p;
}

}  // namespace railmodal::response
