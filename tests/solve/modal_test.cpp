// Modal solve: invariants on every bundled vehicle, classification, checked mass matrix,
// static condensation of massless degrees of freedom.
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "solve/modal_solver.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

class BundledVehicle : public ::testing::TestWithParam<std::string> {};

// Invariants, not magic numbers: relative residual ‖Kφ − λMφ‖ and M-orthonormality at
// round-off level (1e-12 leaves two orders of headroom for n ≤ 15), modes ascending.
TEST_P(BundledVehicle, ResidualOrthonormalityAndOrder) {
  for (DofSet set : {DofSet::vertical, DofSet::lateral, DofSet::all}) {
    const auto system = assemble(load_vehicle(data_file(GetParam())), set);
    if (system.size() == 0) continue;  // e.g. a load that only bounces has no lateral set
    const auto r = solve_modes(system);
    EXPECT_LT(r.max_residual, 1e-12) << to_string(set);
    EXPECT_LT(r.orthonormality_error, 1e-12) << to_string(set);
    for (size_t i = 1; i < r.modes.size(); ++i) EXPECT_LE(r.modes[i - 1].eigenvalue, r.modes[i].eigenvalue);
    for (const auto& m : r.modes) {
      EXPECT_NEAR(m.kinetic_energy_share.sum(), 1.0, 1e-12);
      EXPECT_FALSE(m.name.empty());
      EXPECT_TRUE(std::isfinite(m.frequency_hz) && std::isfinite(m.period_s));
    }
  }
}

std::vector<std::string> bundled_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/vehicles"))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Data, BundledVehicle, ::testing::ValuesIn(bundled_files()),
                         [](const auto& info) {
                           std::string n = info.param.substr(0, info.param.size() - 5);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

LinearSystem two_dof(const Eigen::Matrix2d& M, const Eigen::Matrix2d& K) {
  LinearSystem s;
  s.dofs = {{"a.bounce", 0, Motion::bounce}, {"a.pitch", 0, Motion::pitch}};
  Body b;
  b.name = "a";
  b.mass = 1.0;
  s.vehicle.bodies = {b};
  s.mass = M;
  s.stiffness = K;
  s.gravity_stiffness = Eigen::Matrix2d::Zero();
  s.damping = Eigen::Matrix2d::Zero();
  return s;
}

TEST(ModalSolve, MassMatrixThatIsNotPositiveDefiniteNamesTheDof) {
  Eigen::Matrix2d M;
  M << 1.0, 1.0, 1.0, 1.0;  // singular, no zero row: not condensable
  try {
    solve_modes(two_dof(M, Eigen::Matrix2d::Identity()));
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("'a.pitch'"), std::string::npos) << e.what();
  }
}

// Issue 18 item 15: numbers in messages keep their significant digits; %f printed a 1e-11
// pivot as "0.000000".
TEST(ModalSolve, TinyMassPivotIsReportedWithItsDigits) {
  Eigen::Matrix2d M;
  M << 1e6, 0.0, 0.0, 1e-11;  // pivot 1e-11, below 64·ε·1e6 ≈ 1.4e-8: not positive definite
  try {
    solve_modes(two_dof(M, Eigen::Matrix2d::Identity()));
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("(pivot 1e-11)"), std::string::npos) << e.what();
  }
}

TEST(ModalSolve, ResidualLimitMessageHasSignificantDigits) {
  ModalOptions o;
  o.max_residual = 1e-30;  // below the round-off of any coupled system: the check must refuse
  Eigen::Matrix2d K;
  K << 2.0, -1.0, -1.0, 1.0;
  try {
    solve_modes(two_dof(Eigen::Matrix2d::Identity(), K), o);
    FAIL();
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("exceeds the limit 1e-30"), std::string::npos) << what;
    EXPECT_EQ(what.find("0.000000"), std::string::npos) << what;
  }
}

TEST(ModalSolve, MasslessDofIsCondensedStatically) {
  Eigen::Matrix2d M, K;
  M << 2.0, 0.0, 0.0, 0.0;
  K << 3.0, -1.0, -1.0, 1.0;  // series springs: 1/(1/2 + 1/1)... condensed k = 3 − 1 = 2
  const auto r = solve_modes(two_dof(M, K));
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_NEAR(r.modes[0].eigenvalue, 1.0, 1e-15);  // k/m = 2/2
  EXPECT_EQ(r.condensed, std::vector<std::string>{"a.pitch"});
  EXPECT_NEAR(r.modes[0].shape(1) / r.modes[0].shape(0), 1.0, 1e-15);  // φ_s = −K_ss⁻¹K_sm φ
}

