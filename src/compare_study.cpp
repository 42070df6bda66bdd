// railmodal::compare_study, compare_merged and compare_shard: a study evaluated (or its shards
// read), ranked and written without holding its results (issue 19, item 2), in every format.
// Here, at the top of src/, because it joins an analysis (the streamed ranking, study/), the
// shard reader (input/) and a writer (report/) that must not call each other's way.
#include <mutex>
#include <stdexcept>
#include <string>

#include "input/shard_reader.hpp"
#include "railmodal/comparison_report.hpp"
#include "railmodal/errors.hpp"
#include "report/comparison_document.hpp"
#include "report/streamed_comparison.hpp"
#include "study/parallel_evaluation.hpp"
#include "study/spilled_texts.hpp"
#include "study/streamed_ranking.hpp"

namespace railmodal {
namespace {

using study::StreamedRanking;

// The results of the study's shard files, each variant exactly once, one result in memory at a
// time: a variant in two shards, or in none, is an error at the file that repeats it (or the
// first file).
StreamedRanking::Source merged_results(const Study& study, const std::vector<std::string>& files) {
  if (files.empty()) throw std::invalid_argument("compare_merged: no shard file to merge");
  return [&study, &files](const std::function<void(size_t)>& prepare, const StreamedRanking::Sink& sink) {
    const size_t count = static_cast<size_t>(variant_count(study));
    prepare(count);
    std::vector<bool> seen(count);
    for (const std::string& file : files)
      input::read_shard_each(file, study, [&](VariantResult&& r) {
        const size_t k = static_cast<size_t>(r.index);  // read_shard_each checked it
        if (seen[k]) throw InputError(file, 0, 0, "variant '" + r.name + "' is also in an earlier shard");
        seen[k] = true;
        sink(k, std::move(r));
      });
    for (size_t k = 0; k < count; ++k)
      if (!seen[k])
        throw InputError(files.front(), 0, 0,
                         "no shard holds variant " + std::to_string(k + 1) + " ('" +
                             variant_name(study, static_cast<int>(k)) + "'): give every shard of the study");
  };
}

// The Markdown or HTML document from a streamed ranking: the best kReportRows variants and the
// base kept whole, the counts tallied as the results come, and each evaluated variant's sweep
// point in the ranking's temporary file, read back twice in study order.
void write_streamed_document(std::ostream& out, const Study& study, const StreamedRanking::Source& results,
                             Comparison head, OutputFormat format, const Provenance& provenance) {
  report::DocumentTally tally;
  std::mutex mutex;
  const auto render = [&](const RankedVariant& v) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      tally.add(v, study.ranking);
    }
    return v.result.ok() ? report::to_bytes(report::sweep_point(v, study.ranking)) : std::string();
  };
  const StreamedRanking ranked(study, results, 0, render, kReportRows);
  head.variants = ranked.best();
  if (const RankedVariant* base = ranked.base(); base && base->rank > static_cast<int>(head.variants.size()))
    head.variants.push_back(*base);  // after the best, as write_comparison_document expects it
  const auto points = [&](const std::function<void(const report::SweepPoint&)>& visit) {
    for (size_t k = 0; k < ranked.size(); ++k)
      if (const std::string bytes = ranked.text_at(k); !bytes.empty()) visit(report::sweep_point_from_bytes(bytes));
  };
  report::write_comparison_document(out, study, head, tally, points, comparison_curves(study, head, kReportBest),
                                    format, provenance);
}

// The ranking of `results` written in `format`.
void write_ranked(std::ostream& out, const Study& study, const StreamedRanking::Source& results, OutputFormat format,
                  int top, const Provenance& provenance, const std::string& caller) {
  if (top < 0) throw std::invalid_argument(caller + ": top must be 0 (every variant) or positive, not " + std::to_string(top));
  Comparison head;  // what the writers need besides the variants
  head.study = study.name;
  head.source = study.source;
  head.ranking = study.ranking;
  head.deflection_rule = study.deflection_rule;
  if (format == OutputFormat::markdown || format == OutputFormat::html) {
    if (top > 0) throw std::invalid_argument(caller + ": the " + std::string(to_string(format)) +
                                             " report shows every variant; top applies to table, csv and json");
    return write_streamed_document(out, study, results, std::move(head), format, provenance);
  }
  const StreamedRanking ranked(study, results, static_cast<size_t>(top),
                               report::streamed_row(study.ranking, study.deflection_rule, format));
  report::write_streamed_comparison(out, head, ranked, format, study.notes);
}

}  // namespace

void compare_study(std::ostream& out, const Study& study, const EvaluationOptions& options, OutputFormat format,
                   int top, const Provenance& provenance) {
  if (options.shards != 1)
    throw std::invalid_argument("a streamed ranking ranks the whole study: shards must be 1, not " +
                                std::to_string(options.shards));
  const StreamedRanking::Source results = [&](const std::function<void(size_t)>& prepare,
                                              const StreamedRanking::Sink& sink) {
    // A CSV or table of the ranking writes no mode name: a variant names only the modes its
    // ranking reads (study::ModeNamesRead).
    study::evaluate_each(study, options, prepare, sink, format != OutputFormat::csv && format != OutputFormat::table);
  };
  write_ranked(out, study, results, format, top, provenance, "compare_study");
}

void compare_merged(std::ostream& out, const Study& study, const std::vector<std::string>& shard_files,
                    OutputFormat format, int top, const Provenance& provenance) {
  write_ranked(out, study, merged_results(study, shard_files), format, top, provenance, "compare_merged");
}

void compare_shard(std::ostream& out, const Study& study, const EvaluationOptions& options, const Provenance& inputs) {
  study::SpilledTexts results("a shard keeps its results", "");
  study::evaluate_each(
      study, options, [&](size_t count) { results.resize(count); },
      [&](size_t k, VariantResult&& r) { results.put(k, report::shard_result_json(r)); });
  results.finish();
  report::write_streamed_shard(out, study, options, results.size(), [&](size_t k) { return results.at(k); }, inputs);
}

}  // namespace railmodal
