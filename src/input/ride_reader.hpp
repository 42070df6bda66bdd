// The [ride] table of a scene: what `railmodal ride` computes on the scene's track irregularity.
#pragma once

#include <map>
#include <string>

#include "input/table_reader.hpp"
#include "railmodal/scene.hpp"

namespace railmodal::input {

/// Reads [ride] (`t`). The names only the assembled vehicle can check (an output's body,
/// element or wheelset) are placed in `places` under "ride.output[i].body" and
/// "ride.output[i].element" for check_scene_fits.
RideSpec read_ride(TableReader t, std::map<std::string, KeyPlace>* places);

}  // namespace railmodal::input
