// Turning points and zero crossings of a sampled response (the half-period check of fft-check).
#include <algorithm>
#include <cmath>

#include "railmodal/scene_simulation.hpp"

namespace railmodal {
namespace {

// Cubic Hermite through (0, x0, v0·h) and (1, x1, v1·h) on s ∈ [0, 1].
struct Hermite {
  double x0, x1, d0, d1;  // d = velocity × step
  double value(double s) const {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + s) * d0 + (-2 * s3 + 3 * s2) * x1 + (s3 - s2) * d1;
  }
  // The root of the derivative in [0, 1] (where velocity changes sign).
  double turning() const {
    const double a = 6 * x0 + 3 * d0 - 6 * x1 + 3 * d1, b = -6 * x0 - 4 * d0 + 6 * x1 - 2 * d1, c = d0;
    auto slope = [&](double s) { return (a * s + b) * s + c; };
    double lo = 0.0, hi = 1.0;
    if ((slope(lo) > 0.0) == (slope(hi) > 0.0)) return slope(lo) == 0.0 ? 0.0 : 1.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((slope(mid) > 0.0) == (slope(lo) > 0.0) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  double crossing() const {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((value(mid) > 0.0) == (value(lo) > 0.0) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

std::vector<double> differences(const std::vector<double>& t) {
  std::vector<double> out;
  for (size_t i = 1; i < t.size(); ++i) out.push_back(t[i] - t[i - 1]);
  return out;
}

}  // namespace

std::vector<double> Swings::half_periods_between_turns() const { return differences(turning_times); }
std::vector<double> Swings::half_periods_between_crossings() const { return differences(crossing_times); }

Swings swings(const TimeHistory& history, int dof) {
  Swings out;
  out.dof = history.labels.at(dof);
  const auto x = history.displacement.col(dof), v = history.velocity.col(dof);
  const Eigen::Index n = x.size();
  if (n > 1 && v(0) == 0.0 && x(0) != 0.0) {  // released from rest: the first turning point
    out.turning_times.push_back(history.time(0));
    out.turning_values.push_back(x(0));
  }
  // A spring that sticks stops the motion at a located event inside a sample interval; its
  // time is exact, where interpolating towards the resting sample is not.
  std::vector<double> sticks;
  for (const auto& e : history.events)
    if (e.kind == SimulationEvent::Kind::stick) sticks.push_back(e.time);
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const double h = history.time(i + 1) - history.time(i);
    const Hermite c{x(i), x(i + 1), v(i) * h, v(i + 1) * h};
    // A turn: the velocity changes sign, or comes to rest at the end of the interval.
    const bool turns = (v(i) > 0.0 && v(i + 1) <= 0.0) || (v(i) < 0.0 && v(i + 1) >= 0.0);
    if (turns) {
      const auto stick = std::find_if(sticks.begin(), sticks.end(),
                                      [&](double t) { return t > history.time(i) && t <= history.time(i + 1); });
      const bool rests = v(i + 1) == 0.0 && (i + 2 >= n || x(i + 2) == x(i + 1));
      if (rests && stick != sticks.end()) {
        out.turning_times.push_back(*stick);
        out.turning_values.push_back(x(i + 1));
      } else {
        const double s = c.turning();
        out.turning_times.push_back(history.time(i) + s * h);
        out.turning_values.push_back(c.value(s));
      }
    }
    if ((x(i) > 0.0) != (x(i + 1) > 0.0) && x(i) != 0.0) out.crossing_times.push_back(history.time(i) + c.crossing() * h);
  }
  out.comes_to_rest = n > 2 && v(n - 1) == 0.0 && v(n - 2) == 0.0;
  return out;
}

}  // namespace railmodal
