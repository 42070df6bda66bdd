// The ride's frequency grid: log base, graded near the resonances, the band edges inserted.
//
// Why graded: the area under a resonance peak of damping ζ at f_n is carried by its half-power
// bandwidth 2ζf_n; the trapezoid rule on a log grid of 100 points a decade (spacing 2.3 %)
// misses most of a 1 %-damped peak (bandwidth 2 %) or doubles it, depending on where the points
// fall. With p points in the bandwidth the trapezoid's error on the peak's Lorentzian falls as
// 1/p² (measured: docs/accuracy.md, "Ride: frequency grid").
#include "ride/ride_grid.hpp"

#include <algorithm>
#include <cmath>

namespace railmodal::ride {

namespace {

// The spacing the grid allows at f: the base log spacing, or finer near a mode.
double spacing(double f, double base_ratio, const std::vector<GridMode>& modes, int per_bandwidth) {
  double h = f * base_ratio;
  for (const GridMode& m : modes) {
    const double zeta = std::max(m.damping_ratio, kMinGridDamping);
    if (zeta >= 1.0) continue;  // overdamped: no peak to resolve
    const double bandwidth = 2.0 * zeta * m.frequency;
    h = std::min(h, bandwidth / per_bandwidth * std::max(1.0, std::abs(f - m.frequency) / bandwidth));
  }
  return h;
}

}  // namespace

Eigen::VectorXd frequency_grid(const RideOptions& options, const std::vector<GridMode>& modes,
                               const std::vector<double>& extra, const std::vector<double>& avoid) {
  const double lo = options.min_frequency, hi = options.max_frequency;
  const double base_ratio = std::pow(10.0, 1.0 / options.points_per_decade) - 1.0;
  std::vector<double> f;
  for (double x = lo; x < hi; x += spacing(x, base_ratio, modes, options.points_per_bandwidth)) f.push_back(x);
  f.push_back(hi);
  for (const GridMode& m : modes)
    if (m.frequency > lo && m.frequency < hi) f.push_back(m.frequency);
  for (double x : extra)
    if (x > lo && x < hi) f.push_back(x);
  std::sort(f.begin(), f.end());
  std::vector<double> kept;
  for (double x : f) {
    if (!kept.empty() && x - kept.back() <= 1e-9 * x) continue;
    bool near = false;
    for (double a : avoid) near = near || std::abs(x - a) <= 1e-6 * a;
    if (near) {
      // The range's own ends stay, moved off the singular frequency.
      if (x == lo) kept.push_back(x * (1.0 - 2e-6));
      else if (x == hi) kept.push_back(x * (1.0 + 2e-6));
      continue;
    }
    kept.push_back(x);
  }
  return Eigen::Map<Eigen::VectorXd>(kept.data(), static_cast<Eigen::Index>(kept.size()));
}

BandWeights band_weights(const Eigen::VectorXd& grid, double low, double high) {
  const Eigen::Index n = grid.size();
  BandWeights b;
  b.weights = Eigen::VectorXd::Zero(n);
  b.inside.assign(n > 0 ? n - 1 : 0, 0);
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    const double mid = 0.5 * (grid(k) + grid(k + 1));
    if (mid < low || mid > high) continue;
    b.inside[k] = 1;
    const double h = grid(k + 1) - grid(k);
    b.weights(k) += 0.5 * h;
    b.weights(k + 1) += 0.5 * h;
  }
  // Every other point: an odd point (not the last) is replaced by the line through its
  // neighbours, y_k ≈ α y_k−1 + (1 − α) y_k+1, so its weight moves to them.
  b.coarse_weights = b.weights;
  for (Eigen::Index k = 1; k + 1 < n; k += 2) {
    const double alpha = (grid(k + 1) - grid(k)) / (grid(k + 1) - grid(k - 1));
    b.coarse_weights(k - 1) += alpha * b.weights(k);
    b.coarse_weights(k + 1) += (1.0 - alpha) * b.weights(k);
    b.coarse_weights(k) = 0.0;
  }
  return b;
}

}  // namespace railmodal::ride
