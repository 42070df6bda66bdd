// What several parts of the response must decide alike about modes: whether damping acts on a
// mode, whether it moves a given quantity (a DOF, an element's stretch), and which modes share
// one eigenspace.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal::response {

/// No damping acts on the mode: φᵀCφ is round-off of ‖C‖‖φ‖² (a damper the mode does not move,
/// e.g. one on the axis of symmetry of an antisymmetric mode, gives ~1e-17 in the computed φ;
/// taken at face value it would give a finite "resonance" of 1e14).
inline bool undamped(const LinearSystem& system, const Mode& mode) {
  return std::abs(mode.shape.dot(system.damping * mode.shape)) <= 1e-12 * system.damping.norm() * mode.shape.squaredNorm();
}

/// The modal force φᵀQ, or exactly 0 where it is round-off of ‖φ‖‖Q‖: a symmetry zero that the
/// computed eigenvectors blur to ~1e-17 (a load on the bogies' pitch against a bounce mode).
/// Below that a load neither drives a mode at resonance nor adds to a response.
inline std::complex<double> modal_force(const Mode& mode, const Eigen::VectorXcd& load) {
  const std::complex<double> f = mode.shape.cast<std::complex<double>>().dot(load);
  return std::abs(f) > 1e-12 * mode.shape.norm() * load.norm() ? f : 0.0;
}

/// The mode moves the quantity row·x: by more than 1e-9 of its largest entry times ‖row‖₁
/// (symmetry zeros are round-off, far below).
inline bool moves(const Eigen::RowVectorXd& row, const Eigen::VectorXd& shape) {
  return std::abs(row.dot(shape)) > 1e-9 * shape.cwiseAbs().maxCoeff() * row.cwiseAbs().sum();
}

/// Oscillatory modes grouped by frequency: a repeated frequency (relative gap below 1e-8, as
/// Mode::repeated) is one eigenspace, whose basis the solver chose arbitrarily. Modes come in
/// ascending order, so each group is a run; the critical speeds name a group by its first mode.
inline std::vector<std::vector<const Mode*>> eigenspaces(const ModalResult& modes) {
  std::vector<std::vector<const Mode*>> groups;
  for (const Mode& m : modes.modes) {
    if (m.kind != ModeKind::oscillatory) continue;
    if (!groups.empty() && std::abs(m.eigenvalue - groups.back().front()->eigenvalue) <= 1e-8 * m.eigenvalue)
      groups.back().push_back(&m);
    else
      groups.push_back({&m});
  }
  return groups;
}

/// The eigenspace whose first mode has 1-based index `mode` (CriticalSpeed::mode); empty if none.
inline std::vector<const Mode*> eigenspace_of(const ModalResult& modes, int mode) {
  for (auto& group : eigenspaces(modes))
    if (group.front()->index == mode) return group;
  return {};
}

}  // namespace railmodal::response
