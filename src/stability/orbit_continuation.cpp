// Hopf point, pseudo-arclength continuation of the periodic orbits and fold refinement
// (docs/stability.md, "Continuation of the limit cycles"; the method is the textbook one:
// Yu. A. Kuznetsov, Elements of Applied Bifurcation Theory, 3rd ed. 2004, ch. 10 "Numerical
// analysis of bifurcations" (pseudo-arclength continuation; shooting for cycles with a phase
// condition; the monodromy matrix); R. Seydel, Practical Bifurcation and Stability Analysis,
// 3rd ed. 2010, the chapters on continuation and on periodic solutions).
#include "stability/orbit_continuation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shortest_text.hpp"

namespace railmodal::stability {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The Jacobian at the equilibrium by central differences of this size in every state: the
// saturation's departure from linear is of the relative order of the creep force over μN, far
// below 1e-6 at such a displacement; at x = 0 rounding is relative to f itself.
constexpr double kEquilibriumStep = 1e-10;
// Fold refinement: golden-section steps until the amplitude bracket is below this fraction of
// amplitude_scale (0.1 µm for hunting: the speed is flat at the fold, so its error is far
// smaller), at most kRefinements solves (0.618^40 of the first bracket).
constexpr double kFoldAmplitudeTolerance = 1e-4;
constexpr int kRefinements = 40;
// Step control: a corrector this quick lengthens the next step, one this slow shortens it.
constexpr int kQuickNewton = 3;
constexpr int kSlowNewton = 6;

Eigen::MatrixXd equilibrium_jacobian(const VectorField& field, int n, double parameter) {
  Eigen::MatrixXd j(n, n);
  Eigen::VectorXd plus(n), minus(n);
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    x[k] = kEquilibriumStep;
    field(parameter, x, &plus);
    x[k] = -kEquilibriumStep;
    field(parameter, x, &minus);
    j.col(k) = (plus - minus) / (2.0 * kEquilibriumStep);
  }
  return j;
}

// The rightmost eigenvalue with a positive imaginary part (a real one cannot give a Hopf point)
// and the largest real part of all.
struct Rightmost {
  double growth = -HUGE_VAL;  // the largest real part of any eigenvalue
  double oscillatory = -HUGE_VAL;
  Eigen::Index index = -1;
};

Rightmost rightmost(const Eigen::EigenSolver<Eigen::MatrixXd>& eigen) {
  Rightmost r;
  const Eigen::VectorXcd& values = eigen.eigenvalues();
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    r.growth = std::max(r.growth, values[i].real());
    if (values[i].imag() > 0.0 && values[i].real() > r.oscillatory) {
      r.oscillatory = values[i].real();
      r.index = i;
    }
  }
  return r;
}

double growth_of_oscillation(const VectorField& field, int n, double p) {
  Eigen::EigenSolver<Eigen::MatrixXd> eigen(equilibrium_jacobian(field, n, p), false);
  return rightmost(eigen).oscillatory;
}

// The arclength coordinates of an orbit.
Eigen::Vector2d projected(const OrbitProblem& p, const Orbit& o) {
  return {o.start_value / p.amplitude_scale, o.parameter / p.parameter_scale};
}

Orbit interpolate(const Orbit& a, const Orbit& b, double s) {
  Orbit o = a;
  o.start = a.start + s * (b.start - a.start);
  o.period = a.period + s * (b.period - a.period);
  o.parameter = a.parameter + s * (b.parameter - a.parameter);
  return o;
}

