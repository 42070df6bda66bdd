// load_vehicle: the [vehicle] table, then a template or the general bodies-and-elements form.
#include <algorithm>
#include <cmath>
#include <set>

#include "input/body_reader.hpp"
#include "input/document_readers.hpp"
#include "input/input_warnings.hpp"
#include "input/spring_reader.hpp"
#include "input/table_reader.hpp"
#include "input/templates.hpp"
#include "model/assembly.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/input.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace input {
namespace {

Eigen::Vector3d to_vector(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }

// A point of the general form, warned where a coordinate is beyond a wagon's scale (a bare
// "-4000" meant in mm is 4000 m: a pitch of 1153 Hz, the user audit of 2026-11-28b).
std::array<double, 3> read_point(TableReader& t, const std::string& key) {
  const std::array<double, 3> p = t.point(key);
  warn_implausible_point(t, key, p);
  return p;
}

// `[[wheelset]]`: a body on the rails. Its bounce, roll and pitch are held (they follow the
// rails in the linear model) and its longitudinal motion stays held; its lateral and yaw
// motions are what the contact acts on, so they must be free.
void read_wheelsets(TableReader& root, std::vector<TableReader>& body_tables, Vehicle* v) {
  if (!root.has("wheelset")) return;
  std::set<std::string> taken;
  for (auto& t : root.tables("wheelset")) {
    Wheelset w;
    w.body = t.string("body");
    const auto found =
        std::find_if(v->bodies.begin(), v->bodies.end(), [&](const Body& b) { return b.name == w.body; });
    if (found == v->bodies.end()) t.fail("body", "no body is named '" + w.body + "'");
    if (!taken.insert(w.body).second) t.fail("body", "body '" + w.body + "' is already a wheelset");
    Body& body = *found;
    TableReader& bt = body_tables[static_cast<size_t>(found - v->bodies.begin())];
    if (body.longitudinal_free)
      bt.fail("free", "frees the longitudinal motion of '" + body.name +
                          "', a wheelset: a wheelset's longitudinal motion is held (it rolls with the track)");
    if (body.bending)
      bt.fail("bending", "'" + body.name + "' is a wheelset: a wheelset is rigid, it carries no bending mode");
    for (Motion m : {Motion::lateral, Motion::yaw})
      if (std::find(body.held.begin(), body.held.end(), m) != body.held.end())
        bt.fail("held", std::string("holds the ") + to_string(m) + " motion of '" + body.name +
                            "', a wheelset: its lateral and yaw motions are what the wheel–rail contact acts on");
    // The contact acts at the axle centre, taken as the centre of gravity, on the track's centre
    // line in the axle plane (y = z = 0): elsewhere the contact points and the elements' levers
    // would disagree silently. Only x may vary (the axle's position; the reference point may lie
    // ahead of or behind it, the contact takes that lever).
    if (body.centre_of_gravity.y() != 0.0 || body.centre_of_gravity.z() != 0.0)
      bt.fail("centre_of_gravity", "'" + body.name +
                                       "' is a wheelset: its centre of gravity is the axle centre, on the track's "
                                       "centre line in the axle plane (y = z = 0; only x may vary)");
    if (body.reference_point.y() != 0.0 || body.reference_point.z() != 0.0)
      bt.fail("reference_point", "'" + body.name +
                                     "' is a wheelset: its reference point must lie on the axle's line along the "
                                     "track (y = z = 0; only x may differ from the centre of gravity's)");
    if (!(body.inertia.z() > 0.0))
      bt.fail(bt.has("inertia") ? "inertia" : "radius_of_gyration",
              "'" + body.name + "' is a wheelset: its yaw inertia must be positive (its yaw motion is free)");
    for (Motion m : kWheelsetHeld)
      if (std::find(body.held.begin(), body.held.end(), m) == body.held.end()) body.held.push_back(m);
    w.spin_inertia = read_spin_inertia(t);
    w.contact = read_contact(t);
    t.finish();
    v->wheelsets.push_back(w);
  }
}

// A track element whose static load is a pull: its wheel would lift off the rail, which the
// linear model cannot show (it holds the wheel down, with the spring in tension, and the modes
// come out as if nothing were wrong). The loads are the assembly's (model::element_static_loads),
// so the check and the model summary of `critical-speed` agree. The two-axle template refuses the
// same vehicle by its geometry (a CG outside the wheelbase); the general form has no wheelbase,
// so the statics decide. A vehicle the assembly refuses (no equilibrium) is left to it and its
// message. Tolerance: the statics are solved to 1e-8 of the weights (assembly.cpp); a pull below
// that is round-off of a load that is zero (an element exactly under a support line).
void refuse_lifting_wheels(std::vector<TableReader>& element_tables, const Vehicle& v) {
  if (std::none_of(v.elements.begin(), v.elements.end(),
                   [](const Element& e) { return e.lower.empty() && !e.vertical_stages.empty(); }))
    return;
  std::vector<double> loads;
  try {
    loads = model::element_static_loads(v);
  } catch (const std::exception&) {
    return;
  }
  double weight = 0.0;
  for (const Body& b : v.bodies) weight += b.mass * v.gravity;
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    if (!e.lower.empty() || !(loads[k] < -1e-8 * weight)) continue;
    element_tables[k].fail(
        "point", "element '" + e.name + "' stands on the track and carries a static load of " +
                     shortest_text(loads[k] / 1e3, 4) +
                     " kN, a pull: its wheel lifts off the rail, which the linear model cannot represent. The "
                     "centre of gravity lies outside the track elements' support; move the points or the "
                     "centre of gravity (the static loads are in `critical-speed`'s model summary)");
  }
}

