#include "ride/ride_friction_march.hpp"

#include <cmath>
#include <limits>

#include "model/analysis_limits.hpp"
#include "railmodal/errors.hpp"

namespace railmodal::ride {

SampledRideTrack::SampledRideTrack(const TrackUnderWheels& track, double speed, double start)
    : track_(track), speed_(speed), start_(start) {}

// ẇ = V ∂w/∂ξ on the piece; ẅ = 0 inside a piece (the kinks are the breakpoints).
void SampledRideTrack::motion(double t, double piece, Eigen::VectorXd* w, Eigen::VectorXd* dw,
                              Eigen::VectorXd* ddw) const {
  const int m = 3 * track_.inputs();
  w->resize(m);
  dw->resize(m);
  ddw->setZero(m);
  Eigen::Vector3d u, slope;
  for (int i = 0; i < track_.inputs(); ++i) {
    track_.on_segment(i, start_ + speed_ * t, start_ + speed_ * piece, &u, &slope);
    w->segment<3>(3 * i) = u;
    dw->segment<3>(3 * i) = speed_ * slope;
  }
}

// Wheel i passes sample j when start + V t − lag_i = j·Δx. The same formula gives a
// breakpoint each time it is asked, so a time the integration stopped on is never returned
// again.
double SampledRideTrack::next_break(double t) const {
  const double dx = track_.step();
  double next = std::numeric_limits<double>::infinity();
  for (int i = 0; i < track_.inputs(); ++i) {
    const double lag = track_.lag(i);
    double j = std::floor((start_ + speed_ * t - lag) / dx) + 1.0;
    double at = (lag + j * dx - start_) / speed_;
    while (at <= t) at = (lag + (++j) * dx - start_) / speed_;
    if (at > t && at - t > 0.0) next = std::min(next, at);
  }
  return next;
}

FrictionMarch march_with_effects(const LinearSystem& system, const RideStateSpace& model,
                                 const TrackUnderWheels& track, const std::vector<OutputRow>& rows, long count,
                                 double step, double speed, const NonlinearEffects& effects) {
  // The nonlinear simulation holds M, C and K only: no stroke states (s below is (q, v)). A
  // vehicle read from a file is refused at that file, which holds the damper (railmodal ride
  // would otherwise place a library refusal in the scene, whose vehicle key --vehicle replaces).
  try {
    model::refuse_series_dampers(system, "the ride with nonlinear effects");
  } catch (const std::invalid_argument& e) {
    if (system.vehicle.source.empty()) throw;
    throw InputError(system.vehicle.source, 0, 0, e.what());
  }
  const SampledRideTrack sampled(track, speed, track.span());
  SimulationOptions options;
  options.speed = speed;
  options.duration = static_cast<double>(count - 1) * step;
  options.time_step = step;
  // The linear march's start s = 0 is q = 0, q̇ = M⁻¹Bv·w(0) (its v is q̇ − M⁻¹Bv·w): the same
  // start here, so that both paths run the same problem (rest, when no damper stands on the track).
  Eigen::VectorXd w0;
  track.displacement(track.span(), &w0);
  const Eigen::VectorXd v0 = model.mass_inverse * (model.Bv * w0);
  for (int d = 0; d < model.n; ++d)
    if (v0(d) != 0.0) options.initial.push_back({system.dofs[d].label, 0.0, v0(d)});
  FrictionMarch out;
  out.y.resize(count, static_cast<Eigen::Index>(rows.size()));
  const int n = model.n;
  Eigen::VectorXd w, dw, s(2 * n), linear(n);
  long k = 0;
  // The outputs as the linear rows give them on s = (q, q̇ − M⁻¹Bv·w), plus La·(q̈ − q̈_linear):
  // what the nonlinear forces add to an acceleration (displacements and velocities need no
  // more than the state).
  const auto receive = [&](double, const Eigen::VectorXd& y, const Eigen::VectorXd& acceleration) {
    const double leading = track.span() + speed * step * static_cast<double>(k);
    track.displacement(leading, &w);
    track.slope(leading, &dw);
    dw *= speed;
    s.head(n) = y.head(n);
    s.tail(n) = y.tail(n) - model.mass_inverse * (model.Bv * w);
    linear = model.mass_inverse * (-system.stiffness * y.head(n) - system.damping * y.tail(n) + model.Bd * w +
                                   model.Bv * dw);
    const Eigen::VectorXd extra = acceleration - linear;
    for (size_t j = 0; j < rows.size(); ++j) {
      double value = rows[j].Ls.dot(s) + rows[j].Lw.dot(w) + rows[j].Ld.dot(dw);
      if (rows[j].La.size() == n) value += rows[j].La.dot(extra);
      out.y(k, static_cast<Eigen::Index>(j)) = value;
    }
    ++k;
  };
  out.history = simulate::simulate_nonlinear_sampled(system, sampled, options, effects, receive);
  return out;
}

}  // namespace railmodal::ride
