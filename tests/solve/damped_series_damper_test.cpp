// Damped modes with series dampers (a dashpot c in series with a spring k, each carried by the
// stroke of its dashpot): one mass against the closed-form roots of its cubic, the limit of a
// stiff series spring (the plain damper), and the coach with yaw dampers against the hunting
// analysis' first-order system without creep.
#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <vector>

#include "railmodal/wheel_rail.hpp"
#include "stability/first_order_system.hpp"
#include "series_damper_coach.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

using cd = std::complex<double>;

// One mass m bouncing on a spring K, held to the ground besides by a damper c with a spring k in
// series: m ẍ + K x + f = 0, f + (c/k) ḟ = c ẋ.
LinearSystem mass_with_series_damper(double m, double K, double c, double k) {
  LinearSystem s;
  Body b;
  b.name = "mass";
  b.mass = m;
  b.inertia = {1.0, 1.0, 1.0};
  s.vehicle.bodies.push_back(b);
  Element damper;
  damper.name = "damper";
  damper.upper = "mass";
  s.vehicle.elements.push_back(damper);
  s.dofs.push_back({"mass.bounce", 0, Motion::bounce});
  s.mass = Eigen::MatrixXd::Constant(1, 1, m);
  s.damping = Eigen::MatrixXd::Zero(1, 1);
  s.stiffness = Eigen::MatrixXd::Constant(1, 1, K);
  s.gravity_stiffness = Eigen::MatrixXd::Zero(1, 1);
  s.series_dampers.push_back({0, Motion::bounce, Eigen::RowVectorXd::Ones(1), c, k});
  return s;
}

// The roots of a3 λ³ + a2 λ² + a1 λ + a0 by Cardano's formula: λ = t − a2/(3a3) with
// t³ + p t + q = 0, t = u + v, u³ = −q/2 + √(q²/4 + p³/27), uv = −p/3, over the three cube roots.
std::vector<cd> cubic_roots(double a3, double a2, double a1, double a0) {
  const double b = a2 / a3, c = a1 / a3, d = a0 / a3;
  const double p = c - b * b / 3.0, q = 2.0 * b * b * b / 27.0 - b * c / 3.0 + d;
  const cd u3 = -q / 2.0 + std::sqrt(cd(q * q / 4.0 + p * p * p / 27.0));
  const cd u = std::pow(u3, 1.0 / 3.0);
  const cd turn = std::polar(1.0, 2.0 * kPi / 3.0);
  std::vector<cd> roots;
  for (cd w : {cd(1.0), turn, turn * turn}) {
    const cd t = u * w - p / (3.0 * u * w);
    roots.push_back(t - b / 3.0);
  }
  return roots;
}

std::vector<cd> all_eigenvalues(const DampedModalResult& r) {
  std::vector<cd> out;
  for (const DampedMode& m : r.modes) out.insert(out.end(), m.eigenvalues.begin(), m.eigenvalues.end());
  return out;
}

// The largest distance from each of `ours` to the nearest unused one of `theirs` (the same count).
double largest_mismatch(const std::vector<cd>& ours, const std::vector<cd>& theirs) {
  EXPECT_EQ(ours.size(), theirs.size());
  std::vector<bool> used(theirs.size(), false);
  double worst = 0.0;
  for (const cd& l : ours) {
    size_t best = theirs.size();
    for (size_t i = 0; i < theirs.size(); ++i)
      if (!used[i] && (best == theirs.size() || std::abs(theirs[i] - l) < std::abs(theirs[best] - l))) best = i;
    if (best == theirs.size()) return INFINITY;
    used[best] = true;
    worst = std::max(worst, std::abs(theirs[best] - l));
  }
  return worst;
}

bool is_relaxation(const DampedMode& m) { return m.name.rfind("series damper relaxation (", 0) == 0; }

