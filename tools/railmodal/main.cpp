// railmodal: modal analysis of railway wagons from the command line.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/input.hpp"
#include "railmodal/version.hpp"

namespace railmodal::cli {

std::function<void(double)> terminal_progress(const std::string& name) {
  if (!isatty(STDERR_FILENO)) return {};
  const auto start = std::chrono::steady_clock::now();
  return [name, start](double fraction) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed < 1.0) return;
    if (fraction >= 1.0) {
      std::cerr << "\r" << std::string(name.size() + 8, ' ') << "\r" << std::flush;
      return;
    }
    std::cerr << "\r" << name << ": " << static_cast<int>(100.0 * fraction) << " %" << std::flush;
  };
}

double command_line_speed(const std::string& text, const std::string& option) {
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  const bool bare = end != text.c_str() && text.find_first_not_of(" \t", static_cast<size_t>(end - text.c_str())) == std::string::npos;
  if (bare && number != 0.0)
    throw UsageError(option + ": give the speed its unit, such as \"" + text + " km/h\" or \"" + text +
                     " m/s\": a bare number is not a speed");
  try {
    return parse_speed(text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(option + ": " + e.what());
  }
}

void add_quiet_flag(CLI::App& cmd, bool* quiet) {
  const std::string help = "No progress on stderr (shown on a terminal for runs over a second)";
  if (quiet)
    cmd.add_flag("-q,--quiet", *quiet, help);
  else
    cmd.add_flag("-q,--quiet")->description(help + "; this command shows none: accepted, as by every command");
}

void print_input_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << w << "\n";
}

Vehicle load_vehicle_and_warn(const std::string& path) {
  std::vector<std::string> warnings;
  Vehicle vehicle = load_vehicle(path, &warnings);
  print_input_warnings(warnings);
  return vehicle;
}

void warn_deprecated_spelling(const std::string& old_spelling, const std::string& new_spelling) {
  std::cerr << "railmodal: note: '" << old_spelling << "' is deprecated and will be removed; write 'railmodal "
            << new_spelling << "'\n";
}

}  // namespace railmodal::cli

int main(int argc, char** argv) {
  using namespace railmodal::cli;
  CLI::App app{"railmodal: natural modes and critical speeds of railway wagons"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "railmodal " + std::string(railmodal::version()));
  // One convention for every subcommand (README.md, "Commands").
  app.footer(
      "Every command takes the file it analyses as its argument: modes VEHICLE, critical-speed SCENE, "
      "simulate SCENE, fft-check SCENE, compare STUDY, stability VEHICLE, hunting SCENE, balance LOCOMOTIVE, ride SCENE. A scene names its vehicle; --vehicle VEHICLE "
      "replaces it.");
  auto run_modes = add_modes_command(app);
  auto run_critical_speed = add_critical_speed_command(app);
  auto run_simulate = add_simulate_command(app);
  auto run_fft_check = add_fft_check_command(app);
  auto run_compare = add_compare_command(app);
  auto run_stability = add_stability_command(app);
  auto run_hunting = add_hunting_command(app);
  auto run_balance = add_balance_command(app);
  auto run_ride = add_ride_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kSuccess;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return kSuccess;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return kSuccess;
  } catch (const CLI::ParseError& e) {
    // Point at the subcommand's own help when the error is in its options, as the commands' own
    // usage errors do ("Run 'railmodal stability --help'").
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    const std::string help =
        parsed.empty() ? "railmodal --help" : "railmodal " + parsed.front()->get_name() + " --help";
    std::cerr << "railmodal: error: " << e.what() << "\nRun '" << help << "' for usage.\n";
    return kUsage;
  }
  try {
    if (app.got_subcommand("modes")) return run_modes();
    if (app.got_subcommand("critical-speed")) return run_critical_speed();
    if (app.got_subcommand("simulate")) return run_simulate();
    if (app.got_subcommand("fft-check")) return run_fft_check();
    if (app.got_subcommand("compare")) return run_compare();
    if (app.got_subcommand("stability")) return run_stability();
    if (app.got_subcommand("hunting")) return run_hunting();
    if (app.got_subcommand("balance")) return run_balance();
    if (app.got_subcommand("ride")) return run_ride();
  } catch (const OutputError& e) {
    std::cerr << e.what() << "\n";
    return e.code();
  } catch (const std::exception& e) {
    std::cerr << "railmodal: internal error: " << e.what() << "\n";
    return kInternal;
  }
  return kUsage;
}
