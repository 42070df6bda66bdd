// Damped modes: reduction to the undamped solve at C = 0, Rayleigh damping, the closed form
// of one damped oscillator through critical damping, massless damped DOFs (first-order
// states), rigid-body and divergent modes, and an independent state-space solve.
#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <filesystem>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

using cd = std::complex<double>;

// A system of bare bouncing points (one body each, for the mode names) with given matrices.
LinearSystem points(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K) {
  LinearSystem s;
  for (int i = 0; i < M.rows(); ++i) {
    Body b;
    b.name = "p" + std::to_string(i);
    b.mass = 1.0;
    s.vehicle.bodies.push_back(b);
    s.dofs.push_back({b.name + ".bounce", i, Motion::bounce});
  }
  s.mass = M;
  s.damping = C;
  s.stiffness = K;
  s.gravity_stiffness = Eigen::MatrixXd::Zero(M.rows(), M.cols());
  return s;
}

LinearSystem oscillator(double m, double c, double k) {
  return points(Eigen::MatrixXd::Constant(1, 1, m), Eigen::MatrixXd::Constant(1, 1, c),
                Eigen::MatrixXd::Constant(1, 1, k));
}

// Nothing a report prints may be NaN or infinite.
void expect_finite(const DampedModalResult& r) {
  for (const auto& m : r.modes) {
    for (const cd& l : m.eigenvalues) EXPECT_TRUE(std::isfinite(l.real()) && std::isfinite(l.imag())) << m.name;
    for (const auto& v : {m.damped_frequency_hz, m.damping_ratio, m.natural_frequency_hz})
      if (v) {
        EXPECT_TRUE(std::isfinite(*v)) << m.name;
      }
    EXPECT_TRUE(std::isfinite(m.decay_rate)) << m.name;
    EXPECT_TRUE(m.shape.allFinite()) << m.name;
  }
}

int eigenvalue_count(const DampedModalResult& r) {
  int count = 0;
  for (const auto& m : r.modes) count += static_cast<int>(m.eigenvalues.size());
  return count;
}

std::vector<std::string> bundled_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/vehicles"))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class DampedBundled : public ::testing::TestWithParam<std::string> {};

// With C = 0 the damped solve must be the undamped one: the state matrix is block diagonal
// in the modal coordinates, so the frequencies are the undamped ω to the last bit or two
// (1e-10 is the requirement), ζ is exactly 0, the shapes are the undamped ones.
TEST_P(DampedBundled, WithoutDampingItIsTheUndampedSolve) {
  for (DofSet set : {DofSet::vertical, DofSet::lateral, DofSet::all}) {
    auto system = assemble(load_vehicle(data_file(GetParam())), set);
    if (system.size() == 0) continue;
    system.damping.setZero();
    const auto r = solve_damped_modes(system);
    const auto& u = r.undamped;
    ASSERT_EQ(r.modes.size(), u.modes.size()) << to_string(set);
    EXPECT_TRUE(r.first_order.empty());
    EXPECT_LT(r.max_residual, 1e-12);
    expect_finite(r);
    for (size_t k = 0; k < r.modes.size(); ++k) {
      const DampedMode& d = r.modes[k];
      const Mode& m = u.modes[k];
      ASSERT_EQ(d.undamped_mode, static_cast<int>(k) + 1);
      EXPECT_EQ(d.name, m.name);
      if (m.kind == ModeKind::oscillatory) {
        EXPECT_EQ(d.kind, DampedModeKind::underdamped);
        ASSERT_TRUE(d.damped_frequency_hz && d.damping_ratio && d.natural_frequency_hz);
        EXPECT_NEAR(*d.damped_frequency_hz, m.frequency_hz, 1e-10 * m.frequency_hz) << m.name;
        EXPECT_NEAR(*d.natural_frequency_hz, m.frequency_hz, 1e-10 * m.frequency_hz) << m.name;
        EXPECT_EQ(*d.damping_ratio, 0.0) << m.name;
        EXPECT_TRUE(d.stable);
        // Same shape (the phase is fixed against the undamped shape): M-norm of the difference.
        const Eigen::VectorXcd diff = d.shape - m.shape.cast<cd>();
        EXPECT_LT(std::sqrt(std::abs(diff.dot(system.mass.cast<cd>() * diff))), 1e-10) << m.name;
      } else if (m.kind == ModeKind::unstable) {
        EXPECT_EQ(d.kind, DampedModeKind::divergent);
        EXPECT_FALSE(d.stable);
      }
    }
  }
}

