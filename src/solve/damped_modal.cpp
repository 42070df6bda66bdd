// Damped (complex) modes: the state-space eigenproblem of M q̈ + C q̇ + K q = 0 written in
// the undamped modal coordinates, each eigenvalue matched to the undamped mode it comes from.
//
// Coordinates. q = Φ η + G w: Φ holds the mass-normalised undamped modes (massless DOFs
// recovered statically, as solve_modes() gives them), w the deviation of each massless
// *damped* DOF from that static follower, G its influence (1 on the DOF itself, the static
// response −K_uu⁻¹K_ud of the massless undamped DOFs u, 0 on the DOFs with mass). In these
// coordinates the pencil is exact and small:
//   λ² diag(I, 0) + λ Ĉ + diag(Λ, K_w),   Ĉ = [Φ G]ᵀ C [Φ G],  K_w = Gᵀ K G,
// because Φ is M-orthonormal and K-orthogonal and the static recovery makes ΦᵀKG = 0. The
// massless undamped DOFs carry no equation of their own any more (their rows are satisfied
// by construction), so no infinite eigenvalues appear; a massless damped DOF gives
// ẇ = −C_ww⁻¹(C_wη η̇ + K_w w), a first-order state.
//
// State. x = (ω₁η₁, η̇₁, ω₂η₂, η̇₂, …, w) with ω_i = √|λ_i|: each undamped mode is the 2×2
// block [[0, ω],[∓ω, 0]] plus damping terms. This is the energy norm (|ωη|² + |η̇|² is twice
// the mode's energy), so the state matrix is balanced by construction, and with C = 0 it is
// block diagonal: the real Schur form needs no rotation and the eigenvalues come out as
// exactly ±iω_i, ζ = 0. A rigid-body mode's position never enters the equations (Λ_r = 0),
// so it is left out of the state and reported with the exact eigenvalue 0: keeping it would
// make a defective double zero that round-off splits by √ε.
//
// Solver. Eigen::EigenSolver on the real state matrix (Hessenberg reduction and real Schur
// form, Golub & Van Loan §7.5): complex eigenvalues come in exact conjugate pairs from its
// 2×2 blocks, which makes pairing certain; a complex solver would not keep them conjugate, and
// a generalised (QZ) solver on the 2n pencil would bring back the infinite eigenvalues of the
// massless DOFs that the coordinates above remove exactly. The w states have other units,
// so the matrix is balanced by powers of two (Parlett–Reinsch, as LAPACK's dgebal) before the
// solve: exact in floating point, a no-op on the already balanced mode blocks.
//
// Series dampers. Each becomes one more massless damped DOF, the stroke of its dashpot
// (model/series_damper_strokes.hpp, which says why the stroke rather than the force), so it is
// one more w above and nothing else changes: the undamped modes are the system's own (the
// stroke follows the stretch statically, the entries of Φ on the strokes), the pencil and the
// residual are those of the extended M, C, K. Its root, near −k/c, is a first-order mode named
// "series damper relaxation (<element>)", as `railmodal stability` names it.
#include "railmodal/damped_modal.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "model/analysis_limits.hpp"
#include "model/series_damper_strokes.hpp"
#include "railmodal/errors.hpp"
#include "require_valid.hpp"
#include "shortest_text.hpp"
#include "solve/balance.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

const char* to_string(DampedModeKind kind) {
  switch (kind) {
    case DampedModeKind::underdamped: return "underdamped";
    case DampedModeKind::critical: return "critical";
    case DampedModeKind::overdamped: return "overdamped";
    case DampedModeKind::divergent: return "divergent";
    case DampedModeKind::first_order: return "first-order";
    case DampedModeKind::rigid_body: return "rigid-body";
  }
  return "?";
}

std::optional<DampedModeKind> damped_mode_kind_from_string(const std::string& word) {
  for (DampedModeKind k : {DampedModeKind::underdamped, DampedModeKind::critical, DampedModeKind::overdamped,
                           DampedModeKind::divergent, DampedModeKind::first_order, DampedModeKind::rigid_body})
    if (word == to_string(k)) return k;
  return std::nullopt;
}

