// railmodal modes VEHICLE [--dofs vertical|lateral|all] [--format table|csv|json] [--damped] [-o OUT]
// railmodal modes --mass M.mtx --stiffness K.mtx [--damping C.mtx] [--format ...] [--damped] [-o OUT]
//   both with [--solver dense|arpack|auto] [--modes N] [--shift SIGMA] (undamped modes)
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/railmodal.hpp"

namespace railmodal::cli {
namespace {

// The dense solver holds M, K and a few n × n work matrices: 10 000 DOFs is ~4 GB.
constexpr long long kMaxDenseDofs = 10000;
// The formats `modes` writes, its default first.
const std::vector<std::string> kModesFormats{"table", "csv", "json"};

struct ModesOptions {
  std::string file;
  std::string mass, stiffness, damping;
  std::string dofs = "all";
  bool dofs_given = false;
  std::string format;  // "": report_format's rule
  std::string output = "-";
  bool damped = false;  // complex modes of M q̈ + C q̇ + K q = 0 instead of K φ = λ M φ
  std::string solver = "auto";
  int modes = 0;  // 0: all (dense), kArpackDefaultModes (ARPACK)
  double shift = std::numeric_limits<double>::quiet_NaN();  // ARPACK's σ, 1/s²; NaN: automatic
};

// What the command was given is either a vehicle or matrices; "" if that is fine.
std::string input_problem(const ModesOptions& o) {
  const bool matrices = !o.mass.empty() || !o.stiffness.empty() || !o.damping.empty();
  if (!o.file.empty() && matrices)
    return "give either a vehicle file or --mass and --stiffness matrices, not both";
  if (o.file.empty() && !matrices) return "give a vehicle file (TOML) or --mass M.mtx --stiffness K.mtx";
  if (matrices && o.mass.empty()) return "--stiffness and --damping need --mass";
  if (matrices && o.stiffness.empty()) return "--mass needs --stiffness";
  if (matrices && o.dofs_given)
    return "--dofs selects motions of a vehicle's bodies; it does not apply to --mass/--stiffness matrices";
  return "";
}

LinearSystem vehicle_system(const ModesOptions& o) {
  const Vehicle vehicle = load_vehicle_and_warn(o.file);
  try {
    return assemble(vehicle, *dof_set_from_string(o.dofs));  // CLI11 checked the word
  } catch (const std::invalid_argument& e) {
    throw InputError(o.file, 0, 0, e.what());
  }
}

ModalOptions modal_options(const ModesOptions& o) {
  ModalOptions options;
  options.solver = *modal_solver_from_string(o.solver);  // CLI11 checked the word
  options.mode_count = o.modes;
  options.arpack.shift = o.shift;
  return options;
}

// A given shift is ARPACK's: refused when the dense solver takes the model.
void check_shift_applies(const ModesOptions& o, const ModalOptions& options, int dofs) {
  if (!std::isnan(o.shift) && choose_solver(options.solver, dofs, options.mode_count) == ModalSolver::dense)
    throw std::invalid_argument("--shift applies to the ARPACK solver, and the dense solver takes this model (" +
                                std::to_string(dofs) + " DOFs); add --solver arpack --modes N");
}

// Matrices stay sparse unless the dense solver takes them (ARPACK never sees a dense copy).
std::string solve_matrices(const ModesOptions& o, const ModalOptions& options, ModalResult* result) {
  const SparseSystem system = to_sparse_system(load_matrix_model(o.mass, o.stiffness, o.damping));
  check_shift_applies(o, options, system.size());
  if (choose_solver(options.solver, system.size(), options.mode_count) == ModalSolver::dense &&
      system.size() > kMaxDenseDofs)
    throw InputError(o.mass, 0, 0, std::to_string(system.size()) + " degrees of freedom: more than the " +
                                       std::to_string(kMaxDenseDofs) +
                                       " the dense modal solver takes; use --solver arpack --modes N");
  *result = solve_modes(system, options);
  return system.name;
}

// Damped modes: the state-space problem of every mode, dense (vehicle or matrices).
int run_damped(const ModesOptions& o, bool matrices, OutputFormat format, std::ostream& out) {
  LinearSystem system;
  if (matrices) {
    const MatrixModel model = load_matrix_model(o.mass, o.stiffness, o.damping);
    if (static_cast<long long>(model.labels.size()) > kMaxDenseDofs)
      throw InputError(o.mass, 0, 0, std::to_string(model.labels.size()) + " degrees of freedom: more than the " +
                                         std::to_string(kMaxDenseDofs) + " the dense damped-mode solver takes");
    system = to_linear_system(model);
  } else {
    system = vehicle_system(o);
    if (system.size() == 0) {
      std::cerr << o.file << ": error: no free degrees of freedom in the " << o.dofs << " set\n";
      return kInput;
    }
  }
  // Nothing here throws std::invalid_argument for a vehicle file: the default options are valid,
  // the assembled C is n × n and the reader refuses a series damper without a positive, finite
  // damping and stiffness with its line (what solve_damped_modes refuses).
  const DampedModalResult result = solve_damped_modes(system);
  write_damped_modes(out, system, result, format);
  return kSuccess;
}

int run(const ModesOptions& o) {
  if (const std::string problem = input_problem(o); !problem.empty()) return usage_error("modes", problem);
  if (o.damped && (o.solver == "arpack" || o.modes > 0 || !std::isnan(o.shift)))
    return usage_error("modes",
        "--damped solves every mode densely; --solver arpack, --modes and --shift apply to undamped modes");
  const bool matrices = o.file.empty();
  const std::string source = matrices ? o.mass + ", " + o.stiffness : o.file;  // for numerical errors
  const ModalOptions options = modal_options(o);
  try {
    const OutputFormat format = report_format(o.format, o.output, kModesFormats);
    OutputFiles outputs;
    std::ostream& out = outputs.open(o.output);
    outputs.refuse_inputs({o.file, o.mass, o.stiffness, o.damping});
    if (o.damped) {
      const int code = run_damped(o, matrices, format, out);
      if (code == kSuccess) outputs.commit();
      return code;
    }
    ModalResult result;
    std::string title;
    if (matrices) {
      title = solve_matrices(o, options, &result);
    } else {
      const LinearSystem system = vehicle_system(o);
      if (system.size() == 0) {
        std::cerr << o.file << ": error: no free degrees of freedom in the " << o.dofs << " set\n";
        return kInput;
      }
      title = system.vehicle.name;
      check_shift_applies(o, options, system.size());
      result = solve_modes(system, options);
    }
    write_modes(out, title, result, format);
    outputs.commit();
    return kSuccess;
  } catch (const std::invalid_argument& e) {  // --modes beyond what ARPACK can give, --shift for dense
    return usage_error("modes", e.what());
  } catch (...) {
    return exit_of_error("modes", source);
  }
}

// CLI11 check of --shift: a finite number (nan and inf parse as doubles but are no shift).
std::string finite_number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) return "must be a finite number, got " + text;
  return "";
}

}  // namespace

