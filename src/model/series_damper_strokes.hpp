// A series damper (a dashpot c in series with a spring k: SeriesDamperRow) as one more degree
// of freedom, the stroke u of its dashpot. With s = stretch·q the element's stretch, the spring
// stretches by s − u and the dashpot by u, so the element stores ½k(s − u)² and dissipates
// through c·u̇:
//   K gains [[k·stretchᵀstretch, −k·stretchᵀ], [−k·stretch, k]],  C gains c on u alone,  M nothing,
// and u's own row, c·u̇ = k(s − u), is the damper's law f + (c/k)·ḟ = c·ṡ for its force
// f = c·u̇ = k(s − u) (the Maxwell element of ride_transfer.hpp's k_s(ω) = iωck/(k + iωc)).
//
// Why the stroke and not the force f (the state stability's FirstOrderSystem carries): u is a
// displacement like q, so the extended M, C, K stay symmetric, in the units of the others
// (m, N/m, N·s/m: a matrix exponential or a balanced eigensolver sees blocks of ω² and 1/s,
// where f would bring rows of k ≈ 1e7 N/m beside M⁻¹ ≈ 1e-5); and statically u follows s (the
// damper carries no static force), so the undamped modes are unchanged and a solver that
// already carries massless damped degrees of freedom as first-order states needs nothing new.
#pragma once

#include <Eigen/Core>

#include "railmodal/linear_system.hpp"

namespace railmodal::model {

/// `system` with one massless degree of freedom appended per series damper, in
/// system.series_dampers order: its stroke, labelled "<element>.<direction> stroke", body −1,
/// motion the damper's direction. The dampers move into M, C and K (as in the file comment), so
/// series_dampers is empty; gravity_stiffness, element_vertical_map and the track inputs' loads
/// gain zero entries for the strokes (no track input reaches a stroke: the analyses refuse a
/// series damper on an element standing on the track). Throws std::invalid_argument for a
/// damper whose stretch is not one entry per degree of freedom, or whose damping or stiffness is
/// not positive and finite.
LinearSystem with_series_damper_strokes(const LinearSystem& system);

/// Each stroke's static follower: u = stretch·q, one row per series damper (m × n): the
/// strokes' entries of an undamped mode shape.
Eigen::MatrixXd stroke_followers(const LinearSystem& system);

}  // namespace railmodal::model
