// (b): Welch's PSD of a realised track component against the expected value of the same
// estimate under the synthesis' law. Derivation: docs/ride.md, "Realisations".
#include <cmath>
#include <complex>

#include "ride/realisation_checks.hpp"
#include "spectrum/real_fft.hpp"

namespace railmodal::ride {
namespace {

constexpr double kPi = 3.14159265358979323846;

// D(θ) = Σ_{n<N} e^{−iθn} = e^{−iθ(N−1)/2} sin(Nθ/2)/sin(θ/2).
std::complex<double> dirichlet(double theta, Eigen::Index n) {
  const double half = std::sin(theta / 2.0);
  const double count = static_cast<double>(n);
  if (std::abs(half) < 1e-12) return count;  // θ a multiple of 2π: every term is 1
  return std::polar(1.0, -theta * (count - 1.0) / 2.0) * (std::sin(count * theta / 2.0) / half);
}

// The periodic Hann window's transform: ½D(θ) − ¼D(θ − 2π/N) − ¼D(θ + 2π/N).
double hann_power(double theta, Eigen::Index n) {
  const double shift = 2.0 * kPi / static_cast<double>(n);
  return std::norm(0.5 * dirichlet(theta, n) - 0.25 * dirichlet(theta - shift, n) - 0.25 * dirichlet(theta + shift, n));
}

// Wilson & Hilferty's cube-root approximation of the chi-square quantile ("The distribution
// of chi-square", PNAS 17, 1931): ν(1 − 2/(9ν) + z√(2/(9ν)))³, to 1e-3 for ν ≥ 10.
double chi_square_quantile(double nu, double z) {
  const double a = 2.0 / (9.0 * nu);
  return nu * std::pow(1.0 - a + z * std::sqrt(a), 3);
}

}  // namespace

WelchCheck welch_band_check(const Eigen::VectorXd& profile, double step, const TrackSpectrum& target,
                            Eigen::Index segment) {
  const Eigen::Index n = profile.size(), shift = segment / 2;
  WelchCheck check;
  if (segment < 16 || n < segment) return check;
  Eigen::VectorXd window(segment);
  for (Eigen::Index i = 0; i < segment; ++i) window(i) = 0.5 - 0.5 * std::cos(2.0 * kPi * i / segment);
  const double power = window.squaredNorm();
  // Ŝ_j = Δx |Σ w_n z_n e^{−iθ_j n}|² / (π Σ w²) averaged over the segments: one-sided in
  // rad/m, E Ŝ → S for a smooth S (the kernel's area is 2π Σw²/Δx, and half of a real
  // line's power falls at +Ω).
  spectrum::RealFft fft(segment);
  Eigen::VectorXd estimate = Eigen::VectorXd::Zero(segment / 2 + 1);
  const Eigen::Index segments = (n - segment) / shift + 1;
  for (Eigen::Index s = 0; s < segments; ++s) {
    fft.input() = profile.segment(s * shift, segment).cwiseProduct(window);
    fft.execute();
    estimate += fft.output().cwiseAbs2();
  }
  estimate *= step / (kPi * power * static_cast<double>(segments));
  double overlap = 0.0;
  for (Eigen::Index i = 0; i + shift < segment; ++i) overlap += window(i) * window(i + shift);
  const double rho = std::pow(overlap / power, 2);
  const double k = static_cast<double>(segments);
  check.degrees_of_freedom = 2.0 * k / (1.0 + 2.0 * (1.0 - 1.0 / k) * rho);
  const double lower = chi_square_quantile(check.degrees_of_freedom, -1.959964) / check.degrees_of_freedom;
  const double upper = chi_square_quantile(check.degrees_of_freedom, 1.959964) / check.degrees_of_freedom;

  // E Ŝ_j = Δx/(πΣw²) Σ_k (P_k/2)(|W(θ_j − φ_k)|² + |W(θ_j + φ_k)|²) over the synthesis'
  // lines P_k = S(Ω_k)ΔΩ at φ_k = Ω_kΔx (track_synthesis.cpp's law).
  const double dOmega = 2.0 * kPi / (static_cast<double>(n) * step);
  int outside = 0;
  for (Eigen::Index j = 1; j < segment / 2; ++j) {
    const double omega = 2.0 * kPi * static_cast<double>(j) / (static_cast<double>(segment) * step);
    const double density = target.density(omega);
    if (density <= 0.0) continue;
    const double theta = omega * step;
    double expected = 0.0;
    for (Eigen::Index line = 1; line < n / 2; ++line) {
      const double p = target.density(static_cast<double>(line) * dOmega) * dOmega;
      if (p <= 0.0) continue;
      const double phi = static_cast<double>(line) * dOmega * step;
      expected += 0.5 * p * (hann_power(theta - phi, segment) + hann_power(theta + phi, segment));
    }
    expected *= step / (kPi * power);
    check.leakage_bias = std::max(check.leakage_bias, std::abs(expected / density - 1.0));
    const double ratio = estimate(j) / expected;
    if (ratio < lower || ratio > upper) ++outside;
    ++check.bins;
  }
  if (check.bins > 0) check.fraction_outside = static_cast<double>(outside) / check.bins;
  return check;
}

}  // namespace railmodal::ride
