// Reading [ride] (docs/scenes.md, "The ride"): the speeds, the frequency grid, the outputs and
// an optional time-domain run on a realisation of the track.
#include "input/ride_reader.hpp"

#include <cstdio>
#include <set>
#include <vector>

#include "input/speed_text.hpp"
#include "railmodal/input.hpp"

namespace railmodal::input {
namespace {

// `speeds = "100 km/h:200 km/h:20 km/h"` or `speeds = ["100 km/h", "160 km/h"]` (parse_speeds).
std::vector<double> read_speeds(TableReader& t) {
  const toml::value& v = t.raw("speeds");
  if (v.is_array()) {
    const std::vector<double> speeds = t.quantities("speeds", Quantity::speed);
    if (speeds.empty()) t.fail("speeds", "give at least one speed");
    for (double s : speeds)
      if (!(s > 0.0)) t.fail("speeds", "a speed must be above zero");
    if (has_repeated_speed(speeds))
      t.fail("speeds", "a speed is given twice: give each once");
    return speeds;
  }
  if (!v.is_string())
    t.fail("speeds", "expected a range \"MIN:MAX:STEP\" such as \"100 km/h:200 km/h:20 km/h\", or an array of speeds");
  try {
    return parse_speeds(v.as_string().str);
  } catch (const std::invalid_argument& e) {
    t.fail("speeds", e.what());
  }
}

// The grid and the indices' options, each checked by RideOptions::is_valid at its key.
void read_options(TableReader& t, RideOptions& o) {
  // Without speeds here, `railmodal ride --speeds` gives them.
  if (t.has("speeds")) o.speeds = read_speeds(t);
  o.min_frequency = t.optional_positive("min_frequency", Quantity::frequency).value_or(o.min_frequency);
  o.max_frequency = t.optional_positive("max_frequency", Quantity::frequency).value_or(o.max_frequency);
  if (!(o.max_frequency > o.min_frequency)) t.fail("max_frequency", "must be above min_frequency");
  o.points_per_decade = t.optional_count("points_per_decade", 10).value_or(o.points_per_decade);
  o.points_per_bandwidth = t.optional_count("points_per_bandwidth", 1).value_or(o.points_per_bandwidth);
  o.modes = t.optional_count("modes", 0).value_or(o.modes);
  o.contact_half_spacing =
      t.optional_positive("contact_half_spacing", Quantity::length).value_or(o.contact_half_spacing);
  o.rolling_radius = t.optional_positive("rolling_radius", Quantity::length).value_or(o.rolling_radius);
  o.percentile_window = t.optional_positive("percentile_window", Quantity::time).value_or(o.percentile_window);
  o.friction_tolerance = t.optional_positive("friction_tolerance", Quantity::dimensionless).value_or(o.friction_tolerance);
  if (!(o.friction_tolerance < 0.1)) t.fail("friction_tolerance", "is a relative tolerance, below 0.1 (default 1e-6)");
  o.friction_iterations = t.optional_count("friction_iterations", 1).value_or(o.friction_iterations);
}

RideAxis read_axis(TableReader& t) {
  const std::string word = t.optional_string("axis").value_or("vertical");
  if (const auto axis = ride_axis_from_string(word)) return *axis;
  t.fail("axis", "must be vertical, lateral or longitudinal, not '" + word + "'");
}

// "(9.5, 0, 1.2) m": a point as a default output name says it.
std::string point_text(const Eigen::Vector3d& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g) m", p.x(), p.y(), p.z());
  return text;
}

// One [[ride.output]]; `k` its index, for the places of the names it gives; `names` the names
// of the outputs before it (each must be unique: reports key their rows by it).
RideOutput read_output(TableReader& t, size_t k, std::set<std::string>* names,
                       std::map<std::string, KeyPlace>* places) {
  RideOutput out;
  const std::string kind = t.optional_string("kind").value_or("point");
  const auto parsed = ride_output_kind_from_string(kind);
  if (!parsed)
    t.fail("kind", "must be point, element_deflection, element_force or wheel_rail_force, not '" + kind + "'");
  out.kind = *parsed;
  out.axis = read_axis(t);
  const std::string at = "ride.output[" + std::to_string(k) + "].";
  if (out.kind == RideOutput::Kind::point) {
    out.body = t.string("body");
    (*places)[at + "body"] = t.place("body");
    (*places)[at + "point"] = t.place("point");  // scene_warnings: a point beyond the body
    const auto p = t.point("point");
    out.point = Eigen::Vector3d(p[0], p[1], p[2]);
    const std::string quantity = t.optional_string("quantity").value_or("acceleration");
    if (const auto q = response_quantity_from_string(quantity)) out.quantity = *q;
    else t.fail("quantity", "must be displacement, velocity or acceleration, not '" + quantity + "'");
    // body: as an accelerometer on the floor reads it (with gravity's component, g·φ), the
    // EN 12299 measurement; track: inertial (docs/ride.md, "Lateral acceleration's frame").
    const std::string frame = t.optional_string("frame").value_or("body");
    if (const auto f = ride_frame_from_string(frame)) out.frame = *f;
    else t.fail("frame", "must be body (an accelerometer fixed to the body, reading gravity's component g·φ) or "
                         "track (inertial), not '" + frame + "'");
  } else {
    // A wheel–rail force names its wheelset's body; the element outputs an element.
    const char* key = out.kind == RideOutput::Kind::wheel_rail_force ? "wheelset" : "element";
    // The linear contact's two longitudinal creep forces are equal and opposite: their sum on the
    // wheelset, the output, would be a silent zero (docs/ride.md, "The wheel–rail force across
    // the track").
    if (out.kind == RideOutput::Kind::wheel_rail_force && out.axis == RideAxis::longitudinal)
      t.fail("axis", "a longitudinal wheel-rail force is zero in the linear contact (the two wheels' longitudinal "
                     "creep forces are equal and opposite); give lateral or vertical");
    out.element = t.string(key);
    (*places)[at + "element"] = t.place(key);
  }
  // The default name says what the output is: "body (9.5, 0, 1.2) m, acceleration, vertical".
  out.name = out.kind == RideOutput::Kind::point
                 ? out.body + " " + point_text(out.point) + ", " + to_string(out.quantity)
                 : out.element + ", " + to_string(out.kind);
  out.name = t.optional_string("name").value_or(out.name + ", " + to_string(out.axis));
  if (out.name.empty()) t.fail("name", "must not be empty");
  if (!names->insert(out.name).second)
    t.fail(t.has("name") ? "name" : "kind", "an output named '" + out.name + "' is already given; give each its own name");
  t.finish();
  return out;
}

// [ride.realisation]: the synthesised track's length, step and seed.
TrackSynthesisOptions read_realisation(TableReader t) {
  TrackSynthesisOptions r;
  r.length = t.positive("length", Quantity::length);
  r.step = t.positive("step", Quantity::length);
  if (!(r.step < r.length)) t.fail("step", "must be shorter than the length");
  if (r.length / r.step > 1e8) t.fail("step", "gives more than 1e8 samples; take a longer step or a shorter length");
  if (t.has("seed")) {
    const toml::value& v = t.raw("seed");
    if (!v.is_integer() || v.as_integer() < 0) t.fail("seed", "expected a whole number ≥ 0");
    r.seed = static_cast<std::uint64_t>(v.as_integer());
  }
  t.finish();
  return r;
}

// [ride.simulation]: the run's speed, step, settling time, window and the effects it simulates.
// What [ride] says of the track and the indices holds for the run too (`ride`): the contact
// half spacing that turns cross-level into roll, and the averaging window unless the run
// gives its own.
RideSimulationOptions read_simulation(TableReader t, const RideOptions& ride) {
  RideSimulationOptions s;
  s.speed = t.positive("speed", Quantity::speed);
  // Without it, simulate_ride's default (1 ms, or the track's step over the speed if shorter).
  s.time_step = t.optional_positive("time_step", Quantity::time).value_or(0.0);
  s.settle_time = t.optional_positive("settle_time", Quantity::time, true).value_or(0.0);
  s.window = t.optional_positive("window", Quantity::time).value_or(ride.percentile_window);
  s.contact_half_spacing = ride.contact_half_spacing;
  s.rolling_radius = ride.rolling_radius;
  if (t.has("effects"))
    for (const std::string& effect : t.strings("effects")) {
      if (effect == "leaf_friction") s.effects.leaf_friction = true;
      else if (effect == "progressive_springs") s.effects.progressive_springs = true;
      else if (effect == "constant_friction") s.effects.leaf_friction = s.effects.constant_friction = true;
      else
        t.fail("effects", "unknown effect '" + effect +
                              "' (leaf_friction, constant_friction, progressive_springs; viscous dampers are always "
                              "in the linear model)");
    }
  t.finish();
  return s;
}

}  // namespace

RideSpec read_ride(TableReader t, std::map<std::string, KeyPlace>* places) {
  RideSpec ride;
  // Where a ride without speeds is refused (railmodal ride, when --speeds gives none either):
  // the speeds key, or the [ride] table when it is absent.
  (*places)["ride.speeds"] = t.place("speeds");
  read_options(t, ride.options);
  std::set<std::string> names;
  if (t.has("output"))
    for (auto& o : t.tables("output")) ride.outputs.push_back(read_output(o, ride.outputs.size(), &names, places));
  if (t.has("realisation")) ride.realisation = read_realisation(t.table("realisation"));
  if (t.has("simulation")) ride.simulation = read_simulation(t.table("simulation"), ride.options);
  if (ride.realisation && !ride.simulation)
    t.fail("realisation", "a realisation is run through [ride.simulation], which is missing");
  t.finish();
  return ride;
}

}  // namespace railmodal::input
