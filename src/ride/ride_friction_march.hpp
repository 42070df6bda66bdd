// The time-domain ride with the vehicle's nonlinear effects (leaf friction with sticking,
// progressive springs): the sampled track handed to the nonlinear simulation
// (simulate/sampled_track.hpp), and the ride outputs computed from its samples. Method:
// docs/ride.md, "Friction in time".
#pragma once

#include <Eigen/Core>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/simulation.hpp"
#include "ride/ride_state_space.hpp"
#include "ride/track_under_wheels.hpp"
#include "simulate/sampled_track.hpp"

namespace railmodal::ride {

/// The track under the wheels as a function of time, the leading wheel at start + V·t: each
/// wheel's motion is linear between the times it passes two samples, and those times are the
/// breakpoints.
class SampledRideTrack : public simulate::SampledTrack {
 public:
  SampledRideTrack(const TrackUnderWheels& track, double speed, double start);
  void motion(double t, double piece, Eigen::VectorXd* w, Eigen::VectorXd* dw, Eigen::VectorXd* ddw) const override;
  double next_break(double t) const override;
  double shortest_piece() const override { return track_.step() / speed_; }

 private:
  const TrackUnderWheels& track_;
  double speed_, start_;
};

struct FrictionMarch {
  Eigen::MatrixXd y;    ///< the outputs' samples, one column each, `count` rows every `step`
  TimeHistory history;  ///< events, integrator steps and summary (no samples)
};

/// The vehicle with `effects` over the track from rest: samples every `step` s, `count` of
/// them, of the outputs `rows` (with their La terms: an acceleration carries the nonlinear
/// forces), at the nonlinear path's default tolerance (SimulationOptions::tolerance, 1e-10).
/// A series damper is refused: InputError at the vehicle's file (Vehicle::source), or
/// std::invalid_argument for a vehicle built in code.
FrictionMarch march_with_effects(const LinearSystem& system, const RideStateSpace& model,
                                 const TrackUnderWheels& track, const std::vector<OutputRow>& rows, long count,
                                 double step, double speed, const NonlinearEffects& effects);

}  // namespace railmodal::ride
