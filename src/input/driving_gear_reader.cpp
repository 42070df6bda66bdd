// load_driving_gear: the [driving_gear] table (docs/driving_gear.md, "Input"): the engine's
// wheels, its cylinders with their rods, and the masses turning with each wheel.
#include <cmath>
#include <map>
#include <set>

#include "input/driving_gear_reader.hpp"
#include "input/table_reader.hpp"
#include "railmodal/driving_gear.hpp"
#include "railmodal/errors.hpp"

namespace railmodal {

namespace input {
namespace {

constexpr double kQuarterTurn = M_PI / 2;

// The left crank's angle from the right's: −90° when the right leads (the Су), +90° when the left does.
double left_crank_angle(TableReader& head) {
  if (head.has("left_crank_angle")) return head.quantity("left_crank_angle", Quantity::angle);
  const std::string leading = head.optional_string("leading_side").value_or("right");
  if (leading == "right") return -kQuarterTurn;
  if (leading == "left") return kQuarterTurn;
  head.fail("leading_side", "must be \"right\" or \"left\" (whose crank leads by 90°)");
}

RotatingMass read_mass_entry(TableReader& t) {
  RotatingMass m;
  m.name = t.optional_string("name").value_or("mass");
  m.mass = t.positive("mass", Quantity::mass, true);
  m.radius = t.positive("radius", Quantity::length, true);
  m.angle = t.optional_quantity("angle", Quantity::angle).value_or(0.0);
  m.plane_offset = t.optional_quantity("plane_offset", Quantity::length).value_or(0.0);
  m.overbalance = t.optional_boolean("overbalance").value_or(false);
  return m;
}

GearAxle read_axle(TableReader& t, double left_offset) {
  GearAxle a;
  a.name = t.string("name");
  a.position = t.optional_quantity("position", Quantity::length).value_or(0.0);
  a.crank_radius = t.positive("crank_radius", Quantity::length);
  a.right.static_load = a.left.static_load = t.positive("static_wheel_load", Quantity::force);
  a.left.crank_offset = left_offset;
  if (!t.has("mass")) return a;
  for (TableReader& m : t.tables("mass")) {
    const std::string side = m.optional_string("side").value_or("both");
    if (side != "both" && side != "right" && side != "left")
      m.fail("side", "must be \"both\", \"right\" or \"left\" (the wheel the mass turns with)");
    const RotatingMass mass = read_mass_entry(m);
    m.finish();
    if (side != "left") a.right.masses.push_back(mass);
    if (side != "right") a.left.masses.push_back(mass);
  }
  return a;
}

GearCylinder read_cylinder(TableReader& t, const std::map<std::string, int>& axles, double left_offset) {
  GearCylinder c;
  const std::string side = t.string("side");
  if (side != "right" && side != "left" && side != "centre")
    t.fail("side", "must be \"right\", \"left\" or \"centre\" (where the cylinder sits)");
  c.name = t.optional_string("name").value_or(side);
  const double lateral = t.positive("lateral", Quantity::length, true);  // from the centreline, outward
  c.lateral = side == "left" ? -lateral : lateral;
  if (side == "centre" && lateral != 0.0) t.fail("lateral", "a centre cylinder lies on the centreline: lateral = 0");
  const std::optional<double> angle = t.optional_quantity("crank_angle", Quantity::angle);
  if (!angle && side == "centre") t.fail("crank_angle", "a centre cylinder needs its crank angle from the right crank");
  c.crank_offset = angle.value_or(side == "left" ? left_offset : 0.0);
  const std::string axle = t.string("axle");
  const auto found = axles.find(axle);
  if (found == axles.end()) t.fail("axle", "no [[driving_gear.axle]] is named '" + axle + "'");
  c.axle = found->second;
  c.crank_radius = t.positive("crank_radius", Quantity::length);
  c.rod_length = t.positive("rod_length", Quantity::length);
  if (!(c.rod_length > c.crank_radius)) t.fail("rod_length", "must exceed crank_radius (the crank could not turn)");
  c.rod_mass = t.positive("rod_mass", Quantity::mass, true);
  c.rod_centre_of_mass = t.positive("rod_centre_of_mass", Quantity::length, true);
  if (c.rod_centre_of_mass > c.rod_length)
    t.fail("rod_centre_of_mass", "must lie on the rod: at most rod_length from the crosshead pin");
  const double inertia = t.positive("rod_inertia", Quantity::inertia, true);
  const std::string about = t.optional_string("rod_inertia_about").value_or("centre_of_mass");
  double distance = 0.0;
  if (about == "crosshead_pin") {
    distance = c.rod_centre_of_mass;
  } else if (about == "crank_pin") {
    distance = c.rod_length - c.rod_centre_of_mass;
  } else if (about != "centre_of_mass") {
    t.fail("rod_inertia_about", "must be \"centre_of_mass\", \"crosshead_pin\" or \"crank_pin\"");
  }
  c.rod_inertia = rod_inertia_about_centre(inertia, c.rod_mass, distance);
  if (c.rod_inertia < 0.0)
    t.fail("rod_inertia", "is less than rod_mass times the squared distance from the " + about +
                              " to the centre of mass: no rod has a negative inertia about its centre");
  c.reciprocating_mass = t.positive("reciprocating_mass", Quantity::mass, true);
  return c;
}

// A scene that drives its vehicle by a gear names the gear's own file in a source's `gear` key:
// handed to `balance`, it would only be "missing driving_gear" (user audit 2026-11-27c, F10).
void refuse_a_scene(const toml::value& document, const TableReader& root) {
  if (root.has("driving_gear") || !document.contains("scene")) return;
  std::string named;
  if (document.contains("source") && document.at("source").is_array())
    for (const toml::value& source : document.at("source").as_array())
      if (source.is_table() && source.contains("gear") && source.at("gear").is_string()) {
        named = source.at("gear").as_string();
        break;
      }
  root.fail("driving_gear", "this is a scene file, not a driving gear's: give the gear file" +
                                (named.empty() ? std::string(" (a [driving_gear] table)")
                                               : " its driving_gear source names, gear = \"" + named + "\" (relative to the scene)"));
}

DrivingGear read_driving_gear(const toml::value& document, const std::string& path, std::vector<bool>* positioned) {
  TableReader root(document, path, "");
  refuse_a_scene(document, root);
  TableReader head = root.table("driving_gear");
  DrivingGear g;
  g.source = path;
  g.name = head.optional_string("name").value_or("driving gear");
  g.design_speed = head.optional_positive("design_speed", Quantity::speed).value_or(0.0);
  g.wheel_diameter = head.positive("wheel_diameter", Quantity::length);
  g.wheel_plane_half_spacing = head.positive("wheel_plane_spacing", Quantity::length) / 2.0;
  const std::string rotation = head.optional_string("rotation").value_or("forward");
  const std::optional<GearRotation> r = gear_rotation_from_string(rotation);
  if (!r) head.fail("rotation", "must be \"forward\" or \"backward\"");
  g.rotation = *r;
  const double left_offset = left_crank_angle(head);
  std::map<std::string, int> axles;
  for (TableReader& t : head.tables("axle")) {
    if (positioned) positioned->push_back(t.has("position"));
    g.axles.push_back(read_axle(t, left_offset));
    if (!axles.emplace(g.axles.back().name, static_cast<int>(g.axles.size()) - 1).second)
      t.fail("name", "an axle named '" + g.axles.back().name + "' already exists");
    t.finish();
  }
  if (head.has("cylinder"))
    for (TableReader& t : head.tables("cylinder")) {
      g.cylinders.push_back(read_cylinder(t, axles, left_offset));
      t.finish();
    }
  head.finish();
  std::string why;
  if (!g.is_valid(&why)) root.fail("driving_gear", why);
  return g;
}

}  // namespace

DrivingGear load_driving_gear(const std::string& path, std::vector<bool>* positioned) {
  if (positioned) positioned->clear();
  return read_driving_gear(parse_toml_file(path), path, positioned);
}

}  // namespace input

DrivingGear load_driving_gear(const std::string& path) { return input::load_driving_gear(path, nullptr); }

}  // namespace railmodal