bool DampedModalOptions::is_valid(std::string* why) const {
  if (!undamped.is_valid(why)) return false;
  if (!(critical_gap > 0.0 && critical_gap < 1e-2))
    return invalid(why, "critical_gap must satisfy 0 < critical_gap < 1e-2");
  return true;
}

namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 6.283185307179586476925;
// Re λ above this fraction of the largest |λ| is growth, not round-off. The state matrix is
// balanced, so its eigenvalues carry absolute errors of order ε·max|λ| ≈ 2e-16·max|λ| times
// a modest condition number; 1e-11 leaves that five orders of headroom yet still sees a
// negative damping ratio of 1e-11·f_max/f on any mode.
constexpr double kGrowthTolerance = 1e-11;

Eigen::MatrixXd take(const Eigen::MatrixXd& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  Eigen::MatrixXd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) out(i, j) = A(rows[i], cols[j]);
  return out;
}

// Massless DOFs: with damping (row or column of C) they become first-order states w, without
// they stay condensed statically.
struct MasslessDofs {
  std::vector<int> damped, undamped;
};

// The coordinates q = Φ η + G w of the file comment.
struct ModalCoordinates {
  Eigen::MatrixXd Phi;      // the mass-normalised undamped modes, one per column
  Eigen::MatrixXd G;        // the influence of each w
  std::vector<int> damped;  // the massless damped DOF of each w
  int modes() const { return static_cast<int>(Phi.cols()); }
  int first_order() const { return static_cast<int>(damped.size()); }
};

// The equations in (η, w): η̈ = −Λη − D η̇ + E w and ẇ = −F η̇ − Gw w.
struct ReducedEquations {
  Eigen::VectorXd lambda;  // Λ
  Eigen::MatrixXd D, E, F, Gw;
  Eigen::MatrixXd Kw;  // GᵀKG, empty without w
};

// Where each undamped mode's coordinates sit in the state vector.
struct StateLayout {
  std::vector<int> position;  // -1 for a rigid-body mode (left out)
  std::vector<int> velocity;
  std::vector<double> omega;  // the position slot holds ω_k η_k; 0 for a rigid-body mode
  int first_w = 0;
  int size = 0;
  int modes() const { return static_cast<int>(velocity.size()); }
  int first_order() const { return size - first_w; }
};

struct StateEigensolution {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
};

// One eigenvalue of the state matrix (or the exact 0 of a rigid-body position), with its
// state vector and the share of energy each slot carries in it.
struct Root {
  cd lambda;
  Eigen::VectorXcd state;  // empty for the exact zero of a rigid-body position
  bool pair = false;       // stands for itself and its conjugate
  int slot = -1;
};
using RootGroup = std::vector<const Root*>;  // the roots of one damped mode

// The share of a root's energy that one slot carries.
struct Share {
  double value;
  int root, slot;
};

// |λ| up to `zero` is zero, Re λ above `growth` is growth; both relative to the largest |λ|.
struct RootTolerances {
  double zero = 0.0;
  double growth = 0.0;
};

double relative_residual(const LinearSystem& s, const Eigen::MatrixXd& C, cd lambda, const Eigen::VectorXcd& phi,
                         double norm_M, double norm_C, double norm_K) {
  const Eigen::VectorXcd r = (lambda * lambda) * (s.mass.cast<cd>() * phi) + lambda * (C.cast<cd>() * phi) +
                             s.stiffness.cast<cd>() * phi;
  const double a = std::abs(lambda);
  const double denom = (a * a * norm_M + a * norm_C + norm_K) * phi.norm();
  return denom > 0.0 ? r.norm() / denom : 0.0;
}

MasslessDofs massless_dofs(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C) {
  MasslessDofs massless;
  for (int i = 0; i < M.rows(); ++i) {
    if (M.row(i).cwiseAbs().maxCoeff() != 0.0) continue;
    const bool has_damper = C.row(i).cwiseAbs().maxCoeff() > 0.0 || C.col(i).cwiseAbs().maxCoeff() > 0.0;
    (has_damper ? massless.damped : massless.undamped).push_back(i);
  }
  return massless;
}

