// The wheel–rail creep contact in the ride: at each speed the vehicle's equations gain the
// linear contact terms the stability analysis assembles (C_c/V + V·G, K_c), and the track's
// alignment y_t loads each wheelset through the same terms, on the part of its state that is
// measured from the rail (docs/ride.md, "Lateral ride through the creep forces").
#pragma once

#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/wheel_rail.hpp"

namespace railmodal::ride {

/// What every speed shares: the contact matrices and, per wheelset, where its alignment input
/// acts.
struct CreepContact {
  ContactMatrices matrices;
  /// Per wheelset (vehicle.wheelsets order): its lateral DOF, the x of its axle (the input's
  /// delay), and ρ = (κ − 1)/κ, κ = 1 + σ·r0/l0: the share of the lateral creepage's ẏ term that
  /// the wheelset's roll on the rails makes, and so measures from the rail.
  std::vector<int> lateral;
  std::vector<double> x;
  std::vector<double> relative_share;
  /// With cross-level (creep_contact's `cross_level`): per wheelset, its yaw DOF, r0, W, the
  /// spin term I_y/r0, the rails' roll per metre of cross-level 1/(2b), and the generalised
  /// forces of the elements that hold it per radian of its roll with the rails (stiff, viscous):
  /// an element attached at height h above the axle plane moves there sideways by −θ·h.
  bool cross_level = false;
  std::vector<int> yaw;
  std::vector<double> lever;  ///< x_axle − x_ref (wheelset_dofs)
  std::vector<double> rolling_radius, axle_load, spin_term, roll_per_cross_level;
  std::vector<Eigen::VectorXd> suspension_roll_stiff, suspension_roll_viscous;
};

/// Whether the vehicle's wheelsets move laterally in `system` (wheelsets, and their lateral DOF
/// assembled): then the ride must include the contact, or the wheelsets' lateral modes would
/// stand on their suspension alone.
bool acts_through_contact(const LinearSystem& system);

/// The contact of `system`'s wheelsets (contact_matrices; its errors name the wheelset). With
/// `cross_level`, also what the rails' roll θ = Δz/(2b) does through it (b: `contact_half_spacing`
/// when positive, else the wheelset's l0, the convention of cross_level_directions).
CreepContact creep_contact(const LinearSystem& system, double contact_half_spacing = 0.0, bool cross_level = false);

/// `system` at speed V with the contact: damping + C_c/V + V·G, stiffness + K_c, and one track
/// input per wheelset appended after the elements' (element = −1, at its axle), whose lateral
/// column carries the alignment's generalised force: K_c·e_y per metre of y_t, and
/// (ρ·C_c/V + V·G)·e_y per m/s of ẏ_t (e_y the wheelset's lateral DOF). With
/// `contact.cross_level`, one more input per wheelset after those (element = kRailRollInput, at
/// its axle) whose first column carries the generalised force per metre of cross-level Δz
/// (rail_roll_load; the track's displacement of this input is (Δz, 0, 0): contact_direction).
LinearSystem with_creep(const LinearSystem& system, const CreepContact& contact, double speed);

/// TrackInput::element of the contact's inputs: the alignment's (lateral column) and the rails'
/// roll (first column, per metre of cross-level).
constexpr int kAlignmentInput = -1;
constexpr int kRailRollInput = -2;

/// The track displacement of a contact input (element kAlignmentInput or kRailRollInput) per
/// unit of a component: the alignment input takes the alignment, (0, 1, 0); the roll input
/// takes the cross-level, (1, 0, 0) (its column is per metre of Δz); nothing else reaches them
/// (the level lifts both rails, which the wheelset follows).
Eigen::Vector3d contact_direction(int element, TrackIrregularity kind);

/// The generalised force of the rails' roll on the DOFs per metre of cross-level at speed V,
/// stiff and viscous parts (docs/ride.md, "Cross-level through the contact"), for wheelset i;
/// `contact_only` leaves out the elements holding the wheelset (the wheel–rail force output).
struct RollLoad {
  Eigen::VectorXd stiff, viscous;
};
RollLoad rail_roll_load(const CreepContact& contact, std::size_t i, double speed, bool contact_only);

/// The eigenvalues of `system`'s first-order form, x = (q, q̇, F) with the series dampers'
/// forces F (with its contact terms when it is with_creep's), 1/s.
Eigen::VectorXcd first_order_roots(const LinearSystem& system);

/// A free motion of `system`'s first-order form that grows (above the linear critical speed):
/// its root λ (Re λ > 0; of a complex pair the one with Im λ ≥ 0) and its displacement shape, the
/// q part of its eigenvector over system.dofs.
struct GrowingMotion {
  std::complex<double> root;
  Eigen::VectorXcd shape;
};

/// Every growing motion of `system` (a root with a real part above round-off); none below the
/// linear critical speed. The eigenvectors are computed only when some root grows.
std::vector<GrowingMotion> growing_motions(const LinearSystem& system);

}  // namespace railmodal::ride
