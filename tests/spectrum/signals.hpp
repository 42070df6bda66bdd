// Test signals for the spectrum tests: tones, sums of tones and damped free responses.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace railmodal::test {

/// n samples at fs of amplitude·sin(2πft + phase).
inline Eigen::VectorXd tone(Eigen::Index n, double fs, double f, double amplitude, double phase = 0.0) {
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i)
    x(i) = amplitude * std::sin(2.0 * 3.14159265358979323846 * f * static_cast<double>(i) / fs + phase);
  return x;
}

/// n samples at fs of e^{−ζωt}·cos(ω_d t), ω = 2πf, ω_d = ω√(1 − ζ²): the free decay of a
/// viscously damped oscillator (the small ζω/ω_d·sin term of a release from rest left out).
inline Eigen::VectorXd damped_free_response(Eigen::Index n, double fs, double f, double zeta) {
  const double omega = 2.0 * 3.14159265358979323846 * f, omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    x(i) = std::exp(-zeta * omega * t) * std::cos(omega_d * t);
  }
  return x;
}

}  // namespace railmodal::test