// m λ³ + (m k/c) λ² + (K + k) λ + K k/c = 0: (mλ² + K)(λ + k/c) + kλ = 0, the mass's equation
// with the damper force f = k c λ/(k + c λ) x (its Laplace transform).
TEST(DampedSeriesDamper, OneMassHasTheRootsOfItsCubic) {
  constexpr double m = 1000.0, K = 4e5, c = 2e4, k = 1e6;  // ω₀ = 20 rad/s, k/c = 50 /s
  const DampedModalResult r = solve_damped_modes(mass_with_series_damper(m, K, c, k));
  const std::vector<cd> expected = cubic_roots(m, m * k / c, K + k, K * k / c);
  double scale = 0.0;
  for (const cd& l : expected) scale = std::max(scale, std::abs(l));
  // Both sides are backward stable to ε ≈ 2e-16 of a matrix or polynomial of norm ~ scale, and
  // the three roots are simple and apart (condition ~ 10): 1e-12 of the largest root leaves
  // two orders of headroom.
  EXPECT_LT(largest_mismatch(all_eigenvalues(r), expected), 1e-12 * scale);
  EXPECT_LT(r.max_residual, 1e-12);
  ASSERT_EQ(r.modes.size(), 2u);
  ASSERT_EQ(r.dofs.size(), 2u);
  EXPECT_EQ(r.dofs[1].label, "damper.bounce stroke");
  EXPECT_EQ(r.first_order, std::vector<std::string>{"damper.bounce stroke"});
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("series dampers: in"), std::string::npos);
  // The pair is the mass's bounce, the real root the damper's relaxation, reported as such: a
  // first-order mode, no frequency, its decay rate the cubic's real root (k/c = 50 /s for the
  // damper alone, the mass held; the mass moving with it changes that).
  const DampedMode& bounce = r.modes[0].kind == DampedModeKind::underdamped ? r.modes[0] : r.modes[1];
  const DampedMode& relaxation = r.modes[0].kind == DampedModeKind::underdamped ? r.modes[1] : r.modes[0];
  EXPECT_EQ(bounce.kind, DampedModeKind::underdamped);
  EXPECT_EQ(bounce.undamped_mode, 1);
  EXPECT_EQ(relaxation.kind, DampedModeKind::first_order);
  EXPECT_EQ(relaxation.name, "series damper relaxation (damper)");
  EXPECT_EQ(relaxation.undamped_mode, 0);
  EXPECT_FALSE(relaxation.damped_frequency_hz);
  ASSERT_EQ(relaxation.eigenvalues.size(), 1u);
  EXPECT_EQ(relaxation.eigenvalues[0].imag(), 0.0);
  EXPECT_DOUBLE_EQ(relaxation.decay_rate, -relaxation.eigenvalues[0].real());
  const auto real_root = std::min_element(expected.begin(), expected.end(),
                                          [](cd a, cd b) { return std::abs(a.imag()) < std::abs(b.imag()); });
  EXPECT_NEAR(relaxation.decay_rate, -real_root->real(), 1e-12 * scale);
  // Its shape is mostly the stroke (scaled to 1 at its largest entry).
  EXPECT_NEAR(std::abs(relaxation.shape(1)), 1.0, 1e-12);
}

// As k → ∞ the series spring is rigid and the element a plain damper c along its stretch:
// C + c·stretchᵀstretch. The Maxwell damper's force per unit stretch rate, c/(1 + cλ/k), differs
// from c by δc(λ) = c/(1 + cλ/k) − c ≈ −c²λ/k, so each root of the plain system moves, to first
// order, by δλ = w·δA(λ)·v (v, w its right and left eigenvectors of the plain state matrix,
// w·v = 1, δA = [[0, 0], [0, −M⁻¹Σ δc(λ) sᵀs]]). Checked: first order in 1/k (a tenfold k divides
// the difference by about ten, measured 0.103 and 0.108; 0.2 allowed) and, at the stiffest k
// (k × 1e5), the roots where the prediction puts them: the differences (32, 3.3, 0.36 /s at
// k × 1e3, 1e4, 1e5; the largest root 251 /s) are the predicted shifts (largest 36.6, 3.63,
// 0.363 /s) less a remainder of second order in cλ/k (8.5 % and 1.0 % of the largest shift at
// 1e4 and 1e5: tenfold k, 8.4 times less): within 5 % of the largest shift at the stiffest.
TEST(DampedSeriesDamper, AStiffSeriesSpringIsThePlainDamper) {
  const LinearSystem coach = assemble(coach_with_yaw_dampers(), DofSet::lateral);
  ASSERT_EQ(coach.series_dampers.size(), 4u);  // two a bogie, both stretched by the bogie's yaw
  LinearSystem plain = coach;
  plain.series_dampers.clear();
  for (const SeriesDamperRow& d : coach.series_dampers)
    plain.damping += d.damping * d.stretch.transpose() * d.stretch;
  const DampedModalResult reference = solve_damped_modes(plain);
  const std::vector<cd> expected = all_eigenvalues(reference);
  // The plain system's state matrix, its eigenvectors V and the left ones, the rows of V⁻¹.
  const int n = coach.size();
  const Eigen::MatrixXd mass_inverse = plain.mass.inverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -mass_inverse * plain.stiffness;
  A.bottomRightCorner(n, n) = -mass_inverse * plain.damping;
  const Eigen::EigenSolver<Eigen::MatrixXd> plain_state(A);
  const Eigen::MatrixXcd V = plain_state.eigenvectors(), W = V.inverse();
  std::vector<double> mismatch;
  for (double factor : {1e3, 1e4, 1e5}) {
    LinearSystem stiff = coach;
    for (SeriesDamperRow& d : stiff.series_dampers) d.stiffness *= factor;
    const DampedModalResult r = solve_damped_modes(stiff);
    std::vector<cd> ours;
    for (const DampedMode& m : r.modes)
      if (!is_relaxation(m)) ours.insert(ours.end(), m.eigenvalues.begin(), m.eigenvalues.end());
    mismatch.push_back(largest_mismatch(ours, expected));
    RecordProperty("mismatch_" + std::to_string(static_cast<int>(std::log10(factor))), std::to_string(mismatch.back()));
    if (factor < 1e5) continue;
    std::vector<cd> predicted;
    double largest_shift = 0.0;
    for (Eigen::Index j = 0; j < V.cols(); ++j) {
      const cd l = plain_state.eigenvalues()(j);
      Eigen::MatrixXcd change = Eigen::MatrixXcd::Zero(n, n);  // Σ δc(λ) sᵀs
      for (const SeriesDamperRow& d : stiff.series_dampers)
        change += (d.damping / (1.0 + d.damping * l / d.stiffness) - d.damping) *
                  (d.stretch.transpose() * d.stretch).cast<cd>();
      const cd shift = -(W.row(j).tail(n) * mass_inverse.cast<cd>() * change * V.col(j).tail(n))(0);
      predicted.push_back(l + shift);
      largest_shift = std::max(largest_shift, std::abs(shift));
    }
    EXPECT_NEAR(mismatch.back(), largest_shift, 0.05 * largest_shift);
    EXPECT_LT(largest_mismatch(ours, predicted), 0.05 * largest_shift);
  }
  EXPECT_LT(mismatch[1], 0.2 * mismatch[0]);
  EXPECT_LT(mismatch[2], 0.2 * mismatch[1]);
}

