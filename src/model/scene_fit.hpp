// What a scene's analyses check of it besides its names (check_scene_fits, scene.hpp): a ride
// scene given to them, a series damper they cannot represent.
#pragma once

#include <string>

#include "railmodal/scene.hpp"

namespace railmodal::model {

/// Throws InputError at the scene's irregularity source when a random track irregularity is
/// all the scene excites the vehicle with: `analysis` ("critical speeds", "the simulation")
/// takes periodic sources only, and the ride on random track is `railmodal ride`.
void refuse_ride_only_scene(const Scene& scene, const std::string& analysis);

/// Throws InputError at the vehicle's file (Vehicle::source: the --vehicle file when one
/// replaced the scene's; the scene's for a vehicle built in code) when `system` has a series
/// damper some kept motion stretches: `analysis` ("critical speeds", "simulation") stands on M,
/// C and K alone, which the damper's first-order state is not in (refuse_series_dampers). The
/// ride and the hunting stability take series dampers and do not call it (docs/input.md,
/// "Series dampers").
void refuse_scene_series_dampers(const Scene& scene, const LinearSystem& system, const char* analysis);

}  // namespace railmodal::model
