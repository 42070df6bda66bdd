// What the ride says about its default floor points (default_ride_outputs, ride.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride.hpp"

namespace railmodal::ride {

/// The note a ride result carries, once, when `outputs` include any of default_ride_outputs(system)
/// and the car body does not give its floor height (Body::floor_height): those points then lie at
/// the body's reference point, which for the templates is the plane of the secondary springs or
/// of the axles, and a lateral acceleration there lacks the roll's share at the floor. None
/// otherwise.
std::optional<std::string> default_floor_note(const LinearSystem& system, const std::vector<RideOutput>& outputs);

}  // namespace railmodal::ride
