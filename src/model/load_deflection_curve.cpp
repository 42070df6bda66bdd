// A progressive spring's piecewise-linear load–deflection curve (springs digest §2.9, the
// Khanin spring of Example 10 replaced by straight segments, as the book does).
#include <algorithm>

#include "railmodal/vehicle.hpp"

namespace railmodal {
namespace {

// Index i of the segment [i, i+1] that holds value v in xs (the first segment below xs[0],
// the last beyond the end). `upper` picks the segment above a point that lies exactly on a kink.
size_t segment(const std::vector<double>& xs, double v, bool upper) {
  const auto it = upper ? std::upper_bound(xs.begin(), xs.end(), v) : std::lower_bound(xs.begin(), xs.end(), v);
  const size_t i = static_cast<size_t>(it - xs.begin());
  return std::clamp<size_t>(i == 0 ? 0 : i - 1, 0, xs.size() - 2);
}

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double v) {
  const size_t i = segment(xs, v, false);
  return ys[i] + (ys[i + 1] - ys[i]) * (v - xs[i]) / (xs[i + 1] - xs[i]);
}

}  // namespace

double LoadDeflectionCurve::load_at(double d) const { return interpolate(deflection, load, d); }

double LoadDeflectionCurve::deflection_at(double p) const { return interpolate(load, deflection, p); }

double LoadDeflectionCurve::stiffness_at(double p) const {
  const size_t i = segment(load, p, true);
  return (load[i + 1] - load[i]) / (deflection[i + 1] - deflection[i]);
}

}  // namespace railmodal
