// Shooting for periodic orbits: fixed-step Dormand–Prince flow, Newton with a finite-difference
// Jacobian (its x0 block is the monodromy matrix), Floquet multipliers (docs/stability.md,
// "Continuation of the limit cycles").
#include "stability/periodic_orbits.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "simulate/dormand_prince.hpp"

namespace railmodal::stability {
namespace {

// Forward differences of the flow with this step relative to the state's own scale: the fixed-step
// flow is reproduced to rounding (1e-16 relative), so 1e-7 leaves 1e-9 of rounding in a column and
// a truncation error of the same order: Newton converges regardless (a Jacobian good to 1e-6 only
// slows the last iteration), and the multipliers are good to about 1e-7.
constexpr double kDifferenceStep = 1e-7;
// Backtracking: a Newton step that raises the residual is halved this many times at most (a
// flange crossing that moves by a step can make the full step overshoot).
constexpr int kHalvings = 4;

struct Unknowns {
  Eigen::VectorXd xi;  // x0 / scale
  double period = 0.0, parameter = 0.0;
};

class Shooting {
 public:
  // `size`: the orbit's amplitude, so that the closure and the phase are measured relative to it
  // (an absolute tolerance would accept the linear guess of a 0.1 mm orbit as it stands).
  Shooting(const OrbitProblem& p, const OrbitCondition& c, double size, long* flows) : p_(p), c_(c), flows_(flows) {
    n_ = static_cast<int>(p.scale.size());
    phase_norm_ = (p.phase.cwiseAbs().transpose().cwiseProduct(p.scale)).sum() * size;
    size_ = size;
  }
  int size() const { return n_ + 2; }
  Eigen::VectorXd state(const Unknowns& u) const { return u.xi.cwiseProduct(p_.scale); }

  // Closure (scaled), phase, condition; the peak over the period in *peak.
  Eigen::VectorXd residual(const Unknowns& u, double* peak) const {
    const Eigen::VectorXd x0 = state(u);
    const Eigen::VectorXd x1 = orbit_flow(p_, x0, u.period, u.parameter, peak);
    ++*flows_;
    Eigen::VectorXd r(size());
    r.head(n_) = (x1 - x0).cwiseQuotient(p_.scale) / size_;
    r[n_] = p_.phase.dot(x0) / phase_norm_;
    const double value = p_.amplitude.dot(x0);
    if (c_.fixed_amplitude) {
      r[n_ + 1] = (value - c_.target) / p_.amplitude_scale;
    } else {
      r[n_ + 1] = (value - c_.from_value) / p_.amplitude_scale * c_.tangent_value +
                  (u.parameter - c_.from_parameter) / p_.parameter_scale * c_.tangent_parameter - c_.step;
    }
    return r;
  }

  Eigen::MatrixXd jacobian(const Unknowns& u, const Eigen::VectorXd& r0) const {
    Eigen::MatrixXd j(size(), size());
    for (int k = 0; k < size(); ++k) {
      Unknowns v = u;
      double h;
      if (k < n_) {
        h = kDifferenceStep * size_;
        v.xi[k] += h;
      } else if (k == n_) {
        h = kDifferenceStep * u.period;
        v.period += h;
      } else {
        h = kDifferenceStep * std::max(std::abs(u.parameter), p_.parameter_scale);
        v.parameter += h;
      }
      j.col(k) = (residual(v, nullptr) - r0) / h;
    }
    return j;
  }

  int n_ = 0;