// Rayleigh damping C = αM + βK keeps the undamped modes: ζ_i = α/(2ω_i) + βω_i/2 exactly
// (Clough & Penzien, eq. 12-33); the only error is the round-off of ΦᵀCΦ and of the 2×2
// blocks, ~1e-15 against the 1e-10 asked for. A massless DOF (bogie roll, leaf-spring ends)
// gets damping βK on its row: its first-order root is λ = −1/β, since (1 + βλ)K_s φ = 0.
TEST_P(DampedBundled, RayleighDampingGivesTheClosedFormRatios) {
  auto system = assemble(load_vehicle(data_file(GetParam())), DofSet::all);
  const double alpha = 0.4, beta = 2e-3;  // ζ between about 0.01 and 0.5 on these vehicles
  system.damping = alpha * system.mass + beta * system.stiffness;
  const auto r = solve_damped_modes(system);
  expect_finite(r);
  EXPECT_LT(r.max_residual, 1e-12);
  int first_order = 0;
  for (const auto& d : r.modes) {
    if (d.kind == DampedModeKind::first_order) {
      ++first_order;
      EXPECT_NEAR(d.eigenvalues[0].real(), -1.0 / beta, 1e-10 / beta) << d.name;
      continue;
    }
    const Mode& m = r.undamped.modes[d.undamped_mode - 1];
    if (m.kind != ModeKind::oscillatory) continue;
    const double w = m.omega_rad_s, zeta = alpha / (2.0 * w) + beta * w / 2.0;
    ASSERT_TRUE(d.damping_ratio.has_value()) << d.name;
    EXPECT_NEAR(*d.damping_ratio, zeta, 1e-10 * zeta) << d.name;
    EXPECT_NEAR(*d.natural_frequency_hz, m.frequency_hz, 1e-10 * m.frequency_hz) << d.name;
    if (zeta < 1.0) {
      ASSERT_TRUE(d.damped_frequency_hz.has_value()) << d.name;
      EXPECT_NEAR(*d.damped_frequency_hz, m.frequency_hz * std::sqrt(1.0 - zeta * zeta), 1e-10 * m.frequency_hz);
    }
  }
  EXPECT_EQ(first_order, static_cast<int>(r.first_order.size()));
  EXPECT_EQ(eigenvalue_count(r), 2 * static_cast<int>(r.undamped.modes.size()) + first_order);
}

INSTANTIATE_TEST_SUITE_P(Data, DampedBundled, ::testing::ValuesIn(bundled_files()), [](const auto& info) {
  std::string n = info.param.substr(0, info.param.size() - 5);
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
});

// One oscillator m ẍ + c ẋ + k x = 0, c = 2ζ√(km): λ = −ζω ± ω√(ζ² − 1).
class Oscillator : public ::testing::TestWithParam<double> {};

