// The names a scene uses, checked against its assembled vehicle before any analysis: a DOF
// or a body the vehicle lacks is the scene file's error, at the key that names it; and the
// series dampers an analysis of the scene cannot represent, the vehicle file's error.
#include "railmodal/scene.hpp"

#include <cmath>
#include <stdexcept>

#include "model/analysis_limits.hpp"
#include "model/scene_fit.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

// An InputError at the place the scene writes `place_key`, naming `key`.
[[noreturn]] void fail_at(const Scene& scene, const std::string& place_key, const std::string& key,
                          const std::string& message) {
  const auto found = scene.name_places.find(place_key);
  const KeyPlace place = found == scene.name_places.end() ? KeyPlace{} : found->second;
  throw InputError(scene.source, place.line, place.column, "key '" + key + "': " + message);
}

// Checks that `dof` is one of the system's DOFs.
void check_dof(const Scene& scene, const LinearSystem& system, const std::string& dof, const std::string& place_key,
               const std::string& key) {
  if (system.index_of(dof) >= 0) return;
  std::string known;
  for (const auto& d : system.dofs) known += (known.empty() ? "" : ", ") + d.label;
  fail_at(scene, place_key, key,
          "'" + dof + "' is not a degree of freedom of this vehicle in the '" + to_string(scene.dofs) + "' set (" +
              known + ")");
}

// Checks that a ride output's body, element or wheelset is one of the vehicle's.
void check_ride_output(const Scene& scene, const LinearSystem& system, const RideOutput& o, size_t k) {
  const Vehicle& v = system.vehicle;
  const std::string at = "ride.output[" + std::to_string(k) + "].";
  auto list = [](const auto& items, auto name) {
    std::string known;
    for (const auto& item : items) known += (known.empty() ? "" : ", ") + name(item);
    return known.empty() ? std::string("none") : known;
  };
  if (o.kind == RideOutput::Kind::point) {
    for (const Body& b : v.bodies) {
      if (b.name != o.body) continue;
      // A bending beam's length is the body's: a point beyond its ends is not on the body (the
      // tolerance of model::BendingMode::shape_at, which would refuse it without the key).
      // Without a beam the body's ends are not known: scene_warnings warns instead.
      if (b.bending) {
        const double centre = b.bending->centre.value_or(b.centre_of_gravity.x());
        const double half = 0.5 * b.bending->length;
        if (std::abs(o.point.x() - centre) > half * (1.0 + 2e-9))
          fail_at(scene, at + "point", at + "point",
                  "x = " + shortest_text(o.point.x()) + " m is beyond the ends of body '" + b.name +
                      "' (its bending beam: x = " + shortest_text(centre - half) + " m to " +
                      shortest_text(centre + half) + " m)");
      }
      return;
    }
    fail_at(scene, at + "body", at + "body",
            "the vehicle has no body '" + o.body + "' (" + list(v.bodies, [](const Body& b) { return b.name; }) + ")");
  }
  if (o.kind == RideOutput::Kind::wheel_rail_force) {
    for (const Wheelset& w : v.wheelsets) {
      if (w.body != o.element) continue;
      if (o.axis != RideAxis::lateral) return;
      // The lateral one is the creep contact's, which the ride assembles with the wheelset's
      // lateral motion free (docs/ride.md, "The wheel–rail force across the track").
      for (const Dof& d : system.dofs)
        if (d.motion == Motion::lateral && v.bodies[d.body].name == w.body) return;
      fail_at(scene, at + "element", at + "wheelset",
              "the lateral wheel-rail force of wheelset '" + w.body + "' is the creep contact's, which needs the "
              "wheelsets' lateral and yaw motions: give scene.dofs = \"all\" or \"lateral\" (this scene's: '" +
                  to_string(scene.dofs) + "')");
    }
    fail_at(scene, at + "element", at + "wheelset",
            "the vehicle has no wheelset on a body '" + o.element + "' (wheelsets: " +
                list(v.wheelsets, [](const Wheelset& w) { return w.body; }) + ")");
  }
  for (const Element& e : v.elements)
    if (e.name == o.element) return;
  fail_at(scene, at + "element", at + "element",
          "the vehicle has no element '" + o.element + "' (" +
              list(v.elements, [](const Element& e) { return e.name; }) + ")");
}

}  // namespace

namespace model {

void refuse_ride_only_scene(const Scene& scene, const std::string& analysis) {
  if (!scene.irregularity || !scene.sources.empty()) return;
  fail_at(scene, "irregularity", "source.kind",
          "the scene's only source is a random track irregularity, which " + analysis +
              " do not take (they are for periodic sources: rail joints, wheel flats, …); its ride on random "
              "track is 'railmodal ride " + scene.source + "'");
}

void refuse_scene_series_dampers(const Scene& scene, const LinearSystem& system, const char* analysis) {
  try {
    refuse_series_dampers(system, analysis);
  } catch (const std::invalid_argument& e) {
    // The file that holds the damper is the vehicle's as read (a --vehicle in place of the
    // scene's key included), not the scene's key that named another; a vehicle built in code
    // has none, and the scene that asked for the analysis is blamed.
    const std::string& file = system.vehicle.source.empty() ? scene.source : system.vehicle.source;
    throw InputError(file, 0, 0, e.what());
  }
}

}  // namespace model

void check_scene_fits(const Scene& scene, const LinearSystem& system) {
  for (size_t i = 0; i < scene.outputs.size(); ++i) {
    const std::string key = "output[" + std::to_string(i) + "].dof";
    check_dof(scene, system, scene.outputs[i].dof, key, key);
  }
  if (scene.simulation) {
    const std::vector<std::string>& outputs = scene.simulation->outputs;
    for (size_t i = 0; i < outputs.size(); ++i)
      check_dof(scene, system, outputs[i], "simulation.outputs[" + std::to_string(i) + "]", "simulation.outputs");
    const std::vector<InitialCondition>& initial = scene.simulation->initial;
    for (size_t i = 0; i < initial.size(); ++i) {
      const std::string key = "simulation.initial[" + std::to_string(i) + "].dof";
      check_dof(scene, system, initial[i].dof, key, key);
    }
  }
  for (size_t i = 0; i < scene.sources.size(); ++i) {
    if (const auto misfit = scene.sources[i]->misfit(system)) {
      const std::string key = "source[" + std::to_string(i) + "]." + misfit->key;
      fail_at(scene, key, key, misfit->reason);
    }
    // A lateral input under a wheelset is refused by the source's load (ExcitationSource::load):
    // asked here once, so that the scene's error names the source and its line.
    if (!system.vehicle.wheelsets.empty()) try {
        (void)scene.sources[i]->load(system, scene.sources[i]->wavelength(), 1);
      } catch (const std::invalid_argument& e) {
        const std::string key = "source[" + std::to_string(i) + "].kind";
        fail_at(scene, key, key, e.what());
      }
  }
  if (scene.ride)
    for (size_t k = 0; k < scene.ride->outputs.size(); ++k) check_ride_output(scene, system, scene.ride->outputs[k], k);
  // No refusal of series dampers here: the ride (both domains) and the hunting stability take
  // them; the analyses that stand on M, C and K alone call model::refuse_scene_series_dampers.
}

}  // namespace railmodal
