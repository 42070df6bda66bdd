#include "input/templates.hpp"

#include <cmath>
#include <iterator>
#include <optional>
#include <string>

#include "input/body_reader.hpp"
#include "input/input_warnings.hpp"
#include "input/spring_reader.hpp"

namespace railmodal::input {
namespace {

// A wagon's length (a spacing, a wheelbase, a height), warned when beyond a wagon's scale
// (input_warnings.hpp); `positive`: refused unless > 0.
double wagon_dimension(TableReader& t, const std::string& key, bool positive = true) {
  const double value = positive ? t.positive(key, Quantity::length) : t.quantity(key, Quantity::length);
  warn_implausible_length(t, key, value, kBodyLength);
  return value;
}

// A spacing across the track (springs, hangers, dampers), warned beyond the widest body.
double lateral_spacing(TableReader& t, const std::string& key) {
  const double value = t.positive(key, Quantity::length);
  warn_implausible_length(t, key, value, kLateralSpacing);
  return value;
}

std::optional<double> optional_wagon_dimension(TableReader& t, const std::string& key) {
  if (!t.has(key)) return std::nullopt;
  return wagon_dimension(t, key, false);
}

// Damping of an element from optional keys of a template table.
void read_damping(TableReader& t, Element* e) {
  e->vertical_damping = t.optional_positive("vertical_damping", Quantity::damping, true).value_or(0.0);
  e->lateral_damping = t.optional_positive("lateral_damping", Quantity::damping, true).value_or(0.0);
  e->longitudinal_damping = t.optional_positive("longitudinal_damping", Quantity::damping, true).value_or(0.0);
}

// A template's [wheelset]: the same wheelset under every axle.
struct AxleWheelset {
  double mass = 0.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  // roll, pitch (= spin), yaw
  double spin_inertia = 0.0;
  WheelRailContact contact;
};

std::optional<AxleWheelset> read_axle_wheelset(TableReader& root, double gravity) {
  if (!root.has("wheelset")) return std::nullopt;
  TableReader t = root.table("wheelset");
  AxleWheelset w;
  w.mass = read_mass(t, gravity);
  w.spin_inertia = read_spin_inertia(t);
  TableReader inertia = t.table("inertia");
  if (inertia.has("pitch"))
    inertia.fail("pitch", "a wheelset's pitch is its spin about the axle: give spin_inertia in [wheelset]");
  const double roll = inertia.positive("roll", Quantity::inertia, true);
  const double yaw = inertia.positive("yaw", Quantity::inertia);  // its lateral and yaw motions are free
  inertia.finish();
  w.inertia = {roll, w.spin_inertia, yaw};
  w.contact = read_contact(t);
  t.finish();
  return w;
}

// One wheelset body under the axle at x, named "wheelset<n>" in the order the axles are made;
// returns its name. Its reference point and CG are on the axle, in the axle plane.
std::string add_wheelset(const AxleWheelset& w, double x, Vehicle* v) {
  Body b;
  b.name = "wheelset" + std::to_string(v->wheelsets.size() + 1);
  b.mass = w.mass;
  b.inertia = w.inertia;
  b.centre_of_gravity = {x, 0.0, 0.0};
  b.reference_point = b.centre_of_gravity;
  b.held.assign(std::begin(kWheelsetHeld), std::end(kWheelsetHeld));
  v->bodies.push_back(b);
  v->wheelsets.push_back(Wheelset{b.name, w.spin_inertia, w.contact});
  return b.name;
}

// [draw_gear]: a coupling at each end of the body, `spacing` apart at `height` above the axle
// plane, holding the body longitudinally against the rest of the train taken as fixed (the
// ground). Only a body whose longitudinal motion is free has one. Returns whether it is given.
bool add_draw_gear(TableReader& root, const Body& body, Vehicle* v) {
  if (!root.has("draw_gear")) return false;
  TableReader t = root.table("draw_gear");
  if (!body.longitudinal_free)
    root.fail("draw_gear",
              "pulls the body longitudinally, but its longitudinal motion is held: add "
              "free = [\"longitudinal\"] to [body]");
  const double half_spacing = wagon_dimension(t, "spacing") / 2.0;
  const double height = wagon_dimension(t, "height", false);
  for (int end : {+1, -1}) {
    Element e;
    e.name = end > 0 ? "front draw gear" : "rear draw gear";
    e.upper = body.name;
    e.point = {body.reference_point.x() + end * half_spacing, 0.0, height};
    e.longitudinal_stages = read_longitudinal_stages(t, "spring", std::nullopt);
    if (e.longitudinal_stages.empty()) t.fail("spring", "missing: the draw gear's spring stages");
    e.longitudinal_damping = t.optional_positive("longitudinal_damping", Quantity::damping, true).value_or(0.0);
    v->elements.push_back(e);
  }
  t.finish();
  return true;
}

// The sprung parts of a bogie (frame, bolster, cradle), one per end, from [bogie]; without
// them (single suspension) only the bolster height is read.
struct BogieFrame {
  double mass = 0.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();
  double cg_height = 0.0;       // h1, above the axle plane
  double half_wheelbase = 0.0;  // l2
  double bolster = 0.0;         // height of the bolster plane
  bool longitudinal_free = false;
};

BogieFrame read_bogie_frame(TableReader& root, bool sprung, double gravity) {
  BogieFrame f;
  if (sprung) {
    TableReader g = root.table("bogie");
    f.mass = read_mass(g, gravity);
    f.inertia = read_inertia(g, f.mass);
    f.cg_height = wagon_dimension(g, "cg_height", false);
    f.half_wheelbase = wagon_dimension(g, "wheelbase") / 2.0;
    f.bolster = optional_wagon_dimension(g, "bolster_height").value_or(0.0);
    f.longitudinal_free = read_longitudinal_free(g);
    g.finish();
  } else if (root.has("bogie")) {  // unsprung bogie frames: only the bolster height matters
    TableReader g = root.table("bogie");
    f.bolster = optional_wagon_dimension(g, "bolster_height").value_or(0.0);
    g.finish();
  }
  return f;
}

// [secondary]: the cradle springs' lateral spacing, a swing hanger, and the anti-roll bar.
// yaw_damper = {...}: a longitudinal damper with its end bushes (a series spring) each side,
// between the body and the bogie frame; the pair resists their relative yaw.
struct YawDamper {
  double damping = 0.0;           // N·s/m, of one damper
  double series_stiffness = 0.0;  // N/m, of its end bushes
  double half_spacing = 0.0;      // lateral, from the centre line
  std::optional<double> height;   // above the axle plane; none: the bolster plane
};

struct Secondary {
  double half_spacing = 0.0;  // b3
  std::optional<SwingHanger> hanger;
  double anti_roll_bar = 0.0;  // roll stiffness between body and each bogie (torsion bar), N·m/rad
  std::optional<YawDamper> yaw_damper;
};

Secondary read_secondary(TableReader& sec) {
  Secondary s;
  s.half_spacing = lateral_spacing(sec, "spacing") / 2.0;
  if (sec.has("hanger")) s.hanger = read_hanger(sec);
  s.anti_roll_bar = sec.optional_positive("anti_roll_bar", Quantity::rotational_stiffness, true).value_or(0.0);
  if (sec.has("yaw_damper")) {
    TableReader t = sec.table("yaw_damper");
    YawDamper& d = s.yaw_damper.emplace();
    d.damping = t.positive("damping", Quantity::damping);
    d.series_stiffness = t.positive("series_stiffness", Quantity::stiffness);
    d.half_spacing = lateral_spacing(t, "spacing") / 2.0;
    d.height = optional_wagon_dimension(t, "height");
    t.finish();
  }
  return s;
}

// One end of the wagon: its bogie's name, what the body's springs stand on there (the bogie,
// or the track for single suspension: empty), and the bogie centre's x.
struct BogieEnd {
  std::string name;
  std::string lower;
  double x = 0.0;
};

Body bogie_body(const BogieEnd& end, const BogieFrame& f, const TableReader& pri) {
  Body bogie;
  bogie.name = end.name;
  bogie.mass = f.mass;
  bogie.inertia = f.inertia;
  bogie.reference_point = {end.x, 0.0, 0.0};  // pitch about the axle plane, §2.5
  bogie.centre_of_gravity = {end.x, 0.0, f.cg_height};
  const bool lateral = pri.has("lateral"), longitudinal = pri.has("longitudinal");
  if (!lateral) bogie.held.push_back(Motion::lateral);  // wheelsets guide the frame
  if (!lateral && !longitudinal) bogie.held.push_back(Motion::yaw);
  bogie.longitudinal_free = f.longitudinal_free;
  return bogie;
}

// Primary springs: four axlebox locations (half wheelbase l2, half spacing b2), each carrying
// `load`, a quarter of the bogie's share.
// With wheelsets, each axle's springs stand on its wheelset instead of the track.
void add_axlebox_springs(TableReader& pri, const BogieEnd& end, double l2, double b2, double load, bool triple,
                         const std::optional<AxleWheelset>& wheelset, Vehicle* v) {
  for (int axle : {+1, -1}) {
    const std::string lower = wheelset ? add_wheelset(*wheelset, end.x + axle * l2, v) : "";
    for (int side : {+1, -1}) {
      Element e;
      e.name = end.name + (axle > 0 ? " leading" : " trailing") + (side > 0 ? " left" : " right") + " axlebox";
      e.upper = end.name;
      e.lower = lower;
      e.point = {end.x + axle * l2, side * b2, 0.0};
      e.vertical_stages = read_spring_stages(pri, "spring", load);
      if (e.vertical_stages.empty()) pri.fail("spring", "missing: the axlebox spring stages");
      if (triple && e.vertical_stages.size() < 2)
        pri.fail("spring", "triple suspension needs two primary stages in series (leaf, then coil)");
      e.lateral_stages = read_spring_stages(pri, "lateral", load);
      e.longitudinal_stages = read_longitudinal_stages(pri, "longitudinal", load);
      read_damping(pri, &e);
      v->elements.push_back(e);
    }
  }
}

// Secondary (cradle) springs: one set each side, in the bolster plane, each carrying `load`.
void add_cradle_springs(TableReader& sec, const Secondary& s, const BogieEnd& end, double bolster, double load,
                        Vehicle* v) {
  for (int side : {+1, -1}) {
    Element e;
    e.name = end.name + (side > 0 ? " left" : " right") + " cradle";
    e.lower = end.lower;
    e.upper = "body";
    e.point = {end.x, side * s.half_spacing, bolster};
    e.vertical_stages = read_spring_stages(sec, "spring", load);
    if (e.vertical_stages.empty()) sec.fail("spring", "missing: the cradle spring stages");
    e.lateral_stages = read_spring_stages(sec, "lateral", load);
    e.longitudinal_stages = read_longitudinal_stages(sec, "longitudinal", load);
    e.hanger = s.hanger;
    read_damping(sec, &e);
    v->elements.push_back(e);
  }
}

void add_anti_roll_bar(const Secondary& s, const BogieEnd& end, double bolster, Vehicle* v) {
  if (!(s.anti_roll_bar > 0.0)) return;
  Element bar;
  bar.name = end.name + " anti-roll bar";
  bar.lower = end.lower;
  bar.upper = "body";
  bar.point = {end.x, 0.0, bolster};
  bar.rotational_stiffness = {s.anti_roll_bar, 0.0, 0.0};
  v->elements.push_back(bar);
}

void add_yaw_dampers(const Secondary& s, const BogieEnd& end, double bolster, Vehicle* v) {
  if (!s.yaw_damper) return;
  const YawDamper& d = *s.yaw_damper;
  for (int side : {+1, -1}) {
    Element e;
    e.name = end.name + (side > 0 ? " left" : " right") + " yaw damper";
    e.lower = end.lower;
    e.upper = "body";
    e.point = {end.x, side * d.half_spacing, d.height.value_or(bolster)};
    e.series_dampers = {SeriesDamper{Motion::longitudinal, d.damping, d.series_stiffness}};
    v->elements.push_back(e);
  }
}

// A bogie wagon's body or bogie frames that free their longitudinal motion need something
// that holds them longitudinally, or the freed motion is a rigid-body mode.
void check_longitudinal_support(TableReader& root, const Body& body, const BogieFrame& frame, const TableReader& sec,
                                const std::optional<TableReader>& pri) {
  if (body.longitudinal_free && !sec.has("longitudinal") && !root.has("draw_gear"))
    root.fail("body",
              "frees its longitudinal motion, but nothing holds it longitudinally: give [secondary] "
              "longitudinal stages or add [draw_gear]");
  if (frame.longitudinal_free && !pri->has("longitudinal"))
    root.fail("bogie",
              "frees the bogie frames' longitudinal motion, but nothing holds them longitudinally: give "
              "[primary] longitudinal stages");
}

}  // namespace

void read_two_axle(TableReader& head, TableReader& root, Vehicle* v) {
  head.finish();
  TableReader b = root.table("body");
  Body body;
  body.name = "body";
  body.mass = read_mass(b, v->gravity);
  body.inertia = read_inertia(b, body.mass);
  const double l = wagon_dimension(b, "cg_height", false);  // CG above the axle plane
  const double offset = optional_wagon_dimension(b, "cg_offset").value_or(0.0);
  body.longitudinal_free = read_longitudinal_free(b);
  body.bending = read_bending(b);
  body.floor_height = read_floor_height(b);
  b.finish();
  body.centre_of_gravity = {offset, 0.0, l};
  body.reference_point = {offset, 0.0, 0.0};  // O: in the axle plane below the CG (§2.2)
  const std::optional<AxleWheelset> wheelset = read_axle_wheelset(root, v->gravity);
  // The axlebox guides hold the body laterally and in yaw on the track; on wheelsets, the
  // springs' lateral and longitudinal stages do.
  if (!wheelset) body.held = {Motion::lateral, Motion::yaw};
  v->bodies.push_back(body);

  TableReader s = root.table("suspension");
  if (wheelset)
    for (const char* key : {"lateral", "longitudinal"})
      if (!s.has(key)) {
        s.refuse_misspelling(key);
        s.fail(key, std::string("missing: on wheelsets the body is guided by the springs' ") + key + " stages, e.g. " +
                        key + " = { stiffness = \"3000 kN/m\" }");
      }
  const double a1 = wagon_dimension(s, "wheelbase") / 2.0;
  const double b1 = lateral_spacing(s, "spring_spacing") / 2.0;
  if (std::abs(offset) >= a1) root.fail("body", "cg_offset puts the CG outside the wheelbase");
  if (!body.longitudinal_free && s.has("longitudinal_damping"))
    s.fail("longitudinal_damping",
           "damps the body's surge, but its longitudinal motion is held: add free = [\"longitudinal\"] to [body]");
  const double weight = body.mass * v->gravity;
  for (int axle : {+1, -1}) {
    // Lever rule: each spring of an axle carries half that axle's share of the weight.
    const double load = weight * (a1 + axle * offset) / (2.0 * a1) / 2.0;
    const std::string own = axle > 0 ? "front_spring" : "rear_spring";
    const std::string key = s.has(own) ? own : "spring";
    const std::string lower = wheelset ? add_wheelset(*wheelset, axle * a1, v) : "";
    for (int side : {+1, -1}) {
      Element e;
      e.name = std::string(axle > 0 ? "front" : "rear") + (side > 0 ? " left" : " right") + " spring";
      e.upper = "body";
      e.lower = lower;
      e.point = {axle * a1, side * b1, 0.0};
      // Re-read for each spring: the stage tables are shared, their loads are not.
      e.vertical_stages = read_spring_stages(s, key, load);
      if (e.vertical_stages.empty()) s.fail(key, "missing: the springs' stages, e.g. spring = [{ kind = \"leaf\", stiffness = \"910 kgf/cm\" }]");
      if (wheelset) {
        e.lateral_stages = read_spring_stages(s, "lateral", load);
        e.longitudinal_stages = read_longitudinal_stages(s, "longitudinal", load);
      }
      read_damping(s, &e);
      v->elements.push_back(e);
    }
  }
  if (s.has("spring") && s.has("front_spring") && s.has("rear_spring"))
    s.fail("spring", "unused: front_spring and rear_spring are both given");
  s.finish();
  if (!add_draw_gear(root, body, v) && body.longitudinal_free)
    root.fail("body", "frees its longitudinal motion, but nothing holds it longitudinally: add [draw_gear]");
  check_bending_reach(b, v->bodies.front(), v->elements);
}

void read_bogie(TableReader& head, TableReader& root, Vehicle* v) {
  const std::string suspension = head.string("suspension");
  if (suspension != "single" && suspension != "double" && suspension != "triple")
    head.fail("suspension", "must be \"single\", \"double\" or \"triple\"");
  head.finish();

  TableReader bt = root.table("body");
  Body body;
  body.name = "body";
  body.mass = read_mass(bt, v->gravity);
  body.inertia = read_inertia(bt, body.mass);
  const double d0 = wagon_dimension(bt, "cg_height", false);  // above the bolster plane
  const double l3 = wagon_dimension(bt, "bogie_spacing") / 2.0;
  body.longitudinal_free = read_longitudinal_free(bt);
  body.bending = read_bending(bt);
  body.floor_height = read_floor_height(bt);
  bt.finish();

  const bool sprung_bogies = suspension != "single";
  const BogieFrame frame = read_bogie_frame(root, sprung_bogies, v->gravity);
  body.reference_point = {0.0, 0.0, frame.bolster};
  body.centre_of_gravity = {0.0, 0.0, frame.bolster + d0};
  v->bodies.push_back(body);

  TableReader sec = root.table("secondary");
  const Secondary secondary = read_secondary(sec);
  std::optional<TableReader> pri;
  double b2 = 0.0;
  if (sprung_bogies) {
    pri.emplace(root.table("primary"));
    b2 = lateral_spacing(*pri, "spacing") / 2.0;
  } else if (root.has("primary")) {
    root.fail("primary", "a single-suspension wagon has no primary springs (its bogie frames are unsprung)");
  }
  check_longitudinal_support(root, body, frame, sec, pri);
  if (secondary.yaw_damper && !sprung_bogies)
    sec.fail("yaw_damper", "acts between the body and a bogie frame; a single-suspension wagon's frames are unsprung");
  const std::optional<AxleWheelset> wheelset = read_axle_wheelset(root, v->gravity);
  if (wheelset && !sprung_bogies)
    root.fail("wheelset", "stands under primary (axlebox) springs; a single-suspension wagon has none");
  if (wheelset)
    for (const char* key : {"lateral", "longitudinal"})
      if (!pri->has(key)) {
        pri->refuse_misspelling(key);
        pri->fail(key, std::string("missing: on wheelsets the bogie frame is guided by the axlebox springs' ") + key +
                           " stages, e.g. " + key + " = { stiffness = \"3000 kN/m\" }");
      }

  const double g = v->gravity;
  for (int k = 0; k < 2; ++k) {
    BogieEnd end{k == 0 ? "bogie1" : "bogie2", "", k == 0 ? l3 : -l3};
    if (sprung_bogies) {
      v->bodies.push_back(bogie_body(end, frame, *pri));
      end.lower = end.name;
      add_axlebox_springs(*pri, end, frame.half_wheelbase, b2, (body.mass / 2.0 + frame.mass) * g / 4.0,
                          suspension == "triple", wheelset, v);
    }
    add_cradle_springs(sec, secondary, end, frame.bolster, body.mass * g / 4.0, v);
    add_anti_roll_bar(secondary, end, frame.bolster, v);
    add_yaw_dampers(secondary, end, frame.bolster, v);
  }
  add_draw_gear(root, v->bodies.front(), v);
  sec.finish();
  if (pri) pri->finish();
  check_bending_reach(bt, v->bodies.front(), v->elements);
}

}  // namespace railmodal::input
