// Two tests on a mode that several parts of the response must decide alike: whether damping
// acts on it, and whether it moves a given quantity (a DOF, an element's stretch).
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal::response {

/// No damping acts on the mode: φᵀCφ is round-off of ‖C‖‖φ‖² (a damper the mode does not move,
/// e.g. one on the axis of symmetry of an antisymmetric mode, gives ~1e-17 in the computed φ;
/// taken at face value it would give a finite "resonance" of 1e14).
inline bool undamped(const LinearSystem& system, const Mode& mode) {
  return std::abs(mode.shape.dot(system.damping * mode.shape)) <= 1e-12 * system.damping.norm() * mode.shape.squaredNorm();
}

/// The mode moves the quantity row·x: by more than 1e-9 of its largest entry times ‖row‖₁
/// (symmetry zeros are round-off, far below).
inline bool moves(const Eigen::RowVectorXd& row, const Eigen::VectorXd& shape) {
  return std::abs(row.dot(shape)) > 1e-9 * shape.cwiseAbs().maxCoeff() * row.cwiseAbs().sum();
}

}  // namespace railmodal::response
