// The [driving_gear] reader's one private addition to load_driving_gear (driving_gear.hpp):
// which axles the file places (`position` given), so that a scene placing the gear on a
// vehicle can require an `x` for the others instead of putting them silently at 0.
#pragma once

#include <string>
#include <vector>

#include "railmodal/driving_gear.hpp"

namespace railmodal::input {

/// load_driving_gear, and positioned[a] = whether axle a's table gives `position`.
DrivingGear load_driving_gear(const std::string& path, std::vector<bool>* positioned);

}  // namespace railmodal::input