void read_general(TableReader& root, Vehicle* v) {
  std::set<std::string> names;
  std::vector<TableReader> body_tables = root.tables("body");
  for (auto& t : body_tables) {
    Body b;
    b.name = t.string("name");
    if (b.name.empty() || b.name == "track") t.fail("name", "must be a non-empty name other than 'track'");
    if (!names.insert(b.name).second) t.fail("name", "a body named '" + b.name + "' already exists");
    b.mass = read_mass(t, v->gravity);
    b.inertia = read_inertia(t, b.mass);
    b.centre_of_gravity = to_vector(read_point(t, "centre_of_gravity"));
    b.reference_point = t.has("reference_point") ? to_vector(read_point(t, "reference_point")) : b.centre_of_gravity;
    if (t.has("held"))
      for (const auto& word : t.strings("held")) {
        const auto m = motion_from_string(word);
        if (!m) t.fail("held", "unknown motion '" + word + "' (lateral, bounce, roll, pitch, yaw, longitudinal)");
        if (*m == Motion::bending)
          t.fail("held", "bending is no rigid motion and cannot be held; a body without a bending table is rigid");
        b.held.push_back(*m);
      }
    b.longitudinal_free = read_longitudinal_free(t);
    if (b.longitudinal_free && std::find(b.held.begin(), b.held.end(), Motion::longitudinal) != b.held.end())
      t.fail("free", "longitudinal motion cannot be both free and held");
    b.bending = read_bending(t);
    b.floor_height = read_floor_height(t);
    t.finish();
    v->bodies.push_back(b);
  }
  read_wheelsets(root, body_tables, v);
  if (!root.has("element")) return;
  std::vector<TableReader> element_tables = root.tables("element");
  for (auto& t : element_tables) {
    Element e;
    e.name = t.optional_string("name").value_or("element");
    e.upper = t.string("upper");
    if (!names.count(e.upper)) t.fail("upper", "no body is named '" + e.upper + "'");
    e.lower = t.optional_string("lower").value_or("track");
    if (e.lower == "track") e.lower.clear();
    if (!e.lower.empty() && !names.count(e.lower)) t.fail("lower", "no body is named '" + e.lower + "' (or write \"track\")");
    if (e.lower == e.upper) t.fail("lower", "an element cannot connect a body to itself");
    e.point = to_vector(read_point(t, "point"));
    const auto load = t.optional_positive("load", Quantity::force);
    e.vertical_stages = read_spring_stages(t, "vertical", load);
    // Neither the friction criterion nor the simulation models two leaves with friction in series
    // (which one holds and which slides at each reversal); refused here for both.
    if (std::count_if(e.vertical_stages.begin(), e.vertical_stages.end(),
                      [](const SpringStage& s) { return s.relative_friction > 0.0; }) > 1)
      t.fail("vertical",
             "two stages with leaf friction in series are not modelled; give the element one friction stage");
    e.lateral_stages = read_spring_stages(t, "lateral", load);
    e.longitudinal_stages = read_longitudinal_stages(t, "longitudinal", load);
    if (t.has("hanger")) e.hanger = read_hanger(t);
    e.rotational_stiffness = read_rotational_stiffness(t);
    e.vertical_damping = t.optional_positive("vertical_damping", Quantity::damping, true).value_or(0.0);
    e.lateral_damping = t.optional_positive("lateral_damping", Quantity::damping, true).value_or(0.0);
    e.longitudinal_damping = t.optional_positive("longitudinal_damping", Quantity::damping, true).value_or(0.0);
    e.series_dampers = read_series_dampers(t);
    t.finish();
    v->elements.push_back(e);
  }
  for (size_t b = 0; b < v->bodies.size(); ++b) check_bending_reach(body_tables[b], v->bodies[b], v->elements);
  refuse_lifting_wheels(element_tables, *v);
}

}  // namespace

Vehicle read_vehicle(const toml::value& document, const std::string& path, std::vector<std::string>* warnings) {
  TableReader root(document, path, "");
  Vehicle v;
  v.source = path;
  const WarningCollector collector(warnings);
  TableReader head = root.table("vehicle");
  v.name = head.string("name");
  v.gravity = head.optional_positive("gravity", Quantity::acceleration).value_or(9.81);
  const std::string form = head.optional_string("template").value_or("general");
  if (form == "two-axle") {
    read_two_axle(head, root, &v);
  } else if (form == "bogie") {
    read_bogie(head, root, &v);
  } else if (form == "general") {
    head.finish();
    read_general(root, &v);
  } else {
    head.fail("template", "unknown template '" + form + "' (two-axle, bogie, general)");
  }
  // A locomotive's [driving_gear] is read by load_driving_gear (driving_gear.hpp), not here.
  if (root.has("driving_gear")) (void)root.raw("driving_gear");
  root.finish();
  return v;
}

}  // namespace input

Vehicle load_vehicle(const std::string& path, std::vector<std::string>* warnings) {
  return input::read_vehicle(input::parse_toml_file(path), path, warnings);
}

}  // namespace railmodal