// The undamped modes over the DOFs of `system`: `und`'s shapes (solved without the series
// dampers, `original`), and below them each series damper's stroke, which follows its stretch.
Eigen::MatrixXd undamped_shapes(const LinearSystem& original, const ModalResult& und) {
  const int n = original.size(), nm = static_cast<int>(und.modes.size());
  const Eigen::MatrixXd S = model::stroke_followers(original);
  Eigen::MatrixXd Phi(n + S.rows(), nm);
  for (int k = 0; k < nm; ++k) Phi.col(k).head(n) = und.modes[k].shape;
  Phi.bottomRows(S.rows()).noalias() = S * Phi.topRows(n);
  return Phi;
}

// Φ the undamped modes; G is 1 on each w's own DOF and the static response −K_uu⁻¹K_ud on
// the massless undamped DOFs u, which must be restrained without the w.
ModalCoordinates modal_coordinates(const LinearSystem& system, Eigen::MatrixXd Phi, const MasslessDofs& massless) {
  const int n = system.size();
  const std::vector<int>& damped = massless.damped;
  const int nw = static_cast<int>(damped.size());
  ModalCoordinates q;
  q.damped = damped;
  q.Phi = std::move(Phi);
  q.G = Eigen::MatrixXd::Zero(n, nw);
  for (int k = 0; k < nw; ++k) q.G(damped[k], k) = 1.0;
  if (nw > 0 && !massless.undamped.empty()) {
    const Eigen::MatrixXd& K = system.stiffness;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(take(K, massless.undamped, massless.undamped));
    lu.setThreshold(1e-12);
    if (!lu.isInvertible())
      throw NumericalError("the massless degrees of freedom without damping have no restraint of their own once '" +
                           system.dofs[damped[0]].label + "' (massless, damped) is free to move");
    const Eigen::MatrixXd follow = -lu.solve(take(K, massless.undamped, damped));
    for (size_t a = 0; a < massless.undamped.size(); ++a)
      q.G.row(massless.undamped[a]) = follow.row(static_cast<int>(a));
  }
  return q;
}

// Names the massless damped DOFs that move in a direction no damper resists.
NumericalError undamped_motion_error(const Eigen::FullPivLU<Eigen::MatrixXd>& lu, const LinearSystem& system,
                                     const std::vector<int>& damped) {
  const Eigen::VectorXd v = lu.kernel().col(0);
  std::string names;
  for (int k = 0; k < static_cast<int>(damped.size()); ++k)
    if (std::abs(v(k)) > 1e-6 * v.cwiseAbs().maxCoeff())
      names += (names.empty() ? "'" : ", '") + system.dofs[damped[k]].label + "'";
  return NumericalError("the massless degrees of freedom " + names +
                        " have dampers but some combination of them moves without damping; give them "
                        "inertia, a damper of their own, or remove the damper");
}

// The pencil in (η, w): Ĉ = BᵀCB with B = [Φ G]; Λ exact (0 for rigid-body modes, which
// solve_modes() found below its zero tolerance); K_w = GᵀKG. The w rows are solved for ẇ.
ReducedEquations reduce_equations(const LinearSystem& system, const Eigen::MatrixXd& C, const ModalResult& und,
                                  const ModalCoordinates& q) {
  const int nm = q.modes(), nw = q.first_order();
  Eigen::MatrixXd B(system.size(), nm + nw);
  B << q.Phi, q.G;
  const Eigen::MatrixXd Chat = B.transpose() * C * B;
  ReducedEquations eq;
  eq.lambda.resize(nm);
  for (int k = 0; k < nm; ++k) eq.lambda(k) = und.modes[k].kind == ModeKind::rigid_body ? 0.0 : und.modes[k].eigenvalue;
  eq.D = Chat.topLeftCorner(nm, nm);  // velocity coupling of the modes
  eq.E = Eigen::MatrixXd::Zero(nm, nw), eq.F = Eigen::MatrixXd::Zero(nw, nm), eq.Gw = Eigen::MatrixXd::Zero(nw, nw);
  if (nw == 0) return eq;
  eq.Kw = q.G.transpose() * system.stiffness * q.G;
  const Eigen::MatrixXd Cww = Chat.bottomRightCorner(nw, nw);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Cww);
  lu.setThreshold(1e-12);
  if (!lu.isInvertible()) throw undamped_motion_error(lu, system, q.damped);
  const Eigen::MatrixXd Cwe = Chat.bottomLeftCorner(nw, nm), Cew = Chat.topRightCorner(nm, nw);
  eq.F = lu.solve(Cwe);  // ẇ = −F η̇ − Gw w
  eq.Gw = lu.solve(eq.Kw);
  eq.D -= Cew * eq.F;  // η̈ = −Λη − D η̇ + E w
  eq.E = Cew * eq.Gw;
  return eq;
}

