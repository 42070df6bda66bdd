#include "ride/track_under_wheels.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace railmodal::ride {

namespace {

// The wheelset an element stands on (its lower body), else the first one; null without wheelsets.
// A contact input of the ride (element < 0, ride_contact.hpp) is no element: the first one (its
// direction is the contact's own, contact_direction).
const Wheelset* wheelset_under(const LinearSystem& system, int element) {
  const Vehicle& v = system.vehicle;
  if (element < 0) return v.wheelsets.empty() ? nullptr : &v.wheelsets.front();
  for (const Wheelset& w : v.wheelsets)
    if (w.body == v.elements[element].lower) return &w;
  return v.wheelsets.empty() ? nullptr : &v.wheelsets.front();
}

}  // namespace

std::vector<Eigen::Vector3d> cross_level_directions(const LinearSystem& system, double contact_half_spacing,
                                                    double rolling_radius) {
  constexpr double kStandardHalfSpacing = 0.75;
  std::vector<Eigen::Vector3d> out;
  for (const TrackInput& t : system.track_inputs) {
    const Wheelset* w = wheelset_under(system, t.element);
    double b = contact_half_spacing, r0 = rolling_radius;
    if (!(b > 0.0)) b = w && w->contact.contact_half_spacing > 0.0 ? w->contact.contact_half_spacing : kStandardHalfSpacing;
    if (!(r0 > 0.0)) r0 = w ? w->contact.rolling_radius : 0.0;
    out.emplace_back(0.0, -(t.point.z() + r0) / (2.0 * b), t.point.y() / (2.0 * b));
  }
  return out;
}

bool knows_rolling_radius(const LinearSystem& system, double rolling_radius) {
  if (rolling_radius > 0.0) return true;
  for (const Wheelset& w : system.vehicle.wheelsets)
    if (w.contact.rolling_radius > 0.0) return true;
  return false;
}

TrackUnderWheels::TrackUnderWheels(const LinearSystem& system, const TrackGeometry& geometry,
                                   std::vector<Eigen::Vector3d> cross_level)
    : geometry_(geometry), cross_level_(std::move(cross_level)) {
  double lead = -INFINITY;
  for (const TrackInput& input : system.track_inputs) lead = std::max(lead, input.point.x());
  for (const TrackInput& input : system.track_inputs) {
    lags_.push_back(lead - input.point.x());
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
  // i is in [0, n] here (s wrapped into [0, n], or clamped): the indices i mod n and
  // (i + 1) mod n without an integer division
  Eigen::Index next = i + 1;
  if (next >= n) next -= n;
  if (i >= n) i -= n;
  const double a = profile(i), b = profile(next);
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
  *u = Eigen::Vector3d(0.0, align, level) + cross * cross_level_[input];
  *slope = Eigen::Vector3d(0.0, align_slope, level_slope) + cross_slope * cross_level_[input];
}

double TrackUnderWheels::step() const { return geometry_.step; }

const Eigen::VectorXd& TrackUnderWheels::profile(int p) const {
  return p == 0 ? geometry_.alignment : p == 1 ? geometry_.vertical_level : geometry_.cross_level;
}

bool TrackUnderWheels::periodic() const { return geometry_.periodic; }

Eigen::Vector3d TrackUnderWheels::direction(int input, int profile) const {
  return profile == 0 ? Eigen::Vector3d::UnitY() : profile == 1 ? Eigen::Vector3d::UnitZ() : cross_level_[input];
}

Eigen::Vector3d TrackUnderWheels::displacement_of(int input, double leading) const {
  const double x = leading - lags_[input];
  return Eigen::Vector3d(0.0, sample(geometry_.alignment, x), sample(geometry_.vertical_level, x)) +
         sample(geometry_.cross_level, x) * cross_level_[input];
}

void TrackUnderWheels::displacement(double leading, Eigen::VectorXd* w) const {
  w->resize(3 * inputs());
  for (int i = 0; i < inputs(); ++i) w->segment<3>(3 * i) = displacement_of(i, leading);
}

void TrackUnderWheels::slope(double leading, Eigen::VectorXd* dw) const {
  dw->resize(3 * inputs());
  for (int i = 0; i < inputs(); ++i) {
    const double x = leading - lags_[i];
    dw->segment<3>(3 * i) =
        Eigen::Vector3d(0.0, sample_slope(geometry_.alignment, x), sample_slope(geometry_.vertical_level, x)) +
        sample_slope(geometry_.cross_level, x) * cross_level_[i];
  }
}

}  // namespace railmodal::ride