TEST(ModalSolve, MasslessUnrestrainedDofIsAnErrorNamingIt) {
  Eigen::Matrix2d M, K;
  M << 2.0, 0.0, 0.0, 0.0;
  K << 3.0, 0.0, 0.0, 0.0;
  try {
    solve_modes(two_dof(M, K));
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("'a.pitch' has neither mass nor a restraint"), std::string::npos) << e.what();
  }
}

TEST(ModalSolve, NegativeZeroAndPositiveEigenvaluesAreClassified) {
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity(), K;
  K << -4.0, 0.0, 0.0, 9.0;
  auto r = solve_modes(two_dof(M, K));
  EXPECT_EQ(r.modes[0].kind, ModeKind::unstable);
  EXPECT_DOUBLE_EQ(r.modes[0].divergence_rate, 2.0);
  EXPECT_EQ(r.modes[1].kind, ModeKind::oscillatory);
  EXPECT_DOUBLE_EQ(r.modes[1].omega_rad_s, 3.0);
  K << 0.0, 0.0, 0.0, 9.0;
  r = solve_modes(two_dof(M, K));
  EXPECT_EQ(r.modes[0].kind, ModeKind::rigid_body);
  EXPECT_EQ(r.modes[0].period_s, 0.0);
}

// A mass ratio of 1e-12 is not singular: it solves, with residual and orthonormality intact.
TEST(ModalSolve, NearlySingularMassSolves) {
  Eigen::Matrix2d M, K;
  M << 1.0, 0.0, 0.0, 1e-12;
  K << 2.0, -1.0, -1.0, 1.0;
  const auto r = solve_modes(two_dof(M, K));
  EXPECT_LT(r.max_residual, 1e-12);
  EXPECT_LT(r.orthonormality_error, 1e-9);
  EXPECT_NEAR(r.modes[0].eigenvalue, 1.0, 1e-9);  // the stiff mode of the tiny mass aside
}

// Exactly repeated frequencies (the two bogies of a symmetric wagon pitch at one frequency):
// both modes are flagged, and what is checked is the invariant subspace they span, not
// single vectors: K Φ = M Φ Λ on the pair, and the pair is M-orthonormal.
TEST(ModalSolve, RepeatedFrequenciesAreFlaggedAndSpanTheSubspace) {
  const auto system = assemble(load_vehicle(data_file("fette_car.toml")), DofSet::vertical);
  const auto r = solve_modes(system);
  std::vector<const Mode*> pair;
  for (const auto& m : r.modes)
    if (m.repeated) pair.push_back(&m);
  ASSERT_EQ(pair.size(), 2u);
  Eigen::MatrixXd Phi(system.size(), 2);
  Phi << pair[0]->shape, pair[1]->shape;
  const double lambda = pair[0]->eigenvalue;
  EXPECT_LT((system.stiffness * Phi - lambda * system.mass * Phi).norm(),
            1e-12 * system.stiffness.norm() * Phi.norm());
  EXPECT_LT((Phi.transpose() * system.mass * Phi - Eigen::Matrix2d::Identity()).norm(), 1e-12);
  for (const auto& m : r.modes)
    if (&m != pair[0] && &m != pair[1]) {
      EXPECT_FALSE(m.repeated) << m.name;
    }
}

TEST(ModalSolve, InvalidOptionsAreRejected) {
  ModalOptions o;
  o.zero_tolerance = -1.0;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("zero_tolerance"), std::string::npos);
  EXPECT_THROW(solve_modes(two_dof(Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Identity()), o),
               std::invalid_argument);
}

