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
/// The displacement of every track input per metre of cross-level Δz = z_left − z_right, the
/// one convention of both domains (docs/ride.md, "The track"): the rails roll by θ = Δz/(2b)
/// about the rail top, r0 below the axle plane (z = 0), so an input at (y, z) moves by
/// (0, −θ·(z + r0), θ·y). b: `contact_half_spacing` when positive, else the contact_half_spacing
/// of the wheelset the input's element stands on, else the first wheelset's, else 0.75 m
/// (standard gauge); r0 likewise from `rolling_radius` and the wheelsets' rolling_radius, else 0.
std::vector<Eigen::Vector3d> cross_level_directions(const LinearSystem& system, double contact_half_spacing,
                                                    double rolling_radius);

/// Whether cross_level_directions had a rolling radius to use (the option or a wheelset's).
bool knows_rolling_radius(const LinearSystem& system, double rolling_radius);

class TrackUnderWheels {
 public:
  /// `cross_level` (cross_level_directions) turns the cross-level Δz at each input into its
  /// displacement.
  TrackUnderWheels(const LinearSystem& system, const TrackGeometry& geometry,
                   std::vector<Eigen::Vector3d> cross_level);

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
  /// Wheel i's displacement per metre of cross-level (cross_level_directions).
  const Eigen::Vector3d& cross_level(int input) const { return cross_level_[input]; }
  /// u_i alone (3 values) for wheel i when the leading wheel is at `leading`.
  Eigen::Vector3d displacement_of(int input, double leading) const;
  /// u_i and ∂u_i/∂ξ for wheel i at `leading`, on the segment of the interpolation under the
  /// wheel when the leading one is at `anchor` (extended linearly to `leading`): the smooth
  /// piece a nonlinear integrator's step stays on (simulate/sampled_track.hpp).
  void on_segment(int input, double leading, double anchor, Eigen::Vector3d* u, Eigen::Vector3d* slope) const;
  /// The geometry's step, m: the length of every segment.
  double step() const;

  /// The track's profiles one at a time, for a march that sums the inputs standing at one
  /// track position and reads the samples itself (ride_modal_march.hpp): profile 0 is the
  /// alignment, 1 the vertical level, 2 the cross-level (empty when the geometry has none);
  /// u_i = Σ_p direction(i, p)·(profile p interpolated at x_i).
  static constexpr int kProfiles = 3;
  const Eigen::VectorXd& profile(int p) const;
  bool periodic() const;
  /// ∂u_i/∂(profile p): (0, 1, 0) for the alignment, (0, 0, 1) for the level, cross_level(i).
  Eigen::Vector3d direction(int input, int profile) const;

 private:
  double sample(const Eigen::VectorXd& profile, double position) const;
  double sample_slope(const Eigen::VectorXd& profile, double position) const;
  void segment(const Eigen::VectorXd& profile, double position, double anchor, double* value, double* slope) const;

  const TrackGeometry& geometry_;
  std::vector<double> lags_;
  std::vector<Eigen::Vector3d> cross_level_;
  double span_ = 0.0;
};

}  // namespace railmodal::ride
