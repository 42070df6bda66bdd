// What a scene asks of its vehicle that the vehicle gives nothing to, or that lies beyond it:
// accepted, and warned (scene.hpp, scene_warnings; docs/input.md, "Implausible inputs").
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "model/spring_stages.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/vehicle.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

// "scene.toml:20:12: warning: key 'k': message", at the place the scene recorded for `place_key`.
std::string scene_warning(const Scene& scene, const std::string& place_key, const std::string& key,
                          const std::string& message) {
  std::string where = scene.source;
  const auto found = scene.name_places.find(place_key);
  if (found != scene.name_places.end() && found->second.line > 0)
    where += ":" + std::to_string(found->second.line) + ":" + std::to_string(found->second.column);
  return where + ": warning: key '" + key + "': " + message;
}

bool any_stage(const Vehicle& v, bool (*has)(const SpringStage&)) {
  bool found = false;
  model::each_spring_stage(v, [&](const SpringStage& s) { found = found || has(s); });
  return found;
}

// Why the effect has nothing to act on in `v` ("" when it has): what the vehicle lacks.
std::string idle_effect(const std::string& effect, const Vehicle& v) {
  if (effect == "viscous_dampers") {
    // What scene_system builds or leaves out: the elements' vertical and lateral dampers.
    const bool dampers = std::any_of(v.elements.begin(), v.elements.end(), [](const Element& e) {
      return e.vertical_damping > 0.0 || e.lateral_damping > 0.0;
    });
    return dampers ? "" : "no element has vertical_damping or lateral_damping";
  }
  if (effect == "leaf_friction")
    return any_stage(v, [](const SpringStage& s) { return s.relative_friction > 0.0; })
               ? ""
               : "no spring stage has relative_friction or leaf_friction";
  if (effect == "progressive_springs")
    return any_stage(v, [](const SpringStage& s) { return s.curve.has_value(); })
               ? ""
               : "no spring stage has a load_deflection curve";
  return "";
}

// The body's extent along x: its reference point and the points of the elements on it.
std::pair<double, double> element_extent(const Vehicle& v, const Body& body) {
  double rear = body.reference_point.x(), front = rear;
  for (const Element& e : v.elements)
    if (e.upper == body.name || e.lower == body.name) {
      rear = std::min(rear, e.point.x());
      front = std::max(front, e.point.x());
    }
  return {rear, front};
}

std::string metres(double x) { return shortest_text(std::round(x * 1000.0) / 1000.0) + " m"; }

}  // namespace

std::vector<std::string> scene_warnings(const Scene& scene, const Vehicle& vehicle) {
  std::vector<std::string> out;
  const std::string named = "vehicle '" + vehicle.name + "'";
  if (scene.simulation) {
    const std::vector<std::string>& effects = scene.simulation->effects;
    for (size_t k = 0; k < effects.size(); ++k) {
      const std::string lacks = idle_effect(effects[k], vehicle);
      if (!lacks.empty())
        out.push_back(scene_warning(scene, "simulation.effects[" + std::to_string(k) + "]", "simulation.effects",
                                    "'" + effects[k] + "' does nothing: " + named + " has no part it acts on (" +
                                        lacks + ")"));
    }
  }
  if (scene.ride)
    for (size_t k = 0; k < scene.ride->outputs.size(); ++k) {
      const RideOutput& o = scene.ride->outputs[k];
      if (o.kind != RideOutput::Kind::point) continue;
      const auto body = std::find_if(vehicle.bodies.begin(), vehicle.bodies.end(),
                                     [&](const Body& b) { return b.name == o.body; });
      if (body == vehicle.bodies.end()) continue;  // check_scene_fits refuses it
      const double x = o.point.x();
      const std::string key = "ride.output[" + std::to_string(k) + "].point";
      if (body->bending) continue;  // its beam gives its ends: check_scene_fits refuses a point beyond them
      // The vehicle does not say where the body ends. A wagon's body overhangs its outermost
      // supports by a few metres (a two-axle wagon's 4 m wheelbase under a 10–14 m body; a
      // coach's bogie centres 19 m apart under 26 m): beyond a quarter of the supports' span,
      // and at least 4 m, the point is not plausibly on the body.
      const auto [rear, front] = element_extent(vehicle, *body);
      const double margin = std::max(4.0, 0.25 * (front - rear));
      if (x > front + margin || x < rear - margin)
        out.push_back(scene_warning(scene, key, key,
                                    "x = " + metres(x) + " is " + metres(x > front ? x - front : rear - x) +
                                        " beyond the outermost element on body '" + body->name + "' (x = " +
                                        metres(rear) + " to " + metres(front) +
                                        "); a body overhangs its supports by a few metres: is the point on it?"));
    }
  return out;
}

}  // namespace railmodal