StateLayout lay_out_state(const ModalResult& und, const Eigen::VectorXd& lambda, int nw) {
  const int nm = static_cast<int>(und.modes.size());
  StateLayout layout;
  layout.position.assign(nm, -1);
  layout.velocity.assign(nm, -1);
  layout.omega.assign(nm, 0.0);
  for (int k = 0; k < nm; ++k) {
    if (und.modes[k].kind != ModeKind::rigid_body) {
      layout.position[k] = layout.size++;
      layout.omega[k] = std::sqrt(std::abs(lambda(k)));
    }
    layout.velocity[k] = layout.size++;
  }
  layout.first_w = layout.size;
  layout.size += nw;
  return layout;
}

// ẋ = A x for x = (ω₁η₁, η̇₁, …, w); each elastic mode is the block [[0, ω],[−λ/ω, 0]] plus damping.
Eigen::MatrixXd state_matrix(const StateLayout& layout, const ReducedEquations& eq) {
  const int nm = layout.modes(), nw = layout.first_order();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(layout.size, layout.size);
  for (int k = 0; k < nm; ++k) {
    const int v = layout.velocity[k], p = layout.position[k];
    if (p >= 0) {
      A(p, v) = layout.omega[k];
      A(v, p) = -eq.lambda(k) / layout.omega[k];
    }
    for (int j = 0; j < nm; ++j) A(v, layout.velocity[j]) = -eq.D(k, j);
    for (int j = 0; j < nw; ++j) A(v, layout.first_w + j) = eq.E(k, j);
  }
  for (int k = 0; k < nw; ++k) {
    for (int j = 0; j < nm; ++j) A(layout.first_w + k, layout.velocity[j]) = -eq.F(k, j);
    for (int j = 0; j < nw; ++j) A(layout.first_w + k, layout.first_w + j) = -eq.Gw(k, j);
  }
  if (!A.allFinite()) throw NumericalError("the state matrix of the damped system is not finite");
  return A;
}

// Balanced first (see the file comment); the eigenvectors are scaled back to the state x.
StateEigensolution solve_state_matrix(Eigen::MatrixXd A) {
  const Eigen::VectorXd scaling = solve::balance(A);
  Eigen::EigenSolver<Eigen::MatrixXd> eig(A, true);
  if (eig.info() != Eigen::Success) throw NumericalError("the state-space eigensolver did not converge");
  return {eig.eigenvalues(), scaling.cast<cd>().asDiagonal() * eig.eigenvectors()};
}

RootTolerances root_tolerances(const Eigen::VectorXcd& values, double zero_tolerance) {
  double scale = 0.0;
  for (int i = 0; i < values.size(); ++i) scale = std::max(scale, std::abs(values(i)));
  return {std::sqrt(zero_tolerance) * scale, kGrowthTolerance * scale};
}

// Roots: conjugate pairs once (Eigen stores them adjacent, +Im first), real roots singly.
std::vector<Root> state_roots(const StateEigensolution& solution) {
  const Eigen::VectorXcd& values = solution.values;
  std::vector<Root> roots;
  for (int i = 0; i < values.size(); ++i) {
    Root r;
    r.lambda = values(i);
    r.state = solution.vectors.col(i);
    if (values(i).imag() != 0.0) {
      r.pair = true;
      if (values(i).imag() < 0.0) r.lambda = std::conj(r.lambda), r.state = r.state.conjugate();
      ++i;  // skip the conjugate
    }
    roots.push_back(std::move(r));
  }
  return roots;
}

