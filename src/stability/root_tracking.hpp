// Following each root of the first-order system from speed to speed.
#pragma once

#include <vector>

#include "stability/first_order_system.hpp"

namespace railmodal::stability {

/// Root paths over the speed grid: path p is root path[s][p] at speed s.
struct RootPaths {
  std::vector<std::vector<int>> root;  ///< [speed][path] → index into that speed's roots
  /// [speed][path]: MAC of the path's shape with its shape at the previous speed (1 at the first).
  std::vector<std::vector<double>> continuity;
};

/// Follows every root (both halves of each conjugate pair, and the real roots) from each speed
/// to the next by a minimum-cost assignment (Hungarian method), the cost of continuing path p
/// with root j being (1 − MAC(shape_p, shape_j)) + |λ_j − λ̂_p| / (|λ_j| + |λ̂_p|), λ̂_p the
/// path's eigenvalue extrapolated linearly from its last two speeds. The MAC keeps a mode's
/// identity where eigenvalues cross; the eigenvalue term tells apart what the MAC cannot: the
/// two halves of a conjugate pair (whose shapes are conjugate, MAC ≈ 1 for a nearly real shape)
/// and the two real roots of an overdamped mode. Needs shapes at every speed.
RootPaths track_roots(const std::vector<SpeedRoots>& speeds);

/// The assignment of rows to columns of a square cost matrix that minimises the total cost
/// (Kuhn–Munkres with potentials, O(n³)); returns the column of each row.
std::vector<int> minimum_cost_assignment(const std::vector<std::vector<double>>& cost);

/// |aᴴb|² / (‖a‖²‖b‖²), 0 when either is zero.
double modal_assurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);

}  // namespace railmodal::stability