TEST_P(Oscillator, MatchesTheClosedForm) {
  const double zeta = GetParam(), m = 1200.0, k = 3.4e5, w = std::sqrt(k / m);
  const auto r = solve_damped_modes(oscillator(m, 2.0 * zeta * std::sqrt(k * m), k));
  expect_finite(r);
  ASSERT_EQ(r.modes.size(), 1u);
  const DampedMode& d = r.modes[0];
  EXPECT_EQ(d.undamped_mode, 1);
  EXPECT_LT(d.residual, 1e-12);
  ASSERT_EQ(d.eigenvalues.size(), 2u);
  ASSERT_TRUE(d.damping_ratio && d.natural_frequency_hz);
  EXPECT_EQ(d.stable, zeta >= 0.0);
  // The double root at ζ = 1 is reported as such (kind `critical`, ζ = 1 exactly, the mean
  // of the two computed roots, accurate to ε where each root is only good to √ε).
  if (zeta == 1.0) {
    EXPECT_EQ(d.kind, DampedModeKind::critical);
    EXPECT_EQ(*d.damping_ratio, 1.0);
    EXPECT_FALSE(d.damped_frequency_hz.has_value());
    EXPECT_NEAR(d.eigenvalues[0].real(), -w, 1e-12 * w);
    EXPECT_EQ(d.eigenvalues[0], d.eigenvalues[1]);
    EXPECT_NEAR(d.decay_rate, w, 1e-12 * w);
    return;
  }
  // ζ and ω_n come from the sum and product of the roots, well conditioned: 1e-12. The damped
  // frequency ω√(1 − ζ²) and the split √(ζ² − 1) lose a factor 1/|1 − ζ²| ≤ 5e3 (ζ = 0.9999)
  // to cancellation in the 2×2 block, hence 1e-10 there.
  EXPECT_NEAR(*d.damping_ratio, zeta, 1e-12 * std::max(1.0, std::abs(zeta)));
  EXPECT_NEAR(*d.natural_frequency_hz * 2.0 * kPi, w, 1e-12 * w);
  if (std::abs(zeta) < 1.0) {
    EXPECT_EQ(d.kind, DampedModeKind::underdamped);
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    ASSERT_TRUE(d.damped_frequency_hz.has_value());
    EXPECT_NEAR(*d.damped_frequency_hz * 2.0 * kPi, wd, 1e-10 * wd);
    EXPECT_NEAR(d.eigenvalues[0].real(), -zeta * w, 1e-12 * w);
    EXPECT_NEAR(d.eigenvalues[0].imag(), wd, 1e-10 * wd);
    EXPECT_EQ(d.eigenvalues[1], std::conj(d.eigenvalues[0]));
  } else {
    EXPECT_EQ(d.kind, DampedModeKind::overdamped);
    EXPECT_FALSE(d.damped_frequency_hz.has_value());
    // Roots without cancellation: the slow one as ω²/(fast one).
    const double fast = -w * (zeta + std::sqrt(zeta * zeta - 1.0)), slow = w * w / fast;
    EXPECT_NEAR(d.eigenvalues[0].real(), slow, 1e-10 * std::abs(slow));
    EXPECT_NEAR(d.eigenvalues[1].real(), fast, 1e-10 * std::abs(fast));
    EXPECT_EQ(d.eigenvalues[0].imag(), 0.0);
    EXPECT_NEAR(d.decay_rate, -slow, 1e-10 * std::abs(slow));
  }
}

INSTANTIATE_TEST_SUITE_P(DampingRatios, Oscillator,
                         ::testing::Values(0.0, 0.05, 0.3, 0.9, 0.99, 0.9999, 1.0, 1.0001, 1.01, 1.5, 10.0, -0.1));

// Critical damping for scales where c = 2√(km) rounds differently: never NaN, always critical.
TEST(DampedModes, CriticalDampingAtManyScalesIsCritical) {
  for (double m : {1.0, 3.0, 1200.0, 32000.0})
    for (double k : {1.0, 7.0, 3.4e5, 1.22e6, 4.3e9}) {
      const auto r = solve_damped_modes(oscillator(m, 2.0 * std::sqrt(k * m), k));
      expect_finite(r);
      ASSERT_EQ(r.modes.size(), 1u);
      EXPECT_EQ(r.modes[0].kind, DampedModeKind::critical) << m << " " << k;
      EXPECT_EQ(*r.modes[0].damping_ratio, 1.0);
      EXPECT_NEAR(*r.modes[0].natural_frequency_hz * 2.0 * kPi, std::sqrt(k / m), 1e-12 * std::sqrt(k / m));
    }
}

