// railmodal ride SCENE [--vehicle VEHICLE] [--speeds "100 km/h:200 km/h:20 km/h"] [--threads N] [--rms-only]
//                      [--format table|csv|json|markdown|html] [-o OUT] [--spectra SPECTRA.csv]
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

// The formats `ride` writes, its default first.
const std::vector<std::string> kRideFormats{"table", "csv", "json", "markdown", "html"};

struct RideCommandOptions {
  std::string scene;
  std::string vehicle;  // "": the scene's
  std::string speeds;   // the scene's [ride] speeds unless speeds_given
  bool speeds_given = false;  // --speeds "" is refused, not taken for the scene's
  int threads = 1;
  bool rms_only = false;  // RideOptions::rms_only
  std::string format;  // "": from the output file's extension, else table
  std::string output = "-";
  std::string spectra;  // also the input and output PSDs, as CSV, to this file ("": not asked)
};

// --speeds, read before any file (a usage error, exit 2); empty: not given.
std::vector<double> command_line_speeds(const RideCommandOptions& o) {
  if (!o.speeds_given) return {};
  try {
    return parse_speeds(o.speeds);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--speeds: ") + e.what());
  }
}

// The scene's [ride] options (or the defaults) with the command line's speeds, threads and
// --rms-only; without speeds in either, the time-domain run's speed (the one its FFT check (c)
// compares at).
RideOptions ride_options(const Scene& scene, const std::vector<double>& speeds, const RideCommandOptions& o) {
  RideOptions options = scene.ride ? scene.ride->options : RideOptions{};
  if (!speeds.empty()) options.speeds = speeds;
  if (options.speeds.empty() && scene.ride && scene.ride->simulation) options.speeds = {scene.ride->simulation->speed};
  if (options.speeds.empty()) {
    // At the [ride] table (its speeds key), or at the irregularity source of a scene without one,
    // with file:line as every input error.
    const std::string message = "no speeds: give them in [ride] (speeds = \"100 km/h:200 km/h:20 km/h\") or as --speeds";
    const auto ride = scene.name_places.find("ride.speeds");
    if (ride != scene.name_places.end())
      throw InputError(scene.source, ride->second.line, ride->second.column, "key 'ride.speeds': " + message);
    const auto source = scene.name_places.find("irregularity");
    const KeyPlace at = source != scene.name_places.end() ? source->second : KeyPlace{};
    throw InputError(scene.source, at.line, at.column, message);
  }
  options.threads = o.threads;
  options.rms_only = o.rms_only;
  return options;
}

// The time-domain run the scene asks for, on a synthesised realisation or measured geometry.
struct TimeDomain {
  RideSimulationResult simulated;
  std::optional<RideFftChecks> checks;
};

// The track of the time-domain run, synthesised or measured; read before any analysis, so that
// a bad geometry file is reported at once.
std::optional<TrackGeometry> run_track(const Scene& scene) {
  if (!scene.ride || !scene.ride->simulation) return std::nullopt;
  return scene.ride->realisation ? synthesise_track(*scene.irregularity, *scene.ride->realisation)
                                 : load_track_geometry(scene.ride->geometry_file);
}

std::optional<TimeDomain> run_time_domain(const Scene& scene, const LinearSystem& system,
                                          const std::vector<RideOutput>& outputs,
                                          const std::optional<TrackGeometry>& track) {
  if (!track) return std::nullopt;
  const RideSpec& spec = *scene.ride;
  const TrackGeometry& geometry = *track;
  TimeDomain run;
  run.simulated = simulate_ride(system, geometry, outputs, *spec.simulation);
  // The checks compare with the spectra the realisation was drawn from: none for measured track.
  if (spec.realisation)
    run.checks = check_ride_realisation(system, *scene.irregularity, geometry, run.simulated, *spec.simulation);
  return run;
}

bool has_spectra(const TrackIrregularitySpectra& t) { return t.vertical_level || t.alignment || t.cross_level; }

