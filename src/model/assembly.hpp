// What the assembly offers the analyses beside assemble (linear_system.hpp): the stiffness
// alone, for an analysis that needs nothing else (the metacentric height of a study's every
// variant), without the damping, track inputs and copy of the vehicle a LinearSystem holds.
#pragma once

#include "railmodal/linear_system.hpp"

namespace railmodal::model {

/// The system of assemble(vehicle, set) with only its dofs, stiffness and gravity_stiffness
/// filled, each bit for bit as assemble gives it (the same sums in the same order); every
/// other member empty. Throws as assemble does.
LinearSystem assemble_stiffness(const Vehicle& vehicle, DofSet set);

/// assemble(vehicle, set) and assemble_stiffness(vehicle, stiffness_set), bit for bit, from one
/// assembly of the full matrices (a study's variant: the vertical system it sweeps and the
/// lateral stiffness of its metacentric height).
struct SystemAndStiffness {
  LinearSystem system;
  LinearSystem stiffness;
};
SystemAndStiffness assemble_with_stiffness(const Vehicle& vehicle, DofSet set, DofSet stiffness_set);
/// The same with the vehicle moved into system.vehicle instead of copied (a study's worker
/// owns the variant it reads). Where it throws, `vehicle` is left as it was.
SystemAndStiffness assemble_with_stiffness(Vehicle&& vehicle, DofSet set, DofSet stiffness_set);

}  // namespace railmodal::model