// The exact zero of each rigid-body position belongs to its mode from the start.
void add_rigid_body_zeros(std::vector<Root>& roots, const ModalResult& und) {
  for (int k = 0; k < static_cast<int>(und.modes.size()); ++k)
    if (und.modes[k].kind == ModeKind::rigid_body) {
      Root r;
      r.lambda = 0.0;
      r.slot = k;
      roots.push_back(r);
    }
}

// The share of each root's energy in each slot (a mode's or a w's), largest first.
std::vector<Share> energy_shares(const std::vector<Root>& roots, const StateLayout& layout, const Eigen::MatrixXd& Kw) {
  const int nm = layout.modes(), nw = layout.first_order(), n_slots = nm + nw;
  std::vector<Share> shares;
  for (int i = 0; i < static_cast<int>(roots.size()); ++i) {
    const Eigen::VectorXcd& x = roots[i].state;
    Eigen::VectorXd e(n_slots);
    for (int k = 0; k < nm; ++k)
      e(k) = std::norm(x(layout.velocity[k])) + (layout.position[k] >= 0 ? std::norm(x(layout.position[k])) : 0.0);
    // w's potential energy, ½wᵀK_w w per DOF, against the modes' ½(|ωη|² + |η̇|²) (twice each).
    for (int k = 0; k < nw; ++k) e(nm + k) = std::norm(x(layout.first_w + k)) * std::abs(Kw(k, k));
    const double total = e.sum();
    for (int k = 0; k < n_slots; ++k) shares.push_back({total > 0.0 ? e(k) / total : 0.0, i, k});
  }
  std::stable_sort(shares.begin(), shares.end(), [](const Share& a, const Share& b) { return a.value > b.value; });
  return shares;
}

// Slots: each undamped mode takes two eigenvalues (a rigid-body mode one more beside its
// exact zero), each first-order DOF one. Roots go to the slot with the largest share of
// their energy, largest shares first, while it has room: a label, as mode shapes under
// non-proportional damping mix the undamped ones.
void assign_slots(std::vector<Root>& roots, const std::vector<Share>& shares, const ModalResult& und, int nw) {
  const int nm = static_cast<int>(und.modes.size());
  std::vector<int> room(nm + nw, 2);
  for (int k = 0; k < nm; ++k)
    if (und.modes[k].kind == ModeKind::rigid_body) room[k] = 1;
  for (int k = 0; k < nw; ++k) room[nm + k] = 1;
  // Pairs first: they need a whole mode, and real roots placed first could leave room only in
  // halves. The real roots then fill exactly the room left, one each.
  for (bool pairs : {true, false})
    for (const Share& s : shares) {
      Root& r = roots[s.root];
      const int weight = r.pair ? 2 : 1;
      if (r.pair == pairs && r.slot < 0 && room[s.slot] >= weight) {
        r.slot = s.slot;
        room[s.slot] -= weight;
      }
    }
  for (const Share& s : shares)  // no slot with room left (only under heavy mixing): the best one
    if (roots[s.root].slot < 0) roots[s.root].slot = s.slot;
}

// The modes of one slot: each complex pair, then the real roots two by two (the rigid-body
// zero first, then the larger real part first).
std::vector<RootGroup> root_groups(const std::vector<Root>& roots, int slot) {
  RootGroup pairs, reals;
  for (const Root& r : roots)
    if (r.slot == slot) (r.pair ? pairs : reals).push_back(&r);
  std::stable_sort(reals.begin(), reals.end(), [](const Root* a, const Root* b) {
    if ((a->state.size() == 0) != (b->state.size() == 0)) return a->state.size() == 0;
    return a->lambda.real() > b->lambda.real();
  });
  std::vector<RootGroup> groups;
  for (const Root* p : pairs) groups.push_back({p});
  for (size_t i = 0; i < reals.size(); i += 2) {
    if (i + 1 < reals.size()) groups.push_back({reals[i], reals[i + 1]});
    else groups.push_back({reals[i]});
  }
  return groups;
}

