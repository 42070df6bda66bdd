// Subcommands of the railmodal program, one file each.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <ostream>
#include <string>

namespace railmodal::cli {

/// Exit codes (docs/product: 0 success, 2 usage, 3 input, 4 numerical, 5 output, 1 internal).
enum ExitCode { kSuccess = 0, kInternal = 1, kUsage = 2, kInput = 3, kNumerical = 4, kOutput = 5 };

/// Registers `modes` on the app; the returned function runs it after parsing.
std::function<int()> add_modes_command(CLI::App& app);
/// Registers `critical-speed`.
std::function<int()> add_critical_speed_command(CLI::App& app);
/// Register `simulate` and `fft-check`.
std::function<int()> add_simulate_command(CLI::App& app);
std::function<int()> add_fft_check_command(CLI::App& app);
/// Registers `compare`.
std::function<int()> add_compare_command(CLI::App& app);

/// Writes `text` to `path` whole or not at all (temporary file, then rename); "-" or ""
/// is standard output. Returns kOutput with a message on stderr when it cannot.
int write_output(const std::string& path, const std::string& text);
/// The same for text that `write` streams into the file as it is produced, so that it is never
/// held whole; `write` returns an exit code, and anything but kSuccess (or an exception)
/// leaves no file.
int write_output(const std::string& path, const std::function<int(std::ostream&)>& write);

/// A progress reporter for long runs: shows "name: 42 %" on stderr, only when stderr is a
/// terminal and only once the run has taken a second; clears the line at 100 %.
std::function<void(double)> terminal_progress(const std::string& name);

}  // namespace railmodal::cli