// A negative stiffness (CG too high for its springs) is divergent whatever the damping: the
// roots −c/2m ± √(c²/4m² + |k|/m) have opposite signs. No ζ, no frequency, no NaN.
TEST(DampedModes, DivergentModeHasNoFrequency) {
  const double m = 10.0, c = 30.0, k = -250.0;
  const auto r = solve_damped_modes(oscillator(m, c, k));
  expect_finite(r);
  ASSERT_EQ(r.modes.size(), 1u);
  const DampedMode& d = r.modes[0];
  EXPECT_EQ(d.kind, DampedModeKind::divergent);
  EXPECT_FALSE(d.stable);
  EXPECT_FALSE(r.stable);
  EXPECT_FALSE(d.damping_ratio || d.natural_frequency_hz || d.damped_frequency_hz);
  const double growth = -c / (2 * m) + std::sqrt(c * c / (4 * m * m) - k / m);
  EXPECT_NEAR(-d.decay_rate, growth, 1e-12 * growth);
}

// Rigid-body modes: two masses joined by a spring and a damper, nothing to the ground, have
// a translation with λ = 0 twice (undamped: the damper does not resist it); a mass on a
// damper alone has λ = 0 and its velocity decays at c/m.
TEST(DampedModes, RigidBodyModes) {
  Eigen::Matrix2d M = Eigen::Vector2d(2.0, 3.0).asDiagonal(), K, C;
  K << 100, -100, -100, 100;
  C << 5, -5, -5, 5;
  auto r = solve_damped_modes(points(M, C, K));
  expect_finite(r);
  ASSERT_EQ(r.modes.size(), 2u);
  EXPECT_EQ(r.modes[0].kind, DampedModeKind::rigid_body);
  EXPECT_EQ(r.modes[0].decay_rate, 0.0);
  EXPECT_TRUE(r.modes[0].stable);
  EXPECT_EQ(r.modes[1].kind, DampedModeKind::underdamped);
  // The relative motion: reduced mass μ = 6/5, ω² = k/μ, ζ = c/(2√(kμ)).
  const double mu = 6.0 / 5.0;
  EXPECT_NEAR(*r.modes[1].damping_ratio, 5.0 / (2.0 * std::sqrt(100.0 * mu)), 1e-12);
  EXPECT_TRUE(r.stable);

  r = solve_damped_modes(oscillator(4.0, 10.0, 0.0));
  expect_finite(r);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_EQ(r.modes[0].kind, DampedModeKind::rigid_body);
  ASSERT_EQ(r.modes[0].eigenvalues.size(), 2u);
  EXPECT_EQ(r.modes[0].eigenvalues[0], cd(0.0, 0.0));
  EXPECT_NEAR(r.modes[0].eigenvalues[1].real(), -2.5, 1e-14);
  EXPECT_NEAR(r.modes[0].decay_rate, 2.5, 1e-14);
}

