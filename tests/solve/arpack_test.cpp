// The ARPACK back-end against the dense solver: every bundled wagon, a 2 000-DOF train,
// whole invariant subspaces for repeated frequencies, rigid-body and unstable modes, massless
// DOFs, and failures that are reported, never a partial answer.
#include <Eigen/Dense>
#include <filesystem>
#include <sstream>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

ModalOptions arpack(int modes) {
  ModalOptions o;
  o.solver = ModalSolver::arpack;
  o.mode_count = modes;
  return o;
}

ModalOptions dense(int modes = 0) {
  ModalOptions o;
  o.solver = ModalSolver::dense;
  o.mode_count = modes;
  return o;
}

Eigen::MatrixXd shapes(const ModalResult& r, int first, int last) {
  Eigen::MatrixXd phi(r.dofs.size(), last - first);
  for (int k = first; k < last; ++k) phi.col(k - first) = r.modes[k].shape;
  return phi;
}

// sin of the largest principal angle between the M-orthonormal bases A and B: the M-norm of
// what A has outside span(B). Independent of the basis chosen inside a repeated frequency's
// subspace, so it checks the subspace, not single vectors.
template <class Matrix>
double subspace_gap(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Matrix& M) {
  const Eigen::MatrixXd outside = A - B * (B.transpose() * (M * A));
  return std::sqrt(std::max(0.0, (outside.transpose() * (M * outside)).diagonal().maxCoeff()));
}

// Modes i − 1 and i of `r` belong to one cluster: flagged repeated, both rigid-body, or
// oscillatory within 1e-6 in frequency. Within such a near-cluster the eigenvectors are
// determined only as a subspace (the Manchester coach has two modes 1.4e-8 apart, not flagged
// repeated: their individual vectors differ between solvers by ~1e-15/1.4e-8).
bool same_cluster(const ModalResult& r, int i) {
  const Mode& p = r.modes[i - 1];
  const Mode& q = r.modes[i];
  if (p.kind != q.kind) return false;
  if (p.kind == ModeKind::rigid_body || (p.repeated && q.repeated)) return true;
  return p.kind == ModeKind::oscillatory && q.frequency_hz - p.frequency_hz <= 1e-6 * q.frequency_hz;
}

// ARPACK's first N modes against the dense solver's: kinds, frequencies (or divergence
// rates) to `tolerance` relative, and the subspace of every cluster of equal or nearly equal
// eigenvalues.
template <class Matrix>
void expect_agree(const ModalResult& a, const ModalResult& d, int count, const Matrix& M, double tolerance,
                  const std::string& what) {
  ASSERT_GE(a.modes.size(), static_cast<size_t>(count)) << what;
  ASSERT_GE(d.modes.size(), a.modes.size()) << what;
  const int n = static_cast<int>(a.modes.size());
  for (int k = 0; k < count; ++k) {
    const Mode& x = a.modes[k];
    const Mode& y = d.modes[k];
    EXPECT_EQ(x.kind, y.kind) << what << " mode " << k + 1;
    if (y.kind == ModeKind::oscillatory) {
      EXPECT_NEAR(x.frequency_hz, y.frequency_hz, tolerance * y.frequency_hz) << what << " mode " << k + 1;
    }
    if (y.kind == ModeKind::unstable) {
      EXPECT_NEAR(x.divergence_rate, y.divergence_rate, tolerance * y.divergence_rate) << what << " mode " << k + 1;
    }
    EXPECT_EQ(x.repeated, y.repeated) << what << " mode " << k + 1;
    // Names come from the shapes: only a mode alone in its cluster has a shape of its own.
    const bool alone = (k == 0 || !same_cluster(d, k)) && (k + 1 >= static_cast<int>(d.modes.size()) || !same_cluster(d, k + 1));
    if (alone && y.kind != ModeKind::rigid_body) {
      EXPECT_EQ(x.name, y.name) << what << " mode " << k + 1;
    }
  }
  // Clusters (of the dense reference) compared as subspaces.
  for (int first = 0; first < n;) {
    int last = first + 1;
    while (last < n && same_cluster(d, last)) ++last;
    // A cluster that runs on past the modes ARPACK was asked for is cut: its part is not a
    // subspace of its own (the frequencies above still agree).
    if (last == n && n < static_cast<int>(d.modes.size()) && same_cluster(d, n)) break;
    // Eigenvector error ≈ residual / relative gap to the next cluster: ≥ 1e-6 by construction
    // (~1e-3 for most), so ≤ 1e-9; 1e-7 leaves room for the dense solver's own error on the
    // lowest modes.
    EXPECT_LT(subspace_gap(shapes(a, first, last), shapes(d, first, last), M), 1e-7)
        << what << " modes " << first + 1 << "–" << last;
    first = last;
  }
}

