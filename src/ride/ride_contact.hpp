// The wheel–rail creep contact in the ride: at each speed the vehicle's equations gain the
// linear contact terms the stability analysis assembles (C_c/V + V·G, K_c), and the track's
// alignment y_t loads each wheelset through the same terms, on the part of its state that is
// measured from the rail (docs/ride.md, "Lateral ride through the creep forces").
#pragma once

#include <vector>

#include "railmodal/linear_system.hpp"
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
};

/// Whether the vehicle's wheelsets move laterally in `system` (wheelsets, and their lateral DOF
/// assembled): then the ride must include the contact, or the wheelsets' lateral modes would
/// stand on their suspension alone.
bool acts_through_contact(const LinearSystem& system);

/// The contact of `system`'s wheelsets (contact_matrices; its errors name the wheelset).
CreepContact creep_contact(const LinearSystem& system);

/// `system` at speed V with the contact: damping + C_c/V + V·G, stiffness + K_c, and one track
/// input per wheelset appended after the elements' (element = −1, at its axle), whose lateral
/// column carries the alignment's generalised force: K_c·e_y per metre of y_t, and
/// (ρ·C_c/V + V·G)·e_y per m/s of ẏ_t (e_y the wheelset's lateral DOF).
LinearSystem with_creep(const LinearSystem& system, const CreepContact& contact, double speed);

/// The eigenvalues of `system`'s first-order form, x = (q, q̇, F) with the series dampers'
/// forces F (with its contact terms when it is with_creep's), 1/s.
Eigen::VectorXcd first_order_roots(const LinearSystem& system);

/// Whether the free motion with these roots decays: none with a real part above round-off.
/// Above the linear critical speed it does not, and the stationary response is unbounded.
bool decays(const Eigen::VectorXcd& roots);

}  // namespace railmodal::ride
