// The three rules for the vertical counterweight (docs/driving_gear.md, "Balancing").
#include "gear/vertical_counterweight.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace railmodal::gear {

namespace {

std::vector<double> samples_of(const std::function<double(double)>& f, int steps) {
  std::vector<double> s(steps);
  for (int i = 0; i < steps; ++i) s[i] = f(2.0 * M_PI * i / steps);
  return s;
}

// The sines and cosines of the steps, computed once for the searches.
struct Steps {
  std::vector<double> sin, cos;
  explicit Steps(int n) : sin(n), cos(n) {
    for (int i = 0; i < n; ++i) {
      sin[i] = std::sin(2.0 * M_PI * i / n);
      cos[i] = std::cos(2.0 * M_PI * i / n);
    }
  }
};

double residual_of(const std::vector<double>& y, const Steps& steps, double a, double b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) worst = std::max(worst, std::abs(y[i] + a * steps.sin[i] + b * steps.cos[i]));
  return worst;
}

// Minimum of a convex function on [lo, hi] by golden sections (to 1e-12 of the interval).
template <class F>
double golden_minimum(F f, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 60; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return (lo + hi) / 2.0;
}

SineForce least_squares(const std::vector<double>& y) {
  // Cancel the first harmonic: a = −(2/n)Σ y sin θ, b = −(2/n)Σ y cos θ.
  const int n = static_cast<int>(y.size());
  SineForce f;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n;
    f.a -= 2.0 / n * y[i] * std::sin(t);
    f.b -= 2.0 / n * y[i] * std::cos(t);
  }
  return f;
}

SineForce minimax(const std::vector<double>& y) {
  // max_i |y_i + a s_i + b c_i| is convex in (a, b) (a maximum of absolute values of affine
  // functions), and so is its minimum over b as a function of a: nested golden sections find the
  // minimum. Every |a|, |b| beyond 2·max|y| leaves a residual above max|y| (the residual at 0).
  const double span = 2.0 * std::abs(*std::max_element(y.begin(), y.end(), [](double p, double q) { return std::abs(p) < std::abs(q); }));
  if (span == 0.0) return {};  // nothing to balance
  const Steps steps(static_cast<int>(y.size()));
  const auto best_b = [&](double a) {
    return golden_minimum([&](double b) { return residual_of(y, steps, a, b); }, -span, span);
  };
  SineForce f;
  f.a = golden_minimum([&](double a) { return residual_of(y, steps, a, best_b(a)); }, -span, span);
  f.b = best_b(f.a);
  return f;
}

SineForce book_rule(const std::function<double(double)>& upward, const std::vector<double>& y) {
  // Zhdanov (76)–(77): amplitude |Y| with the wheel's crank at 90°; the counterweight's force
  // Q sin(θ + γ) at its most negative (θ + γ = 270°) where Y peaks upward. The peak is found on the
  // steps and refined by golden sections within a step on each side.
  const int n = static_cast<int>(y.size());
  const int i = static_cast<int>(std::max_element(y.begin(), y.end()) - y.begin());
  const double step = 2.0 * M_PI / n;
  const double peak = golden_minimum([&](double t) { return -upward(t); }, (i - 1) * step, (i + 1) * step);
  const double amplitude = std::abs(upward(M_PI / 2));
  const double gamma = 1.5 * M_PI - peak;
  return {amplitude * std::cos(gamma), amplitude * std::sin(gamma)};
}

}  // namespace

double largest_residual(const std::function<double(double)>& upward, const SineForce& force, int steps) {
  return residual_of(samples_of(upward, steps), Steps(steps), force.a, force.b);
}

SineForce size_vertical_counterweight(const std::function<double(double)>& upward, VerticalRule rule, int steps) {
  const std::vector<double> y = samples_of(upward, steps);
  switch (rule) {
    case VerticalRule::least_squares:
      return least_squares(y);
    case VerticalRule::minimax:
      return minimax(y);
    case VerticalRule::book:
      break;
  }
  return book_rule(upward, y);
}

}  // namespace railmodal::gear