// A massless node with a damper is a first-order state (a Maxwell element: mass m on a spring
// k1 to the ground and on a spring k2 in series with a damper c). det(λ²M + λC + K) =
// (mλ² + k1 + k2)(cλ + k2) − k2² = m c λ³ + m k2 λ² + (k1 + k2) c λ + k1 k2: three roots, a
// complex pair and a real one. A second massless node without damper between the spring and
// the first (splitting k2 into k2a, k2b in series) is condensed statically: the same cubic
// with k2 = k2a k2b/(k2a + k2b).
TEST(DampedModes, MasslessDamperNodeIsFirstOrder) {
  const double m = 50.0, k1 = 2e4, c = 800.0, k2a = 3e4, k2b = 6e4, k2 = k2a * k2b / (k2a + k2b);
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero(), C = Eigen::Matrix3d::Zero(), K;
  M(0, 0) = m;
  C(2, 2) = c;  // p2: the node on the damper; p1: the node between the springs
  K << k1 + k2a, -k2a, 0, -k2a, k2a + k2b, -k2b, 0, -k2b, k2b;
  const auto r = solve_damped_modes(points(M, C, K));
  expect_finite(r);
  EXPECT_EQ(r.condensed, std::vector<std::string>{"p1.bounce"});
  EXPECT_EQ(r.first_order, std::vector<std::string>{"p2.bounce"});
  ASSERT_EQ(eigenvalue_count(r), 3);
  ASSERT_EQ(r.modes.size(), 2u);
  // In ascending damped frequency: the first-order mode, which does not oscillate (f_d = 0),
  // first (damped_modal.cpp, order_modes).
  EXPECT_EQ(r.modes[0].kind, DampedModeKind::first_order);
  EXPECT_EQ(r.modes[0].name, "p2.bounce first-order");
  EXPECT_EQ(r.modes[0].undamped_mode, 0);
  EXPECT_EQ(r.modes[1].undamped_mode, 1);
  EXPECT_LT(r.max_residual, 1e-12);
  // Each root makes the cubic vanish to round-off of its terms.
  for (const auto& mode : r.modes)
    for (const cd& l : mode.eigenvalues) {
      const cd terms[] = {m * c * l * l * l, m * k2 * l * l, (k1 + k2) * c * l, cd(k1 * k2)};
      double size = 0.0;
      cd sum = 0.0;
      for (const cd& t : terms) sum += t, size += std::abs(t);
      EXPECT_LT(std::abs(sum), 1e-13 * size) << l;
    }
  // The static-follower node moves with the others in the shape: p1 between x and p2.
  const auto& s = r.modes[0].shape;
  EXPECT_NEAR(std::abs(s(1) - (k2a * s(0) + k2b * s(2)) / (k2a + k2b)), 0.0, 1e-12 * s.cwiseAbs().maxCoeff());
}

// Rayleigh damping on a model with massless DOFs: βK damps their rows, so both nodes of a
// chain mass – k2a – node – k2b – node – k3 – ground (and k1 from the mass to the ground)
// become first-order states, each with the root λ = −1/β, since (1 + βλ)K_s φ = 0 (a double
// root with two eigenvectors, not defective); the mass keeps ζ = α/(2ω) + βω/2 with
// ω² = (k1 + k_s)/m, k_s the three springs in series.
TEST(DampedModes, RayleighDampingOnMasslessNodes) {
  const double m = 50.0, k1 = 2e4, k2a = 3e4, k2b = 6e4, k3 = 1e4;
  const double alpha = 0.3, beta = 4e-3, w = std::sqrt((k1 + 1.0 / (1.0 / k2a + 1.0 / k2b + 1.0 / k3)) / m);
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero(), K;
  M(0, 0) = m;
  K << k1 + k2a, -k2a, 0, -k2a, k2a + k2b, -k2b, 0, -k2b, k2b + k3;
  const auto r = solve_damped_modes(points(M, alpha * M + beta * K, K));
  expect_finite(r);
  EXPECT_TRUE(r.condensed.empty());
  EXPECT_EQ(r.first_order.size(), 2u);
  ASSERT_EQ(r.modes.size(), 3u);
  const double zeta = alpha / (2.0 * w) + beta * w / 2.0;
  // The two first-order modes (f_d = 0) first, in ascending damped frequency.
  EXPECT_EQ(r.modes[2].kind, DampedModeKind::underdamped);
  EXPECT_NEAR(*r.modes[2].damping_ratio, zeta, 1e-10 * zeta);
  EXPECT_NEAR(*r.modes[2].natural_frequency_hz * 2.0 * kPi, w, 1e-10 * w);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(r.modes[i].kind, DampedModeKind::first_order);
    EXPECT_NEAR(r.modes[i].eigenvalues[0].real(), -1.0 / beta, 1e-10 / beta);
  }
  EXPECT_LT(r.max_residual, 1e-12);
}

// A damper joining two massless nodes and nothing else damps their difference only: their
// sum moves without damping or inertia. A clear error names them.
TEST(DampedModes, UndampedCombinationOfMasslessDampedNodesIsNamed) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero(), C = Eigen::Matrix3d::Zero(), K;
  M(0, 0) = 1.0;
  C.bottomRightCorner<2, 2>() << 1, -1, -1, 1;
  K << 3, -1, -1, -1, 2, 0, -1, 0, 2;
  try {
    solve_damped_modes(points(M, C, K));
    ADD_FAILURE() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("'p1.bounce', 'p2.bounce'"), std::string::npos) << e.what();
  }
}