// The coach with yaw dampers, lateral: the same roots as the hunting analysis' first-order
// system (force states, stability/first_order_system.hpp) with the wheel–rail contact set to
// zero, its zero-creep limit; there the speed enters nowhere. Both are balanced Hessenberg QR of
// matrices of norm ~ the largest root: 1e-9 of it, as the coach's test against the plain state
// matrix (damped_modal_test.cpp).
TEST(DampedSeriesDamper, CoachWithYawDampersHasTheStabilityRootsWithoutCreep) {
  const LinearSystem coach = assemble(coach_with_yaw_dampers(), DofSet::lateral);
  const int n = coach.size(), d = static_cast<int>(coach.series_dampers.size());
  ASSERT_GT(d, 0);
  const DampedModalResult r = solve_damped_modes(coach);
  EXPECT_LT(r.max_residual, 1e-12);
  EXPECT_TRUE(r.stable);
  ContactMatrices none;
  none.creep_damping = none.gyroscopic = none.stiffness = Eigen::MatrixXd::Zero(n, n);
  const stability::SpeedRoots roots =
      stability::solve_at_speed(stability::FirstOrderSystem(coach, none), 1.0, false);
  const std::vector<cd> expected(roots.values.data(), roots.values.data() + roots.values.size());
  ASSERT_EQ(static_cast<int>(expected.size()), 2 * n + d);
  double scale = 0.0;
  for (const cd& l : expected) scale = std::max(scale, std::abs(l));
  EXPECT_LT(largest_mismatch(all_eigenvalues(r), expected), 1e-9 * scale);
  // One relaxation a damper, a real root each, reported as first-order (its τ in the table); no
  // oscillatory mode takes the name.
  int relaxations = 0;
  for (const DampedMode& m : r.modes)
    if (is_relaxation(m)) {
      ++relaxations;
      EXPECT_EQ(m.kind, DampedModeKind::first_order) << m.name;
      EXPECT_GT(m.decay_rate, 0.0) << m.name;
    }
  EXPECT_EQ(relaxations, d);
  EXPECT_EQ(static_cast<int>(r.dofs.size()), n + d);
}

TEST(DampedSeriesDamper, ABadSeriesDamperIsRefusedByName) {
  LinearSystem s = mass_with_series_damper(1000.0, 4e5, 2e4, 1e6);
  s.series_dampers[0].stiffness = 0.0;
  try {
    solve_damped_modes(s);
    FAIL() << "a series damper without stiffness was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("series damper of element 'damper'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace railmodal::test