// The ride's refusal of one of the scene's spectra once the vehicle is known ("ride: the
// alignment component (...) moves no degree of freedom of this model", "ride: cross-level on a
// vehicle with wheelsets ..."), as the scene file's error at that component's table and key; at
// the scene file when the scene does not say where the component is written (the audit of
// 2026-11-27 met the first with neither line nor key).
InputError ride_scene_error(const Scene& scene, const IrregularityComponentError& refused) {
  const std::string key = to_string(refused.component());
  const auto written = scene.name_places.find("irregularity." + key);
  if (written == scene.name_places.end()) return InputError(scene.source, 0, 0, refused.what());
  return InputError(scene.source, written->second.line, written->second.column,
                    "key 'source." + key + "': " + refused.what());
}

// What the ride leaves out of a scene, said in the report rather than dropped silently: its
// periodic sources (rail joints, wheel defects, …), which `simulate` and `critical-speed` take.
void note_ignored_sources(const Scene& scene, RideResult* result) {
  for (const auto& source : scene.sources)
    result->notes.push_back("the scene's periodic source " + source->description() +
                            " is not part of the ride on random track (railmodal simulate or critical-speed take it)");
}

// A ride whose own checks failed (the friction linearisation not converged) is written, then
// exits 6 with the failed checks on stderr: its figures are not answers to sign off on.
int ride_exit(const std::string& scene_file, const RideResult& result) {
  int failed = 0;
  for (const Check& c : result.summary.checks)
    if (!c.passed) {
      std::cerr << scene_file << ": ride check FAILED: " << c.name << " = " << c.value << " above " << c.limit << "\n";
      ++failed;
    }
  return failed ? kCheckFailed : kSuccess;
}

int run(const RideCommandOptions& o) {
  std::string current = o.scene;  // the file an error without a location belongs to
  OutputFormat format;
  std::vector<double> speeds;
  try {
    format = report_format(o.format, o.output, kRideFormats);
    speeds = command_line_speeds(o);
  } catch (const UsageError& e) {
    return usage_error("ride", e.what());
  }
  try {
    OutputFiles files;
    std::ostream& out = files.open(o.output);
    std::ostream* spectra = o.spectra.empty() ? nullptr : &files.open(o.spectra);
    Scene scene = load_scene(o.scene);
    if (!scene.irregularity) {
      std::cerr << o.scene << ": error: the scene has no [[source]] with kind = \"irregularity\": the ride is the "
                << "response to random track (docs/scenes.md, \"Ride scenes\")\n";
      return kInput;
    }
    if (!o.vehicle.empty()) scene.vehicle_file = o.vehicle;  // the command line wins over the scene
    if (scene.vehicle_file.empty()) {
      std::cerr << "railmodal: error: no vehicle: give --vehicle VEHICLE.toml or a 'vehicle' key in " << o.scene << "\n";
      return kUsage;
    }
    if (o.rms_only && scene.ride && scene.ride->simulation)
      return usage_error("ride", "--rms-only: " + o.scene + " runs the time domain ([ride.simulation]), whose " +
                                     "indices come from its simulated histories, not from the spectral solve the " +
                                     "option shortens: run it without --rms-only");
    if (spectra && !has_spectra(*scene.irregularity))
      return usage_error("ride", "--spectra: " + o.scene + " gives measured geometry alone, whose ride is its " +
                                     "time-domain run: there are no spectra to write");
    const RideOptions options = ride_options(scene, speeds, o);
    const std::vector<std::string> inputs{o.scene, scene.vehicle_file,
                                          scene.ride ? scene.ride->geometry_file : std::string()};
    files.refuse_inputs(inputs);
    current = scene.vehicle_file;
    const Vehicle vehicle = load_vehicle_and_warn(scene.vehicle_file);
    const LinearSystem system = assemble(vehicle, scene.dofs);
    current = o.scene;
    print_input_warnings(scene_warnings(scene, vehicle));  // a floor point beyond the body
    check_scene_fits(scene, system);
    const std::vector<RideOutput> outputs =
        scene.ride && !scene.ride->outputs.empty() ? scene.ride->outputs : default_ride_outputs(system);
    RideResult result;
    result.outputs = outputs;
    std::optional<TimeDomain> time_domain;
    try {
      const std::optional<TrackGeometry> track = run_track(scene);
      // Measured geometry alone has no spectra: only its time-domain run is reported.
      if (has_spectra(*scene.irregularity)) result = solve_ride(system, *scene.irregularity, outputs, options);
      time_domain = run_time_domain(scene, system, outputs, track);
    } catch (const IrregularityComponentError& e) {
      // The reader checked every key it could; what is left is a component only the vehicle, the
      // grid or the realisation can refuse (a component that moves nothing, a band the
      // realisation cannot sample): the scene's error, at the component the library names.
      throw ride_scene_error(scene, e);
    } catch (const std::invalid_argument& e) {
      throw InputError(scene.source, 0, 0, e.what());  // the scene's, at no one component
    }
    note_ignored_sources(scene, &result);
    std::vector<std::string> provenance_files{o.scene, scene.vehicle_file};
    if (scene.ride && !scene.ride->geometry_file.empty()) provenance_files.push_back(scene.ride->geometry_file);
    // The report names the vehicle it ran (--vehicle may replace the scene's).
    const std::string title = scene.name + " — vehicle: " + (system.vehicle.name.empty() ? scene.vehicle_file
                                                                                         : system.vehicle.name);
    write_ride(out, result, format, title, provenance_of(provenance_files),
               time_domain ? &time_domain->simulated : nullptr,
               time_domain && time_domain->checks ? &*time_domain->checks : nullptr);
    if (spectra) write_ride_spectra(*spectra, result);
    files.commit();
    return ride_exit(o.scene, result);
  } catch (...) {
    return exit_of_error("ride", current);
  }
}

}  // namespace