// An independent check on the Manchester coach's own dampers (non-proportional): the
// eigenvalues of the plain state matrix [[0, I], [−M⁻¹K, −M⁻¹C]] (no modal coordinates, no
// balancing) agree. The plain matrix is badly scaled (‖M⁻¹K‖ ~ 1e5 against 1), so it is
// trusted to 1e-9 of max|λ| only.
TEST(DampedModes, CoachAgreesWithThePlainStateMatrix) {
  const auto system = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::all);
  ASSERT_GT(system.damping.norm(), 0.0);
  const auto r = solve_damped_modes(system);
  expect_finite(r);
  EXPECT_LT(r.max_residual, 1e-12);
  EXPECT_TRUE(r.stable);
  const int n = system.size();
  ASSERT_EQ(eigenvalue_count(r), 2 * n);  // no massless DOFs in the coach
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::LDLT<Eigen::MatrixXd> mass(system.mass);
  A.bottomLeftCorner(n, n) = -mass.solve(system.stiffness);
  A.bottomRightCorner(n, n) = -mass.solve(system.damping);
  const Eigen::VectorXcd plain = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  std::vector<cd> ours;
  for (const auto& m : r.modes) ours.insert(ours.end(), m.eigenvalues.begin(), m.eigenvalues.end());
  const double scale = plain.cwiseAbs().maxCoeff();
  std::vector<bool> used(plain.size(), false);
  for (const cd& l : ours) {
    int best = -1;
    for (int i = 0; i < plain.size(); ++i)
      if (!used[i] && (best < 0 || std::abs(plain(i) - l) < std::abs(plain(best) - l))) best = i;
    used[best] = true;
    EXPECT_LT(std::abs(plain(best) - l), 1e-9 * scale) << l << " vs " << plain(best);
  }
  // Plausible dampers: every body mode between 3 % and 60 % of critical.
  for (const auto& m : r.modes)
    if (m.name.rfind("body", 0) == 0 && m.damping_ratio) {
      EXPECT_GT(*m.damping_ratio, 0.03) << m.name;
      EXPECT_LT(*m.damping_ratio, 0.6) << m.name;
    }
}

// The modes in ascending damped frequency, as every mode table (docs/product.md), though the
// coach's dampers move body upper sway (undamped 1.2259 Hz) below body bounce (undamped 1.0739
// Hz): indices 1…n in that order, each undamped mode exactly once.
TEST(DampedModes, OrderedByDampedFrequency) {
  const auto system = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::all);
  const auto r = solve_damped_modes(system);
  std::vector<int> undamped;
  double previous = 0.0;
  for (size_t k = 0; k < r.modes.size(); ++k) {
    const DampedMode& m = r.modes[k];
    EXPECT_EQ(m.index, static_cast<int>(k) + 1);
    ASSERT_TRUE(m.damped_frequency_hz) << m.name;  // every coach mode is underdamped
    EXPECT_GE(*m.damped_frequency_hz, previous) << m.name;
    previous = *m.damped_frequency_hz;
    undamped.push_back(m.undamped_mode);
  }
  std::sort(undamped.begin(), undamped.end());
  for (size_t k = 0; k < undamped.size(); ++k) EXPECT_EQ(undamped[k], static_cast<int>(k) + 1);
  // The case that made the order matter: a mode whose undamped frequency is higher comes first.
  const auto at = [&r](const std::string& name) {
    return std::find_if(r.modes.begin(), r.modes.end(), [&name](const DampedMode& m) { return m.name == name; });
  };
  ASSERT_NE(at("body upper sway"), r.modes.end());
  ASSERT_NE(at("body bounce"), r.modes.end());
  EXPECT_LT(at("body upper sway")->index, at("body bounce")->index);
  EXPECT_GT(at("body upper sway")->undamped_mode, at("body bounce")->undamped_mode);
}