// A split double root: its mean (the real part) is accurate to ε, its split only to √ε.
void set_critical(DampedMode& mode, double root) {
  mode.kind = DampedModeKind::critical;
  mode.eigenvalues = {cd(root, 0.0), cd(root, 0.0)};
  mode.damping_ratio = root <= 0.0 ? 1.0 : -1.0;
  mode.natural_frequency_hz = std::abs(root) / kTwoPi;
  mode.decay_rate = -root;
}

void classify_rigid_body(DampedMode& mode, const RootTolerances& tol) {
  mode.kind = DampedModeKind::rigid_body;
  if (mode.eigenvalues.size() == 1) mode.decay_rate = 0.0;
  else mode.decay_rate = -mode.eigenvalues[1].real();
  if (std::abs(mode.decay_rate) <= tol.zero) mode.decay_rate = 0.0;
  mode.stable = mode.decay_rate >= -tol.growth;
}

void classify_complex_pair(DampedMode& mode, cd l, double critical_gap) {
  const double w = std::abs(l);
  if (2.0 * l.imag() <= critical_gap * w) return set_critical(mode, l.real());
  mode.kind = DampedModeKind::underdamped;
  mode.damped_frequency_hz = l.imag() / kTwoPi;
  mode.damping_ratio = -l.real() / w;
  mode.natural_frequency_hz = w / kTwoPi;
}

// Two real roots a ≥ b.
void classify_real_pair(DampedMode& mode, double a, double b, double critical_gap) {
  if (a - b <= critical_gap * std::max(std::abs(a), std::abs(b)) && a * b > 0.0) {
    set_critical(mode, 0.5 * (a + b));
  } else if (a * b > 0.0) {
    mode.kind = DampedModeKind::overdamped;
    const double w = std::sqrt(a * b);
    mode.damping_ratio = -(a + b) / (2.0 * w);
    mode.natural_frequency_hz = w / kTwoPi;
  } else {
    mode.kind = DampedModeKind::divergent;  // a·b ≤ 0: a saddle, or a zero root
  }
}

// The mode's eigenvalues, stability, kind and the figures that go with the kind.
void classify(DampedMode& mode, const RootGroup& group, bool rigid_body_slot, const RootTolerances& tol,
              double critical_gap) {
  for (const Root* r : group) {
    mode.eigenvalues.push_back(r->lambda);
    if (r->pair) mode.eigenvalues.push_back(std::conj(r->lambda));
  }
  double max_re = -std::numeric_limits<double>::infinity();
  for (const cd& l : mode.eigenvalues) max_re = std::max(max_re, l.real());
  mode.decay_rate = -max_re;
  mode.stable = max_re <= tol.growth;

  const bool rigid =
      rigid_body_slot && std::any_of(group.begin(), group.end(), [](const Root* r) { return r->state.size() == 0; });
  if (rigid || (group.size() == 1 && !group[0]->pair && std::abs(group[0]->lambda) <= tol.zero))
    classify_rigid_body(mode, tol);
  else if (group[0]->pair)
    classify_complex_pair(mode, group[0]->lambda, critical_gap);
  else if (group.size() == 1)
    mode.kind = DampedModeKind::first_order;
  else
    classify_real_pair(mode, group[0]->lambda.real(), group[1]->lambda.real(), critical_gap);
}

// Shapes: η_k = x_p/ω_k (x_v/λ for a rigid-body mode), q = Φη + Gw.
Eigen::VectorXcd physical_shape(const Root& r, const ModalCoordinates& q, const StateLayout& layout, double zero) {
  if (r.state.size() == 0) return q.Phi.col(r.slot).cast<cd>();
  const int nm = q.modes(), nw = q.first_order();
  Eigen::VectorXcd eta(nm), w(nw);
  for (int k = 0; k < nm; ++k) {
    if (layout.position[k] >= 0)
      eta(k) = r.state(layout.position[k]) / layout.omega[k];
    else
      eta(k) = std::abs(r.lambda) > zero ? r.state(layout.velocity[k]) / r.lambda : r.state(layout.velocity[k]);
  }
  for (int k = 0; k < nw; ++k) w(k) = r.state(layout.first_w + k);
  return q.Phi.cast<cd>() * eta + q.G.cast<cd>() * w;
}

