// Where a study's time goes per variant, against the floor (issue 19, item 2): for the first N
// variants of STUDY.toml, on one thread, the processor time of each stage of a variant's
// evaluation, and of the work no implementation can skip — the floor:
//  - eigen-solve: the dense symmetric-definite eigenproblem K φ = ω² M φ of the variant's
//    assembled system (Eigen's GeneralizedSelfAdjointEigenSolver, eigenvectors included), the
//    least any program that reports modes and mode shapes must do;
//  - sweep: the amplitude curves of study_critical_speeds (its "amplitude curves" stage: every
//    output on every grid speed, the vectorised modal sweep), the least a program that reports
//    peak responses on that grid must do.
// The stages (each timed alone on the same variants, so each includes what it repeats):
//  - build: read_variant, the variant's vehicle and scene built from the study's parsed files
//    (its overrides written into the parsed TOML tree, then the usual readers: no text parsed);
//  - assemble: assemble() of the scene's DOF set;
//  - modes: solve_modes() of that system (names and kinds included);
//  - critical-speed study: study_critical_speeds() (assembly, modes, critical speeds, curves, peaks);
//  - evaluate: evaluate_variant() (that study and the summaries a study ranks and writes);
//  - read + evaluate in a worker: evaluate_study() with the variants read in the workers, one
//    thread (what `railmodal compare` does: each variant read from the parsed files and
//    evaluated on the worker's kept base, its coefficients written into the base's assembly);
//  - compare, CSV: compare_study() writing CSV, one thread: read + evaluate in a worker naming
//    only the modes the ranking reads, then the variant's key and CSV row (what `railmodal
//    compare --format csv` does per variant);
// and, for all N together, rank_variants() per variant. Medians over the variants (thread CPU
// time, so that other jobs on a shared machine do not count), with the 10th and 90th percentiles.
//
//   study_stages STUDY.toml [N=2000]
//
// prints one line per stage: "stage median_us p10_us p90_us ratio_to_floor".
#include <algorithm>
#include <Eigen/Dense>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"

using namespace railmodal;

namespace {

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Spread {
  double median = 0.0, p10 = 0.0, p90 = 0.0;
};

Spread spread_us(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  const auto at = [&](double q) { return 1e6 * seconds[static_cast<size_t>(q * static_cast<double>(seconds.size() - 1))]; };
  return {at(0.5), at(0.1), at(0.9)};
}

// The processor time of `work` on each variant, s.
std::vector<double> per_variant(const std::vector<StudyVariant>& variants, const std::function<void(const StudyVariant&)>& work) {
  std::vector<double> times;
  for (const StudyVariant& v : variants) {
    const double start = thread_seconds();
    work(v);
    times.push_back(thread_seconds() - start);
  }
  return times;
}

// The thread time between two progress reports of `run` on one thread reading each variant in
// its worker (the progress is reported on the evaluating thread, after each variant), s.
std::vector<double> per_progress_report(const std::function<void(const EvaluationOptions&)>& run) {
  std::vector<double> times;
  EvaluationOptions options;
  options.threads = 1;
  options.read_in_workers = true;
  double last = thread_seconds();
  options.progress = [&](double) {
    const double now = thread_seconds();
    times.push_back(now - last);
    last = now;
  };
  run(options);
  return times;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: study_stages STUDY.toml [N]\n";
    return 2;
  }
  const int wanted = argc > 2 ? std::atoi(argv[2]) : 2000;
  const Study study = load_study(argv[1], [&](int index) { return index < 0; });  // read none: timed below
  const int n = std::min<int>(wanted, static_cast<int>(study.variants.size()));

