// railmodal simulate SCENE [--vehicle VEHICLE] [--format csv|json] [-o OUT] [--spectra SPECTRA.csv] [--memory-limit GB]
// railmodal fft-check SCENE [--vehicle VEHICLE] [--format table|csv|json|html] [-o OUT] [--memory-limit GB]
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

struct SimulateOptions {
  std::string scene;
  std::string vehicle;
  std::vector<std::string> formats;  // what the command writes, its default first
  std::string format;                 // "": report_format's rule
  OutputFormat chosen = OutputFormat::csv;  // the run's, by report_format
  std::string output = "-";
  std::string spectra;  // simulate: also the amplitude spectra, to this file
  double memory_limit_gb = kDefaultMemoryLimit / 1e9;  // for what a run must hold whole
};

// Loads the scene and its vehicle; the command line's vehicle wins over the scene's.
int load(const SimulateOptions& o, Scene* scene, Vehicle* vehicle) {
  *scene = load_scene(o.scene);
  if (!o.vehicle.empty()) scene->vehicle_file = o.vehicle;
  if (scene->vehicle_file.empty()) {
    std::cerr << "railmodal: error: no vehicle: give --vehicle VEHICLE.toml or a 'vehicle' key in " << o.scene << "\n";
    return kUsage;
  }
  if (!scene->simulation) {
    std::cerr << o.scene << ": error: the scene has no [simulation] table"
              << (scene->ride ? " (it is a ride scene: 'railmodal ride " + o.scene + "' runs its [ride.simulation])"
                              : std::string())
              << "\n";
    return kInput;
  }
  *vehicle = load_vehicle_and_warn(scene->vehicle_file);
  print_input_warnings(scene_warnings(*scene, *vehicle));  // an effect the vehicle has nothing for
  // A part the scene's effects leave out (its dampers): accepted by design, never silently.
  for (const std::string& part : unsimulated_parts(*scene, *vehicle))
    std::cerr << o.scene << ": warning: " << part << "\n";
  return kSuccess;
}

// simulate: a csv history streams to `text` as the run goes; a json one, and the spectra
// (`spectra`, if asked for), are written from the record of the outputs once it is complete.
void write_simulation(const SimulateOptions& o, const Scene& scene, const Vehicle& vehicle, std::ostream& text,
                      std::ostream* spectra) {
  const OutputFormat format = o.chosen;
  CsvHistoryWriter csv(text, scene);
  std::optional<OutputRecord> record;
  if (format == OutputFormat::json || spectra) record.emplace(scene, spectra != nullptr, o.memory_limit_gb * 1e9);
  std::vector<HistorySink*> sinks;
  if (record) sinks.push_back(&*record);  // first: it refuses a record too large before any text
  if (format == OutputFormat::csv) sinks.push_back(&csv);
  const TimeHistory result = simulate_scene(scene, vehicle, sinks);
  if (!record) return;
  const TimeHistory h = record->history(result);
  if (format == OutputFormat::json) write_time_history(text, h, scene, vehicle, format);
  if (spectra) write_spectra(*spectra, output_spectra(h, scene), OutputFormat::csv);
}

// Everything one run writes, into the streams of its outputs (spectra: null when not asked);
// the fft-check's result, when it is one (its report says which checks were made and why not).
std::optional<FftCheckResult> write_run(const SimulateOptions& o, bool check, const Scene& scene,
                                        const Vehicle& vehicle, std::ostream& text, std::ostream* spectra) {
  try {
    if (!check) {
      write_simulation(o, scene, vehicle, text, spectra);
      return std::nullopt;
    }
    FftCheckResult result = fft_check(scene, vehicle, o.memory_limit_gb * 1e9);
    write_fft_check(text, result, scene, vehicle, o.chosen,
                    provenance_of({o.scene, scene.vehicle_file}));
    return result;
  } catch (const std::invalid_argument& e) {
    throw InputError(o.scene, 0, 0, e.what());
  }
}

// An fft-check's exit: 6 when a check made failed, and 6 when nothing could be checked (the
// report's verdict says "NOT CHECKED" and why, and stderr says it): the user asked for a check
// and none was made, which a script reading the exit alone must not take for a pass (as
// `hunting` exits 6 for an answer not converged); 0 only for the verdict "ok".
int check_exit(const std::string& scene_file, const FftCheckResult& result) {
  if (result.failed > 0) {
    std::cerr << scene_file
              << ": fft-check FAILED: " << fft_check_verdict(result).substr(std::string("FAILED: ").size()) << "\n";
    return kCheckFailed;
  }
  if (result.checked == 0) {
    std::cerr << scene_file << ": fft-check: nothing was checked: "
              << fft_check_verdict(result).substr(std::string("NOT CHECKED: ").size())
              << "; \"not checked\" is not a pass\n";
    return kCheckFailed;
  }
  return kSuccess;
}

int run(SimulateOptions o, bool check) {
  try {
    o.chosen = report_format(o.format, o.output, o.formats);
    OutputFiles outputs;
    std::ostream& text = outputs.open(o.output);
    std::ostream* spectra = o.spectra.empty() ? nullptr : &outputs.open(o.spectra);
    Scene scene;
    Vehicle vehicle;
    if (const int code = load(o, &scene, &vehicle); code != kSuccess) return code;
    outputs.refuse_inputs({o.scene, scene.vehicle_file});
    const std::optional<FftCheckResult> result = write_run(o, check, scene, vehicle, text, spectra);
    outputs.commit();
    return result ? check_exit(o.scene, *result) : kSuccess;
  } catch (...) {
    return exit_of_error(check ? "fft-check" : "simulate", o.scene);
  }
}

std::function<int()> add(CLI::App& app, const std::string& name, const std::string& help, bool check,
                         const std::vector<std::string>& formats) {
  auto options = std::make_shared<SimulateOptions>();
  options->formats = formats;
  CLI::App* cmd = app.add_subcommand(name, help);
  cmd->add_option("scene", options->scene, "Scene file (TOML) with a [simulation] table")->required();
  cmd->add_option("--vehicle", options->vehicle, "Vehicle file; default: the scene's 'vehicle'");
  std::string words;
  for (const std::string& f : formats) words += (words.empty() ? "" : ", ") + f;
  cmd->add_option("--format", options->format, "Output format: " + words + "; " + format_rule_help(formats))
      ->check(CLI::IsMember(formats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  if (!check)
    cmd->add_option("--spectra", options->spectra,
                    "Also write the amplitude spectra of the written DOFs (CSV: Hann, zero-padded x4, peak amplitudes)");
  cmd->add_option("--memory-limit", options->memory_limit_gb,
                  "GB a run may hold for a record it needs whole (fft-check, --spectra, json); larger runs are "
                  "refused up front")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  add_quiet_flag(*cmd, nullptr);
  return [options, check] { return run(*options, check); };
}

}  // namespace

std::function<int()> add_simulate_command(CLI::App& app) {
  return add(app, "simulate", "Time histories of a scene's simulation (CSV or JSON; JSON adds the nonlinear events)", false,
             {"csv", "json"});
}

std::function<int()> add_fft_check_command(CLI::App& app) {
  return add(app, "fft-check", "Spectral peaks of a scene's simulated response against the modal frequencies", true,
             {"table", "csv", "json", "html"});
}

}  // namespace railmodal::cli