// Invariants over many random models with heavy non-proportional damping (ζ from 0.01 to
// beyond critical, modes strongly mixed), some with massless damped and undamped DOFs: every
// root is found once (2 per DOF with mass, 1 per massless damped DOF), with a relative
// residual at round-off (1e-11: the state matrices here have condition numbers up to ~1e4),
// nothing NaN, one damped mode per undamped mode, and the same roots as the plain state
// matrix when M is invertible.
TEST(DampedModes, RandomNonProportionalModels) {
  std::srand(7);
  auto uniform = [] { return std::rand() / double(RAND_MAX); };
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + trial % 7;
    const Eigen::MatrixXd R = Eigen::MatrixXd::Random(n, n), S = Eigen::MatrixXd::Random(n, n);
    Eigen::MatrixXd K = R * R.transpose() + 0.1 * n * Eigen::MatrixXd::Identity(n, n);
    const double c_scale = std::pow(10.0, -2.0 + 4.0 * uniform());
    Eigen::MatrixXd C = c_scale * S * S.transpose();
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    int massless_damped = 0;
    for (int i = 0; i < n; ++i) {
      const bool massless = trial % 3 == 0 && i > 0 && i % 3 == 0;
      if (!massless) {
        M(i, i) = 0.5 + uniform();
      } else if (trial % 2 == 0) {  // massless and undamped: condensed
        C.row(i).setZero();
        C.col(i).setZero();
      } else {
        ++massless_damped;
      }
    }
    const auto r = solve_damped_modes(points(M, C, K));
    expect_finite(r);
    int with_mass = 0;
    for (int i = 0; i < n; ++i) with_mass += M(i, i) > 0.0;
    EXPECT_EQ(static_cast<int>(r.first_order.size()), massless_damped) << trial;
    EXPECT_EQ(eigenvalue_count(r), 2 * with_mass + massless_damped) << trial;
    EXPECT_LT(r.max_residual, 1e-11) << trial;
    EXPECT_TRUE(r.stable) << trial;  // M, K positive definite, C semidefinite
    // The matching gives each undamped mode one damped mode (pairs placed first never leave
    // a mode half filled).
    std::vector<int> rows(with_mass + 1, 0);
    for (const auto& m : r.modes) ++rows[m.undamped_mode];
    EXPECT_EQ(rows[0], massless_damped) << trial;
    for (int k = 1; k <= with_mass; ++k) EXPECT_EQ(rows[k], 1) << trial << " mode " << k;
    if (with_mass < n) continue;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -M.inverse() * K;
    A.bottomRightCorner(n, n) = -M.inverse() * C;
    const Eigen::VectorXcd plain = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
    const double scale = plain.cwiseAbs().maxCoeff();
    for (const auto& m : r.modes)
      for (const cd& l : m.eigenvalues) {
        double nearest = std::numeric_limits<double>::infinity();
        for (int i = 0; i < plain.size(); ++i) nearest = std::min(nearest, std::abs(plain(i) - l));
        // A critical double root is reported as the mean of the split pair: √ε-level there.
        EXPECT_LT(nearest, (m.kind == DampedModeKind::critical ? 1e-6 : 1e-9) * scale) << trial << " " << l;
      }
  }
}

