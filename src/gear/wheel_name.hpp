// A wheel of a driving gear as every output names it: its axle's name and its side.
#pragma once

#include <string>

namespace railmodal::gear {

/// "coupled 1 R", "driving L": GearAxle::name and R (right) or L (left), as the balance
/// reports, their notes and the Python records write a wheel (GearWheelLoad::wheel).
inline std::string wheel_name(const std::string& axle, bool right) { return axle + (right ? " R" : " L"); }

}  // namespace railmodal::gear
