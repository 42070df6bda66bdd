// The metacentric height from a lateral stiffness already assembled (a study's variant shares
// one assembly between its vertical system and this; lateral_stability assembles its own).
#pragma once

#include <string>

#include "railmodal/stability.hpp"

namespace railmodal::solve {

/// lateral_stability(vehicle, body_name) but for its stages' clocks, from `lateral`, the
/// lateral set's dofs, stiffness and gravity_stiffness as model::assemble_stiffness gives them.
/// Writes every member of *out but its stages: its body, numbers, analysis, method and its one
/// check, into the storage *out has (a study's worker keeps one). Throws std::invalid_argument
/// when the body has no free roll.
void condense_roll(const Vehicle& vehicle, const LinearSystem& lateral, const std::string& body_name,
                   LateralStability* out);

}  // namespace railmodal::solve