std::vector<std::string> bundled_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/vehicles"))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class ArpackBundledVehicle : public ::testing::TestWithParam<std::string> {};

// Every mode ARPACK can give (n − 1 of those with mass) and the three lowest agree with the
// dense solver to 1e-10 relative in frequency: both solve to residuals of 1e-14, and the
// frequencies' condition is at worst λmax/λ ≈ 1e3 here, so 1e-10 has a margin of 100.
TEST_P(ArpackBundledVehicle, AgreesWithDense) {
  for (DofSet set : {DofSet::vertical, DofSet::lateral, DofSet::all}) {
    const auto system = assemble(load_vehicle(data_file(GetParam())), set);
    if (system.size() == 0) continue;  // e.g. a load that only bounces has no lateral set
    const auto d = solve_modes(system, dense());
    const int most = system.size() - static_cast<int>(d.condensed.size()) - 1;
    if (most < 1) continue;
    // A repeated frequency cut by the last mode ARPACK can give (n − 1 of n) is an error:
    // never half a cluster.
    if (d.modes[most - 1].repeated && d.modes[most].repeated) {
      EXPECT_THROW(solve_modes(system, arpack(most)), NumericalError) << GetParam() << " " << to_string(set);
      continue;
    }
    for (int count : {std::min(3, most), most}) {
      const auto a = solve_modes(system, arpack(count));
      EXPECT_EQ(a.solver.solver, ModalSolver::arpack);
      EXPECT_EQ(a.condensed, d.condensed);
      EXPECT_LT(a.max_residual, 1e-12);
      EXPECT_LT(a.orthonormality_error, 1e-12);
      expect_agree(a, d, count, system.mass, 1e-10, GetParam() + " " + to_string(set) + " N=" + std::to_string(count));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Data, ArpackBundledVehicle, ::testing::ValuesIn(bundled_files()),
                         [](const auto& info) {
                           std::string n = info.param.substr(0, info.param.size() - 5);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// 2 000 DOFs, free along the track: a rigid-body mode (singular K) and 19 longitudinal modes
// from 0.02 Hz. 1e-10 relative in frequency (the dense solver's own error on the lowest is
// ε·λmax/λ ≈ 2e-11 in λ, half that in frequency).
TEST(Arpack, TrainOf2000DofsAgreesWithDense) {
  const SparseSystem train = wagon_train(400);
  ASSERT_EQ(train.size(), 2000);
  const auto a = solve_modes(train, arpack(20));
  const auto d = solve_modes(train, dense(20));
  ASSERT_EQ(a.modes.size(), 20u);
  EXPECT_EQ(a.modes[0].kind, ModeKind::rigid_body);
  EXPECT_LT(a.solver.shift, 0.0);  // the automatic σ sits below the rigid-body mode
  EXPECT_EQ(a.solver.factorisation, "LDLT");
  EXPECT_TRUE(a.solver.count_checked);
  EXPECT_LT(a.max_residual, 1e-12);
  EXPECT_LT(a.orthonormality_error, 1e-12);
  expect_agree(a, d, 20, train.mass, 1e-10, "train");
}

SparseSystem from_triplets(const std::string& name, int n, const Triplets& m, const Triplets& k) {
  SparseSystem s;
  s.name = name;
  for (int i = 0; i < n; ++i) {
    Dof dof;
    dof.label = "dof" + std::to_string(i + 1);
    dof.body = -1;
    s.dofs.push_back(dof);
  }
  s.mass.resize(n, n);
  s.stiffness.resize(n, n);
  s.mass.setFromTriplets(m.begin(), m.end());
  s.stiffness.setFromTriplets(k.begin(), k.end());
  return s;
}

// Two identical trains side by side: every eigenvalue double, two rigid-body modes.
SparseSystem twin_trains(int wagons) {
  const SparseSystem one = wagon_train(wagons);
  const int h = one.size();
  Triplets m, k;
  for (const auto& [A, out] : {std::pair{&one.mass, &m}, std::pair{&one.stiffness, &k}})
    for (int j = 0; j < A->outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(*A, j); it; ++it) {
        out->emplace_back(it.row(), it.col(), it.value());
        out->emplace_back(it.row() + h, it.col() + h, it.value());
      }
  return from_triplets("twin trains", 2 * h, m, k);
}

// N = 5 cuts the third double frequency in half: ARPACK returns its whole subspace (6 modes),
// the same subspace as the dense solver's, for every cluster.
TEST(Arpack, RepeatedFrequenciesComeWithTheirWholeSubspace) {
  const SparseSystem twins = twin_trains(60);  // 600 DOFs
  const auto a = solve_modes(twins, arpack(5));
  const auto d = solve_modes(twins, dense(5));
  ASSERT_EQ(a.modes.size(), 6u);
  ASSERT_EQ(d.modes.size(), 6u);  // the dense solver extends the cluster alike
  for (const auto& m : a.modes) EXPECT_TRUE(m.repeated || m.kind == ModeKind::rigid_body);
  EXPECT_TRUE(a.solver.count_checked);
  expect_agree(a, d, 6, twins.mass, 1e-10, "twin trains");

  // A diagonal system with double eigenvalues 1, 1, 2, 2, ...: Lanczos sees each pair as one
  // direction of the start vector; the inertia count makes sure the second copy is found.
  const int n = 600;
  Triplets m, k;
  for (int i = 0; i < n; ++i) {
    m.emplace_back(i, i, 1.0);
    k.emplace_back(i, i, 1.0 + i / 2);
  }
  const SparseSystem diagonal = from_triplets("diagonal", n, m, k);
  const auto b = solve_modes(diagonal, arpack(7));
  ASSERT_EQ(b.modes.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(b.modes[i].eigenvalue, 1.0 + i / 2, 1e-12);
  // Each pair spans the two coordinate axes of its eigenvalue.
  for (int pair = 0; pair < 4; ++pair) {
    const Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(n, n).middleCols(2 * pair, 2);
    EXPECT_LT(subspace_gap(shapes(b, 2 * pair, 2 * pair + 2), basis, diagonal.mass), 1e-10) << "pair " << pair;
  }
}

// An unstable system (K indefinite) with a rigid-body mode: the automatic σ is lowered below
// the unstable modes (the inertia of K − σM counts them) so that they come first, as with the
// dense solver.
TEST(Arpack, UnstableAndRigidBodyModesComeFirst) {
  const int n = 50;
  Triplets m, k;
  for (int i = 0; i < n; ++i) m.emplace_back(i, i, 2.0);
  // Eigenvalues −50, −0.5, 0, then 1, 2, ... (K/M): one deeply unstable mode far below σ.
  const double lambda[] = {-50.0, -0.5, 0.0};
  for (int i = 0; i < n; ++i) k.emplace_back(i, i, 2.0 * (i < 3 ? lambda[i] : i - 2.0));
  const SparseSystem s = from_triplets("unstable", n, m, k);
  const auto a = solve_modes(s, arpack(4));
  ASSERT_EQ(a.modes.size(), 4u);
  EXPECT_EQ(a.modes[0].kind, ModeKind::unstable);
  EXPECT_NEAR(a.modes[0].divergence_rate, std::sqrt(50.0), 1e-12);
  EXPECT_EQ(a.modes[1].kind, ModeKind::unstable);
  EXPECT_NEAR(a.modes[1].divergence_rate, std::sqrt(0.5), 1e-12);
  EXPECT_EQ(a.modes[2].kind, ModeKind::rigid_body);
  EXPECT_EQ(a.modes[3].kind, ModeKind::oscillatory);
  EXPECT_NEAR(a.modes[3].eigenvalue, 1.0, 1e-12);
  EXPECT_LT(a.solver.shift, -50.0);
  expect_agree(a, solve_modes(s, dense(4)), 4, s.mass, 1e-10, "unstable");
}

// Issue 18 item 8: a long chain's lowest eigenvalues lie far below the fixed fraction
// σ = −1e-6·max Kᵢᵢ/Mᵢᵢ = −2e-6 (λ₁ = 4 sin²(π/2(n+1)) ≈ 2.5e-8 at n = 2·10⁴), where Lanczos
// hardly separates them. The automatic shift moves to the scale of λ₁: within a factor 10 of
// it, and the modes still agree with the closed form.
TEST(Arpack, AutomaticShiftFollowsTheLowestEigenvalues) {
  const int n = 20000;
  Triplets m, k;
  for (int i = 0; i < n; ++i) {
    m.emplace_back(i, i, 1.0);
    k.emplace_back(i, i, 2.0);
    if (i + 1 < n) {
      k.emplace_back(i, i + 1, -1.0);
      k.emplace_back(i + 1, i, -1.0);
    }
  }
  const auto r = solve_modes(from_triplets("chain", n, m, k), arpack(3));
  const double pi = 3.14159265358979323846;
  const double lambda1 = 4.0 * std::pow(std::sin(pi / (2.0 * (n + 1))), 2);
  EXPECT_LT(r.solver.shift, 0.0);
  EXPECT_GT(r.solver.shift, -10.0 * lambda1) << "σ = " << r.solver.shift << ", λ₁ = " << lambda1;
  for (int j = 1; j <= 3; ++j) {
    const double exact = 4.0 * std::pow(std::sin(j * pi / (2.0 * (n + 1))), 2);
    // 1e-9: the refined λ carry 4ε·λ₃ of rounding; the closed form in double a few ε.
    EXPECT_NEAR(r.modes[j - 1].eigenvalue / exact, 1.0, 1e-9) << j;
  }
}

// A massless DOF held by springs is condensed implicitly (shift-invert keeps the iterates in
// the range of (K − σM)⁻¹M, where its row of K is satisfied), as the dense solver does
// explicitly; without a restraint it is the dense solver's error, naming it.
TEST(Arpack, MasslessDegreesOfFreedom) {
  const int n = 40;  // a chain of 40 masses on springs; DOF 20 massless
  Triplets m, k;
  for (int i = 0; i < n; ++i) {
    if (i != 19) m.emplace_back(i, i, 1.0 + 0.01 * i);
    k.emplace_back(i, i, 2000.0);
    if (i + 1 < n) {
      k.emplace_back(i, i + 1, -1000.0);
      k.emplace_back(i + 1, i, -1000.0);
    }
  }
  const SparseSystem chain = from_triplets("chain", n, m, k);
  const auto a = solve_modes(chain, arpack(10));
  const auto d = solve_modes(chain, dense());
  EXPECT_EQ(a.condensed, std::vector<std::string>{"dof20"});
  EXPECT_EQ(d.condensed, a.condensed);
  expect_agree(a, d, 10, chain.mass, 1e-10, "massless");

  Triplets free_k;
  for (const auto& t : k)
    if (t.row() != 19 && t.col() != 19) free_k.push_back(t);
  const SparseSystem loose = from_triplets("loose", n, m, free_k);
  try {
    solve_modes(loose, arpack(5));
    ADD_FAILURE() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("'dof20' has neither mass nor a restraint"), std::string::npos) << e.what();
  }
}

// Non-convergence is an error with a message, never fewer modes than asked.
TEST(Arpack, NonConvergenceIsAnError) {
  const SparseSystem train = wagon_train(400);
  ModalOptions o = arpack(20);
  o.arpack.max_iterations = 1;
  o.arpack.subspace_size = 23;  // nev = 22 (20 + 2) + 1: one restart of a minimal subspace
  o.arpack.tolerance = 1e-15;
  try {
    solve_modes(train, o);
    ADD_FAILURE() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("ARPACK"), std::string::npos) << e.what();
  }
  o = arpack(20);
  o.arpack.max_iterations = 1;
  o.arpack.subspace_size = 30;
  try {
    solve_modes(train, o);
    ADD_FAILURE() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("ARPACK did not converge"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("of 22 Ritz values converged in 1 restarts"), std::string::npos) << e.what();
  }
}

TEST(Arpack, TooManyModesOrBadOptionsAreInvalidArguments) {
  const auto system = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::all);
  EXPECT_THROW(solve_modes(system, arpack(system.size())), std::invalid_argument);
  ModalOptions o = arpack(3);
  o.arpack.tolerance = -1.0;
  EXPECT_THROW(solve_modes(system, o), std::invalid_argument);
  o = arpack(3);
  o.arpack.max_iterations = 0;
  EXPECT_THROW(solve_modes(system, o), std::invalid_argument);
}

// A given σ returns the lowest modes above it.
TEST(Arpack, GivenShiftGivesTheModesNearIt) {
  const int n = 100;
  Triplets m, k;
  for (int i = 0; i < n; ++i) {
    m.emplace_back(i, i, 1.0);
    k.emplace_back(i, i, i + 1.0);
  }
  ModalOptions o = arpack(3);
  o.arpack.shift = 50.2;
  const auto r = solve_modes(from_triplets("diagonal", n, m, k), o);
  ASSERT_EQ(r.modes.size(), 3u);
  EXPECT_NEAR(r.modes[0].eigenvalue, 51.0, 1e-10);
  EXPECT_NEAR(r.modes[1].eigenvalue, 52.0, 1e-10);
  EXPECT_NEAR(r.modes[2].eigenvalue, 53.0, 1e-10);
  EXPECT_TRUE(r.solver.count_checked);
}

TEST(Arpack, AutomaticChoice) {
  EXPECT_EQ(choose_solver(ModalSolver::automatic, kArpackAboveDofs, 0), ModalSolver::dense);
  EXPECT_EQ(choose_solver(ModalSolver::automatic, kArpackAboveDofs + 1, 0), ModalSolver::arpack);
  EXPECT_EQ(choose_solver(ModalSolver::automatic, 1000, 500), ModalSolver::dense);  // half the spectrum
  EXPECT_EQ(choose_solver(ModalSolver::dense, 100000, 20), ModalSolver::dense);
  EXPECT_EQ(choose_solver(ModalSolver::arpack, 10, 2), ModalSolver::arpack);
  for (ModalSolver s : {ModalSolver::dense, ModalSolver::arpack, ModalSolver::automatic})
    EXPECT_EQ(modal_solver_from_string(to_string(s)), s);
  EXPECT_FALSE(modal_solver_from_string("lanczos"));
}

// Matrix Market kept sparse end to end: the train written and read back gives the same modes.
TEST(Arpack, TrainThroughMatrixMarketFiles) {
  const SparseSystem train = wagon_train(120);
  std::vector<std::string> labels;
  for (const auto& d : train.dofs) labels.push_back(d.label);
  std::ostringstream m_text, k_text;
  write_matrix_market(m_text, train.mass, true, labels);
  write_matrix_market(k_text, train.stiffness, true);
  const std::string m_path = write_temp("train_M.mtx", m_text.str());
  const std::string k_path = write_temp("train_K.mtx", k_text.str());
  const SparseSystem read = to_sparse_system(load_matrix_model(m_path, k_path));
  EXPECT_EQ(read.dofs[7].label, "wagon2.body.pitch");
  const auto a = solve_modes(read, arpack(10));
  const auto b = solve_modes(train, arpack(10));
  ASSERT_EQ(a.modes.size(), b.modes.size());
  // 17 significant digits round-trip exactly: the same matrices, the same answer.
  for (size_t i = 0; i < a.modes.size(); ++i) EXPECT_EQ(a.modes[i].eigenvalue, b.modes[i].eigenvalue);
}

TEST(WagonTrain, SizeSymmetryAndOneRigidBodyMode) {
  const SparseSystem t = wagon_train(3);
  ASSERT_EQ(t.size(), 15);
  EXPECT_EQ(t.dofs[0].label, "wagon1.body.longitudinal");
  EXPECT_EQ(t.dofs[14].label, "wagon3.bogie2.bounce");
  const Eigen::MatrixXd K(t.stiffness), M(t.mass), C(t.damping);
  EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((C - C.transpose()).cwiseAbs().maxCoeff(), 0.0);
  const auto r = solve_modes(t, dense());
  int rigid = 0;
  for (const auto& m : r.modes) rigid += m.kind == ModeKind::rigid_body;
  EXPECT_EQ(rigid, 1);  // the whole train rolling along the track
  EXPECT_THROW(wagon_train(0), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::test
