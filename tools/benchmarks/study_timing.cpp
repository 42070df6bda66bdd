// The C++ side of compare_study.py: a sampled design study (by default the 10⁵ spring sets of
// the resort car, resort_car_sample_study.toml) loaded, evaluated on THREADS threads and
// ranked, each step timed. Then, untimed:
//  - thread identity: the first 2000 variants evaluated on 1 thread and on THREADS threads
//    (2 if THREADS is 1) must give byte-identical shard JSON and ranked CSV, and the same
//    bytes as the full run's results for them;
//  - for the first NUMPY_VARIANTS variants, what numpy needs to redo the per-variant work
//    (the system study_critical_speeds assembles and solves — massless DOFs, if any, are left
//    in it: the script condenses them as solve_modes does —, the scene's speed range, its
//    grid, each source's wavelength and each harmonic's load Q(ω) = s(ω)(Q_K + iωQ_C), the
//    output DOFs) and railmodal's answers to compare (modes, critical speeds, grid curves,
//    peak summaries, static deflections), as JSON in OUT.json.
//
//   study_timing STUDY.toml THREADS OUT.json NUMPY_VARIANTS
//
// prints "key value" lines: load_s, evaluate_s, rank_s (wall clock), load_cpu_s, evaluate_cpu_s
// (processor time of all threads), variants, failed, threads, variants_per_min (load +
// evaluate + rank, wall clock), evaluate_variants_per_min, best, then the subset's
// subset_variants, subset_1_thread_s, subset_threads_s (and _cpu_s), threads_identical
// (yes/no; the exit code is 1 when no).
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "model_json.hpp"
#include "railmodal/railmodal.hpp"

using namespace railmodal;

namespace {

using benchmarks::matrix;
using benchmarks::complex_vector;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Processor time of the whole process (all threads), s: less disturbed than the wall clock
// when other jobs share the cores.
double cpu_seconds_since(std::clock_t start) { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

// What numpy needs to redo one variant, and what railmodal found for it.
nlohmann::json variant_json(const StudyVariant& variant, const VariantResult& result) {
  nlohmann::json j;
  j["name"] = variant.name;
  j["failure"] = result.failure;
  nlohmann::json parameters = nlohmann::json::array();
  for (const auto& [key, value] : variant.parameters) parameters.push_back({{"key", key}, {"value", value}});
  j["parameters"] = parameters;
  // Railmodal's summaries (what evaluate_study returned in the timed run).
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& m : result.modes)
    modes.push_back({{"name", m.name}, {"kind", m.kind}, {"frequency_hz", m.frequency_hz}});
  j["modes"] = modes;
  nlohmann::json critical = nlohmann::json::array();
  for (const auto& c : result.critical_speeds)
    critical.push_back({{"speed", c.speed}, {"source", c.source}, {"harmonic", c.harmonic}, {"mode_name", c.mode_name}});
  j["critical_speeds"] = critical;
  nlohmann::json peaks = nlohmann::json::array();
  for (const auto& p : result.peaks)
    peaks.push_back({{"source", p.source}, {"output", p.output}, {"quantity", p.quantity}, {"amplitude", p.amplitude},
                     {"speed", p.speed}, {"unbounded", p.unbounded}});
  j["peaks"] = peaks;
  nlohmann::json deflections = nlohmann::json::array();
  for (const auto& [body, f] : result.static_deflections) deflections.push_back({{"body", body}, {"deflection", f}});
  j["static_deflections"] = deflections;
  if (!result.ok()) return j;

  // The model and loads, as the study itself builds them (same assembly, same modes).
  const Scene& scene = variant.scene;
  const CriticalSpeedStudy study = study_critical_speeds(scene, variant.vehicle);
  const LinearSystem& sys = study.system;
  j["mass"] = matrix(sys.mass);
  j["stiffness"] = matrix(sys.stiffness);
  j["damping"] = matrix(sys.damping);
  j["gravity_stiffness"] = matrix(sys.gravity_stiffness);
  j["gravity"] = variant.vehicle.gravity;
  nlohmann::json dofs = nlohmann::json::array();
  for (const Dof& d : sys.dofs)
    dofs.push_back({{"label", d.label}, {"motion", to_string(d.motion)},
                    {"body", d.body >= 0 ? variant.vehicle.bodies[d.body].name : ""}});
  j["dofs"] = dofs;
  j["condensed"] = study.modes.condensed;
  j["min_speed"] = scene.min_speed;
  j["max_speed"] = scene.max_speed;
  j["speed_step"] = scene.speed_step;
  const SpeedGrid grid = study.curves.empty() ? SpeedGrid() : study.curves.front().speeds;
  j["speeds"] = grid.values();
  nlohmann::json sources = nlohmann::json::array();
  for (const auto& source : scene.sources) {
    nlohmann::json harmonics = nlohmann::json::array();
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      const SeparableLoad p = source->separable_load(sys, k);
      std::vector<double> scale;
      for (double v : grid) scale.push_back(source->load_scale(6.283185307179586 * source->frequency_hz(v, k), p.reference_omega));
      harmonics.push_back({{"harmonic", k}, {"stiffness_part", complex_vector(p.stiffness_part)},
                           {"damping_part", complex_vector(p.damping_part)}, {"load_scale", scale}});
    }
    sources.push_back({{"kind", source->kind()}, {"wavelength", source->wavelength()}, {"harmonics", harmonics}});
  }
  j["sources"] = sources;
  nlohmann::json outputs = nlohmann::json::array();
  for (const auto& o : scene.outputs) outputs.push_back({{"dof", sys.index_of(o.dof)}, {"quantity", to_string(o.quantity)}});
  j["outputs"] = outputs;
  nlohmann::json curves = nlohmann::json::array();
  for (size_t k = 0; k < study.curves.size(); ++k) {
    const AmplitudeCurve& c = study.curves[k];
    std::vector<int> unbounded(c.unbounded.begin(), c.unbounded.end());
    nlohmann::json refined = nlohmann::json::array();
    for (const auto& p : study.peaks)
      if (p.curve == static_cast<int>(k)) refined.push_back({{"speed", p.peak.speed}, {"amplitude", p.peak.amplitude}});
    curves.push_back({{"source", c.source}, {"output", c.output}, {"quantity", to_string(c.quantity)},
                      {"amplitudes", c.amplitudes}, {"unbounded", unbounded}, {"refined_peaks", refined}});
  }
  j["curves"] = curves;
  return j;
}