 private:
  const OrbitProblem& p_;
  const OrbitCondition& c_;
  long* flows_;
  double phase_norm_ = 1.0;
  double size_ = 1.0;
};

bool finite(const Eigen::VectorXd& v) { return v.allFinite(); }

}  // namespace

void set_floquet(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& flow, Orbit* orbit) {
  const Eigen::Index n = monodromy.rows();
  // An orthonormal basis whose first vector is ±f/|f| (a Householder reflection).
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(flow).householderQ() * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd rotated = q.transpose() * monodromy * q;
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(rotated.bottomRightCorner(n - 1, n - 1), false);
  orbit->multipliers.resize(n);
  orbit->multipliers[0] = rotated(0, 0);
  orbit->multipliers.tail(n - 1) = eigen.eigenvalues();
  orbit->largest_multiplier = orbit->multipliers.tail(n - 1).cwiseAbs().maxCoeff();
  orbit->stable = orbit->largest_multiplier < 1.0;
}

Eigen::VectorXd orbit_flow(const OrbitProblem& problem, const Eigen::VectorXd& x0, double period, double parameter,
                           double* peak) {
  const auto rhs = [&](double, const Eigen::VectorXd& x, Eigen::VectorXd* dx) {
    dx->resize(x.size());
    problem.field(parameter, x, dx);
  };
  const double h = period / problem.steps_per_period;
  Eigen::VectorXd x = x0;
  double largest = std::abs(problem.amplitude.dot(x));
  for (int i = 0; i < problem.steps_per_period; ++i) {
    x = simulate::dormand_prince_step(rhs, i * h, x, h).y;
    largest = std::max(largest, std::abs(problem.amplitude.dot(x)));
  }
  if (peak) *peak = largest;
  return x;
}

Orbit solve_orbit(const OrbitProblem& problem, const Orbit& guess, const OrbitCondition& condition, long* flows) {
  const double size = std::max(std::abs(problem.amplitude.dot(guess.start)), 1e-3 * problem.amplitude_scale);
  Shooting shooting(problem, condition, size, flows);
  Unknowns u{guess.start.cwiseQuotient(problem.scale), guess.period, guess.parameter};
  Orbit orbit = guess;
  orbit.converged = false;
  double peak = 0.0;
  Eigen::VectorXd r = shooting.residual(u, &peak);
  double norm = finite(r) ? r.lpNorm<Eigen::Infinity>() : HUGE_VAL;
  int iteration = 0;
  for (; norm > problem.newton_tolerance && iteration < problem.newton_iterations && std::isfinite(norm);
       ++iteration) {
    const Eigen::MatrixXd j = shooting.jacobian(u, r);
    const Eigen::VectorXd step = j.fullPivLu().solve(-r);
    if (!finite(step)) break;
    double fraction = 1.0;
    Unknowns next;
    Eigen::VectorXd next_r;
    double next_norm = HUGE_VAL, next_peak = 0.0;
    for (int halving = 0; halving <= kHalvings; ++halving, fraction /= 2.0) {
      next = {u.xi + fraction * step.head(shooting.n_), u.period + fraction * step[shooting.n_],
              u.parameter + fraction * step[shooting.n_ + 1]};
      if (!(next.period > 0.0)) continue;
      next_r = shooting.residual(next, &next_peak);
      next_norm = finite(next_r) ? next_r.lpNorm<Eigen::Infinity>() : HUGE_VAL;
      if (next_norm < norm) break;
    }
    if (!(next_norm < norm)) break;  // no step lowers the residual: Newton has failed here
    u = next;
    r = next_r;
    norm = next_norm;
    peak = next_peak;
  }
  orbit.start = shooting.state(u);
  orbit.period = u.period;
  orbit.parameter = u.parameter;
  orbit.amplitude = peak;
  orbit.start_value = problem.amplitude.dot(orbit.start);
  orbit.residual = norm;
  orbit.iterations = iteration;
  orbit.converged = std::isfinite(norm) && norm <= problem.newton_tolerance;
  if (orbit.converged) {
    // The monodromy of the scaled state ξ = S⁻¹x, S⁻¹MS (similar to M: the same multipliers), from
    // the x0 block of the Jacobian; the flow direction in the same coordinates, S⁻¹f(x0).
    const int n = shooting.n_;
    const Eigen::MatrixXd jacobian = shooting.jacobian(u, r);
    const Eigen::MatrixXd monodromy = size * jacobian.topLeftCorner(n, n) + Eigen::MatrixXd::Identity(n, n);
    Eigen::VectorXd flow(n);
    problem.field(u.parameter, orbit.start, &flow);
    set_floquet(monodromy, flow.cwiseQuotient(problem.scale), &orbit);
  }
  return orbit;
}

}  // namespace railmodal::stability
