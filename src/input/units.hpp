// Quantities with units, as written in vehicle files: "910 kgf/cm", "57.2 mm", "34 t".
#pragma once

#include <array>
#include <string>

namespace railmodal::input {

/// Exponents of mass, length, time and plane angle.
struct Dimension {
  std::array<int, 4> exponent{0, 0, 0, 0};
  bool operator==(const Dimension& other) const { return exponent == other.exponent; }
  bool operator!=(const Dimension& other) const { return !(*this == other); }
};

/// The physical quantities vehicle files contain, each with its SI dimension and a name
/// and example used in error messages.
enum class Quantity {
  length, mass, force, stiffness, flexibility, inertia, angle, acceleration,
  damping, modulus, speed, rotational_stiffness, dimensionless, time, angular_speed,
  moment,       ///< force·length, N·m (a creep coefficient f23)
  force_area,      ///< force·length², N·m² (the spin creep coefficient f33; a beam's EI)
  mass_per_length, ///< kg/m (a beam's mass per length)
  frequency,       ///< Hz, cycles per second (a bending mode's frequency)
  velocity         ///< m/s of a motion (an initial velocity, a limit on a vibration velocity):
                   ///< a bare number is m/s, where a vehicle's speed needs its unit
};
Dimension dimension_of(Quantity quantity);
const char* name_of(Quantity quantity);     ///< "stiffness (force/length)"
const char* example_of(Quantity quantity);  ///< "\"910 kgf/cm\" or 8.9e5 (N/m)"
std::string describe(const Dimension& dimension);  ///< "force/length"

/// Parses "value unit" and converts to SI for the expected quantity. A bare number is SI.
/// The book writes kg and t for kilogram-force and tonne-force ("910 kg/cm", "10.5 mm/t"):
/// when the units read as mass do not give the expected dimension but read as force do,
/// the force reading is taken. Throws std::invalid_argument with a message saying what was
/// expected and what was found.
double parse_quantity(const std::string& text, Quantity expected);

}  // namespace railmodal::input
