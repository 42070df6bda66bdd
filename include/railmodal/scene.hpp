// A scene: a vehicle on a track at a range of speeds, with the excitation sources it names
// and the outputs it wants. Only the named sources are built and evaluated.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     railmodal::Scene scene = railmodal::load_scene("data/scenes/resort_car_10m_rails.toml");
//     std::cout << scene.name << ": " << scene.min_speed * 3.6 << "-" << scene.max_speed * 3.6 << " km/h\n";
//     for (const auto& source : scene.sources) std::cout << "  " << source->description() << "\n";
//   }
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/errors.hpp"
#include "railmodal/excitation.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/nonlinear_hunting.hpp"
#include "railmodal/response.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/ride_simulation.hpp"
#include "railmodal/simulation.hpp"

namespace railmodal {

struct SceneOutput {
  std::string dof;  ///< DOF label, e.g. "body.bounce"
  ResponseQuantity quantity = ResponseQuantity::displacement;
};

/// The [simulation] table: one run at one speed.
struct SimulationSpec {
  double speed = 0.0;      ///< m/s (0 without sources: a released wagon standing still)
  double final_speed = 0.0;  ///< m/s; > 0: the speed ramps linearly from `speed` to it
  /// Leaf friction law: "proportional" (default, the book's R = c(1 ± φ)(f ± z)) or
  /// "constant" (a Coulomb force φ·P₀, the simplification 1 ± φ ≈ 1 of Example 3).
  std::string friction_law = "proportional";
  double duration = 0.0;   ///< s
  double time_step = 0.0;  ///< s, output step (and the linear path's integration step)
  /// Vehicle effects the scene names: "viscous_dampers", "leaf_friction",
  /// "progressive_springs"; sources come from [[source]]. Nothing else is built.
  std::vector<std::string> effects;
  double tolerance = 1e-10;        ///< nonlinear path: integrator tolerance
  double event_tolerance = 1e-12;  ///< nonlinear path: event location, s
  std::vector<InitialCondition> initial;
  std::vector<std::string> outputs;  ///< DOF labels to write; empty: all
};

/// The [ride] table of a scene: what `railmodal ride` computes on the scene's track
/// irregularity (Scene::irregularity, from its `[[source]] kind = "irregularity"` table).
struct RideSpec {
  RideOptions options;              ///< speeds, frequency grid, modal truncation, …
  std::vector<RideOutput> outputs;  ///< empty: default_ride_outputs of the assembled vehicle
  /// A time-domain run: on a realisation synthesised from the spectra …
  std::optional<TrackSynthesisOptions> realisation;
  /// … or on measured geometry (a file resolved against the scene file's folder).
  std::string geometry_file;
  /// The run's speed, step, settling time and the effects it simulates (present when the
  /// scene asks for a time-domain run).
  std::optional<RideSimulationOptions> simulation;
};

struct Scene {
  std::string name;
  std::string source;        ///< the scene file
  std::string vehicle_file;  ///< resolved against the scene file's folder; "" if not named
  DofSet dofs = DofSet::all;
  double min_speed = 0.0;    ///< m/s
  double max_speed = 0.0;    ///< m/s
  double speed_step = 0.0;   ///< m/s, grid of the amplitude curves
  std::vector<std::shared_ptr<const ExcitationSource>> sources;
  std::vector<SceneOutput> outputs;  ///< empty: the most energetic DOF of each excited mode
  /// [friction] model = "equivalent_viscous": leaf friction also acts as the viscous damping
  /// that dissipates as much at this element stretch amplitude (m); 0 (model = "criterion",
  /// the default): friction only decides whether a resonance can grow.
  double friction_reference_amplitude = 0.0;
  std::optional<SimulationSpec> simulation;  ///< present when the scene simulates
  /// Random track irregularity (`[[source]] kind = "irregularity"`): not a periodic source, so
  /// not in `sources`; read by `railmodal ride` only.
  std::optional<TrackIrregularitySpectra> irregularity;
  std::optional<RideSpec> ride;  ///< the [ride] table
  /// The [nonlinear_hunting] table: what `railmodal hunting` runs (the ramp-down of
  /// solve_nonlinear_hunting). Its effects are the sub-tables the file names
  /// ([nonlinear_hunting.creep_saturation], [nonlinear_hunting.flange_contact]); only those are
  /// simulated (docs/stability.md, "The nonlinear critical speed").
  std::optional<NonlinearHuntingOptions> nonlinear_hunting;
  /// Where the file writes the names that only the assembled vehicle can check, by key path:
  /// "output[0].dof", "simulation.outputs[1]", "simulation.initial[0].dof", and the keys of
  /// sources ExcitationSource::misfit names ("source[2].body", "source[2].phases"; a key left
  /// to its default is placed at its table). Empty for a scene built in code.
  std::map<std::string, KeyPlace> name_places;
};

/// Checks the scene's names against its assembled vehicle: the DOFs of its [[output]] tables
/// and of its simulation's outputs and initial conditions are labels of `system`, and every
/// source fits it (ExcitationSource::misfit). Throws InputError at the key in the scene file,
/// listing the DOFs there are. The analyses of a scene call it before they start.
void check_scene_fits(const Scene& scene, const LinearSystem& system);

/// Reads a scene file; errors are InputError with file, line, column and key.
Scene load_scene(const std::string& path);

/// What the scene asks of `vehicle` that the vehicle gives nothing to, or that lies beyond it,
/// each "scene.toml:20:12: warning: ..." (docs/input.md, "Implausible inputs"): an effect of
/// [simulation] the vehicle has no part for (viscous_dampers without dampers, leaf_friction
/// without leaf friction, progressive_springs without a curve), a [[ride.output]] point beyond
/// the body's extent. Accepted inputs: the caller shows them; no analysis changes.
std::vector<std::string> scene_warnings(const Scene& scene, const Vehicle& vehicle);

}  // namespace railmodal
