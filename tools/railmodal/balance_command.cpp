// railmodal balance LOCO [--speed "100 km/h"] [--alpha 0.3 | --fraction 50%] [--rule book|least_squares|minimax]
//                        [--format table|csv|json|markdown|html] [-o OUT]
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

// The formats `balance` writes, its default first.
const std::vector<std::string> kBalanceFormats{"table", "csv", "json", "markdown", "html"};

struct BalanceCommandOptions {
  std::string locomotive;
  std::string speed;     // "": the file's design_speed
  std::string alpha;     // "": not given
  std::string fraction;  // "": not given
  std::string rule = "book";
  std::string format;  // "": from the output file's extension, else table
  std::string output = "-";
};

// A number in [0, 1], as 0.3 or 30%.
double read_share(const std::string& text, const std::string& option) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end) / (percent ? 100.0 : 1.0);
  if (number.empty() || *end != '\0' || !(value >= 0.0 && value <= 1.0))
    throw UsageError(option + " expects a number from 0 to 1, as 0.3 or 30%, got '" + text + "'");
  return value;
}

BalanceOptions balance_options(const BalanceCommandOptions& o) {
  BalanceOptions b;
  b.rule = *vertical_rule_from_string(o.rule);  // CLI11 checked the word
  if (!o.alpha.empty() && !o.fraction.empty()) throw UsageError("give --alpha or --fraction, not both");
  if (!o.alpha.empty()) {
    b.allowed_alpha = read_share(o.alpha, "--alpha");
    if (!(b.allowed_alpha > 0.0)) throw UsageError("--alpha must be above 0 (leave it out for no overbalance)");
  }
  if (!o.fraction.empty()) b.reciprocating_fraction = read_share(o.fraction, "--fraction");
  return b;
}

int run(const BalanceCommandOptions& o) {
  OutputFormat format;
  BalanceOptions options;
  double speed = 0.0;
  try {
    format = report_format(o.format, o.output, kBalanceFormats);
    options = balance_options(o);
    if (!o.speed.empty()) {
      speed = command_line_speed(o.speed, "--speed");
      if (!(speed > 0.0) || !std::isfinite(speed)) throw UsageError("--speed must be above zero, got '" + o.speed + "'");
    }
  } catch (const UsageError& e) {
    return usage_error("balance", e.what());
  }
  try {
    OutputFiles outputs;
    std::ostream& out = outputs.open(o.output);
    outputs.refuse_inputs({o.locomotive});
    const DrivingGear gear = load_driving_gear(o.locomotive);
    if (speed == 0.0) speed = gear.design_speed;
    if (speed == 0.0) {
      std::cerr << o.locomotive << ": error: the file states no design_speed in [driving_gear]; give --speed\n";
      return kInput;
    }
    const BalanceStudy study = study_balance(gear, speed, options);
    write_balance(out, study, format, provenance_of({o.locomotive}));
    outputs.commit();
    return kSuccess;
  } catch (...) {
    return exit_of_error("balance", o.locomotive);
  }
}

}  // namespace

std::function<int()> add_balance_command(CLI::App& app) {
  auto options = std::make_shared<BalanceCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "balance",
      "A steam locomotive's driving gear: the exact rod forces every 15 degrees, their harmonics, the hammer blow "
      "and overload coefficient alpha per wheel, surging and nosing, and the counterweights by three rules");
  cmd->add_option("locomotive", options->locomotive,
                  "File (TOML) with a [driving_gear] table, e.g. data/locomotives/su.toml")
      ->required();
  cmd->add_option("--speed", options->speed,
                  "Speed to size and judge the balance at, with its unit (\"100 km/h\", \"20 m/s\"): with --alpha the "
                  "overbalance is re-sized to reach alpha there; with --fraction the same counterweights are evaluated "
                  "there; default: the file's design_speed");
  cmd->add_option("--alpha", options->alpha,
                  "Overbalance the coupled wheels up to this overload coefficient (Zhdanov eq. (89a)), as 0.3 or 30%");
  cmd->add_option("--fraction", options->fraction,
                  "Instead of --alpha: the fraction of reciprocating mass to balance, as 0.5 or 50% (default: none)");
  cmd->add_option("--rule", options->rule,
                  "The vertical rule whose wheel loads and trade-off table are printed (all three are sized): book, "
                  "least_squares, minimax")
      ->check(CLI::IsMember({"book", "least_squares", "minimax"}))
      ->capture_default_str();
  cmd->add_option("--format", options->format,
                  "Output format: table, csv, json, markdown, html (with plots against crank angle); " +
                      format_rule_help(kBalanceFormats))
      ->check(CLI::IsMember(kBalanceFormats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  add_quiet_flag(*cmd, nullptr);
  return [options] { return run(*options); };
}

}  // namespace railmodal::cli
