// railmodal hunting SCENE [--vehicle VEHICLE] [--continuation] [--format table|csv|json|markdown|html] [-o OUT]
//
// The nonlinear critical speed of a scene's vehicle (its [nonlinear_hunting] table): a command of
// its own, not a mode of `stability`, because every other command takes one kind of file and
// `stability` takes a vehicle, while the ramp-down needs what only a scene states (the effects
// simulated and their laws, the disturbance, the ramp), as `simulate` and `ride` do.
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

// The formats `hunting` writes, its default first.
const std::vector<std::string> kHuntingFormats{"table", "csv", "json", "markdown", "html"};

struct HuntingCommandOptions {
  std::string scene;
  std::string vehicle;  // "": the scene's
  std::string format;   // "": from the output file's extension, else table
  std::string output = "-";
  bool continuation = false;  // also the branch of limit cycles by continuation from the Hopf point
  bool quiet = false;         // no progress on stderr
};

// The linear critical speed over the ramp's speeds, for the plot's Hopf point: none when the
// centred running is stable over the whole ramp or already unstable at its end speed.
std::optional<double> linear_critical_speed(const LinearSystem& system, const NonlinearHuntingOptions& o) {
  HuntingOptions h;
  h.min_speed = o.end_speed;
  h.max_speed = o.start_speed;
  h.threads = 1;
  const HuntingResult linear = solve_hunting_stability(system, h);
  if (linear.critical) return linear.critical->speed;
  return std::nullopt;
}

int run(const HuntingCommandOptions& o) {
  std::string current = o.scene;  // the file an error without a location belongs to
  try {
    const OutputFormat format = report_format(o.format, o.output, kHuntingFormats);
    OutputFiles files;
    std::ostream& out = files.open(o.output);
    Scene scene = load_scene(o.scene);
    if (!scene.nonlinear_hunting) {
      std::cerr << o.scene << ": error: the scene has no [nonlinear_hunting] table: it states the ramp and the "
                << "effects simulated (docs/stability.md, \"The nonlinear critical speed\"); for the linear "
                << "critical speed run 'railmodal stability VEHICLE'\n";
      return kInput;
    }
    if (!o.vehicle.empty()) scene.vehicle_file = o.vehicle;  // the command line wins over the scene
    if (scene.vehicle_file.empty()) {
      std::cerr << "railmodal: error: no vehicle: give --vehicle VEHICLE.toml or a 'vehicle' key in " << o.scene << "\n";
      return kUsage;
    }
    files.refuse_inputs({o.scene, scene.vehicle_file});
    current = scene.vehicle_file;
    const Vehicle vehicle = load_vehicle_and_warn(scene.vehicle_file);
    if (vehicle.wheelsets.empty()) {
      const std::string why = "the vehicle has no [wheelset] data: hunting needs wheelsets on rails (docs/stability.md)";
      // Blame the scene's `vehicle` key, where the file was chosen; a --vehicle file itself.
      if (!o.vehicle.empty()) throw InputError(scene.vehicle_file, 0, 0, why);
      const KeyPlace at = scene.name_places["scene.vehicle"];
      throw InputError(o.scene, at.line, at.column, "key 'scene.vehicle': " + why);
    }
    const NonlinearHuntingOptions& options = *scene.nonlinear_hunting;
    NonlinearHuntingResult result;
    std::optional<double> linear;
    std::optional<LimitCycleBranch> branch;
    try {
      // The lateral motions, as `stability` assembles them.
      const LinearSystem system = assemble(vehicle, DofSet::lateral);
      linear = linear_critical_speed(system, options);
      result = solve_nonlinear_hunting(system, options);
      if (o.continuation) {
        LimitCycleOptions cycles;
        if (!o.quiet) cycles.progress = terminal_progress("hunting --continuation");
        branch = continue_limit_cycles(system, options, cycles);
      }
    } catch (const std::invalid_argument& e) {
      // The scene's options were checked by its reader; what is left is a wheelset or contact
      // value of the vehicle file the contact model cannot take (it names the wheelset).
      throw InputError(scene.vehicle_file, 0, 0, e.what());
    }
    write_nonlinear_hunting(out, result, options, format, vehicle.name, provenance_of({o.scene, scene.vehicle_file}),
                            linear, branch ? &*branch : nullptr);
    files.commit();
    if (branch && branch->end == ContinuationEnd::newton_failed)
      std::cerr << o.scene << ": warning: the continuation of the limit cycles stopped where its corrector failed: "
                << branch->failure << "\n";
    // A result that did not converge is written (its figures show what went wrong) but is not an
    // answer: exit 6, as a ride whose checks failed, with the reason and what to change on stderr.
    if (result.convergence == NonlinearConvergence::not_converged) {
      std::cerr << o.scene << ": hunting check FAILED: the nonlinear critical speed is not converged: "
                << nonlinear_hunting_warning(result, options) << " The report is written as an estimate.\n";
      return kCheckFailed;
    }
    return kSuccess;
  } catch (...) {
    return exit_of_error("hunting", current);
  }
}

}  // namespace

std::function<int()> add_hunting_command(CLI::App& app) {
  auto options = std::make_shared<HuntingCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "hunting",
      "Nonlinear critical speed of a scene's vehicle on its wheelsets: the speed ramped down from a disturbed start "
      "with the effects the scene names (creep saturation, flange contact), the lowest speed at which a hunting "
      "limit cycle survives and its amplitude, the convergence check, and the bifurcation plot (docs/stability.md)");
  cmd->add_option("scene", options->scene,
                  "Scene file (TOML) with a [nonlinear_hunting] table, e.g. "
                  "data/scenes/wheelset_on_springs_nonlinear_hunting.toml")
      ->required();
  cmd->add_option("--vehicle", options->vehicle, "Vehicle file (TOML) with [wheelset] data, in place of the scene's");
  cmd->add_flag("--continuation", options->continuation,
                "Also follow the branch of limit cycles from the Hopf point by shooting and pseudo-arclength "
                "continuation in speed: the unstable cycles of a subcritical branch and its fold (docs/stability.md, "
                "\"Continuation of the limit cycles\"). Long: about 1 s of CPU for the bundled wheelset, about 2 "
                "minutes for a bogie coach (some 17 000 one-period integrations; far longer in wall time on a loaded "
                "machine); its progress shows on stderr when stderr is a terminal (-q: none)");
  cmd->add_option("--format", options->format,
                  "Output format: table, csv (every half cycle of both ramps: the bifurcation data), json, markdown, "
                  "html (with the bifurcation plot); " + format_rule_help(kHuntingFormats))
      ->check(CLI::IsMember(kHuntingFormats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  add_quiet_flag(*cmd, &options->quiet);
  return [options] { return run(*options); };
}

}  // namespace railmodal::cli
