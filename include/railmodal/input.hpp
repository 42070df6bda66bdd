// railmodal — reading vehicle files (TOML with units).
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Vehicle v = railmodal::load_vehicle("data/vehicles/two_axle_freight_wagon.toml");
//     std::cout << v.name << ": " << v.bodies.size() << " bodies, " << v.elements.size() << " elements\n";
//   }
//
// A file is either a template ("two-axle", "bogie") whose few keys generate the bodies and
// elements, or the general form with [[body]] and [[element]] tables. docs/input.md
// describes every key; the files under data/vehicles/ are commented examples.
#pragma once

#include <string>
#include <vector>

#include "railmodal/vehicle.hpp"

namespace railmodal {

/// Reads a vehicle file. Throws InputError ("file:line:col: error: key 'x': ...") for a
/// syntax error, a missing, unknown or mistyped key, a quantity of the wrong dimension or a
/// non-physical value (negative or zero mass, negative stiffness, NaN).
/// `warnings`, when given, gets what the reader accepted but found unusual, one line each
/// ("wagon.toml:41:10: warning: key 'secondary.hanger.length': read as 734 m ...";
/// docs/input.md, "Implausible inputs"), appended, for the caller to show: they change no
/// result. Without it none are made (a study reads thousands of variants and shows none).
Vehicle load_vehicle(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// A speed written as vehicle and scene files write one: "75 km/h", "20.8 m/s" or a bare number
/// (m/s), in m/s. For programs that take speeds on their command line (railmodal stability
/// --speeds). Throws std::invalid_argument saying what was expected and what was found.
double parse_speed(const std::string& text);

/// Speeds written as a list, "100 km/h, 160 km/h, 200 km/h", or as a range "MIN:MAX:STEP":
/// from MIN to MAX, both included, evenly spaced at most STEP apart ("100 km/h:200 km/h:20 km/h"
/// is 100, 120, … 200 km/h); "MIN:MAX" alone is 11 speeds. Each speed as parse_speed reads it,
/// above zero, and with its unit (a bare number is refused: it would be m/s, and no unit
/// carries from one speed of a list to the next); at most 10 000 speeds; returned in m/s, in the order written (a range
/// increasing). For the ride's speeds (railmodal ride --speeds, a scene's [ride] speeds).
/// Throws std::invalid_argument saying what is wrong.
std::vector<double> parse_speeds(const std::string& text);

}  // namespace railmodal
