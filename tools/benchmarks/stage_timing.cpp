// Where the time of a command goes (issue 19, item 5): the library calls a `railmodal` command
// makes, in the same order, each timed — parsing the input files, assembling the model, the
// analysis (with the stages its AnalysisSummary records), and writing the report in each
// format into memory (an std::ostringstream: the formatting, without the disk). The medians
// of REPEATS runs, in seconds, one "stage seconds" line each, for docs/performance.md.
//
//   stage_timing modes VEHICLE [REPEATS]
//   stage_timing modes-matrices MASS.mtx STIFFNESS.mtx [REPEATS]
//   stage_timing critical-speed SCENE [REPEATS]
//   stage_timing simulate SCENE [REPEATS]
//   stage_timing stability VEHICLE [REPEATS]
//   stage_timing ride SCENE [REPEATS]
//   stage_timing balance LOCOMOTIVE [REPEATS]
//   stage_timing compare STUDY [REPEATS]
//
// What it leaves out of the command: argument parsing, the atomic file commit and process
// start-up and exit (the whole-process time minus the sum of these stages shows them); the
// CLI's own option defaults where the command builds options from flags (stability and ride
// use the library's and the scene's defaults, as the CLI does without flags).
#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "railmodal/balance_report.hpp"
#include "railmodal/comparison_report.hpp"
#include "railmodal/critical_speed_report.hpp"
#include "railmodal/hunting_report.hpp"
#include "railmodal/railmodal.hpp"
#include "railmodal/report.hpp"
#include "railmodal/ride_report.hpp"
#include "railmodal/simulation_report.hpp"

using namespace railmodal;

namespace {

using Clock = std::chrono::steady_clock;

// Stage name → one time per repeat, kept in first-seen order for printing.
class Stages {
 public:
  void add(const std::string& stage, double seconds) {
    if (!times_.count(stage)) order_.push_back(stage);
    times_[stage].push_back(seconds);
  }
  template <typename F>
  auto time(const std::string& stage, F f) {
    const auto start = Clock::now();
    auto result = f();
    add(stage, std::chrono::duration<double>(Clock::now() - start).count());
    return result;
  }
  void add_summary(const std::string& prefix, const AnalysisSummary& summary) {
    for (const StageTiming& s : summary.stages) add(prefix + s.stage, s.seconds);
  }
  void print() const {
    for (const std::string& stage : order_) {
      std::vector<double> t = times_.at(stage);
      std::sort(t.begin(), t.end());
      std::cout << stage << " " << t[t.size() / 2] << "\n";
    }
  }

