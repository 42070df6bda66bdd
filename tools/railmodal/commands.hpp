// Subcommands of the railmodal program, one file each.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "railmodal/vehicle.hpp"

namespace railmodal::cli {

/// Exit codes (docs/product: 0 success, 2 usage, 3 input, 4 numerical, 5 output, 1 internal).
// kCheckFailed: the run and its report are complete, and the check they report failed (fft-check).
enum ExitCode { kSuccess = 0, kInternal = 1, kUsage = 2, kInput = 3, kNumerical = 4, kOutput = 5, kCheckFailed = 6 };

/// An option the command line gives wrongly, found by the command rather than by CLI11 (exit kUsage).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Prints `message` as a usage error of `command` ("railmodal: error: ...", then where its help
/// is) and returns kUsage.
int usage_error(const std::string& command, const std::string& message);

/// The exit of a command's run that ended in an exception, called in its `catch (...)`: rethrows
/// the exception being handled, prints what it says and returns its code. An InputError prints
/// its own message, which names file, line, column and key (kInput); a NumericalError is blamed
/// on `blamed`, the file being analysed when it was thrown (kNumerical); a UsageError is one of
/// `command` (kUsage). Anything else (an OutputError, an internal error) goes on to main().
int exit_of_error(const std::string& command, const std::string& blamed);

/// A speed an option gives ("100 km/h", "20 m/s"), in m/s, with its unit as every speed of the
/// files and options (README.md, "Speeds"): a bare number is a UsageError naming `option`, as
/// is anything parse_speed refuses.
double command_line_speed(const std::string& text, const std::string& option);

/// Registers `modes` on the app; the returned function runs it after parsing.
std::function<int()> add_modes_command(CLI::App& app);
/// Registers `critical-speed`.
std::function<int()> add_critical_speed_command(CLI::App& app);
/// Register `simulate` and `fft-check`.
std::function<int()> add_simulate_command(CLI::App& app);
std::function<int()> add_fft_check_command(CLI::App& app);
/// Registers `compare`.
std::function<int()> add_compare_command(CLI::App& app);
/// Registers `stability`.
std::function<int()> add_stability_command(CLI::App& app);
/// Registers `hunting` (the nonlinear critical speed of a scene).
std::function<int()> add_hunting_command(CLI::App& app);
/// Registers `ride`.
std::function<int()> add_ride_command(CLI::App& app);

/// Registers `balance`.
std::function<int()> add_balance_command(CLI::App& app);
/// Notes on stderr that `old_spelling` still works but is deprecated for `new_spelling`.
void warn_deprecated_spelling(const std::string& old_spelling, const std::string& new_spelling);

/// The readers' warnings (load_vehicle's, open_study's, scene_warnings), one a line on stderr, as
/// the library wrote them ("file:line:col: warning: ..."). Not silenced by -q, which is for
/// progress: a warning is about the input, as an error is (docs/input.md, "Implausible inputs").
void print_input_warnings(const std::vector<std::string>& warnings);

/// load_vehicle, with its reading's warnings printed (print_input_warnings) before it returns.
Vehicle load_vehicle_and_warn(const std::string& path);

/// -q/--quiet, alike on every command (README.md, "Options every command takes"): no progress on
/// stderr. `quiet` is null for a command that shows no progress: it accepts the flag all the
/// same, so that a script may pass -q to any command.
void add_quiet_flag(CLI::App& cmd, bool* quiet);

/// A progress reporter for long runs: shows "name: 42 %" on stderr, only when stderr is a
/// terminal and only once the run has taken a second; clears the line at 100 %.
std::function<void(double)> terminal_progress(const std::string& name);

}  // namespace railmodal::cli
