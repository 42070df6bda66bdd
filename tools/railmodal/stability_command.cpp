// railmodal stability VEHICLE [--speeds "10 km/h:500 km/h"] [--speed-count N | --speed-step STEP]
//                             [--conicity 0.05,0.1,0.2,0.3] [--threshold 5%] [--threads N]
//                             [--format table|csv|json|markdown|html] [-o OUT]
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

// A 10⁵-speed grid already takes minutes and holds every eigenvalue of every speed.
constexpr long long kMaxSpeeds = 100000;
// The design curve solves the whole grid once per conicity.
constexpr size_t kMaxConicities = 100;

// The formats `stability` writes, its default first.
const std::vector<std::string> kStabilityFormats{"table", "csv", "json", "markdown", "html"};

struct StabilityOptions {
  std::string vehicle;
  std::string speeds = "10 km/h:500 km/h";
  int speed_count = 0;  // 0: not given (HuntingOptions' default, or --speed-step)
  std::string speed_step;
  std::string conicity;
  std::string threshold;
  int threads = 0;
  std::string format;  // "": from the output file's extension, else table
  std::string output = "-";
};

// `why` says what the value must be above zero for.
double speed_of(const std::string& text, const std::string& option, const std::string& why) {
  const double speed = command_line_speed(text, option);
  if (!(speed > 0.0) || !std::isfinite(speed)) throw UsageError(option + ": " + why + ", got '" + text + "'");
  return speed;
}

// --speeds "MIN:MAX", each a speed as the files write it.
void read_speeds(const StabilityOptions& o, HuntingOptions* h) {
  const size_t colon = o.speeds.find(':');
  if (colon == std::string::npos || o.speeds.find(':', colon + 1) != std::string::npos)
    throw UsageError("--speeds expects MIN:MAX such as \"10 km/h:500 km/h\", got '" + o.speeds + "'");
  const std::string why = "a speed must be above zero (the creep damping grows as 1/V)";
  h->min_speed = speed_of(o.speeds.substr(0, colon), "--speeds", why);
  h->max_speed = speed_of(o.speeds.substr(colon + 1), "--speeds", why);
  if (!(h->max_speed > h->min_speed))
    throw UsageError("--speeds: the highest speed must be above the lowest, got '" + o.speeds + "'");
  if (!o.speed_step.empty()) {
    if (o.speed_count > 0) throw UsageError("give --speed-count or --speed-step, not both");
    const double step = speed_of(o.speed_step, "--speed-step", "the step between speeds must be above zero");
    // The grid is uniform from MIN to MAX: as many speeds as make its spacing at most the step.
    const double intervals = std::ceil((h->max_speed - h->min_speed) / step * (1.0 - 1e-12));
    if (intervals + 1.0 > static_cast<double>(kMaxSpeeds))
      throw UsageError("--speed-step " + o.speed_step + " gives more than " + std::to_string(kMaxSpeeds) +
                       " speeds; take a coarser step");
    h->speed_count = static_cast<int>(intervals) + 1;
  } else if (o.speed_count > 0) {
    h->speed_count = o.speed_count;
  }
}

// --conicity "0.05,0.1,0.2": finite numbers ≥ 0, comma-separated.
std::vector<double> read_conicities(const std::string& text) {
  std::vector<double> values;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const size_t first = item.find_first_not_of(' '), last = item.find_last_not_of(' ');
    const std::string word = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0' || !std::isfinite(value) || value < 0.0)
      throw UsageError(
          "--conicity expects equivalent conicities (numbers ≥ 0) separated by commas, such as "
          "0.05,0.1,0.2,0.3; '" +
          word + "' is not one");
    values.push_back(value);
  }
  if (!text.empty() && text.back() == ',') throw UsageError("--conicity: a comma with no conicity after it");
  if (values.size() > kMaxConicities)
    throw UsageError("--conicity: at most " + std::to_string(kMaxConicities) + " conicities");
  return values;
}

// --threshold "5%" or "0.05": a damping ratio in (0, 1).
double read_threshold(const std::string& text) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end) / (percent ? 100.0 : 1.0);
  if (number.empty() || *end != '\0' || !(value > 0.0 && value < 1.0))
    throw UsageError("--threshold expects a damping ratio between 0 and 1, as 0.05 or 5%, got '" + text + "'");
  return value;
}

HuntingOptions hunting_options(const StabilityOptions& o) {
  HuntingOptions h;
  read_speeds(o, &h);
  if (!o.conicity.empty()) h.conicities = read_conicities(o.conicity);
  if (!o.threshold.empty()) h.damping_threshold = read_threshold(o.threshold);
  h.threads = o.threads;
  if (std::string why; !h.is_valid(&why)) throw UsageError(why);
  return h;
}

