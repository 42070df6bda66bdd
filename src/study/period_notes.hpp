// What compare says once of a study's periods (Study::notes): the notes `railmodal modes` prints
// of each vehicle file of the study as written, such as that a vehicle on wheelsets has its
// suspension modes, without the wheel–rail contact terms (user audit 2026-11-28, F5: compare gave
// the coach's body lower sway as 1.13 s, 1.72 s on track, without a word).
#pragma once

#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::study {

/// The undamped modes' notes of each vehicle assembled in `dofs` (model::undamped_mode_notes),
/// each once, in the words "periods [s], as `railmodal modes` notes them: ...". A vehicle that
/// does not assemble alone is left to the variants that read it.
std::vector<std::string> period_notes(const std::vector<const Vehicle*>& vehicles, DofSet dofs);

}  // namespace railmodal::study
