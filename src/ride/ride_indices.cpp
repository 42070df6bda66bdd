// Ride indices from a spectrum: integrals over the grid and the χ² estimate of the P95.
//
// The P95 estimate. EN 12299 takes the RMS of the weighted acceleration a_w over windows of
// T = 5 s and the 95th percentile of those values. For a stationary Gaussian a_w of one-sided
// PSD S, the window's mean square m = (1/T)∫₀ᵀ a_w² dt has E[m] = σ² = ∫S df and, for T long
// against the correlation time, Var[m] ≈ (2/T)∫R(τ)² dτ = (1/T)∫₀^∞ S(f)² df (R the
// autocorrelation; Parseval with the two-sided density S/2). Bendat & Piersol (Random Data,
// 4th ed., 2010, §8.2.2) write the same as the normalised random error of a mean-square
// estimate, ε² = 1/(B_s T), with the statistical bandwidth B_s = (∫S)²/∫S². Matching the two
// moments of m to σ²χ²_ν/ν (Satterthwaite, Biometrics Bulletin 2(6), 1946, the approximation
// Welch's effective degrees of freedom rest on), Var = 2σ⁴/ν gives ν = 2TB_s, and
// P95(√m) = σ√(χ²_{ν,0.95}/ν). A narrow-band response (small B_s) spreads the windows' RMS
// widely; a broad one (large ν) gives P95 → σ.
#include "ride/ride_indices.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace railmodal::ride {

namespace {

// P(a, x) by its power series γ(a,x) = x^a e^−x Σ x^n/(a(a+1)…(a+n)) (DLMF 8.7.1 after 8.2.1),
// good for x < a + 1.
double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 100000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < 1e-16 * std::abs(sum)) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) = 1 − P by the continued fraction of Γ(a, x) (DLMF 8.9.2), evaluated by the modified
// Lentz method, good for x ≥ a + 1.
double gamma_q_fraction(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int n = 1; n < 100000; ++n) {
    const double an = -n * (n - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double regularized_gamma_p(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) throw std::invalid_argument("regularized_gamma_p: needs a > 0 and x ≥ 0");
  if (x == 0.0) return 0.0;
  return x < a + 1.0 ? gamma_p_series(a, x) : 1.0 - gamma_q_fraction(a, x);
}

double chi_square_quantile(double p, double nu) {
  if (!(p > 0.0 && p < 1.0) || !(nu > 0.0) || !std::isfinite(nu))
    throw std::invalid_argument("chi_square_quantile: needs 0 < p < 1 and a positive finite ν");
  // Bracket, then bisect on P(ν/2, x/2) = p: monotone in x, and 200 halvings reach round-off.
  double lo = 0.0, hi = nu + 10.0 * std::sqrt(2.0 * nu) + 10.0;
  while (regularized_gamma_p(0.5 * nu, 0.5 * hi) < p) hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (regularized_gamma_p(0.5 * nu, 0.5 * mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double rms_quantile(double variance, double integral_of_square, double window, double p) {
  if (!(variance > 0.0) || !(integral_of_square > 0.0)) return 0.0;
  const double nu = 2.0 * window * variance * variance / integral_of_square;
  // Beyond 1e7 degrees of freedom χ²_ν/ν is within 1e-3 of 1 at the 95th percentile and its
  // quantile is the normal one to 1e-7 (Wilson–Hilferty): the series would take √ν terms.
  if (nu > 1e7) {
    const double z = 1.6448536269514722;  // the standard normal's 95th percentile
    const double c = 2.0 / (9.0 * nu);
    const double ratio = std::pow(1.0 - c + z * std::sqrt(c), 3.0);
    return std::sqrt(variance * ratio);
  }
  return std::sqrt(variance * chi_square_quantile(p, nu) / nu);
}

double integral(const ComponentPower& p, const std::vector<BandWeights>& bands, const Eigen::VectorXd& weight,
                bool coarse) {
  double sum = 0.0;
  for (size_t c = 0; c < p.power.size(); ++c) {
    const Eigen::VectorXd& w = coarse ? bands[c].coarse_weights : bands[c].weights;
    sum += weight.size() ? (w.array() * weight.array() * p.power[c].array()).sum() : w.dot(p.power[c]);
  }
  return sum;
}

double integral_of_square(const ComponentPower& p, const std::vector<BandWeights>& bands,
                          const Eigen::VectorXd& grid, const Eigen::VectorXd& weight) {
  double sum = 0.0;
  for (Eigen::Index k = 0; k + 1 < grid.size(); ++k) {
    double left = 0.0, right = 0.0;
    for (size_t c = 0; c < p.power.size(); ++c)
      if (bands[c].inside[k]) {
        left += p.power[c](k);
        right += p.power[c](k + 1);
      }
    if (weight.size()) {
      left *= weight(k);
      right *= weight(k + 1);
    }
    sum += 0.5 * (grid(k + 1) - grid(k)) * (left * left + right * right);
  }
  return sum;
}

}  // namespace railmodal::ride
