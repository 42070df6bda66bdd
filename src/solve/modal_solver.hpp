// solve_modes into a result kept from a previous solve (a study's worker solves one system of
// the same size per variant).
#pragma once

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"

namespace railmodal::solve {

/// solve_modes(system, options) written into `into`: every member set as solve_modes sets it,
/// the same values bit for bit, with the storage `into` already has (its modes' shapes, energy
/// shares and names, its DOF list) reused instead of made anew. On a throw `into` holds a
/// partial result.
void solve_modes_into(const LinearSystem& system, const ModalOptions& options, ModalResult* into);

}  // namespace railmodal::solve
