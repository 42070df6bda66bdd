// railmodal simulate SCENE [--vehicle WAGON] [--format csv|json] [-o OUT] [--spectra SPECTRA.csv]
// railmodal fft-check SCENE [--vehicle WAGON] [--format table|csv|json|html] [-o OUT]
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

struct SimulateOptions {
  std::string scene;
  std::string vehicle;
  std::string format;
  std::string output = "-";
  std::string spectra;  // simulate: also the amplitude spectra, to this file
};

// Ten significant digits, as every number of the CSV (std::to_string keeps six decimals: a
// relative error of 2e-6 would read -0.000002).
std::string precise(double x) {
  std::ostringstream s;
  s << std::setprecision(10) << x;
  return s.str();
}

// Loads the scene and its vehicle; the command line's vehicle wins over the scene's.
int load(const SimulateOptions& o, Scene* scene, Vehicle* vehicle) {
  *scene = load_scene(o.scene);
  if (!o.vehicle.empty()) scene->vehicle_file = o.vehicle;
  if (scene->vehicle_file.empty()) {
    std::cerr << "railmodal: error: no vehicle: give --vehicle WAGON.toml or a 'vehicle' key in " << o.scene << "\n";
    return kUsage;
  }
  if (!scene->simulation) {
    std::cerr << o.scene << ": error: the scene has no [simulation] table\n";
    return kInput;
  }
  *vehicle = load_vehicle(scene->vehicle_file);
  return kSuccess;
}

std::string history_text(const TimeHistory& h, const Scene& scene, const Vehicle& vehicle, const std::string& format) {
  std::vector<int> columns;
  for (int c = 0; c < static_cast<int>(h.labels.size()); ++c)
    if (scene.simulation->outputs.empty() ||
        std::find(scene.simulation->outputs.begin(), scene.simulation->outputs.end(), h.labels[c]) !=
            scene.simulation->outputs.end())
      columns.push_back(c);
  std::ostringstream out;
  out << std::setprecision(10);
  if (format == "json") {
    nlohmann::json j;
    j["scene"] = scene.name;
    j["time_s"] = std::vector<double>(h.time.data(), h.time.data() + h.time.size());
    j["displacement"] = nlohmann::json::object();
    for (int c : columns) {
      const Eigen::VectorXd col = h.displacement.col(c);
      j["displacement"][h.labels[c]] = std::vector<double>(col.data(), col.data() + col.size());
    }
    if (scene_effects(scene).any()) {  // the nonlinear path: its stick/slip/kink events
      j["events"] = nlohmann::json::array();
      for (const SimulationEvent& e : h.events)
        j["events"].push_back({{"time_s", e.time}, {"element", vehicle.elements.at(e.element).name}, {"kind", to_string(e.kind)}});
      j["integration_steps"] = h.steps_taken;
    }
    out << j.dump() << "\n";
    return out.str();
  }
  out << "time_s";
  for (int c : columns) out << "," << h.labels[c];
  out << "\n";
  for (int i = 0; i < h.time.size(); ++i) {
    out << h.time(i);
    for (int c : columns) out << "," << h.displacement(i, c);
    out << "\n";
  }
  return out.str();
}

