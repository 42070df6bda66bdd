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
  // The regular samples and the states at the events, in time order: the motion is smooth
  // between events (an acceleration jumps at a friction reversal or a kink), so a cubic
  // through two neighbouring points of this list stays O(Δt⁴) accurate where one spanning an
  // event would not.
  struct Point {
    double t, x, v;
  };
  std::vector<Point> p;
  p.reserve(static_cast<size_t>(history.time.size()) + history.events.size());
  for (Eigen::Index i = 0; i < history.time.size(); ++i)
    p.push_back({history.time(i), history.displacement(i, dof), history.velocity(i, dof)});
  for (const auto& e : history.events)
    if (e.displacement.size() > dof) p.push_back({e.time, e.displacement(dof), e.velocity(dof)});
  // Stable: an event at a sample's time comes after the sample and, holding the state after
  // the event, replaces it.
  std::stable_sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.t < b.t; });
  std::vector<Point> q;
  for (const Point& point : p) {
    if (!q.empty() && point.t - q.back().t <= 1e-14 * std::max(1.0, std::abs(point.t))) q.back() = point;
    else q.push_back(point);
  }
  const size_t n = q.size();
  if (n > 1 && q[0].v == 0.0 && q[0].x != 0.0) {  // released from rest: the first turning point
    out.turning_times.push_back(q[0].t);
    out.turning_values.push_back(q[0].x);
  }
  for (size_t i = 0; i + 1 < n; ++i) {
    const double h = q[i + 1].t - q[i].t;
    const Hermite c{q[i].x, q[i + 1].x, q[i].v * h, q[i + 1].v * h};
    // A turn: the velocity changes sign, or comes exactly to rest (a spring sticks).
    const double v0 = q[i].v, v1 = q[i + 1].v;
    if ((v0 > 0.0 && v1 < 0.0) || (v0 < 0.0 && v1 > 0.0)) {
      const double s = c.turning();
      out.turning_times.push_back(q[i].t + s * h);
      out.turning_values.push_back(c.value(s));
    } else if (v0 != 0.0 && v1 == 0.0) {
      out.turning_times.push_back(q[i + 1].t);
      out.turning_values.push_back(q[i + 1].x);
    }
    if ((q[i].x > 0.0) != (q[i + 1].x > 0.0) && q[i].x != 0.0) out.crossing_times.push_back(q[i].t + c.crossing() * h);
  }
  out.comes_to_rest = n > 2 && q[n - 1].v == 0.0 && q[n - 2].v == 0.0;
  return out;
}

}  // namespace railmodal
