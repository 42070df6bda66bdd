// Following each root of the first-order system from speed to speed.
#pragma once

#include <vector>

#include "stability/first_order_system.hpp"

namespace railmodal::stability {

/// Roots closer than this (relative distance |λ − μ|/(|λ| + |μ|)) are twins: taken as one value,
/// in order, by track_roots, and compared as one subspace by the branch continuity (branches.cpp).
inline constexpr double kTwins = 1e-4;

/// Root paths over the speed grid: path p is root path[s][p] at speed s.
struct RootPaths {
  std::vector<std::vector<int>> root;  ///< [speed][path] → index into that speed's roots
  /// [speed][path]: MAC of the path's shape with its shape at the previous speed (1 at the first).
  std::vector<std::vector<double>> continuity;
};

/// Follows every root (both halves of each conjugate pair, and the real roots) from each speed
/// to the next, predicting each path's eigenvalue λ̂ linearly from its last two speeds.
///  - Where the eigenvalues alone decide (each path's nearest root, in relative distance
///    |λ − λ̂|/(|λ| + |λ̂|), is at most a fifth of the distance to the next nearest root of a
///    different value, and no two paths want the same one), each path continues to its nearest
///    root, continuity 1: no shapes are needed there. Twins, roots that agree to a relative 1e-4
///    (a symmetric vehicle's front and rear wheelsets or bogies, whose roots split by 1e-5 and
///    less), count as one value and are taken in order: which twin a path continues to is not
///    decided (nor could a MAC decide it reliably where the split is that small), and its ζ and
///    frequency are right to 1e-4 whichever it is. A true crossing passes through twins without
///    harm: the prediction from the two speeds before carries each path on.
///  - Elsewhere, if both speeds have shapes, by the minimum-cost assignment (Hungarian method)
///    with cost (1 − MAC(shape_p, shape_j)) + |λ_j − λ̂_p|/(|λ_j| + |λ̂_p|), the continuity the
///    MAC. The MAC keeps a mode's identity where eigenvalues come close or cross; the eigenvalue
///    term tells apart what the MAC cannot: the two halves of a conjugate pair (conjugate shapes,
///    MAC ≈ 1 for a nearly real shape) and the two real roots of an overdamped mode.
///  - If shapes are missing there, the assignment uses the eigenvalue term alone and the speeds
///    without shapes are added to `missing`: solve them with shapes and track again.
RootPaths track_roots(const std::vector<SpeedRoots>& speeds, std::vector<int>* missing);

/// The assignment of rows to columns of a square cost matrix that minimises the total cost
/// (Kuhn–Munkres with potentials, O(n³)); returns the column of each row.
std::vector<int> minimum_cost_assignment(const std::vector<std::vector<double>>& cost);

/// |aᴴb|² / (‖a‖²‖b‖²), 0 when either is zero.
double modal_assurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);

}  // namespace railmodal::stability
