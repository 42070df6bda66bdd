// What several parts of the response must decide alike about modes: whether damping acts on a
// mode, whether it moves a given quantity (a DOF, an element's stretch), and which modes share
// one eigenspace.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "railmodal/excitation.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal::response {

/// No damping acts on the mode: φᵀCφ is round-off of ‖C‖‖φ‖² (a damper the mode does not move,
/// e.g. one on the axis of symmetry of an antisymmetric mode, gives ~1e-17 in the computed φ;
/// taken at face value it would give a finite "resonance" of 1e14).
inline bool undamped(const LinearSystem& system, const Mode& mode) {
  // Cφ into this thread's vector, kept between calls (the same product as a temporary's).
  thread_local Eigen::VectorXd damping_shape;
  damping_shape.noalias() = system.damping * mode.shape;
  return std::abs(mode.shape.dot(damping_shape)) <= 1e-12 * system.damping.norm() * mode.shape.squaredNorm();
}

/// The one round-off rule for loads: a load Q_k (one harmonic of a source) drives a mode only
/// where its modal force |φᵀQ_k| exceeds kLoadRoundOff·‖φ‖·‖Q‖, with ‖Q‖ = √(Σ_j ‖Q_j‖²) the
/// source's TOTAL load over all its harmonics, never the harmonic's own: a harmonic whose load
/// is itself round-off (the 3rd harmonic of a cosine dip as long as the rail, ~1e-17 of the
/// fundamental) would otherwise pass a test relative to itself and "resonate" with a growth of
/// 1e-31 mm. Why 1e-9: what a computed modal force holds of round-off is ~1e-16 of ‖φ‖‖Q‖
/// (symmetry zeros seen through eigenvectors with residuals of ~1e-15, closed-form Fourier
/// coefficients at their zeros), so 1e-9 leaves six orders for worse-conditioned eigenvectors;
/// yet a real load component of 1e-9 of the source's grows a resonance by 1e-9 of what the
/// source's main harmonic does, below the digits a report prints. The critical speeds, the
/// direct and modal responses (harmonic_response and modal_harmonic_response, each given its
/// source's `source_load_norm`) and the sweeps all use this one rule.
constexpr double kLoadRoundOff = 1e-9;

/// The modal force φᵀQ, or exactly 0 where it is round-off by the rule above, `source_load`
/// being the source's total load norm √(Σ_j ‖Q_j‖²) (Q's own norm for a one-harmonic load).
/// Below that a load neither drives a mode at resonance nor adds to a response.
inline std::complex<double> modal_force(const Mode& mode, const Eigen::VectorXcd& load, double source_load) {
  const std::complex<double> f = mode.shape.cast<std::complex<double>>().dot(load);
  return std::abs(f) > kLoadRoundOff * mode.shape.norm() * source_load ? f : 0.0;
}

/// The source's total load at a speed, √(Σ_k ‖Q_k‖²) over its harmonics: what kLoadRoundOff
/// is relative to.
inline double source_load_norm(const LinearSystem& system, const ExcitationSource& source, double speed) {
  double squared = 0.0;
  for (int k = 1; k <= source.harmonic_count(); ++k)
    squared += generalized_load(system, source.load(system, speed, k)).squaredNorm();
  return std::sqrt(squared);
}

/// The mode moves the quantity row·x: by more than 1e-9 of its largest entry times ‖row‖₁
/// (symmetry zeros are round-off, far below).
inline bool moves(const Eigen::RowVectorXd& row, const Eigen::VectorXd& shape) {
  return std::abs(row.dot(shape)) > 1e-9 * shape.cwiseAbs().maxCoeff() * row.cwiseAbs().sum();
}

/// Oscillatory modes grouped by frequency: a repeated frequency (relative gap below 1e-8, as
/// Mode::repeated) is one eigenspace, whose basis the solver chose arbitrarily. Modes come in
/// ascending order, so each group is a run; the critical speeds name a group by its first mode.
/// Written into `groups`, whose lists serve again (a study's worker finds them per variant).
inline void eigenspaces_into(const ModalResult& modes, std::vector<std::vector<const Mode*>>* groups) {
  size_t count = 0;
  for (const Mode& m : modes.modes) {
    if (m.kind != ModeKind::oscillatory) continue;
    if (count > 0 && std::abs(m.eigenvalue - (*groups)[count - 1].front()->eigenvalue) <= 1e-8 * m.eigenvalue) {
      (*groups)[count - 1].push_back(&m);
      continue;
    }
    if (count == groups->size()) groups->emplace_back();
    (*groups)[count++].assign(1, &m);
  }
  groups->resize(count);
}

inline std::vector<std::vector<const Mode*>> eigenspaces(const ModalResult& modes) {
  std::vector<std::vector<const Mode*>> groups;
  eigenspaces_into(modes, &groups);
  return groups;
}

/// The name of an eigenspace (CriticalSpeed::mode_name) from its modes' names: its first mode's,
/// and each other's that differs, after " + " (a repeated cluster of twins has one name for the
/// subspace: "bogies pitch (repeated)"). Written into `name`, its storage reused.
inline void name_eigenspace(const std::vector<const Mode*>& group, std::string* name) {
  name->assign(group.front()->name);
  for (size_t g = 1; g < group.size(); ++g)
    if (group[g]->name != group.front()->name) name->append(" + ").append(group[g]->name);
}

/// The eigenspace whose first mode has 1-based index `mode` (CriticalSpeed::mode); empty if none.
inline std::vector<const Mode*> eigenspace_of(const ModalResult& modes, int mode) {
  for (auto& group : eigenspaces(modes))
    if (group.front()->index == mode) return group;
  return {};
}

}  // namespace railmodal::response
