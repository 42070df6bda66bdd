// What the analyses built on M, C and K cannot represent, refused where each one starts rather
// than dropped: a damper with a spring in series adds a first-order state, which the hunting
// stability, the damped modes and the ride (both domains) carry and the others do not
// (docs/stability.md, "What `modes` and `critical-speed` do on a vehicle with wheelsets").
#pragma once

#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::model {

/// Throws std::invalid_argument("<analysis>: element '<name>' has a series damper, which <analysis>
/// does not represent (…)", naming the analyses that do) for the first of the system's
/// series_dampers rows (the dampers some kept motion stretches). `analysis` is a word, not a string built per call: every
/// harmonic solve of a study's variants checks (and a std::string of it was an allocation).
void refuse_series_dampers(const LinearSystem& system, const char* analysis);

/// What the undamped modes of the system leave out, one sentence each (ModalResult::notes):
/// the wheel–rail contact of its wheelsets, its series dampers; empty for neither.
std::vector<std::string> undamped_mode_notes(const LinearSystem& system);

/// What the damped modes of the system leave out or add (DampedModalResult::notes, which
/// the damped reports print): the wheel–rail contact of its wheelsets, as undamped_mode_notes;
/// its series dampers, which they include.
std::vector<std::string> damped_mode_notes(const LinearSystem& system);

/// Whether the element stands on a wheelset of the vehicle (its lower body is one).
bool stands_on_wheelset(const Vehicle& vehicle, const Element& element);

}  // namespace railmodal::model
