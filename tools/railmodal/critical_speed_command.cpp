// railmodal critical-speed SCENE [--vehicle VEHICLE] [--format markdown|html|csv|json] [-o OUT]
// (the old spelling, critical-speed [VEHICLE] --scene SCENE, still works with a deprecation note)
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/critical_speed_report.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

// The formats `critical-speed` writes, its default first.
const std::vector<std::string> kCriticalSpeedFormats{"markdown", "html", "csv", "json"};

struct CriticalSpeedCommandOptions {
  std::string argument;  // the scene; in the old spelling (--scene given), the vehicle
  std::string vehicle;
  std::string scene;
  std::string format;  // "": report_format's rule
  std::string output = "-";
  bool quiet = false;
};

// The old spelling, `critical-speed [VEHICLE] --scene SCENE`, read as the new one with a note on
// stderr; "" if the options are fine, else the usage error.
std::string read_spelling(CriticalSpeedCommandOptions* o) {
  if (o->scene.empty()) {
    if (o->argument.empty())
      return "critical-speed needs a SCENE file: railmodal critical-speed SCENE [--vehicle VEHICLE]";
    o->scene = o->argument;
    return "";
  }
  if (!o->argument.empty() && !o->vehicle.empty())
    return "give the vehicle once: railmodal critical-speed SCENE --vehicle VEHICLE";
  warn_deprecated_spelling("critical-speed [VEHICLE] --scene SCENE", "critical-speed SCENE [--vehicle VEHICLE]");
  if (!o->argument.empty()) o->vehicle = o->argument;
  return "";
}

int run(CriticalSpeedCommandOptions o) {
  if (const std::string problem = read_spelling(&o); !problem.empty()) {
    return usage_error("critical-speed", problem);
  }
  std::string current = o.scene;  // the file an error without a location belongs to
  try {
    const OutputFormat format = report_format(o.format, o.output, kCriticalSpeedFormats);
    OutputFiles outputs;
    std::ostream& out = outputs.open(o.output);
    Scene scene = load_scene(o.scene);
    if (scene.irregularity && scene.sources.empty()) {
      std::cerr << o.scene << ": error: the scene's only source is a random track irregularity, which critical speeds "
                << "do not take (they are for periodic sources): its ride on random track is 'railmodal ride "
                << o.scene << "'\n";
      return kInput;
    }
    if (scene.sources.empty() || scene.max_speed <= 0.0) {
      std::cerr << o.scene << ": error: the scene has no [speed] range and [[source]]: nothing to sweep"
                << (scene.simulation ? " (it is a simulation scene: use 'railmodal simulate' or 'railmodal fft-check')" : "")
                << "\n";
      return kInput;
    }
    if (!o.vehicle.empty()) scene.vehicle_file = o.vehicle;  // the command line wins over the scene
    if (scene.vehicle_file.empty()) {
      std::cerr << "railmodal: error: no vehicle: give --vehicle VEHICLE.toml or a 'vehicle' key in " << o.scene
                << "\n";
      return kUsage;
    }
    current = scene.vehicle_file;
    outputs.refuse_inputs({o.scene, scene.vehicle_file});
    const Vehicle vehicle = load_vehicle_and_warn(scene.vehicle_file);
    try {
      assemble(vehicle, scene.dofs);  // a vehicle that cannot be assembled is the vehicle file's fault
    } catch (const std::invalid_argument& e) {
      throw InputError(current, 0, 0, e.what());
    }
    CriticalSpeedStudy study;
    try {
      study = study_critical_speeds(scene, vehicle, o.quiet ? std::function<void(double)>() : terminal_progress("critical-speed"));
    } catch (const std::invalid_argument& e) {
      throw InputError(o.scene, 0, 0, e.what());  // the scene's sources do not fit this vehicle
    }
    write_critical_speed_report(out, study, format, provenance_of({o.scene, scene.vehicle_file}));
    outputs.commit();
    return kSuccess;
  } catch (...) {
    return exit_of_error("critical-speed", current);
  }
}

}  // namespace

std::function<int()> add_critical_speed_command(CLI::App& app) {
  auto options = std::make_shared<CriticalSpeedCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "critical-speed", "Resonance speeds of a vehicle for the excitation sources of a scene, with a report");
  cmd->add_option("scene", options->argument,
                  "Scene file (TOML) with a [speed] range and [[source]] tables, e.g. "
                  "data/scenes/resort_car_10m_rails.toml");
  cmd->add_option("--vehicle", options->vehicle, "Vehicle file (TOML); default: the scene's 'vehicle'");
  cmd->add_option("--scene", options->scene,
                  "Deprecated spelling: critical-speed [VEHICLE] --scene SCENE (works, with a note on stderr)");
  cmd->add_option("--format", options->format,
                  "Report format: markdown, html (with plots), csv, json; " + format_rule_help(kCriticalSpeedFormats))
      ->check(CLI::IsMember(kCriticalSpeedFormats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  add_quiet_flag(*cmd, &options->quiet);
  return [options] { return run(*options); };
}

}  // namespace railmodal::cli
