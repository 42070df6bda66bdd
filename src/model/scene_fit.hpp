// What a scene's analyses check of it besides its names (check_scene_fits, scene.hpp).
#pragma once

#include <string>

#include "railmodal/scene.hpp"

namespace railmodal::model {

/// Throws InputError at the scene's irregularity source when a random track irregularity is
/// all the scene excites the vehicle with: `analysis` ("critical speeds", "the simulation")
/// takes periodic sources only, and the ride on random track is `railmodal ride`.
void refuse_ride_only_scene(const Scene& scene, const std::string& analysis);

}  // namespace railmodal::model
