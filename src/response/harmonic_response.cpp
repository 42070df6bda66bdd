// Steady harmonic response: direct solve and modal superposition.
#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "railmodal/errors.hpp"
#include "railmodal/response.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
// ω² within this fraction of λ counts as exactly at the natural frequency: critical speeds
// are computed as V = Λf/k, which returns ω² to within a few ulps.
constexpr double kAtResonance = 1e-9;

double modal_damping(const LinearSystem& system, const Mode& mode) {
  return mode.shape.dot(system.damping * mode.shape);
}

// The first undamped mode at ω that the load drives, or 0.
int undamped_resonance(const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
                       double omega) {
  const double scale = load.norm();
  if (!(scale > 0.0)) return 0;
  const double w2 = omega * omega;
  for (const Mode& mode : modes.modes) {
    if (mode.kind != ModeKind::oscillatory) continue;
    if (std::abs(mode.eigenvalue - w2) > kAtResonance * mode.eigenvalue) continue;
    if (std::abs(modal_damping(system, mode)) > 0.0) continue;
    const double driven = std::abs(mode.shape.cast<std::complex<double>>().dot(load));
    if (driven > 1e-12 * scale * mode.shape.norm()) return mode.index;
  }
  return 0;
}

void check_sizes(const LinearSystem& system, const ModalResult& modes, const Eigen::VectorXcd& load,
                 double frequency_hz) {
  if (load.size() != system.size() || static_cast<int>(modes.dofs.size()) != system.size())
    throw std::invalid_argument("harmonic response: load, modes and system sizes differ");
  if (!(frequency_hz >= 0.0) || !std::isfinite(frequency_hz))
    throw std::invalid_argument("harmonic response: frequency must be finite and non-negative");
}

}  // namespace

const char* to_string(ResponseQuantity quantity) {
  switch (quantity) {
    case ResponseQuantity::displacement: return "displacement";
    case ResponseQuantity::velocity: return "velocity";
    case ResponseQuantity::acceleration: return "acceleration";
  }
  return "?";
}

double response_amplitude(const HarmonicResponse& response, int dof, ResponseQuantity quantity) {
  const double omega = kTwoPi * response.frequency_hz;
  const double x = std::abs(response.displacement(dof));
  switch (quantity) {
    case ResponseQuantity::displacement: return x;
    case ResponseQuantity::velocity: return omega * x;
    case ResponseQuantity::acceleration: return omega * omega * x;
  }
  return x;
}

HarmonicResponse harmonic_response(const LinearSystem& system, const ModalResult& modes,
                                   const Eigen::VectorXcd& load, double frequency_hz) {
  check_sizes(system, modes, load, frequency_hz);
  HarmonicResponse out;
  out.frequency_hz = frequency_hz;
  const double omega = kTwoPi * frequency_hz;
  out.resonant_mode = undamped_resonance(system, modes, load, omega);
  out.displacement = Eigen::VectorXcd::Zero(system.size());
  if (out.resonant_mode > 0) {
    out.unbounded = true;
    return out;
  }
  using Matrix = Eigen::MatrixXcd;
  const std::complex<double> i(0.0, 1.0);
  const Matrix D = (system.stiffness - omega * omega * system.mass).cast<std::complex<double>>() +
                   i * omega * system.damping.cast<std::complex<double>>();
  Eigen::PartialPivLU<Matrix> lu(D);
  out.displacement = lu.solve(load);
  // A load on a direction nothing restrains (a rigid-body mode at ω = 0) has no steady state.
  const double residual = (D * out.displacement - load).norm();
  if (!out.displacement.allFinite() || !(residual <= 1e-8 * (load.norm() + D.norm() * out.displacement.norm())))
    throw NumericalError("harmonic response at " + std::to_string(frequency_hz) +
                         " Hz: the dynamic stiffness is singular for this load (an unrestrained direction?)");
  return out;
}

HarmonicResponse modal_harmonic_response(const LinearSystem& system, const ModalResult& modes,
                                         const Eigen::VectorXcd& load, double frequency_hz, int mode_count) {
  check_sizes(system, modes, load, frequency_hz);
  HarmonicResponse out;
  out.frequency_hz = frequency_hz;
  const double omega = kTwoPi * frequency_hz;
  out.resonant_mode = undamped_resonance(system, modes, load, omega);
  out.displacement = Eigen::VectorXcd::Zero(system.size());
  if (out.resonant_mode > 0) {
    out.unbounded = true;
    return out;
  }
  const int count = mode_count > 0 ? std::min<int>(mode_count, static_cast<int>(modes.modes.size()))
                                   : static_cast<int>(modes.modes.size());
  const std::complex<double> i(0.0, 1.0);
  for (int j = 0; j < count; ++j) {
    const Mode& mode = modes.modes[j];
    const Eigen::VectorXcd phi = mode.shape.cast<std::complex<double>>();
    const std::complex<double> denominator =
        mode.eigenvalue - omega * omega + i * omega * modal_damping(system, mode);
    if (std::abs(denominator) == 0.0)
      throw NumericalError("modal response: mode " + std::to_string(mode.index) +
                           " has no stiffness at this frequency (rigid-body mode at 0 Hz)");
    out.displacement += phi * (phi.dot(load) / denominator);
  }
  // Massless DOFs follow their own loads statically: x_m += K_mm⁻¹ Q_m.
  if (!modes.condensed.empty()) {
    std::vector<int> m;
    for (const auto& label : modes.condensed) m.push_back(system.index_of(label));
    Eigen::MatrixXd Kmm(m.size(), m.size());
    Eigen::VectorXcd Qm(m.size());
    for (size_t a = 0; a < m.size(); ++a) {
      Qm(a) = load(m[a]);
      for (size_t b = 0; b < m.size(); ++b) Kmm(a, b) = system.stiffness(m[a], m[b]);
    }
    const Eigen::VectorXcd xm = Kmm.cast<std::complex<double>>().partialPivLu().solve(Qm);
    for (size_t a = 0; a < m.size(); ++a) out.displacement(m[a]) += xm(a);
  }
  return out;
}

}  // namespace railmodal
