// The nonlinear simulation over a track given as samples instead of harmonics: the hook the
// time-domain ride (src/ride/ride_simulation.cpp) runs leaf friction and progressive springs
// through. The track under each wheel is smooth between breakpoints (the kinks of the linearly
// interpolated geometry, where its slope and so the wheel's velocity jump); the integration ends
// a step on every breakpoint, so that each Dormand–Prince step sees a smooth right-hand side and
// its error control holds.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "railmodal/linear_system.hpp"
#include "railmodal/simulation.hpp"

namespace railmodal::simulate {

class SampledTrack {
 public:
  virtual ~SampledTrack() = default;
  /// The displacements, velocities and accelerations of every track input at time t, stacked
  /// as in LinearSystem::track_inputs (3 per input: longitudinal, lateral, vertical), each on
  /// the smooth piece that holds the time `piece` (extended to t: the integrator asks for the
  /// piece of its step, and at a breakpoint for the piece on either side).
  virtual void motion(double t, double piece, Eigen::VectorXd* w, Eigen::VectorXd* dw,
                      Eigen::VectorXd* ddw) const = 0;
  /// The first breakpoint after t (strictly), s; infinity when there is none.
  virtual double next_break(double t) const = 0;
  /// A time shorter than every piece, s: t ± a small part of it picks the piece on either side.
  virtual double shortest_piece() const = 0;
};

/// Receives each output sample: time, state y = (q, q̇) and the acceleration q̈ (the mean of
/// the two sides where the sample falls on a breakpoint).
using SampleReceiver = std::function<void(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& acceleration)>;

/// simulate_nonlinear with the loads of `track` (Bd·w + Bv·ẇ) in place of harmonic sources and
/// each element standing on the track following its track input's vertical motion, from rest
/// at t = 0, samples every options.time_step to options.duration given to `receive`. At a
/// breakpoint a stuck leaf on the track slides (its track's velocity jumps, its upper end's
/// cannot: no finite friction force holds it) and a sliding one may reverse. Returns the
/// events, step count and summary (no samples). Throws as simulate_nonlinear does.
TimeHistory simulate_nonlinear_sampled(const LinearSystem& system, const SampledTrack& track,
                                       const SimulationOptions& options, const NonlinearEffects& effects,
                                       const SampleReceiver& receive);

}  // namespace railmodal::simulate
