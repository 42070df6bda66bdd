#include "ride/track_under_wheels.hpp"

#include <algorithm>
#include <cmath>

namespace railmodal::ride {

double contact_half_spacing(const LinearSystem& system, double option) {
  constexpr double kStandardHalfSpacing = 0.75;
  if (option > 0.0) return option;
  for (const Wheelset& wheelset : system.vehicle.wheelsets)
    if (wheelset.contact.contact_half_spacing > 0.0) return wheelset.contact.contact_half_spacing;
  return kStandardHalfSpacing;
}

TrackUnderWheels::TrackUnderWheels(const LinearSystem& system, const TrackGeometry& geometry, double half_spacing)
    : geometry_(geometry), half_spacing_(half_spacing) {
  double lead = -INFINITY;
  for (const TrackInput& input : system.track_inputs) lead = std::max(lead, input.point.x());
  for (const TrackInput& input : system.track_inputs) {
    lags_.push_back(lead - input.point.x());
    lateral_positions_.push_back(input.point.y());
    span_ = std::max(span_, lags_.back());
  }
}

double TrackUnderWheels::end() const {
  const Eigen::Index n =
      std::max({geometry_.vertical_level.size(), geometry_.alignment.size(), geometry_.cross_level.size()});
  return static_cast<double>(n - 1) * geometry_.step;
}

// Linear interpolation; a periodic profile wraps (its sample n stands again at n·step + length),
// a measured one is read inside its record only (the run is sized so that it stays there).
double TrackUnderWheels::sample(const Eigen::VectorXd& profile, double position) const {
  if (profile.size() == 0) return 0.0;
  const Eigen::Index n = profile.size();
  double s = position / geometry_.step;
  if (geometry_.periodic) s -= std::floor(s / static_cast<double>(n)) * static_cast<double>(n);
  Eigen::Index i = static_cast<Eigen::Index>(std::floor(s));
  if (!geometry_.periodic) i = std::clamp<Eigen::Index>(i, 0, n - 2);
  const double f = s - static_cast<double>(i);
  const double a = profile(i % n), b = profile((i + 1) % n);
  return a + f * (b - a);
}

double TrackUnderWheels::sample_slope(const Eigen::VectorXd& profile, double position) const {
  if (profile.size() == 0) return 0.0;
  const double h = geometry_.step;
  const double s = position / h;
  const double f = s - std::floor(s);
  // On a sample (to round-off) the interpolated track has a kink: take the mean of the two
  // segments, the value its Fourier series converges to there.
  constexpr double kOnSample = 1e-9;
  if (f < kOnSample || f > 1.0 - kOnSample) {
    const double at = std::round(s) * h;
    return (sample(profile, at + h) - sample(profile, at - h)) / (2.0 * h);
  }
  const double left = std::floor(s) * h;
  return (sample(profile, left + h) - sample(profile, left)) / h;
}

// The segment [i, i+1] that holds `anchor`, extended to `position` (i from the anchor, so all
// evaluations of one step use one straight piece, also a hair beyond its ends).
void TrackUnderWheels::segment(const Eigen::VectorXd& profile, double position, double anchor, double* value,
                               double* slope) const {
  *value = *slope = 0.0;
  if (profile.size() == 0) return;
  const Eigen::Index n = profile.size();
  Eigen::Index i = static_cast<Eigen::Index>(std::floor(anchor / geometry_.step));
  // a measured record's ends extend its first and last segments (as `sample` reads it)
  if (!geometry_.periodic) i = std::clamp<Eigen::Index>(i, 0, n - 2);
  const double f = position / geometry_.step - static_cast<double>(i);
  if (geometry_.periodic) {
    i %= n;
    if (i < 0) i += n;
  }
  const double a = profile(i), b = profile((i + 1) % n);
  *value = a + f * (b - a);
  *slope = (b - a) / geometry_.step;
}

void TrackUnderWheels::on_segment(int input, double leading, double anchor, Eigen::Vector3d* u,
                                  Eigen::Vector3d* slope) const {
  const double x = leading - lags_[input], xa = anchor - lags_[input];
  double level, level_slope, align, align_slope, cross, cross_slope;
  segment(geometry_.vertical_level, x, xa, &level, &level_slope);
  segment(geometry_.alignment, x, xa, &align, &align_slope);
  segment(geometry_.cross_level, x, xa, &cross, &cross_slope);
  const double y = lateral_positions_[input] / (2.0 * half_spacing_);
  *u << 0.0, align, level + cross * y;
  *slope << 0.0, align_slope, level_slope + cross_slope * y;
}

double TrackUnderWheels::step() const { return geometry_.step; }

Eigen::Vector3d TrackUnderWheels::displacement_of(int input, double leading) const {
  const double x = leading - lags_[input];
  const double roll = sample(geometry_.cross_level, x) / (2.0 * half_spacing_);
  return {0.0, sample(geometry_.alignment, x), sample(geometry_.vertical_level, x) + roll * lateral_positions_[input]};
}

void TrackUnderWheels::displacement(double leading, Eigen::VectorXd* w) const {
  w->resize(3 * inputs());
  for (int i = 0; i < inputs(); ++i) w->segment<3>(3 * i) = displacement_of(i, leading);
}

void TrackUnderWheels::slope(double leading, Eigen::VectorXd* dw) const {
  dw->resize(3 * inputs());
  for (int i = 0; i < inputs(); ++i) {
    const double x = leading - lags_[i];
    const double roll = sample_slope(geometry_.cross_level, x) / (2.0 * half_spacing_);
    dw->segment<3>(3 * i) << 0.0, sample_slope(geometry_.alignment, x),
        sample_slope(geometry_.vertical_level, x) + roll * lateral_positions_[i];
  }
}

}  // namespace railmodal::ride