  std::vector<StudyVariant> variants(n);
  std::vector<double> build;
  for (int i = 0; i < n; ++i) {
    const double start = thread_seconds();
    variants[i] = read_variant(study, i);
    build.push_back(thread_seconds() - start);
  }
  std::vector<LinearSystem> systems;
  const std::vector<double> assembly = per_variant(variants, [&](const StudyVariant& v) {
    systems.push_back(assemble(v.vehicle, v.scene.dofs));
  });
  size_t k = 0;
  double sink = 0.0;  // keeps the optimiser from dropping the floor's solve
  const std::vector<double> eigen = per_variant(variants, [&](const StudyVariant&) {
    const LinearSystem& s = systems[k++];
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(s.stiffness, s.mass);
    sink += solver.eigenvalues()(0) + solver.eigenvectors()(0, 0);
  });
  k = 0;
  const std::vector<double> modes = per_variant(variants, [&](const StudyVariant&) { sink += solve_modes(systems[k++]).modes.size(); });
  std::vector<double> sweep;
  std::vector<std::pair<std::string, std::vector<double>>> inner;  // the study's own stages (wall clock)
  const std::vector<double> critical = per_variant(variants, [&](const StudyVariant& v) {
    const CriticalSpeedStudy s = study_critical_speeds(v.scene, v.vehicle);
    for (const StageTiming& t : s.summary.stages) {
      if (t.stage == "amplitude curves") sweep.push_back(t.seconds);
      auto named = std::find_if(inner.begin(), inner.end(), [&](const auto& p) { return p.first == t.stage; });
      if (named == inner.end()) named = inner.insert(inner.end(), {t.stage, {}});
      named->second.push_back(t.seconds);
    }
  });
  std::vector<VariantResult> results;
  int i = 0;
  const std::vector<double> evaluate = per_variant(variants, [&](const StudyVariant& v) {
    results.push_back(evaluate_variant(v, i++, study.deflection_rule, hunting_options_of(study), ride_rms_only(study),
                                 variant_work_of(study.ranking, study.deflection_rule)));
  });
  // The workers' path: per variant, the thread time between two progress reports.
  Study first_n = study;
  first_n.variants.resize(n);
  const std::vector<double> in_worker =
      per_progress_report([&](const EvaluationOptions& options) { sink += evaluate_study(first_n, options).size(); });
  // What `railmodal compare --format csv` does per variant: read + evaluate in a worker, then
  // the sink (the ranking's key, the CSV row into the temporary file); a variant names only the
  // modes its ranking reads (no CSV column holds a mode name). The ranking and writing after
  // the last variant are not counted.
  const std::vector<double> in_compare = per_progress_report([&](const EvaluationOptions& options) {
    std::ostringstream csv;
    compare_study(csv, first_n, options, OutputFormat::csv);
    sink += static_cast<double>(csv.str().size());
  });
  // Ranking needs every variant of the study: rank a study of the first n.
  const double rank_start = thread_seconds();
  const Comparison ranked = rank_variants(first_n, results);
  const double rank_seconds = (thread_seconds() - rank_start) / n;

  const Spread e = spread_us(eigen), w = spread_us(sweep);
  const double floor = e.median + w.median;
  std::printf("study %s: %d variants, %d DOFs, %zu curves; sink %g\n", argv[1], n, systems.front().size(),
              results.front().peaks.size(), sink);
  std::printf("%-34s %10s %8s %8s %8s\n", "stage (per variant, thread CPU)", "median_us", "p10_us", "p90_us", "x_floor");
  const auto line = [&](const char* name, const Spread& s) {
    std::printf("%-34s %10.2f %8.2f %8.2f %8.2f\n", name, s.median, s.p10, s.p90, s.median / floor);
  };
  line("floor: eigen-solve (Eigen GSAES)", e);
  line("floor: sweep (amplitude curves)", w);
  std::printf("%-34s %10.2f\n", "floor: total", floor);
  line("build (read_variant)", spread_us(build));
  line("assemble", spread_us(assembly));
  line("modes (solve_modes)", spread_us(modes));
  line("critical-speed study", spread_us(critical));
  for (const auto& [stage, seconds] : inner) line(("  of which " + stage + " (wall)").c_str(), spread_us(seconds));
  line("evaluate (evaluate_variant)", spread_us(evaluate));
  line("read + evaluate in a worker", spread_us(in_worker));
  line("compare, CSV: + key and row", spread_us(in_compare));
  std::printf("%-34s %10.2f %8s %8s %8.2f\n", "rank (rank_variants / n)", 1e6 * rank_seconds, "", "", 1e6 * rank_seconds / floor);
  std::printf("best %s\n", ranked.variants.front().result.name.c_str());
  return 0;
}