std::string checks_text(const FftCheckResult& r, const Scene& scene, const Vehicle& vehicle, const std::string& format) {
  std::ostringstream out;
  if (format == "html") {
    write_fft_check_html(out, r, scene, vehicle);
    return out.str();
  }
  if (format == "json") {
    nlohmann::json j;
    j["scene"] = scene.name;
    j["checks"] = nlohmann::json::array();
    for (const auto& c : r.checks)
      j["checks"].push_back({{"mode", c.mode},
                             {"mode_name", c.mode_name},
                             {"dof", c.dof},
                             {"modal_hz", c.modal_hz},
                             {"peak_hz", c.peak_hz ? nlohmann::json(*c.peak_hz) : nlohmann::json(nullptr)},
                             {"rel_error", c.peak_hz ? nlohmann::json(c.rel_error) : nlohmann::json(nullptr)},
                             {"resolution_hz", c.resolution_hz},
                             {"within_resolution", c.within_resolution},
                             {"excited", c.excited},
                             {"modal_amplitude_ratio", c.modal_amplitude_ratio}});
    if (r.swings) {
      const Swings& w = *r.swings;
      nlohmann::json turns = nlohmann::json::array();
      for (size_t i = 0; i < w.turning_times.size(); ++i)
        turns.push_back({{"time_s", w.turning_times[i]}, {"displacement", w.turning_values[i]}});
      j["half_periods"] = {{"dof", w.dof},
                           {"linear_half_period_s", r.linear_half_period_s},
                           {"between_turning_points_s", w.half_periods_between_turns()},
                           {"between_crossings_s", w.half_periods_between_crossings()},
                           {"turning_points", turns},
                           {"comes_to_rest", w.comes_to_rest}};
    }
    out << j.dump(2) << "\n";
    return out.str();
  }
  if (format == "csv") {
    out << "mode,mode_name,dof,modal_hz,peak_hz,rel_error,resolution_hz,within_resolution,excited,modal_amplitude_ratio\n"
        << std::setprecision(10);
    for (const auto& c : r.checks)
      out << c.mode << ",\"" << c.mode_name << "\"," << c.dof << "," << c.modal_hz << ","
          << (c.peak_hz ? precise(*c.peak_hz) : "") << "," << (c.peak_hz ? precise(c.rel_error) : "") << ","
          << c.resolution_hz << "," << (c.within_resolution ? "true" : "false") << "," << (c.excited ? "true" : "false")
          << "," << c.modal_amplitude_ratio << "\n";
    return out.str();
  }
  out << "railmodal fft-check: " << scene.name << "\n"
      << "spectra: Hann window, zero-padded x4, of " << r.history.time.size() << " samples at "
      << 1.0 / scene.simulation->time_step << " Hz\n\n";
  out << std::left << std::setw(5) << "#" << std::setw(32) << "mode" << std::setw(16) << "dof" << std::right
      << std::setw(11) << "modal [Hz]" << std::setw(11) << "peak [Hz]" << std::setw(12) << "rel. error" << std::setw(13)
      << "resol. [Hz]" << "  check\n";
  for (const auto& c : r.checks) {
    out << std::left << std::setw(5) << c.mode << std::setw(32) << c.mode_name << std::setw(16) << c.dof << std::right
        << std::fixed << std::setprecision(4) << std::setw(11) << c.modal_hz;
    if (c.peak_hz)
      out << std::setw(11) << *c.peak_hz << std::scientific << std::setprecision(2) << std::setw(12) << c.rel_error
          << std::fixed << std::setprecision(4) << std::setw(13) << c.resolution_hz << "  "
          << (c.within_resolution ? "ok" : "OUTSIDE the resolution");
    else
      out << std::setw(11) << "—" << std::setw(12) << "" << std::setw(13) << "" << "  "
          << missing_peak_remark(c, r.swings.has_value());
    out << "\n";
  }
  if (r.swings) {
    const Swings& w = *r.swings;
    out << "\nnonlinear scene: spectral lines are broadened; the half periods of " << w.dof
        << " (linear: " << std::fixed << std::setprecision(4) << r.linear_half_period_s << " s)\n"
        << std::setw(5) << "#" << std::setw(14) << "turn at [s]" << std::setw(16) << "displacement" << std::setw(18)
        << "half period [s]" << "\n";
    const auto halves = w.half_periods_between_turns();
    for (size_t i = 0; i < w.turning_times.size(); ++i) {
      out << std::setw(5) << i + 1 << std::setw(14) << std::setprecision(4) << w.turning_times[i] << std::setw(16)
          << std::setprecision(6) << w.turning_values[i];
      if (i > 0) out << std::setw(18) << std::setprecision(4) << halves[i - 1];
      out << "\n";
    }
    if (w.comes_to_rest) out << "      then at rest (a stuck spring)\n";
    const auto crossings = w.half_periods_between_crossings();
    if (!crossings.empty()) {
      out << "half periods between passes through the static position [s]:";
      for (size_t i = 0; i < crossings.size() && i < 8; ++i) out << " " << std::setprecision(4) << crossings[i];
      if (crossings.size() > 8) out << " … (" << crossings.size() << " in all)";
      out << "\n";
    }
  }
  return out.str();
}

