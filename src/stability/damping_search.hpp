// The least-damped root at a speed, and the speeds where its damping ratio reaches a value.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace railmodal::stability {

/// ζ = −Re λ/|λ| of one root, the scale being root_scale() at that speed (the largest |λ| of the
/// oscillatory roots: not of the creep roots that run off to −∞ as V → 0):
///  - |λ| ≤ 1e-7·scale is a rigid-body root (a free motion nothing restrains: a wheelset at zero
///    conicity without gravitational stiffness): neutral, ζ = 0, and left out of the
///    least-damped search (it neither grows nor decays); 1e-7 and not ε-small because such a
///    zero root can be defective, and round-off splits a double one by √ε (damping_search.cpp);
///  - |Re λ| ≤ 1e-11·scale is round-off of an undamped root: ζ = 0 exactly, so that round-off
///    never makes an undamped mode unstable (the eigenvalues of a balanced matrix carry errors
///    of order ε·scale; 1e-11 leaves five orders of headroom);
///  - a real root gives ζ = −sign λ: +1 for a decaying root, −1 for a divergent one (growth
///    without oscillation is an instability as much as a negative damping ratio).
/// Never NaN. `raw`: without the round-off band (ζ = −Re λ/|λ| however small Re λ is), for the
/// refinement of a crossing, whose accuracy the band would otherwise limit to about
/// 1e-11·scale/|d Re λ/dV| (7e-6 m/s for a free wheelset hunting from 1.4 m/s, where the creep
/// roots make the scale 1e4 times the hunting root).
struct RootDamping {
  double zeta = 0.0;
  bool rigid = false;
};
RootDamping root_damping(std::complex<double> value, double scale, bool raw = false);

/// The largest |λ| of the complex roots of a set (the largest of all when none is complex). The
/// real roots are left out because the creep roots are real and grow as 1/V at low speed: with
/// them in the scale, every suspension mode fell into the rigid-body band below about 1e-6 m/s.
double root_scale(const Eigen::VectorXcd& values);

/// The smallest ζ over the roots that are not rigid-body, and which root it is (−1 when every
/// root is rigid-body: ζ = 0 then).
struct LeastDamped {
  double zeta = 0.0;
  int root = -1;
};
LeastDamped least_damped(const Eigen::VectorXcd& values, bool raw = false);

/// A root of f in [a, b] (f(a), f(b) of opposite signs or one zero) by Brent's method (Brent,
/// Algorithms for Minimization without Derivatives, 1973, ch. 4: inverse quadratic and secant
/// steps inside a bisection bracket), stopped when the bracket is at most `relative_tolerance`
/// times the speed. `evaluations` counts the calls of f.
struct BracketedRoot {
  double x = 0.0;
  int evaluations = 0;
};
BracketedRoot bracketed_root(const std::function<double(double)>& f, double a, double b, double fa, double fb,
                             double relative_tolerance);

/// The minimum of f on [a, b] by golden-section search, stopped early as soon as f < 0 is found
/// (the caller only asks whether a dip reaches below zero) or when the bracket is below
/// `relative_tolerance`·b.
struct Minimum {
  double x = 0.0;
  double value = 0.0;
  int evaluations = 0;
};
Minimum dip_minimum(const std::function<double(double)>& f, double a, double b, double relative_tolerance);

}  // namespace railmodal::stability