std::function<int()> add_ride_command(CLI::App& app) {
  auto options = std::make_shared<RideCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "ride",
      "Ride on random track: the response spectra of a scene's vehicle to its track irregularity, the RMS, EN 12299 "
      "weighted RMS and P95, Sperling's Wz and N_MV per floor point, with the dominant modes (docs/ride.md)");
  cmd->add_option("scene", options->scene,
                  "Scene file (TOML) with a [[source]] of kind = \"irregularity\" and a [ride] table, e.g. "
                  "data/scenes/manchester_coach_ore_low.toml")
      ->required();
  cmd->add_option("--vehicle", options->vehicle, "Vehicle file (TOML), in place of the scene's");
  CLI::Option* speeds = cmd->add_option("--speeds", options->speeds,
                  "Speeds, in place of the scene's: a list \"100 km/h, 160 km/h\" or a range MIN:MAX:STEP such as "
                  "\"100 km/h:200 km/h:20 km/h\" (MIN:MAX alone: 11 speeds)");
  cmd->add_option("--threads", options->threads, "Threads over speeds (default 1: a ride of a few speeds takes milliseconds; threads pay on a long grid)")->check(CLI::Range(1, 1024));
  cmd->add_flag("--rms-only", options->rms_only,
                "Only each output's RMS and EN 12299 weighted RMS, at about 55 % of the CPU: no Sperling Wz, P95 "
                "estimate, N_MV, modal shares or grid error estimate (the report says so); the same RMS and weighted "
                "RMS bit for bit. Not for a scene with [ride.simulation] (the time domain)");
  cmd->add_option("--format", options->format,
                  "Output format: table, csv (one row per speed), json, markdown, html (with the input and "
                  "output spectra and the indices against speed); " + format_rule_help(kRideFormats))
      ->check(CLI::IsMember(kRideFormats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  cmd->add_option("--spectra", options->spectra,
                  "Also write the spectra behind the RMS to this file, always CSV: one row per speed and frequency, "
                  "the track inputs' PSDs [m²/Hz] and each output's [unit²/Hz] against frequency [Hz], for plotting "
                  "in another tool");
  add_quiet_flag(*cmd, nullptr);
  return [options, speeds] {
    options->speeds_given = speeds->count() > 0;
    return run(*options);
  };
}

}  // namespace railmodal::cli
