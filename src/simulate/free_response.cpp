// A linear scene's free response by mode, and what a Hann spectrum shows of a decaying line.
#include "simulate/free_response.hpp"

#include <cmath>
#include <complex>

#include "railmodal/response.hpp"

namespace railmodal::simulate {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// The initial state less the forced steady state's at t = 0: x₀ − Σ Re X_n, v₀ − Σ Re(iω_n X_n).
void free_start(const LinearSystem& system, const ModalResult& modes,
                const std::vector<const ExcitationSource*>& sources, double speed,
                const std::vector<InitialCondition>& initial, Eigen::VectorXd* x0, Eigen::VectorXd* v0) {
  *x0 = Eigen::VectorXd::Zero(system.size());
  *v0 = Eigen::VectorXd::Zero(system.size());
  for (const InitialCondition& ic : initial) {
    const int d = system.index_of(ic.dof);
    if (d >= 0) (*x0)(d) = ic.displacement, (*v0)(d) = ic.velocity;
  }
  for (const ExcitationSource* source : sources) {
    double norm2 = 0.0;  // the source's whole load, as harmonic_response judges "drives"
    for (int k = 1; k <= source->harmonic_count(); ++k)
      norm2 += generalized_load(system, source->load(system, speed, k)).squaredNorm();
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      const HarmonicLoad load = source->load(system, speed, k);
      const Eigen::VectorXcd Q = generalized_load(system, load);
      if (Q.norm() == 0.0) continue;
      const HarmonicResponse x = harmonic_response(system, modes, Q, load.frequency_hz, std::sqrt(norm2));
      const std::complex<double> i_omega(0.0, kTwoPi * load.frequency_hz);
      *x0 -= x.displacement.real();
      *v0 -= (x.displacement * i_omega).real();
    }
  }
}

}  // namespace

std::vector<FreeMode> free_modes(const LinearSystem& system, const ModalResult& modes, const DampedModalResult* damped,
                                 const std::vector<const ExcitationSource*>& sources, double speed,
                                 const std::vector<InitialCondition>& initial) {
  Eigen::VectorXd x0, v0;
  free_start(system, modes, sources, speed, initial, &x0, &v0);
  const Eigen::VectorXd Mx = system.mass * x0, Mv = system.mass * v0;
  std::vector<FreeMode> out(modes.modes.size());
  for (size_t r = 0; r < modes.modes.size(); ++r) {
    const Mode& mode = modes.modes[r];
    if (mode.kind != ModeKind::oscillatory) continue;
    FreeMode& f = out[r];
    f.damped_hz = mode.frequency_hz;
    if (damped)
      for (const DampedMode& d : damped->modes)
        if (d.undamped_mode == mode.index && d.damped_frequency_hz && d.damping_ratio) {
          f.damped_hz = *d.damped_frequency_hz;
          f.damping_ratio = *d.damping_ratio;
          f.decay_rate = d.decay_rate;
        }
    const double eta = mode.shape.dot(Mx), eta_dot = mode.shape.dot(Mv);
    const double omega_d = kTwoPi * f.damped_hz;
    f.initial_amplitude = omega_d > 0.0 ? std::hypot(eta, (eta_dot + f.decay_rate * eta) / omega_d) : std::abs(eta);
  }
  return out;
}

double hann_decay_gain(double decay_rate, double duration) {
  const double sT = decay_rate * duration;
  if (!(sT > 1e-9)) return 1.0;  // steady within round-off: (1 − e^{−x})/x → 1
  const double omega = kTwoPi / duration;
  return -std::expm1(-sT) / sT * omega * omega / (decay_rate * decay_rate + omega * omega);
}

}  // namespace railmodal::simulate