// The fold between orbits a and c, b between them with the extreme parameter: the extremum of
// p(A), A = amplitude·x0, by golden-section search with fixed-amplitude solves. Golden section
// rather than parabolic steps because p(A) need not be smooth there: the flange's dead zone makes
// the branch turn sharply once the amplitude reaches the clearance (p(A) is then only C¹), where a
// parabola through three points misplaces the vertex.
Orbit refine_fold(const OrbitProblem& problem, const Orbit& a, const Orbit& b, const Orbit& c, long* flows) {
  // +1: the fold is a minimum of p (the branch came down and goes up again); −1: a maximum.
  const double sense = b.parameter < a.parameter ? 1.0 : -1.0;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  std::vector<Orbit> known{a, b, c};
  const auto solve_at = [&](double value, Orbit* out) {
    // The guess: the known orbit nearest in amplitude, scaled to it.
    const Orbit* near = &known.front();
    for (const Orbit& o : known)
      if (std::abs(o.start_value - value) < std::abs(near->start_value - value)) near = &o;
    Orbit guess = *near;
    guess.start *= value / near->start_value;
    OrbitCondition at;
    at.target = value;
    *out = solve_orbit(problem, guess, at, flows);
    if (out->converged) known.push_back(*out);
    return out->converged;
  };
  double low = std::min(a.start_value, c.start_value), high = std::max(a.start_value, c.start_value);
  Orbit best = b, inner, outer;
  double x1 = high - golden * (high - low), x2 = low + golden * (high - low);
  if (!solve_at(x1, &inner) || !solve_at(x2, &outer)) return best;
  for (int i = 0; i < kRefinements && high - low > kFoldAmplitudeTolerance * problem.amplitude_scale; ++i) {
    if (sense * inner.parameter < sense * outer.parameter) {
      high = x2;
      x2 = x1;
      outer = inner;
      x1 = high - golden * (high - low);
      if (!solve_at(x1, &inner)) break;
    } else {
      low = x1;
      x1 = x2;
      inner = outer;
      x2 = low + golden * (high - low);
      if (!solve_at(x2, &outer)) break;
    }
  }
  for (const Orbit& o : known)
    if (sense * o.parameter < sense * best.parameter) best = o;
  return best;
}

}  // namespace

std::optional<HopfPoint> find_hopf(const VectorField& field, int n, double low, double high, int scan_points) {
  double previous_p = low;
  double previous = growth_of_oscillation(field, n, low);
  for (int i = 1; i <= scan_points; ++i) {
    const double p = low + (high - low) * i / scan_points;
    const double g = growth_of_oscillation(field, n, p);
    if (previous < 0.0 && g >= 0.0) {
      double a = previous_p, b = p;
      while (b - a > 1e-12 * std::max(1.0, std::abs(b))) {
        const double middle = 0.5 * (a + b);
        (growth_of_oscillation(field, n, middle) < 0.0 ? a : b) = middle;
      }
      HopfPoint h;
      h.parameter = 0.5 * (a + b);
      Eigen::EigenSolver<Eigen::MatrixXd> eigen(equilibrium_jacobian(field, n, h.parameter), true);
      Rightmost r = rightmost(eigen);
      if (r.index < 0) {  // the pair turned real at the midpoint: b, where it grows, has it
        h.parameter = b;
        eigen.compute(equilibrium_jacobian(field, n, b), true);
        r = rightmost(eigen);
      }
      h.frequency = eigen.eigenvalues()[r.index].imag();
      h.vector = eigen.eigenvectors().col(r.index);
      return h;
    }
    previous = g;
    previous_p = p;
  }
  return std::nullopt;
}

bool turns_at(const std::vector<double>& p, std::size_t m) {
  if (m < 1 || m + 1 >= p.size()) return false;
  return (p[m + 1] - p[m]) * (p[m] - p[m - 1]) < 0.0;
}

std::optional<std::size_t> lowest_exchange_turn(const std::vector<double>& p, const std::vector<bool>& stable) {
  if (stable.size() != p.size()) throw std::invalid_argument("lowest_exchange_turn: one stability per orbit");
  std::optional<std::size_t> lowest;
  for (std::size_t m = 1; m + 1 < p.size(); ++m)
    if (turns_at(p, m) && stable[m - 1] != stable[m + 1] && (!lowest || p[m] < p[*lowest])) lowest = m;
  return lowest;
}

double continuation_progress(const ContinuationSettings& settings, std::size_t orbits, double amplitude) {
  const double by_points = static_cast<double>(orbits) / settings.max_points;
  const double by_amplitude = std::abs(amplitude) / settings.max_amplitude;
  return std::clamp(std::max(by_points, by_amplitude), 0.0, 0.99);
}

