// Periodic orbits of an autonomous vector field ẋ = f(p, x) by shooting: the initial state x0,
// the period T and the parameter p are the unknowns of φ(x0, T, p) − x0 = 0, a phase condition
// and one more condition (a fixed amplitude, or a pseudo-arclength step); Newton's method with the
// Jacobian by finite differences of the flow, whose x0 block is the monodromy matrix, and the
// orbit's Floquet multipliers from it (docs/stability.md, "Continuation of the limit cycles").
// Generic: the hunting equations and the Hopf normal form of the tests go through the same code.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace railmodal::stability {

/// ẋ = f(p, x): `dx` is resized by the caller to x's size.
using VectorField = std::function<void(double parameter, const Eigen::VectorXd& x, Eigen::VectorXd* dx)>;

/// The orbit problem: the field and the linear functionals that pin the orbit down.
struct OrbitProblem {
  VectorField field;
  /// The phase condition phase·x0 = 0 (for hunting: the watched wheelset's lateral velocity, so
  /// that t = 0 is a peak of its displacement).
  Eigen::RowVectorXd phase;
  /// The watched coordinate: amplitude·x is the displacement whose largest |·| over the orbit is
  /// the orbit's amplitude.
  Eigen::RowVectorXd amplitude;
  /// A typical magnitude of each state at unit amplitude of the watched coordinate (> 0): the
  /// Newton residual and the finite-difference steps are measured in x/scale.
  Eigen::VectorXd scale;
  double amplitude_scale = 1.0;  ///< the unit of the amplitude in the arclength norm
  double parameter_scale = 1.0;  ///< the unit of the parameter in the arclength norm
  /// Fixed Dormand–Prince steps over one period: the flow map is then a smooth function of x0,
  /// T and p wherever f is smooth (an adaptive step would make it jump), so its finite
  /// differences are derivatives.
  int steps_per_period = 1000;
  /// ‖residual‖∞ that counts as converged: the closure φ − x0 of each state over its scale and
  /// over the orbit's amplitude (the guess's |amplitude·x0|, at least a thousandth of
  /// amplitude_scale), the phase alike, the condition in units of amplitude_scale.
  double newton_tolerance = 1e-9;
  int newton_iterations = 10;      ///< at most this many corrections
};

/// One converged (or failed) shooting solve.
struct Orbit {
  Eigen::VectorXd start;      ///< x0 at the peak of the watched coordinate
  double period = 0.0;        ///< T
  double parameter = 0.0;     ///< p
  double amplitude = 0.0;     ///< the largest |amplitude·x| over the fixed steps of one period
  double start_value = 0.0;   ///< amplitude·x0: the arclength coordinate
  /// Floquet multipliers: the trivial one (along the flow) first, then the others (set_floquet).
  Eigen::VectorXcd multipliers;
  /// The largest |μ| once the trivial multiplier (along the flow f(x0)) is deflated (set_floquet).
  double largest_multiplier = 0.0;
  bool stable = false;              ///< largest_multiplier < 1
  double residual = 0.0;            ///< ‖residual‖∞ (scaled) at the returned point
  int iterations = 0;
  bool converged = false;
};

/// The extra condition beside closure and phase.
struct OrbitCondition {
  /// Fixed amplitude: amplitude·x0 = target (a natural-parameter solve). Otherwise
  /// pseudo-arclength: ((amplitude·x0 − from_value)/amplitude_scale)·tangent_value +
  /// ((p − from_parameter)/parameter_scale)·tangent_parameter = step.
  bool fixed_amplitude = true;
  double target = 0.0;
  double from_value = 0.0, from_parameter = 0.0;
  double tangent_value = 0.0, tangent_parameter = 0.0, step = 0.0;
};

/// The state after one period T at parameter p from x0 (fixed steps); the largest |amplitude·x|
/// over the steps in *peak when given.
Eigen::VectorXd orbit_flow(const OrbitProblem& problem, const Eigen::VectorXd& x0, double period, double parameter,
                           double* peak = nullptr);

/// The Floquet multipliers of `monodromy` with the trivial one set aside by deflating the flow
/// direction `flow` (the field at x0 in the monodromy's coordinates; M·f(x0) = f(x0): a shift along
/// an autonomous orbit comes back shifted). In an orthonormal basis whose first vector is f, M's
/// first column is (1, 0, …): the trivial multiplier, and the others are the eigenvalues of the
/// block that remains once that row and column are dropped (the monodromy of the motions across
/// the orbit). orbit->multipliers: the trivial one first (1 to the differences' accuracy), then
/// those; largest_multiplier the largest |μ| of those; stable its < 1. Not the multiplier nearest
/// 1 set aside from M's eigenvalues: near a fold a second multiplier nears 1, and where the period
/// changes along the branch the two form a near-Jordan block, which splits the differences' error
/// ε into a pair 1 ± √ε; dropping the coupling keeps the error ε.
void set_floquet(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& flow, Orbit* orbit);

/// Newton from `guess` (its start, period and parameter): closure, phase and `condition`. Counts
/// the flows integrated in *flows. Never throws for a failure to converge: `converged` is false
/// and `residual` says how far it got; a non-finite state ends the iteration the same way.
Orbit solve_orbit(const OrbitProblem& problem, const Orbit& guess, const OrbitCondition& condition, long* flows);

}  // namespace railmodal::stability
