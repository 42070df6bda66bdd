// Damping ratios of roots, Brent's root finder and the golden-section dip search.
#include "stability/damping_search.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <utility>

namespace railmodal::stability {

namespace {
// The rigid-body band, |λ| ≤ 1e-7·scale. A free motion's zero root need not be simple: at zero
// conicity a vehicle on its wheelsets yawed as a whole by ψ runs off laterally at V·ψ without
// creep, so the zero root of its lateral translation has a Jordan chain of length 2, and a
// double defective root moved by the eigen-solve's backward error ε·‖A‖ splits into a pair of
// size √ε·scale ≈ 1.5e-8·scale, real (one of them positive) or complex (Lidskii's perturbation
// theory of a Jordan block: size δ^(1/k) for a chain of length k). The Manchester coach at λ = 0
// (user audit 2026-11-28, F1) puts it at 0.5e-9 to 1.8e-8 of the scale over 10–500 km/h; 1e-9
// caught only the simple roots, and the split pair read as a divergence and a hunting at 12.58 km/h.
// 1e-7 is 5.6 times the largest split seen and 17 times below the coach's kinematic root at the
// 1 mm/s floor of min_speed and λ = 0.05 (2πV/Λ = 3.8e-4 1/s, the scale 222 1/s there). That root
// goes as V·√λ: at that floor a conicity under about 2e-4 reads as neutral, which it nearly is.
constexpr double kRigidTolerance = 1e-7;
constexpr double kGrowthTolerance = 1e-11;
}  // namespace

RootDamping root_damping(std::complex<double> value, double scale, bool raw) {
  const double magnitude = std::abs(value);
  if (magnitude <= kRigidTolerance * scale) return {0.0, true};
  if (!raw && std::abs(value.real()) <= kGrowthTolerance * scale) return {0.0, false};
  return {-value.real() / magnitude, false};
}

double root_scale(const Eigen::VectorXcd& values) {
  // Real roots are left out: as V → 0 the creep roots run off to −∞ as 1/V on the real axis, and
  // a scale they set would put every suspension mode inside the bands (at V = 1e-6 m/s a car
  // body's roll at 6 rad/s is 1e-12 of a creep root at 1e13/s). The oscillatory roots keep
  // the scale of the suspension; only when there are none do the real roots set it.
  double complex_scale = 0.0, scale = 0.0;
  for (int i = 0; i < values.size(); ++i) {
    scale = std::max(scale, std::abs(values(i)));
    if (values(i).imag() != 0.0) complex_scale = std::max(complex_scale, std::abs(values(i)));
  }
  return complex_scale > 0.0 ? complex_scale : scale;
}

LeastDamped least_damped(const Eigen::VectorXcd& values, bool raw) {
  const double scale = root_scale(values);
  LeastDamped out;
  for (int i = 0; i < values.size(); ++i) {
    const RootDamping d = root_damping(values(i), scale, raw);
    if (d.rigid) continue;
    if (out.root < 0 || d.zeta < out.zeta) out = {d.zeta, i};
  }
  return out;
}

BracketedRoot bracketed_root(const std::function<double(double)>& f, double a, double b, double fa, double fb,
                             double relative_tolerance) {
  BracketedRoot out;
  if (fa == 0.0) return {a, 0};
  if (fb == 0.0) return {b, 0};
  // b is the best estimate, a the previous one, c the other end of the bracket [b, c].
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) c = a, fc = fa, d = e = b - a;
    if (std::abs(fc) < std::abs(fb)) {
      a = b, b = c, c = a;
      fa = fb, fb = fc, fc = fa;
    }
    // Half the allowed bracket (the bracket |c − b| ends at most relative_tolerance·|b|), and
    // never below round-off.
    const double tol =
        std::max(0.5 * relative_tolerance * std::abs(b), 4.0 * std::numeric_limits<double>::epsilon() * std::abs(b));
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) break;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {  // secant
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {  // inverse quadratic interpolation
        const double r = fb / fc, t = fa / fc;
        p = s * (2.0 * m * t * (t - r) - (b - a) * (r - 1.0));
        q = (t - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0)
        q = -q;
      else
        p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m, e = m;
      }
    } else {
      d = m, e = m;
    }
    a = b, fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
    ++out.evaluations;
  }
  out.x = b;
  return out;
}

Minimum dip_minimum(const std::function<double(double)>& f, double a, double b, double relative_tolerance) {
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - r * (b - a), x2 = a + r * (b - a);
  double f1 = f(x1), f2 = f(x2);
  Minimum out{x1, f1, 2};
  while (f1 >= 0.0 && f2 >= 0.0 && (b - a) > relative_tolerance * b) {
    if (f1 <= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - r * (b - a);
      f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + r * (b - a);
      f2 = f(x2);
    }
    ++out.evaluations;
  }
  if (f1 <= f2)
    out.x = x1, out.value = f1;
  else
    out.x = x2, out.value = f2;
  return out;
}

}  // namespace railmodal::stability