// Unit modal mass, in the phase that makes φ_uᵀMφ real and positive for the undamped mode φ_u
// it comes from; a first-order (or massless) shape is scaled to 1 at its largest component.
Eigen::VectorXcd normalised_shape(Eigen::VectorXcd phi, const Eigen::MatrixXd& M, const ModalCoordinates& q, int slot) {
  const double mass = phi.dot(M.cast<cd>() * phi).real();
  if (mass > 0.0 && slot < q.modes()) {
    phi /= std::sqrt(mass);
    const cd p = q.Phi.col(slot).cast<cd>().dot(M.cast<cd>() * phi);  // φ_uᵀMφ
    if (std::abs(p) > 0.0) phi *= std::conj(p) / std::abs(p);
  } else {
    Eigen::Index at = 0;
    phi.cwiseAbs().maxCoeff(&at);
    if (std::abs(phi(at)) > 0.0) phi /= phi(at);
  }
  return phi;
}

// What every damped mode is built from.
struct ModeContext {
  const LinearSystem& original;  // as given: its series dampers are the strokes of `system`
  const LinearSystem& system;    // the original with the strokes (the original without any)
  const Eigen::MatrixXd& C;
  const ModalResult& undamped;
  const ModalCoordinates& q;
  const StateLayout& layout;
  RootTolerances tol;
  double critical_gap;
  double norm_M, norm_C, norm_K;
};

// A first-order mode's name: its massless damped DOF's, or for a series damper's stroke the
// relaxation it is (the name `railmodal stability` gives it).
std::string first_order_name(const ModeContext& c, int dof) {
  const int damper = dof - c.original.size();
  if (damper < 0) return c.system.dofs[dof].label + " first-order";
  const int element = c.original.series_dampers[static_cast<size_t>(damper)].element;
  const auto& elements = c.original.vehicle.elements;
  return "series damper relaxation (" +
         (element >= 0 && element < static_cast<int>(elements.size()) ? elements[static_cast<size_t>(element)].name
                                                                       : c.system.dofs[dof].label) +
         ")";
}

DampedMode damped_mode(const RootGroup& group, int slot, const ModeContext& c) {
  const int nm = c.q.modes();
  DampedMode mode;
  mode.undamped_mode = slot < nm ? slot + 1 : 0;
  mode.name = slot < nm ? c.undamped.modes[slot].name : first_order_name(c, c.q.damped[slot - nm]);
  classify(mode, group, slot < nm && c.undamped.modes[slot].kind == ModeKind::rigid_body, c.tol, c.critical_gap);
  // Residual of each root with its own computed eigenvalue (a backward error: the mean
  // of a split critical pair is more accurate but its eigenvectors are not).
  for (const Root* r : group) {
    const Eigen::VectorXcd phi = physical_shape(*r, c.q, c.layout, c.tol.zero);
    const double residual = relative_residual(c.system, c.C, r->lambda, phi, c.norm_M, c.norm_C, c.norm_K);
    mode.residual = std::max(mode.residual, residual);
  }
  mode.shape = normalised_shape(physical_shape(*group[0], c.q, c.layout, c.tol.zero), c.system.mass, c.q, slot);
  return mode;
}

