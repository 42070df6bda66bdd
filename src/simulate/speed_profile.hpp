// The vehicle's speed along a simulated run: what the integrator drives the track with, and
// what the history's writers report beside the samples of a ramp.
#pragma once

namespace railmodal::simulate {

/// The run's speed: constant, or ramping linearly (V = V₀ + a·t, x = V₀t + a·t²/2).
struct SpeedProfile {
  double initial = 0.0;       ///< V₀, m/s
  double acceleration = 0.0;  ///< a, m/s²
  double speed(double t) const { return initial + acceleration * t; }
  double distance(double t) const { return (initial + 0.5 * acceleration * t) * t; }
};

/// A run at `speed` (m/s) that ramps linearly to `final_speed` over `duration` (s) when
/// final_speed > 0 (SimulationOptions, SimulationSpec), and otherwise holds its speed.
inline SpeedProfile speed_profile(double speed, double final_speed, double duration) {
  SpeedProfile profile;
  profile.initial = speed;
  if (final_speed > 0.0) profile.acceleration = (final_speed - speed) / duration;
  return profile;
}

}  // namespace railmodal::simulate