// The amplitude spectra of the written DOFs: Hann, zero-padded ×4 (as fft-check takes them),
// one column per DOF, peak amplitudes in m or rad, up to the Nyquist frequency.
std::string spectra_text(const TimeHistory& h, const Scene& scene) {
  const double fs = 1.0 / scene.simulation->time_step;
  SpectrumOptions options;
  options.window = Window::hann;
  options.padding = Padding::to_length;
  options.padded_length = 4 * h.time.size();
  SpectrumAnalyzer analyzer(h.time.size(), options);
  std::vector<int> columns;
  for (int c = 0; c < static_cast<int>(h.labels.size()); ++c)
    if (scene.simulation->outputs.empty() ||
        std::find(scene.simulation->outputs.begin(), scene.simulation->outputs.end(), h.labels[c]) !=
            scene.simulation->outputs.end())
      columns.push_back(c);
  std::vector<Spectrum> spectra;
  for (int c : columns) spectra.push_back(analyzer.compute(h.displacement.col(c), fs));
  std::ostringstream out;
  out << std::setprecision(10) << "frequency_hz";
  for (int c : columns) out << "," << h.labels[c];
  out << "\n";
  for (Eigen::Index b = 0; !spectra.empty() && b < spectra.front().amplitude.size(); ++b) {
    out << spectra.front().frequency(b);
    for (const Spectrum& s : spectra) out << "," << s.amplitude(b);
    out << "\n";
  }
  return out.str();
}

int run(const SimulateOptions& o, bool check) {
  try {
    Scene scene;
    Vehicle vehicle;
    if (const int code = load(o, &scene, &vehicle); code != kSuccess) return code;
    std::string text, spectra;
    try {
      if (check) {
        text = checks_text(fft_check(scene, vehicle), scene, vehicle, o.format);
      } else {
        const TimeHistory h = simulate_scene(scene, vehicle);
        text = history_text(h, scene, vehicle, o.format);
        if (!o.spectra.empty()) spectra = spectra_text(h, scene);
      }
    } catch (const std::invalid_argument& e) {
      throw InputError(o.scene, 0, 0, e.what());
    }
    if (!o.spectra.empty())
      if (const int code = write_output(o.spectra, spectra); code != kSuccess) return code;
    return write_output(o.output, text);
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return kInput;
  } catch (const NumericalError& e) {
    std::cerr << o.scene << ": error: numerical failure: " << e.what() << "\n";
    return kNumerical;
  }
}

std::function<int()> add(CLI::App& app, const std::string& name, const std::string& help, bool check,
                         const std::vector<std::string>& formats) {
  auto options = std::make_shared<SimulateOptions>();
  options->format = formats.front();
  CLI::App* cmd = app.add_subcommand(name, help);
  cmd->add_option("scene", options->scene, "Scene file (TOML) with a [simulation] table")->required();
  cmd->add_option("--vehicle", options->vehicle, "Vehicle file; default: the scene's 'vehicle'");
  cmd->add_option("--format", options->format, "Output format")->check(CLI::IsMember(formats))->capture_default_str();
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  if (!check)
    cmd->add_option("--spectra", options->spectra,
                    "Also write the amplitude spectra of the written DOFs (CSV: Hann, zero-padded x4, peak amplitudes)");
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
