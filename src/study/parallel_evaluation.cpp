// The variants of a shard on several threads. Each result depends only on its variant and
// lands in its own slot, so the output is the same whatever the number of threads. With
// read_in_workers each thread also reads the variants it evaluates from the study's parsed
// files (issue 19, item 2): reading is spread over the threads, and a read vehicle lives only
// while it is evaluated.
#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "railmodal/errors.hpp"
#include "railmodal/study.hpp"
#include "load_study.hpp"
#include "require_valid.hpp"
#include "study/parallel_evaluation.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

bool EvaluationOptions::is_valid(std::string* why) const {
  if (shards < 1 || shard < 1 || shard > shards) return invalid(why, "shard must be K/N with 1 <= K <= N");
  if (threads < 0) return invalid(why, "threads must be 0 (every core) or positive");
  return true;
}

std::optional<HuntingOptions> hunting_options_of(const Study& study) {
  const auto names_it = [](const std::string& metric) { return canonical_metric(metric) == "hunting_speed"; };
  const Ranking& ranking = study.ranking;
  if (std::none_of(ranking.constraints.begin(), ranking.constraints.end(),
                   [&](const RankingConstraint& c) { return names_it(c.metric); }) &&
      std::none_of(ranking.objective.begin(), ranking.objective.end(),
                   [&](const RankingCriterion& c) { return names_it(c.metric); }))
    return std::nullopt;
  HuntingOptions options;
  options.threads = 1;  // the variants are spread over the threads
  return options;
}

study::ModeNamesRead study::mode_names_ranked(const Ranking& ranking) {
  ModeNamesRead names;
  names.all = false;
  const auto see = [&](const std::string& metric) {
    const std::string name = canonical_metric(metric);
    for (auto [prefix, list] : {std::pair{"period:", &names.periods}, {"critical_speed:", &names.critical_speeds}})
      if (name.rfind(prefix, 0) == 0) list->push_back(name.substr(std::char_traits<char>::length(prefix)));
  };
  for (const RankingConstraint& c : ranking.constraints) see(c.metric);
  for (const RankingCriterion& c : ranking.objective) see(c.metric);
  return names;
}

int study::evaluate_each(const Study& study, const EvaluationOptions& options,
                         const std::function<void(size_t)>& prepare,
                         const std::function<void(size_t, VariantResult&&)>& sink, bool names_written) {
  require_valid(options, "");
  std::vector<int> indices;
  const bool opened = study.variants.empty() && study.plan;  // open_study: no variant listed, none read
  const int count = variant_count(study);
  for (int i = 0; i < count; ++i)
    if (in_shard(i, options.shard, options.shards)) {
      if ((opened || !study.variants[i].read) && !(options.read_in_workers && study.plan))
        throw std::invalid_argument("variant " + std::to_string(i + 1) + " ('" + variant_name(study, i) +
                                    "') was not read: load the study with this shard");
      indices.push_back(i);
    }
  prepare(indices.size());
  const VariantSettings settings{study.deflection_rule, hunting_options_of(study), ride_rms_only(study),
                                 study.every_analysis ? VariantWork{} : variant_work_of(study.ranking, study.deflection_rule),
                                 names_written ? ModeNamesRead{} : mode_names_ranked(study.ranking),
                                 // A study built in code has no file to send the error back to.
                                 !study.plan};
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, static_cast<int>(indices.size())));

  std::atomic<size_t> next{0};
  std::mutex progress_mutex;
  size_t done = 0;
  // The first variant that could not be read (read_in_workers) or whose input an analysis
  // refused: once one is found no thread takes another, and every index below the largest taken
  // was taken and finished, so the lowest one recorded is the study's first bad variant whatever
  // the thread count.
  std::mutex error_mutex;
  std::atomic<bool> stop{false};
  size_t error_at = indices.size();
  std::exception_ptr error;
  auto work = [&] {
    Workspace workspace;  // this thread's: its base assembly and systems, kept between variants
    while (!stop) {
      const size_t k = next++;  // a taken index is always finished: see error_at
      if (k >= indices.size()) break;
      const int index = indices[k];
      const StudyVariant* variant = opened ? nullptr : &study.variants[index];
      StudyVariant read;  // this thread's copy of an unread variant, dropped once evaluated
      if (!variant || !variant->read) {
        try {
          // Into the vehicle and scene of the variant before (the workspace holds them once
          // evaluated): their storage serves this one.
          read.vehicle = std::move(workspace.system.vehicle);
          read.scene = std::move(workspace.scene);
          detail::read_variant_into(study, index, &read);
          variant = &read;
        } catch (const InputError&) {
          const std::lock_guard<std::mutex> lock(error_mutex);
          if (k < error_at) error_at = k, error = std::current_exception();
          stop = true;
          continue;
        }
      }
      VariantResult result;
      try {
        // A variant read here is this thread's own: given up, it is moved, not copied, into the
        // evaluation (its name and parameters stay).
        result = variant == &read
                     ? evaluate_owned_variant(std::move(read), index, settings, &workspace)
                     : evaluate_in_workspace(*variant, index, settings, &workspace);
      } catch (const InputError& e) {
        // The variant's input an analysis refuses (a scene output that does not fit its vehicle,
        // a series damper): the study file's error at the variant's line, as a bad override is.
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (k < error_at) error_at = k, error = std::make_exception_ptr(detail::variant_input_error(study, index, e));
        stop = true;
        continue;
      } catch (const std::exception& e) {  // evaluate_variant keeps design failures; this is a bug
        result = VariantResult{};
        result.index = index;
        result.name = variant->name;
        result.parameters = variant->parameters;
        result.failure = std::string("internal error: ") + e.what();
      }
      try {
        sink(k, std::move(result));
      } catch (...) {  // the sink's own failure (a full disk, no memory): every thread stops, then it is rethrown
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (k < error_at) error_at = k, error = std::current_exception();
        stop = true;
        continue;
      }
      if (options.progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        options.progress(static_cast<double>(++done) / static_cast<double>(indices.size()));
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return threads;
}

std::vector<VariantResult> evaluate_study(const Study& study, const EvaluationOptions& options,
                                          AnalysisSummary* summary) {
  require_valid(options, "");
  if (summary) *summary = AnalysisSummary{};
  StageClock clock(summary);  // no clock, no strings without a summary
  std::vector<VariantResult> results;
  const int threads = study::evaluate_each(
      study, options, [&](size_t count) { results.resize(count); },
      [&](size_t k, VariantResult&& r) { results[k] = std::move(r); });  // one slot each: no lock
  clock.lap("evaluate variants");
  if (summary) {
    summary->analysis = "design study, shard " + std::to_string(options.shard) + " of " + std::to_string(options.shards);
    // What runs: each thread evaluates the variants it takes in its own workspace
    // (study::Workspace), not through evaluate_variant, and reads those not read beforehand.
    const bool reads = options.read_in_workers && study.plan;
    summary->method = "variants evaluated on " + std::to_string(threads) +
                      " thread(s), each in its thread's workspace (the base's assembly kept between variants)" +
                      (reads ? ", a variant not read beforehand read by the thread that takes it" : "") +
                      ", one result slot per variant";
    const double failed = static_cast<double>(
        std::count_if(results.begin(), results.end(), [](const VariantResult& r) { return !r.ok(); }));
    summary->checks.push_back({"variants evaluated", static_cast<double>(results.size()),
                               std::numeric_limits<double>::infinity(), true});
    summary->checks.push_back({"variants that failed", failed, std::numeric_limits<double>::infinity(), true});
  }
  return results;
}

}  // namespace railmodal
