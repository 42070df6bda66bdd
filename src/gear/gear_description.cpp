// The rules of a driving-gear description and of its options, and the names of its enum.
#include <cmath>
#include <string>

#include "railmodal/driving_gear.hpp"
#include "require_valid.hpp"

namespace railmodal {

const char* to_string(GearRotation rotation) { return rotation == GearRotation::forward ? "forward" : "backward"; }

std::optional<GearRotation> gear_rotation_from_string(const std::string& word) {
  if (word == "forward") return GearRotation::forward;
  if (word == "backward") return GearRotation::backward;
  return std::nullopt;
}

namespace {

bool finite_at_least(double value, double least) { return std::isfinite(value) && value >= least; }

bool cylinder_valid(const GearCylinder& c, int axles, const std::string& at, std::string* why) {
  if (!(std::isfinite(c.crank_radius) && c.crank_radius > 0.0)) return invalid(why, at + "crank_radius must be positive");
  if (!(std::isfinite(c.rod_length) && c.rod_length > c.crank_radius))
    return invalid(why, at + "rod_length must exceed crank_radius (the crank could not turn)");
  if (!finite_at_least(c.rod_mass, 0.0)) return invalid(why, at + "rod_mass must be finite and >= 0");
  if (!(finite_at_least(c.rod_centre_of_mass, 0.0) && c.rod_centre_of_mass <= c.rod_length))
    return invalid(why, at + "rod_centre_of_mass must lie on the rod, 0 <= d <= rod_length");
  if (!finite_at_least(c.rod_inertia, 0.0))
    return invalid(why, at + "rod_inertia (about the centre of mass) must be finite and >= 0");
  if (!finite_at_least(c.reciprocating_mass, 0.0)) return invalid(why, at + "reciprocating_mass must be finite and >= 0");
  if (!std::isfinite(c.lateral) || !std::isfinite(c.crank_offset))
    return invalid(why, at + "lateral and crank_offset must be finite");
  if (c.axle < 0 || c.axle >= axles) return invalid(why, at + "axle " + std::to_string(c.axle) + " is not an axle of the gear");
  return true;
}

bool wheel_valid(const GearWheel& w, const std::string& at, std::string* why) {
  if (!(std::isfinite(w.static_load) && w.static_load > 0.0)) return invalid(why, at + "static_load must be positive");
  if (!std::isfinite(w.crank_offset)) return invalid(why, at + "crank_offset must be finite");
  for (const RotatingMass& m : w.masses) {
    const std::string here = at + "mass '" + m.name + "': ";
    if (!finite_at_least(m.mass, 0.0) || !finite_at_least(m.radius, 0.0))
      return invalid(why, here + "mass and radius must be finite and >= 0");
    if (!std::isfinite(m.angle) || !std::isfinite(m.plane_offset))
      return invalid(why, here + "angle and plane_offset must be finite");
  }
  return true;
}

}  // namespace

bool DrivingGear::is_valid(std::string* why) const {
  if (!(std::isfinite(wheel_diameter) && wheel_diameter > 0.0)) return invalid(why, "wheel_diameter must be positive");
  if (!(std::isfinite(wheel_plane_half_spacing) && wheel_plane_half_spacing > 0.0))
    return invalid(why, "wheel_plane_half_spacing must be positive");
  if (axles.empty()) return invalid(why, "axles must name at least the driving axle");
  for (const GearCylinder& c : cylinders)
    if (!cylinder_valid(c, static_cast<int>(axles.size()), "cylinder '" + c.name + "': ", why)) return false;
  for (const GearAxle& a : axles) {
    if (!(std::isfinite(a.crank_radius) && a.crank_radius > 0.0))
      return invalid(why, "axle '" + a.name + "': crank_radius must be positive");
    if (!std::isfinite(a.position)) return invalid(why, "axle '" + a.name + "': position must be finite");
    if (!wheel_valid(a.right, "axle '" + a.name + "' right: ", why)) return false;
    if (!wheel_valid(a.left, "axle '" + a.name + "' left: ", why)) return false;
  }
  return true;
}

bool GearOptions::is_valid(std::string* why) const {
  if (steps < 8) return invalid(why, "steps must be at least 8 (crank angles per revolution)");
  if (harmonics < 1 || harmonics > steps / 2 - 1)
    return invalid(why, "harmonics must be 1 ... steps/2 - 1 (" + std::to_string(steps / 2 - 1) + ")");
  return true;
}

}  // namespace railmodal
