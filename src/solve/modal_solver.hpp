// solve_modes into a result kept from a previous solve (a study's worker solves one system of
// the same size per variant), its modes named then or later.
#pragma once

#include "railmodal/linear_system.hpp"
#include "railmodal/modal.hpp"
#include "solve/mode_naming.hpp"

namespace railmodal::solve {

/// When solve_modes_into names the modes: `now`, as solve_modes does; `deferred`, not at all
/// (every Mode::name empty, no centre of oscillation) for a caller that names only the modes it
/// reads, with name_mode. Naming is a study variant's most expensive step after the solve
/// that a CSV or table of its ranking never shows (issue 19, item 2).
enum class ModeNaming { now, deferred };

/// solve_modes(system, options) written into `into`: every member set as solve_modes sets it,
/// the same values bit for bit, with the storage `into` already has (its modes' shapes, energy
/// shares and names, its DOF list) reused instead of made anew; with `naming` deferred, every
/// member but the modes' names and centres. On a throw `into` holds a partial result.
void solve_modes_into(const LinearSystem& system, const ModalOptions& options, ModalResult* into,
                      ModeNaming naming = ModeNaming::now);

/// Names `mode` of the system `namer` was made for, and sets its centre of oscillation, as
/// solve_modes does (the same name, the same bits): a mode solve_modes_into left unnamed.
void name_mode(const ModeNamer& namer, Mode* mode);

}  // namespace railmodal::solve
