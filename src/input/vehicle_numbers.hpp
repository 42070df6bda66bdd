// Every number of a Vehicle, and the rest of it as text: what a study's fast path compares
// to learn which numbers a key of the vehicle file sets (src/input/variant_fast_path.cpp).
#pragma once

#include <string>
#include <vector>

#include "railmodal/vehicle.hpp"

namespace railmodal::input {

/// The vehicle's numbers (every double, vectors' and optional members' included), in a fixed
/// order that depends only on its shape. A field added to the vehicle's structs must be added
/// here (test VehicleNumbers.CoverEveryField counts the fields by the structs' sizes).
std::vector<double*> vehicle_numbers(Vehicle* vehicle);
/// The same into *numbers, its storage reused (a study's fast path, once a variant).
void vehicle_numbers(Vehicle* vehicle, std::vector<double*>* numbers);

/// Everything of the vehicle but its numbers, as text: names, kinds, counts, held motions,
/// flags, which optional parts are present and how long each list is. Two vehicles of the
/// same shape have their numbers in the same order.
std::string vehicle_shape(const Vehicle& vehicle);

}  // namespace railmodal::input
