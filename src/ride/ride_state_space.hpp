// The vehicle on moving track as a first-order system without input derivatives, and the
// ride outputs as rows on it. With the track displacements w (TrackUnderWheels) the loads are
// Bd·w + Bv·ẇ (LinearSystem::TrackInput); with the state s = (q, v), v = q̇ − M⁻¹Bv·w,
//   q̇ = v + M⁻¹Bv w,   v̇ = −M⁻¹K q − M⁻¹C v + M⁻¹(Bd − C M⁻¹Bv) w,
// so ṡ = A s + B w has no ẇ: a piecewise-linear track gives a piecewise-linear input, which
// the first-order hold integrates exactly (ride_march.hpp). (v is a velocity, so A's blocks
// are of the vehicle's ω² and ω: the matrix exponential sees a well-scaled matrix, where the
// momentum M q̇ − Bv w would mix N·s with m and lose digits of the small blocks.)
//
// Series dampers (LinearSystem::series_dampers) add the stroke u of each dashpot to the state,
// s = (q, v, u) (model/series_damper_strokes.hpp: a displacement, so A keeps its blocks of ω²
// and 1/s, where the damper's force would bring rows of k ≈ 1e7 beside M⁻¹):
//   v̇ = … − M⁻¹(K_qu u) with K_qq, K_qu the extended stiffness' rows of q,   u̇ = (k/c)(stretch·q − u),
// no input reaching u (a series damper on an element standing on the track is refused, as the
// frequency domain refuses it). Its transfer function is the frequency domain's with the
// Maxwell stiffness k_s(ω) = iωck/(k + iωc) (ride_transfer.hpp).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride.hpp"

namespace railmodal::ride {

struct RideStateSpace {
  int n = 0;                // degrees of freedom
  int strokes = 0;          // series dampers; the state has 2n + strokes: (q, v, u)
  Eigen::MatrixXd A, B;     // states × states, states × 3·inputs
  Eigen::MatrixXd mass_inverse, Bd, Bv;  // M⁻¹ and the inputs' loads, n × 3·inputs
  /// The elastic forces on the DOFs are −position_stiffness·(q, u): K (with each series
  /// spring's k·stretchᵀstretch) and −k·stretchᵀ per stroke, n × (n + strokes).
  Eigen::MatrixXd position_stiffness;
  int states() const { return 2 * n + strokes; }
};

/// Throws std::invalid_argument for massless degrees of freedom (the time-domain ride integrates
/// M⁻¹) and for a series damper on an element standing on the track, and NumericalError for a
/// mass matrix that is not positive definite.
RideStateSpace ride_state_space(const LinearSystem& system);

/// An output as y = Ls·s + Lw·w + Ld·ẇ.
struct OutputRow {
  Eigen::RowVectorXd Ls, Lw, Ld;
  /// An acceleration's r (y = r·q̈), for the nonlinear path to add r·(q̈ − q̈_linear); empty
  /// for other quantities.
  Eigen::RowVectorXd La;
};

/// The rows of `outputs`. Throws std::invalid_argument for an output naming no body or
/// element of the system, and for the kinds the time domain does not build yet (element
/// forces, wheel–rail forces, deflections other than vertical).
std::vector<OutputRow> output_rows(const LinearSystem& system, const RideStateSpace& model,
                                   const std::vector<RideOutput>& outputs);

}  // namespace railmodal::ride
