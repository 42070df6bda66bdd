// Exact time stepping of the ride state space (ride_state_space.hpp) over the linearly
// interpolated track. The step h is Δx/(mV) for a whole m, so the samples of the track pass
// every wheel at times on a grid of period m·h with a fixed offset δ_i in [0, h) per wheel:
// within each step the input of wheel i is linear on [0, δ_i] and on [δ_i, h], and the
// first-order hold over both pieces (Van Loan's integrals at δ_i and h − δ_i) is exact.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "ride/ride_state_space.hpp"
#include "ride/track_under_wheels.hpp"

namespace railmodal::ride {

class RideMarch {
 public:
  /// `start`: where the leading wheel is at t = 0, m; `step`: h, s, with step·speed dividing
  /// the geometry's step (the caller rounds it so).
  RideMarch(const RideStateSpace& model, const TrackUnderWheels& track, double speed, double step, double start);
  double step() const { return h_; }
  /// The leading wheel's track position at step k.
  double leading(long k) const;
  /// s(t_k) → s(t_{k+1}).
  void advance(long k, Eigen::VectorXd* s);
  /// Φ(h)^count by squaring: the state transition over `count` steps.
  Eigen::MatrixXd transition_power(long count) const;

 private:
  const TrackUnderWheels& track_;
  double speed_, h_, start_;
  Eigen::MatrixXd Phi_;
  std::vector<Eigen::MatrixXd> P0_, Pd_, P1_;  // per wheel, 2n × 3
  std::vector<double> offsets_;                // δ_i, s
  Eigen::VectorXd next_;
};

}  // namespace railmodal::ride