// In ascending damped frequency f_d, as every mode table is ordered (docs/product.md): damping
// moves modes by different amounts, so the undamped order is not the damped one (the coach's
// body bounce, 1.0703 Hz damped, comes after a mode at 1.0597 Hz whose undamped frequency is
// higher). A mode that does not oscillate (rigid-body, overdamped, critically damped, divergent,
// first-order) has f_d = 0 and comes first; among equals, the undamped order (slot order
// already), first-order modes last and by decay rate.
void order_modes(std::vector<DampedMode>& modes) {
  std::stable_sort(modes.begin(), modes.end(), [](const DampedMode& a, const DampedMode& b) {
    if ((a.undamped_mode == 0) != (b.undamped_mode == 0)) return b.undamped_mode == 0;
    if (a.undamped_mode == 0) return a.decay_rate < b.decay_rate;
    return a.undamped_mode < b.undamped_mode;
  });
  std::stable_sort(modes.begin(), modes.end(), [](const DampedMode& a, const DampedMode& b) {
    return a.damped_frequency_hz.value_or(0.0) < b.damped_frequency_hz.value_or(0.0);
  });
  for (size_t i = 0; i < modes.size(); ++i) modes[i].index = static_cast<int>(i) + 1;
}

}  // namespace

DampedModalResult solve_damped_modes(const LinearSystem& original, const DampedModalOptions& options) {
  require_valid(options, "DampedModalOptions: ");
  const int n = original.size();
  if (original.damping.size() != 0 && (original.damping.rows() != n || original.damping.cols() != n))
    throw std::invalid_argument("the damping matrix is " + std::to_string(original.damping.rows()) + " x " +
                                std::to_string(original.damping.cols()) + ", the system has " + std::to_string(n) +
                                " degrees of freedom");
  if (!original.damping.allFinite()) throw NumericalError("the damping matrix contains NaN or infinity");

  DampedModalResult result;
  StageClock clock(&result.summary);
  // Undamped modes without the series dampers: they carry no static force (the file comment).
  result.undamped = solve_modes(original, options.undamped);  // checks M and K, condenses, names
  clock.lap("undamped modes");
  result.notes = model::damped_mode_notes(original);  // the series dampers are in here
  LinearSystem system = model::with_series_damper_strokes(original);
  if (system.damping.size() == 0) system.damping = Eigen::MatrixXd::Zero(n, n);
  const Eigen::MatrixXd& C = system.damping;
  result.dofs = system.dofs;
  const ModalResult& und = result.undamped;

  const MasslessDofs massless = massless_dofs(system.mass, C);
  for (int i : massless.damped) result.first_order.push_back(system.dofs[i].label);
  for (int i : massless.undamped) result.condensed.push_back(system.dofs[i].label);
  const ModalCoordinates q = modal_coordinates(system, undamped_shapes(original, und), massless);
  const ReducedEquations eq = reduce_equations(system, C, und, q);
  const StateLayout layout = lay_out_state(und, eq.lambda, q.first_order());
  const StateEigensolution solution = solve_state_matrix(state_matrix(layout, eq));
  clock.lap("state-space eigenvalues");

  std::vector<Root> roots = state_roots(solution);
  const std::vector<Share> shares = energy_shares(roots, layout, eq.Kw);
  add_rigid_body_zeros(roots, und);
  assign_slots(roots, shares, und, q.first_order());

  const RootTolerances tolerances = root_tolerances(solution.values, options.undamped.zero_tolerance);
  const ModeContext context{original, system, C, und, q, layout, tolerances, options.critical_gap,
                            system.mass.norm(), C.norm(), system.stiffness.norm()};
  for (int slot = 0; slot < q.modes() + q.first_order(); ++slot)
    for (const RootGroup& group : root_groups(roots, slot)) {
      result.modes.push_back(damped_mode(group, slot, context));
      result.max_residual = std::max(result.max_residual, result.modes.back().residual);
      result.stable = result.stable && result.modes.back().stable;
    }
  order_modes(result.modes);
  clock.lap("matching and shapes");
  result.summary.analysis = "damped modes";
  result.summary.method = "QR of the balanced state matrix on the undamped modal basis (Eigen), roots matched to "
                          "undamped modes by their energy";
  result.summary.checks.push_back({"max relative residual", result.max_residual, options.undamped.max_residual,
                                   result.max_residual <= options.undamped.max_residual});
  if (!(result.max_residual <= options.undamped.max_residual))
    throw NumericalError("damped eigen-solution residual " + shortest_text(result.max_residual, 3) +
                         " exceeds the limit " + shortest_text(options.undamped.max_residual, 3));
  return result;
}

}  // namespace railmodal