std::string shard_text(const Study& study, const std::vector<VariantResult>& results) {
  std::ostringstream out;
  write_shard(out, study, EvaluationOptions{}, results);
  return out.str();
}

std::string csv_text(const Study& study, const std::vector<VariantResult>& results) {
  std::ostringstream out;
  write_comparison(out, rank_variants(study, results), OutputFormat::csv);
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: study_timing STUDY.toml THREADS OUT.json NUMPY_VARIANTS\n";
    return 2;
  }
  const int threads = std::max(1, std::atoi(argv[2]));
  const int numpy_variants = std::max(0, std::atoi(argv[4]));
  try {
    auto start = Clock::now();
    auto cpu = std::clock();
    const Study study = load_study(argv[1]);
    const double load_s = seconds_since(start), load_cpu_s = cpu_seconds_since(cpu);

    EvaluationOptions options;
    options.threads = threads;
    start = Clock::now();
    cpu = std::clock();
    const std::vector<VariantResult> results = evaluate_study(study, options);
    const double evaluate_s = seconds_since(start), evaluate_cpu_s = cpu_seconds_since(cpu);

    std::vector<VariantResult> copy = results;  // rank_variants takes its own copy
    start = Clock::now();
    const Comparison comparison = rank_variants(study, std::move(copy));
    const double rank_s = seconds_since(start);

    const double n = static_cast<double>(study.variants.size());
    const long failed = std::count_if(results.begin(), results.end(), [](const VariantResult& r) { return !r.ok(); });
    std::cout << "load_s " << load_s << "\nload_cpu_s " << load_cpu_s << "\nevaluate_s " << evaluate_s
              << "\nevaluate_cpu_s " << evaluate_cpu_s << "\nrank_s " << rank_s << "\nvariants "
              << study.variants.size() << "\nfailed " << failed << "\nthreads " << threads << "\nvariants_per_min "
              << 60.0 * n / (load_s + evaluate_s + rank_s) << "\nevaluate_variants_per_min " << 60.0 * n / evaluate_s
              << "\nbest " << (comparison.variants.empty() ? "-" : comparison.variants.front().result.name) << std::endl;

    // Thread identity on the first 2000 variants (untimed for the figures above).
    Study subset;
    subset.name = study.name;
    subset.source = study.source;
    subset.ranking = study.ranking;
    const size_t m = std::min<size_t>(2000, study.variants.size());
    subset.variants.assign(study.variants.begin(), study.variants.begin() + m);
    EvaluationOptions one = options, many = options;
    one.threads = 1;
    many.threads = threads > 1 ? threads : 2;
    start = Clock::now();
    cpu = std::clock();
    const std::vector<VariantResult> r1 = evaluate_study(subset, one);
    const double subset_1_s = seconds_since(start), subset_1_cpu_s = cpu_seconds_since(cpu);
    start = Clock::now();
    cpu = std::clock();
    const std::vector<VariantResult> rn = evaluate_study(subset, many);
    const double subset_n_s = seconds_since(start), subset_n_cpu_s = cpu_seconds_since(cpu);
    const std::vector<VariantResult> from_full(results.begin(), results.begin() + m);
    const std::string shard1 = shard_text(subset, r1);
    const bool identical = shard1 == shard_text(subset, rn) && shard1 == shard_text(subset, from_full) &&
                           csv_text(subset, r1) == csv_text(subset, rn);
    std::cout << "subset_variants " << m << "\nsubset_1_thread_s " << subset_1_s << "\nsubset_1_thread_cpu_s "
              << subset_1_cpu_s << "\nsubset_threads " << many.threads << "\nsubset_threads_s " << subset_n_s
              << "\nsubset_threads_cpu_s " << subset_n_cpu_s << "\nthreads_identical " << (identical ? "yes" : "no")
              << std::endl;

    nlohmann::json j;
    j["study"] = study.name;
    j["variants"] = nlohmann::json::array();
    for (int i = 0; i < numpy_variants && i < static_cast<int>(study.variants.size()); ++i)
      j["variants"].push_back(variant_json(study.variants[i], results[i]));
    std::ofstream(argv[3]) << j.dump();
    return identical ? 0 : 1;
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "study_timing: " << e.what() << "\n";
    return 4;
  }
}
