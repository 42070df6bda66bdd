// railmodal modes FILE [--dofs vertical|lateral|all] [--format table|csv|json] [--damped] [-o OUT]
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

struct ModesOptions {
  std::string file;
  std::string dofs = "all";
  std::string format = "table";
  std::string output = "-";
  bool damped = false;  // complex modes of M q̈ + C q̇ + K q = 0 instead of K φ = λ M φ
};

int run(const ModesOptions& o) {
  // CLI11 has checked the words against the lists below.
  const DofSet set = *dof_set_from_string(o.dofs);
  const OutputFormat format = *output_format_from_string(o.format);
  try {
    const Vehicle vehicle = load_vehicle(o.file);
    LinearSystem system;
    try {
      system = assemble(vehicle, set);
    } catch (const std::invalid_argument& e) {
      throw InputError(o.file, 0, 0, e.what());
    }
    if (system.size() == 0) {
      std::cerr << o.file << ": error: no free degrees of freedom in the " << o.dofs << " set\n";
      return kInput;
    }
    std::ostringstream text;
    if (o.damped)
      write_damped_modes(text, system, solve_damped_modes(system), format);
    else
      write_modes(text, system, solve_modes(system), format);
    return write_output(o.output, text.str());
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return kInput;
  } catch (const NumericalError& e) {
    std::cerr << o.file << ": error: numerical failure: " << e.what() << "\n";
    return kNumerical;
  }
}

}  // namespace

std::function<int()> add_modes_command(CLI::App& app) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand("modes", "Natural frequencies, periods and mode shapes of a vehicle");
  cmd->add_option("file", options->file, "Vehicle file (TOML), e.g. data/vehicles/resort_car.toml")
      ->required();
  cmd->add_option("--dofs", options->dofs, "Motions: vertical (bounce, pitch), lateral (lateral, roll, yaw) or all")
      ->check(CLI::IsMember({"vertical", "lateral", "all"}))
      ->capture_default_str();
  cmd->add_option("--format", options->format, "Output format")
      ->check(CLI::IsMember({"table", "csv", "json"}))
      ->capture_default_str();
  cmd->add_flag("--damped", options->damped,
                 "Damped modes (viscous dampers in C): damped frequency, damping ratio, stability, "
                 "and the undamped frequency beside them");
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  return [options] { return run(*options); };
}

}  // namespace railmodal::cli