namespace {

// continue_from_hopf up to its last progress call (1, once the branch ended at any of its returns).
OrbitBranch follow_branch(const OrbitProblem& problem, const HopfPoint& hopf, const ContinuationSettings& s) {
  OrbitBranch branch;
  double done = 0.0;  // the progress shown: the largest estimate yet, so that it never goes back
  const auto one_more = [&](const Orbit& o) {
    branch.orbits.push_back(o);
    if (!s.progress) return;
    done = std::max(done, continuation_progress(s, branch.orbits.size(), o.start_value));
    s.progress(done);
  };
  // The linear orbit through the peak of the watched coordinate: phase·Re(v·e^{iθ}) = 0.
  const double real_part = problem.phase.dot(hopf.vector.real());
  const double imaginary_part = problem.phase.dot(hopf.vector.imag());
  const double theta = std::atan2(real_part, imaginary_part);
  Eigen::VectorXd shape = (hopf.vector * std::complex<double>(std::cos(theta), std::sin(theta))).real();
  const double watched = problem.amplitude.dot(shape);
  if (!(std::abs(watched) > 1e-12 * shape.cwiseAbs().maxCoeff())) {
    // The watched coordinate does not move in the Hopf mode: no amplitude to continue in.
    branch.end = BranchEnd::newton_failed;
    branch.failure = "the watched coordinate does not move in the Hopf mode";
    return branch;
  }
  shape /= watched;
  Orbit guess;
  guess.start = s.start_amplitude * shape;
  guess.period = 2.0 * kPi / hopf.frequency;
  guess.parameter = hopf.parameter;
  for (const double factor : {1.0, 2.0}) {
    OrbitCondition fixed;
    fixed.target = factor * s.start_amplitude;
    if (factor == 2.0) guess.start *= 2.0;
    const Orbit o = solve_orbit(problem, guess, fixed, &branch.flows);
    if (!o.converged) {
      branch.end = BranchEnd::newton_failed;
      branch.failure = "no orbit of amplitude " + shortest_text(fixed.target, 6) + " near the Hopf point (residual " +
                       shortest_text(o.residual, 6) + ")";
      return branch;
    }
    one_more(o);
    guess = o;
  }
  double step = s.initial_step;
  while (true) {
    const Orbit& last = branch.orbits.back();
    const Orbit& before = branch.orbits[branch.orbits.size() - 2];
    if (std::abs(last.start_value) > s.max_amplitude) {
      branch.end = BranchEnd::amplitude_reached;
      break;
    }
    if (last.parameter < s.parameter_low || last.parameter > s.parameter_high) {
      branch.end = BranchEnd::parameter_range_left;
      break;
    }
    if (static_cast<int>(branch.orbits.size()) >= s.max_points) {
      branch.end = BranchEnd::point_limit;
      break;
    }
    const Eigen::Vector2d secant = projected(problem, last) - projected(problem, before);
    const Eigen::Vector2d tangent = secant.normalized();
    OrbitCondition arc;
    arc.fixed_amplitude = false;
    arc.from_value = last.start_value;
    arc.from_parameter = last.parameter;
    arc.tangent_value = tangent[0];
    arc.tangent_parameter = tangent[1];
    Orbit next;
    while (true) {
      arc.step = step;
      // The predictor: along the secant of the whole unknown vector, to the step's length.
      const Orbit predicted = interpolate(last, before, -step / secant.norm());
      next = solve_orbit(problem, predicted, arc, &branch.flows);
      if (next.converged) break;
      step /= 2.0;
      if (step < s.min_step) {
        branch.end = BranchEnd::newton_failed;
        branch.failure = "the corrector failed at parameter " + shortest_text(last.parameter, 6) + ", amplitude " +
                         shortest_text(last.start_value, 6) + " even with a step of " + shortest_text(step, 6) +
                         " (residual " + shortest_text(next.residual, 6) + ")";
        return branch;
      }
    }
    if (next.iterations <= kQuickNewton) step = std::min(1.5 * step, s.max_step);
    if (next.iterations >= kSlowNewton) step = std::max(0.7 * step, s.min_step);
    one_more(next);
    const std::size_t k = branch.orbits.size() - 1;
    const double turn = (branch.orbits[k].parameter - branch.orbits[k - 1].parameter) *
                        (branch.orbits[k - 1].parameter - branch.orbits[k - 2].parameter);
    if (turn < 0.0) {  // the condition of turns_at(·, k − 1), on the orbits as they come
      branch.folds.push_back(
          refine_fold(problem, branch.orbits[k - 2], branch.orbits[k - 1], branch.orbits[k], &branch.flows));
      branch.fold_orbits.push_back(k - 1);
    }
  }
  return branch;
}

}  // namespace

OrbitBranch continue_from_hopf(const OrbitProblem& problem, const HopfPoint& hopf, const ContinuationSettings& s) {
  OrbitBranch branch = follow_branch(problem, hopf, s);
  if (s.progress) s.progress(1.0);
  return branch;
}

}  // namespace railmodal::stability
