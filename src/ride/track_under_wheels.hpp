// The sampled track as each wheel meets it: linear interpolation between samples, the
// cross-level turned into the vertical displacement it gives at a wheel's lateral position.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride_simulation.hpp"

namespace railmodal::ride {

/// The track displacements of every track input, stacked as w = (u_0; u_1; …), each u_i
/// (longitudinal, lateral, vertical) in m as LinearSystem::TrackInput takes it. Wheel i sits
/// lag_i = x_lead − x_i behind the leading one, so when the leading wheel is at track distance
/// ξ wheel i is at ξ − lag_i (it meets each point lag_i/V later).
/// b for the cross-level: `option` when positive, else the first wheelset's
/// contact_half_spacing, else 0.75 m (standard gauge: 1.5 m between the contact points).
double contact_half_spacing(const LinearSystem& system, double option);

class TrackUnderWheels {
 public:
  /// `half_spacing` b turns the cross-level Δz into the roll θ = Δz/(2b), which moves a wheel
  /// at lateral position y (left positive) by θ·y vertically.
  TrackUnderWheels(const LinearSystem& system, const TrackGeometry& geometry, double half_spacing);

  int inputs() const { return static_cast<int>(lags_.size()); }
  double lag(int input) const { return lags_[input]; }
  /// The largest lag: the leading wheel starts this far along, so the last wheel starts at 0.
  double span() const { return span_; }
  /// Where the record ends for the leading wheel (non-periodic geometry), m.
  double end() const;
  /// w for the leading wheel at `leading` m (size 3·inputs()).
  void displacement(double leading, Eigen::VectorXd* w) const;
  /// ∂w/∂ξ for the leading wheel at `leading` m: the slope of the segment under each wheel,
  /// the mean of the two segments on a sample (where the interpolated track has a kink).
  void slope(double leading, Eigen::VectorXd* dw) const;
  /// The lateral position of wheel i, m (left positive), and b.
  double lateral_position(int input) const { return lateral_positions_[input]; }
  double half_spacing() const { return half_spacing_; }
  /// u_i alone (3 values) for wheel i when the leading wheel is at `leading`.
  Eigen::Vector3d displacement_of(int input, double leading) const;
  /// u_i and ∂u_i/∂ξ for wheel i at `leading`, on the segment of the interpolation under the
  /// wheel when the leading one is at `anchor` (extended linearly to `leading`): the smooth
  /// piece a nonlinear integrator's step stays on (simulate/sampled_track.hpp).
  void on_segment(int input, double leading, double anchor, Eigen::Vector3d* u, Eigen::Vector3d* slope) const;
  /// The geometry's step, m: the length of every segment.
  double step() const;

 private:
  double sample(const Eigen::VectorXd& profile, double position) const;
  double sample_slope(const Eigen::VectorXd& profile, double position) const;
  void segment(const Eigen::VectorXd& profile, double position, double anchor, double* value, double* slope) const;

  const TrackGeometry& geometry_;
  std::vector<double> lags_, lateral_positions_;
  double half_spacing_ = 0.0, span_ = 0.0;
};

}  // namespace railmodal::ride