// Damping that is not proportional couples the undamped modes, and the coupling moves their
// frequencies either way. Two equal masses m on springs k, coupled by kc, with one damper c under
// the first only: modes (1, 1)/√(2m) at ω₁² = k/m and (1, −1)/√(2m) at ω₂² = (k + 2kc)/m, modal
// damping d_ij = φ_iᵀCφ_j = c/(2m) = d for every i, j. In modal coordinates
// (λ² + λD + Ω²)u = 0; with u = e_i + O(d), row j ≠ i gives u_j ≈ −iω_i d_ji/(ω_j² − ω_i²), and
// row i to second order: Im λ_i = ω_i − d_ii²/(8ω_i) + (ω_i/2)Σ_j d_ij²/(ω_j² − ω_i²), and
// |λ_i| = ω_i(1 + ½Σ_j d_ij²/(ω_j² − ω_i²)). The first term is the proportional ζ²/2; the
// coupling pulls the two frequencies together, so the lower mode's damped frequency here exceeds
// its undamped one (4·ω₁² > ω₂² − ω₁²). The neglected terms are fourth order, of relative size
// (d/ω₁)² = 2.5e-4 of the shift (d·ω₁/(ω₂² − ω₁²) is the same here); 2e-3 (8 times) allowed.
// The roots themselves against Newton on det(λ²M + λC + K), to 1e-12 of ω.
TEST(DampedModes, NonProportionalDampingRaisesTheLowerFrequency) {
  const double m = 1000.0, k = 1e6, kc = 5e5, c = 1000.0;
  Eigen::MatrixXd K(2, 2);
  K << k + kc, -kc, -kc, k + kc;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2, 2);
  C(0, 0) = c;
  const DampedModalResult r = solve_damped_modes(points(m * Eigen::MatrixXd::Identity(2, 2), C, K));
  ASSERT_EQ(r.modes.size(), 2u);
  const double w1 = std::sqrt(k / m), w2 = std::sqrt((k + 2.0 * kc) / m), d = c / (2.0 * m);
  const double w[2] = {w1, w2};
  const auto det = [&](cd l) { return (m * l * l + c * l + k + kc) * (m * l * l + k + kc) - kc * kc; };
  const auto det_slope = [&](cd l) {
    return (2.0 * m * l + c) * (m * l * l + k + kc) + (m * l * l + c * l + k + kc) * (2.0 * m * l);
  };
  for (int i = 0; i < 2; ++i) {
    const DampedMode& mode = r.modes[i];
    ASSERT_EQ(mode.undamped_mode, i + 1);  // in ascending f_d, which keeps the undamped order here
    EXPECT_NEAR(r.undamped.modes[i].omega_rad_s, w[i], 1e-12 * w[i]);
    const double other = w[1 - i];
    const double coupling = 0.5 * w[i] * d * d / (other * other - w[i] * w[i]);
    const double shift = coupling - d * d / (8.0 * w[i]);  // Im λ − ω, rad/s
    const double damped = 2.0 * kPi * *mode.damped_frequency_hz, natural = 2.0 * kPi * *mode.natural_frequency_hz;
    EXPECT_NEAR(damped - w[i], shift, 2e-3 * std::abs(shift)) << i;
    EXPECT_NEAR(natural - w[i], coupling, 2e-3 * std::abs(coupling)) << i;
    cd root(0.0, w[i]);
    for (int step = 0; step < 50; ++step) root -= det(root) / det_slope(root);
    ASSERT_EQ(mode.eigenvalues.size(), 2u);
    const cd upper = mode.eigenvalues[0].imag() > 0.0 ? mode.eigenvalues[0] : mode.eigenvalues[1];
    EXPECT_NEAR(std::abs(upper - root), 0.0, 1e-12 * w[i]) << i;
  }
  // The lower mode oscillates above its undamped frequency (by 2.97e-3 rad/s, 4.7e-4 Hz), the
  // upper below.
  EXPECT_GT(*r.modes[0].damped_frequency_hz, r.undamped.modes[0].frequency_hz);
  EXPECT_LT(*r.modes[1].damped_frequency_hz, r.undamped.modes[1].frequency_hz);
}

TEST(DampedModes, BadOptionsAndDampingOfTheWrongSize) {
  DampedModalOptions o;
  o.critical_gap = 0.0;
  EXPECT_THROW(solve_damped_modes(oscillator(1, 1, 1), o), std::invalid_argument);
  auto s = oscillator(1, 1, 1);
  s.damping = Eigen::MatrixXd::Zero(2, 2);
  EXPECT_THROW(solve_damped_modes(s), std::invalid_argument);
  s.damping = Eigen::MatrixXd::Constant(1, 1, std::nan(""));
  EXPECT_THROW(solve_damped_modes(s), NumericalError);
}

}  // namespace
}  // namespace railmodal::test
