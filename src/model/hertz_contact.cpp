// Hertz's contact ellipse of a wheel on its rail, solved exactly through the complete elliptic
// integrals (docs/stability.md, "Creep coefficients: Hertz and Kalker", derives it).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "railmodal/wheel_rail.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The complete elliptic integrals K and E of the ellipse whose minor-to-major axis ratio is k
// (k is the complementary modulus: the modulus is e = √(1 − k²), the ellipse's eccentricity),
// in the two combinations Hertz's solution needs, each divided by e² so that neither vanishes
// at the circle:
//   shape = (K − E)/e²,   other = (E/k² − K)/e²,   and K itself.
struct EllipseIntegrals {
  double shape, other, k_integral;
};

EllipseIntegrals ellipse_integrals(double k) {
  const double e2 = (1.0 - k) * (1.0 + k);  // 1 − k² without the cancellation near k = 1
  if (e2 < 1e-4) {
    // Nearly a circle: K − E and E/k² − K lose their digits to cancellation (about 1e-16/e² of
    // each), and Hertz's shape equation needs their ratio minus one, which is ~ e². Their
    // series in e² (from K, E in Abramowitz & Stegun, Handbook of Mathematical Functions,
    // §17.3) to second order are exact to O(e⁶) < 1e-12; the switch at e² = 1e-4 balances the
    // two errors, each below 1e-11 in the curvature ratio.
    return {kPi / 4.0 * (1.0 + e2 * (3.0 / 8.0 + e2 * 15.0 / 64.0)),
            kPi / 4.0 * (1.0 + e2 * (9.0 / 8.0 + e2 * 75.0 / 64.0)),
            kPi / 2.0 * (1.0 + e2 * (1.0 / 4.0 + e2 * 9.0 / 64.0))};
  }
  double K, E;
  if (k < 1e-3) {
    // Very slender: e = √(1 − k²) keeps too few digits of k (and rounds to 1 below k ≈ 1e-8,
    // where K(e) is infinite); the expansions in the complementary modulus (A & S §17.3) are
    // exact to O(k⁴ ln k) < 1e-11 here, better than std::comp_ellint_1 from e.
    const double L = std::log(4.0 / k);
    K = L + k * k / 4.0 * (L - 1.0);
    E = 1.0 + k * k / 2.0 * (L - 0.5);
  } else {
    const double e = std::sqrt(e2);
    K = std::comp_ellint_1(e);
    E = std::comp_ellint_2(e);
  }
  return {(K - E) / e2, (E / (k * k) - K) / e2, K};
}

// Hertz's shape equation: the ratio of the larger to the smaller principal relative curvature
// fixes the axis ratio k = minor/major of the ellipse (Johnson, Contact Mechanics, 1985,
// §3.5, the two curvature relations divided): B/A = (E/k² − K)/(K − E). The ratio falls monotonically from ∞
// (k → 0) to 1 (the circle); solve it for k by bisection on ln k, which converges to the last
// bit whatever the ratio.
double axis_ratio(double curvature_ratio) {
  if (curvature_ratio == 1.0) return 1.0;
  const auto ratio_at = [](double k) {
    const EllipseIntegrals i = ellipse_integrals(k);
    return i.other / i.shape;
  };
  double lo = 0.0;  // ln k where the ratio is too large
  while (ratio_at(std::exp(lo)) < curvature_ratio) {
    lo -= 2.0;
    // k = e^-60 ≈ 1e-26 answers curvature ratios near 1e50: beyond any contact of two bodies.
    if (lo < -60.0) throw std::invalid_argument("hertz_contact: the curvature ratio is too large for point contact");
  }
  double hi = 0.0;  // ln k where the ratio is too small (k = 1: the circle)
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ratio_at(std::exp(mid)) > curvature_ratio ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("hertz_contact: " + message);
}

}  // namespace

HertzContact hertz_contact(const HertzContactInput& input, double rolling_radius) {
  require(input.wheel_load.has_value(), "the wheel load is not set");
  const double load = *input.wheel_load;
  require(std::isfinite(load) && load > 0.0, "the wheel load must be positive and finite, not " + shortest_text(load));
  require(std::isfinite(rolling_radius) && rolling_radius > 0.0,
          "the rolling radius must be positive and finite, not " + shortest_text(rolling_radius));
  require(std::isfinite(input.rail_head_radius) && input.rail_head_radius > 0.0,
          "the rail head radius must be positive and finite, not " + shortest_text(input.rail_head_radius));
  require(std::isfinite(input.youngs_modulus) && input.youngs_modulus > 0.0,
          "Young's modulus must be positive and finite, not " + shortest_text(input.youngs_modulus));
  require(std::isfinite(input.poisson_ratio) && input.poisson_ratio >= 0.0 && input.poisson_ratio <= 0.5,
          "Poisson's ratio must lie in [0, 0.5], not " + shortest_text(input.poisson_ratio));
  double wheel_curvature = 0.0;  // a straight (conical) tread across the wheel
  if (input.wheel_transverse_radius) {
    const double r = *input.wheel_transverse_radius;
    require(std::isfinite(r) && r != 0.0,
            "the wheel's transverse radius must be finite and nonzero, not " + shortest_text(r));
    wheel_curvature = 1.0 / r;
  }

  // Principal relative curvatures (half the sums of the two bodies' curvatures, Johnson §4.2):
  // along the track the wheel's rolling radius against the straight rail, across it the tread
  // (negative when hollow) against the rail head.
  const double along = 0.5 / rolling_radius;
  const double across = 0.5 * (1.0 / input.rail_head_radius + wheel_curvature);
  require(across > 0.0, "a hollow tread of transverse radius " + shortest_text(*input.wheel_transverse_radius) +
                            " m conforms to or wraps the rail head of radius " +
                            shortest_text(input.rail_head_radius) +
                            " m: no point contact (Hertz needs |radius| > the rail head radius)");

  // Contact modulus of two bodies of one steel: 1/E* = 2(1 − ν²)/E.
  const double nu = input.poisson_ratio;
  const double e_star = input.youngs_modulus / (2.0 * (1.0 - nu * nu));

  // The ellipse's long axis lies along the direction of the smaller curvature.
  const double smaller = std::min(along, across), larger = std::max(along, across);
  const double k = axis_ratio(larger / smaller);
  const EllipseIntegrals i = ellipse_integrals(k);
  // With P = (2/3)π p0 a b (the load the semi-ellipsoidal pressure carries) the smaller
  // curvature gives the major semi-axis: a³ = 3P(K − E)/(2π E* A e²) (Johnson §3.5);
  // the approach is δ = p0 b K / E* (the same section). With k = 1 they are the circle's
  // a³ = 3PR/(4E*) and δ = a²/R.
  const double major = std::cbrt(3.0 * load * i.shape / (2.0 * kPi * e_star * smaller));
  const double minor = k * major;
  const double p0 = 3.0 * load / (2.0 * kPi * major * minor);

  HertzContact contact;
  contact.a = along <= across ? major : minor;  // a runs along the track
  contact.b = along <= across ? minor : major;
  contact.max_pressure = p0;
  contact.approach = p0 * minor * i.k_integral / e_star;
  return contact;
}

}  // namespace railmodal
