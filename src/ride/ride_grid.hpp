// The ride's frequency grid and the integration rule over it (docs/accuracy.md, "Ride:
// frequency grid").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "railmodal/ride.hpp"

namespace railmodal::ride {

/// A resonance the grid must resolve: its natural frequency (Hz) and damping ratio.
struct GridMode {
  double frequency = 0.0;
  double damping_ratio = 0.0;
};

/// The grid, increasing, over [min_frequency, max_frequency]: log-spaced with
/// points_per_decade points a decade, graded near each mode so that its half-power bandwidth
/// 2ζf holds points_per_bandwidth points and the spacing grows in proportion to the distance
/// from the peak (a graded mesh: the tails of a peak are smooth on the scale of their distance
/// from it). A damping ratio below kMinGridDamping (an undamped mode) is refined as if it
/// were kMinGridDamping. `extra` frequencies inside the range are added (the speeds' band
/// edges, where a track spectrum jumps to zero); no point comes within a relative 1e-6 of an
/// `avoid` frequency (an undamped mode, where the dynamic stiffness is singular).
Eigen::VectorXd frequency_grid(const RideOptions& options, const std::vector<GridMode>& modes,
                               const std::vector<double>& extra, const std::vector<double>& avoid);

/// ζ below this is refined as ζ = kMinGridDamping: the bandwidth of an undamped mode is zero.
constexpr double kMinGridDamping = 1e-4;

/// One track component's band on the grid at one speed and the integration weights of it.
struct BandWeights {
  /// ∫ y df ≈ Σ_k weights(k) y(f_k): the exact integral of the piecewise-linear interpolant of y
  /// over the grid's intervals that lie inside [low, high] (the trapezoid rule).
  Eigen::VectorXd weights;
  /// The same integral of the interpolant through every other grid point (the first, the third,
  /// …, and the last), still over the fine intervals inside the band: what halving the grid
  /// would give (RideResult::grid_error_estimate).
  Eigen::VectorXd coarse_weights;
  std::vector<char> inside;  ///< per interval k (f_k … f_k+1): 1 when inside the band
};

/// The weights over the band [low, high] Hz (intervals are inside when their midpoint is;
/// exact when the band edges are grid points, which frequency_grid's `extra` makes them).
BandWeights band_weights(const Eigen::VectorXd& grid, double low, double high);

}  // namespace railmodal::ride
