// From wheel inputs and point forces to the generalised load on the degrees of freedom.
#include <cmath>
#include <stdexcept>

#include "model/rigid_body.hpp"
#include "railmodal/excitation.hpp"

namespace railmodal {

HarmonicLoad ExcitationSource::load(const LinearSystem& system, double speed, int harmonic) const {
  if (!(speed > 0.0) || !std::isfinite(speed))
    throw std::invalid_argument(kind() + ": the speed must be positive and finite");
  if (harmonic < 1) throw std::invalid_argument(kind() + ": harmonics count from 1");
  return load_at(system, speed, harmonic);
}

Eigen::VectorXcd generalized_load(const LinearSystem& system, const HarmonicLoad& load) {
  constexpr double kTwoPi = 6.28318530717958647692;
  const int n = system.size();
  const double omega = kTwoPi * load.frequency_hz;
  const std::complex<double> i(0.0, 1.0);
  Eigen::VectorXcd Q = Eigen::VectorXcd::Zero(n);
  for (const WheelInput& w : load.wheels) {
    if (w.track_input < 0 || w.track_input >= static_cast<int>(system.track_inputs.size()))
      throw std::invalid_argument("generalized_load: no such track input");
    const TrackInput& t = system.track_inputs[w.track_input];
    const Eigen::Vector3cd u = w.amplitude * std::exp(-i * omega * w.delay_s);
    Q += t.load_per_displacement.cast<std::complex<double>>() * u +
         i * omega * (t.load_per_velocity.cast<std::complex<double>>() * u);
  }
  for (const PointForce& f : load.forces) {
    if (f.body < 0 || f.body >= static_cast<int>(system.vehicle.bodies.size()))
      throw std::invalid_argument("generalized_load: no such body");
    const model::PointMap G = model::point_map(system.vehicle.bodies[f.body], f.point);
    for (int d = 0; d < n; ++d)
      if (system.dofs[d].body == f.body)
        Q(d) += G.col(static_cast<int>(system.dofs[d].motion)).cast<std::complex<double>>().dot(f.amplitude);
  }
  return Q;
}

}  // namespace railmodal