std::function<int()> add_modes_command(CLI::App& app) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "modes", "Natural frequencies, periods and mode shapes of a vehicle, or of M and K matrices (Matrix Market)");
  cmd->add_option("vehicle", options->file, "Vehicle file (TOML), e.g. data/vehicles/resort_car.toml");
  cmd->add_option("--mass", options->mass, "Mass matrix M (Matrix Market .mtx), instead of a vehicle file");
  cmd->add_option("--stiffness", options->stiffness, "Stiffness matrix K (Matrix Market), with --mass");
  cmd->add_option("--damping", options->damping,
                  "Damping matrix C (Matrix Market), optional with --mass; used by --damped");
  CLI::Option* dofs =
      cmd->add_option(
             "--dofs", options->dofs,
             "Motions: vertical (bounce, pitch, and surge where a body frees it), lateral (lateral, roll, yaw) "
             "or all; a subset drops the couplings between the two sets, exact only for a "
             "vehicle symmetric about its centre line")
          ->check(CLI::IsMember({"vertical", "lateral", "all"}))
          ->capture_default_str();
  cmd->add_option("--format", options->format, "Output format: table, csv, json; " + format_rule_help(kModesFormats))
      ->check(CLI::IsMember(kModesFormats));
  cmd->add_flag("--damped", options->damped,
                 "Damped modes (viscous dampers in C): damped frequency, damping ratio, stability, "
                 "and the undamped frequency beside them");
  cmd->add_option("--solver", options->solver,
                  "Eigensolver: dense (every mode), arpack (the lowest modes of a large sparse model, shift-invert "
                  "Lanczos) or auto (ARPACK above " + std::to_string(kArpackAboveDofs) + " DOFs)")
      ->check(CLI::IsMember({"dense", "arpack", "auto"}))
      ->capture_default_str();
  cmd->add_option("--modes", options->modes,
                  "The N lowest modes (and the rest of a repeated frequency's cluster); default all (dense), " +
                      std::to_string(kArpackDefaultModes) + " (ARPACK)")
      ->check(CLI::Range(1, 1 << 30));
  cmd->add_option("--shift", options->shift,
                  "ARPACK's shift σ in 1/s² (ω² units): the modes returned are the lowest above σ. Default: "
                  "automatic, just below zero at the scale of the lowest eigenvalues")
      ->check(finite_number);
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  add_quiet_flag(*cmd, nullptr);
  return [options, dofs] {
    options->dofs_given = dofs->count() > 0;
    return run(*options);
  };
}

}  // namespace railmodal::cli