// A double's bits: the kept solve must give the same bits, signed zeros included.
std::uint64_t modes_bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// A study's worker solves each variant's modes into the previous variant's ModalResult
// (solve::solve_modes_into) to reuse its storage. Every field must then be the fresh solve's,
// bit for bit, whatever was there before: more or fewer modes, condensed DOFs, an unstable mode,
// and after a solve that threw half-way (review of 2026-11-27: a field reset by hand that a
// later change forgets would carry the previous variant's value). Timings are left out.
void expect_same_modes(const ModalResult& kept, const ModalResult& fresh, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(kept.dofs.size(), fresh.dofs.size());
  for (size_t i = 0; i < kept.dofs.size(); ++i) {
    EXPECT_EQ(kept.dofs[i].label, fresh.dofs[i].label);
    EXPECT_EQ(kept.dofs[i].body, fresh.dofs[i].body);
    EXPECT_EQ(kept.dofs[i].motion, fresh.dofs[i].motion);
  }
  ASSERT_EQ(kept.modes.size(), fresh.modes.size());
  for (size_t i = 0; i < kept.modes.size(); ++i) {
    const Mode &a = kept.modes[i], &b = fresh.modes[i];
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(modes_bits(a.eigenvalue), modes_bits(b.eigenvalue));
    EXPECT_EQ(modes_bits(a.omega_rad_s), modes_bits(b.omega_rad_s));
    EXPECT_EQ(modes_bits(a.frequency_hz), modes_bits(b.frequency_hz));
    EXPECT_EQ(modes_bits(a.period_s), modes_bits(b.period_s));
    EXPECT_EQ(modes_bits(a.divergence_rate), modes_bits(b.divergence_rate));
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.shape.size(), b.shape.size());
    for (Eigen::Index k = 0; k < a.shape.size(); ++k) EXPECT_EQ(modes_bits(a.shape(k)), modes_bits(b.shape(k)));
    ASSERT_EQ(a.kinetic_energy_share.size(), b.kinetic_energy_share.size());
    for (Eigen::Index k = 0; k < a.kinetic_energy_share.size(); ++k)
      EXPECT_EQ(modes_bits(a.kinetic_energy_share(k)), modes_bits(b.kinetic_energy_share(k)));
    ASSERT_EQ(a.centre.has_value(), b.centre.has_value());
    if (a.centre) {
      EXPECT_EQ(a.centre->body, b.centre->body);
      EXPECT_EQ(a.centre->about, b.centre->about);
      EXPECT_EQ(modes_bits(a.centre->position), modes_bits(b.centre->position));
      EXPECT_EQ(a.centre->at_infinity, b.centre->at_infinity);
    }
    EXPECT_EQ(a.repeated, b.repeated);
    EXPECT_EQ(modes_bits(a.residual), modes_bits(b.residual));
    EXPECT_EQ(modes_bits(a.eigenvalue_error), modes_bits(b.eigenvalue_error));
  }
  EXPECT_EQ(kept.condensed, fresh.condensed);
  EXPECT_EQ(modes_bits(kept.max_residual), modes_bits(fresh.max_residual));
  EXPECT_EQ(modes_bits(kept.orthonormality_error), modes_bits(fresh.orthonormality_error));
  EXPECT_EQ(kept.solver.analysis, fresh.solver.analysis);
  EXPECT_EQ(kept.solver.method, fresh.solver.method);
  ASSERT_EQ(kept.solver.checks.size(), fresh.solver.checks.size());
  for (size_t i = 0; i < kept.solver.checks.size(); ++i) {
    EXPECT_EQ(kept.solver.checks[i].name, fresh.solver.checks[i].name);
    EXPECT_EQ(modes_bits(kept.solver.checks[i].value), modes_bits(fresh.solver.checks[i].value));
    EXPECT_EQ(modes_bits(kept.solver.checks[i].limit), modes_bits(fresh.solver.checks[i].limit));
    EXPECT_EQ(kept.solver.checks[i].passed, fresh.solver.checks[i].passed);
  }
  ASSERT_EQ(kept.solver.stages.size(), fresh.solver.stages.size());
  for (size_t i = 0; i < kept.solver.stages.size(); ++i) EXPECT_EQ(kept.solver.stages[i].stage, fresh.solver.stages[i].stage);
  EXPECT_EQ(kept.solver.solver, fresh.solver.solver);
  EXPECT_EQ(kept.solver.factorisation, fresh.solver.factorisation);
  EXPECT_EQ(kept.solver.count_checked, fresh.solver.count_checked);
  EXPECT_EQ(kept.notes, fresh.notes);
}

TEST(ModalSolve, ModesSolvedIntoAKeptResultAreTheFreshOnes) {
  const LinearSystem all = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::all);
  const LinearSystem vertical = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::vertical);
  const LinearSystem wheelsets =
      assemble(load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  Eigen::Matrix2d M, K;
  M << 2.0, 0.0, 0.0, 0.0;
  K << 3.0, -1.0, -1.0, 1.0;
  const LinearSystem condensed = two_dof(M, K);
  M = Eigen::Matrix2d::Identity();
  K << -4.0, 0.0, 0.0, 9.0;
  const LinearSystem unstable = two_dof(M, K);
  Eigen::Matrix2d M0, K0;
  M0 << 2.0, 0.0, 0.0, 0.0;
  K0 << 3.0, 0.0, 0.0, 0.0;
  const LinearSystem throws = two_dof(M0, K0);

  ModalResult kept;
  const auto solve_and_compare = [&](const LinearSystem& system, const std::string& what) {
    solve::solve_modes_into(system, {}, &kept);
    expect_same_modes(kept, solve_modes(system), what);
  };
  solve_and_compare(all, "resort car, every DOF");
  solve_and_compare(vertical, "resort car, vertical (fewer modes)");
  solve_and_compare(wheelsets, "coach with wheelsets (notes, more modes)");
  solve_and_compare(condensed, "a condensed massless DOF");
  EXPECT_THROW(solve::solve_modes_into(throws, {}, &kept), NumericalError);
  solve_and_compare(unstable, "an unstable mode, after a solve that threw");
  solve_and_compare(all, "resort car again");
}

}  // namespace
}  // namespace railmodal::test