int run(const StabilityOptions& o) {
  OutputFormat format;
  HuntingOptions options;
  try {
    format = report_format(o.format, o.output, kStabilityFormats);
    options = hunting_options(o);
  } catch (const UsageError& e) {
    return usage_error("stability", e.what());
  }
  try {
    OutputFiles outputs;
    std::ostream& out = outputs.open(o.output);
    outputs.refuse_inputs({o.vehicle});
    const Vehicle vehicle = load_vehicle_and_warn(o.vehicle);
    if (vehicle.wheelsets.empty()) {
      std::cerr << o.vehicle << ": error: the vehicle has no [wheelset] data: the hunting stability needs wheelsets "
                << "on rails (docs/stability.md; 'railmodal modes' and 'critical-speed' analyse it without)\n";
      return kInput;
    }
    HuntingResult result;
    try {
      // The lateral motions: the wheelsets' lateral and yaw, and what they couple to (vertical
      // decouples in the linear model of a vehicle symmetric about its centre line).
      result = solve_hunting_stability(assemble(vehicle, DofSet::lateral), options);
    } catch (const std::invalid_argument& e) {
      // The options were checked above (HuntingOptions::is_valid), so this is a wheelset or
      // contact value the reader let through and the contact model cannot take
      // (wheel_rail_contact.cpp names the wheelset): an input error of the file, whose line is
      // not known here; InputError with line 0 prints "FILE: error: ...", no position.
      throw InputError(o.vehicle, 0, 0, e.what());
    }
    write_hunting_stability(out, result, format, vehicle.name, provenance_of({o.vehicle}));
    outputs.commit();
    // A run whose own checks failed (the eigen residual, the branches' tracking) is written, its
    // report saying so under the verdict, then exits 6 with the checks on stderr, as `ride` does.
    bool failed = false;
    for (const Check& c : result.summary.checks)
      if (!c.passed) {
        std::cerr << o.vehicle << ": stability check FAILED: " << c.name << " = " << c.value << " above " << c.limit
                  << "\n";
        failed = true;
      }
    return failed ? kCheckFailed : kSuccess;
  } catch (...) {
    return exit_of_error("stability", o.vehicle);
  }
}

}  // namespace

std::function<int()> add_stability_command(CLI::App& app) {
  auto options = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stability",
      "Hunting stability of a vehicle on its wheelsets: root locus against speed, the linear critical speed, "
      "every unstable speed interval, and the critical speed against conicity");
  cmd->add_option("vehicle", options->vehicle,
                  "Vehicle file (TOML) with [wheelset] data, e.g. data/vehicles/wheelset_on_springs.toml")
      ->required();
  cmd->add_option("--speeds", options->speeds,
                  "Speed range MIN:MAX, each with its unit as in the files (\"75 km/h\", \"20 m/s\"); MIN > 0")
      ->capture_default_str();
  cmd->add_option("--speed-count", options->speed_count, "Speeds of the uniform grid from MIN to MAX (default 200)")
      ->check(CLI::Range(2, static_cast<int>(kMaxSpeeds)));
  cmd->add_option("--speed-step", options->speed_step,
                  "Instead of --speed-count: the largest spacing of the grid, e.g. \"2 km/h\"");
  cmd->add_option("--conicity", options->conicity,
                  "Equivalent conicities for the design curve (critical speed against conicity), comma-separated, "
                  "e.g. 0.05,0.1,0.2,0.3; the root locus is at the vehicle's own conicity");
  cmd->add_option("--threshold", options->threshold,
                  "A damping ratio to report the speed of, as 0.05 or 5%: the lowest speed at which the "
                  "least-damped branch's damping falls to it");
  cmd->add_option("--threads", options->threads, "Threads over speeds and conicities; 0 (default): every core")
      ->check(CLI::Range(0, 1024));
  cmd->add_option(
         "--format", options->format,
         "Output format: table, csv (each oscillatory branch's eigenvalue, Im λ > 0, at every speed; real and nearly "
         "real roots, Im λ under 1 % of |λ|, left out), json, markdown, html (with the root locus, damping and conicity plots); " +
             format_rule_help(kStabilityFormats))
      ->check(CLI::IsMember(kStabilityFormats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  add_quiet_flag(*cmd, nullptr);
  return [options] { return run(*options); };
}

}  // namespace railmodal::cli