 private:
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> times_;
};

const std::vector<OutputFormat> kFormats = {OutputFormat::table, OutputFormat::markdown, OutputFormat::csv,
                                            OutputFormat::json, OutputFormat::html};

// Each format's report into memory, timed; formats the report refuses are skipped.
void write_all(Stages* stages, const std::function<void(std::ostream&, OutputFormat)>& write) {
  for (OutputFormat format : kFormats) {
    std::ostringstream out;
    const auto start = Clock::now();
    try {
      write(out, format);
      stages->add(std::string("output ") + to_string(format),
                  std::chrono::duration<double>(Clock::now() - start).count());
    } catch (const std::invalid_argument&) {  // this report has no such format
      stages->add(std::string("output ") + to_string(format) + " (refused)",
                  std::chrono::duration<double>(Clock::now() - start).count());
    }
  }
}

void modes(Stages* s, const std::string& file) {
  const Vehicle vehicle = s->time("parse", [&] { return load_vehicle(file); });
  const LinearSystem system = s->time("assembly", [&] { return assemble(vehicle, DofSet::all); });
  const ModalResult result = s->time("solve", [&] { return solve_modes(system); });
  s->add_summary("  solve: ", result.solver);
  write_all(s, [&](std::ostream& out, OutputFormat f) { write_modes(out, system.vehicle.name, result, f); });
}

void modes_matrices(Stages* s, const std::string& mass, const std::string& stiffness) {
  const MatrixModel model = s->time("parse", [&] { return load_matrix_model(mass, stiffness, ""); });
  const SparseSystem system = s->time("assembly", [&] { return to_sparse_system(model); });
  const ModalResult result = s->time("solve", [&] { return solve_modes(system, ModalOptions{}); });
  s->add_summary("  solve: ", result.solver);
  write_all(s, [&](std::ostream& out, OutputFormat f) { write_modes(out, "matrices", result, f); });
}

void critical_speed(Stages* s, const std::string& file) {
  const Scene scene = s->time("parse", [&] { return load_scene(file); });
  const Vehicle vehicle = s->time("parse vehicle", [&] { return load_vehicle(scene.vehicle_file); });
  s->time("assembly", [&] { return assemble(vehicle, scene.dofs); });
  const CriticalSpeedStudy study = s->time("analysis", [&] { return study_critical_speeds(scene, vehicle); });
  s->add_summary("  analysis: ", study.summary);
  write_all(s, [&](std::ostream& out, OutputFormat f) { write_critical_speed_report(out, study, f); });
}

void simulate(Stages* s, const std::string& file) {
  const Scene scene = s->time("parse", [&] { return load_scene(file); });
  const Vehicle vehicle = s->time("parse vehicle", [&] { return load_vehicle(scene.vehicle_file); });
  s->time("assembly", [&] { return assemble(vehicle, scene.dofs); });
  const TimeHistory history = s->time("analysis", [&] { return simulate_scene(scene, vehicle); });
  s->add_summary("  analysis: ", history.summary);
  // csv streams as the run goes (CsvHistoryWriter): its cost is the run with the writer less
  // the run without; json is written from the whole history afterwards.
  std::ostringstream csv_text;
  CsvHistoryWriter csv(csv_text, scene);
  std::vector<HistorySink*> sinks{&csv};
  s->time("analysis + csv streamed", [&] { return simulate_scene(scene, vehicle, sinks); });
  std::ostringstream json;
  s->time("output json", [&] {
    write_time_history(json, history, scene, vehicle, OutputFormat::json);
    return 0;
  });
}

void stability(Stages* s, const std::string& file) {
  const Vehicle vehicle = s->time("parse", [&] { return load_vehicle(file); });
  const LinearSystem system = s->time("assembly", [&] { return assemble(vehicle, DofSet::lateral); });
  const HuntingResult result = s->time("analysis", [&] { return solve_hunting_stability(system); });
  s->add_summary("  analysis: ", result.summary);
  write_all(s, [&](std::ostream& out, OutputFormat f) { write_hunting_stability(out, result, f); });
}

void ride(Stages* s, const std::string& file) {
  const Scene scene = s->time("parse", [&] { return load_scene(file); });
  const Vehicle vehicle = s->time("parse vehicle", [&] { return load_vehicle(scene.vehicle_file); });
  const LinearSystem system = s->time("assembly", [&] { return assemble(vehicle, scene.dofs); });
  RideOptions options = scene.ride ? scene.ride->options : RideOptions{};
  if (options.speeds.empty() && scene.ride && scene.ride->simulation) options.speeds = {scene.ride->simulation->speed};
  const std::vector<RideOutput> outputs =
      scene.ride && !scene.ride->outputs.empty() ? scene.ride->outputs : default_ride_outputs(system);
  const RideResult result =
      s->time("analysis", [&] { return solve_ride(system, *scene.irregularity, outputs, options); });
  s->add_summary("  analysis: ", result.summary);
  write_all(s, [&](std::ostream& out, OutputFormat f) { write_ride(out, result, f); });
}

void balance(Stages* s, const std::string& file) {
  const DrivingGear gear = s->time("parse", [&] { return load_driving_gear(file); });
  const BalanceStudy study = s->time("analysis", [&] { return study_balance(gear, gear.design_speed); });
  for (const BalanceResult& rule : study.by_rule) s->add_summary("  analysis: ", rule.summary);
  write_all(s, [&](std::ostream& out, OutputFormat f) { write_balance(out, study, f); });
}

void compare(Stages* s, const std::string& file) {
  const Study study = s->time("parse (load_study: every variant built)", [&] { return load_study(file); });
  std::vector<VariantResult> results = s->time("analysis (evaluate_study, 1 thread)", [&] {
    EvaluationOptions options;
    options.threads = 1;
    return evaluate_study(study, options);
  });
  const Comparison comparison = s->time("rank", [&] { return rank_variants(study, std::move(results)); });
  const ComparisonCurves curves = s->time("curves of the best (documents only)", [&] {
    return comparison_curves(study, comparison, kReportBest);
  });
  write_all(s, [&](std::ostream& out, OutputFormat f) {
    const bool document = f == OutputFormat::markdown || f == OutputFormat::html;
    write_comparison_report(out, study, comparison, document ? curves : ComparisonCurves{}, f);
  });
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: stage_timing COMMAND FILE [FILE] [REPEATS] (see the comment at the top)\n";
    return 2;
  }
  const std::string command = argv[1];
  const int files = command == "modes-matrices" ? 2 : 1;
  const int repeats = argc > 2 + files ? std::max(1, std::atoi(argv[2 + files])) : 3;
  Stages stages;
  try {
    for (int r = 0; r < repeats; ++r) {
      const auto start = Clock::now();
      if (command == "modes") modes(&stages, argv[2]);
      else if (command == "modes-matrices") modes_matrices(&stages, argv[2], argv[3]);
      else if (command == "critical-speed") critical_speed(&stages, argv[2]);
      else if (command == "simulate") simulate(&stages, argv[2]);
      else if (command == "stability") stability(&stages, argv[2]);
      else if (command == "ride") ride(&stages, argv[2]);
      else if (command == "balance") balance(&stages, argv[2]);
      else if (command == "compare") compare(&stages, argv[2]);
      else {
        std::cerr << "stage_timing: unknown command " << command << "\n";
        return 2;
      }
      stages.add("total (the above and what lies between them)",
                 std::chrono::duration<double>(Clock::now() - start).count());
    }
  } catch (const std::exception& e) {
    std::cerr << "stage_timing: " << e.what() << "\n";
    return 1;
  }
  stages.print();
  return 0;
}
