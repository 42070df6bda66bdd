// railmodal::compare_study: a study evaluated, ranked and written without holding its results
// (issue 19, item 2), in every format. Here, at the top of src/, because it joins an analysis (the streamed
// ranking, study/) and a writer (report/) that must not call each other's way.
#include <mutex>
#include <stdexcept>
#include <string>

#include "railmodal/comparison_report.hpp"
#include "report/comparison_document.hpp"
#include "report/streamed_comparison.hpp"
#include "study/parallel_evaluation.hpp"
#include "study/spilled_texts.hpp"
#include "study/streamed_ranking.hpp"

namespace railmodal {
namespace {

// The Markdown or HTML document from a streamed ranking: the best kReportRows variants and the
// base kept whole, the counts tallied as the results come, and each evaluated variant's sweep
// point in the ranking's temporary file, read back twice in study order.
void write_streamed_document(std::ostream& out, const Study& study, const EvaluationOptions& options,
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
  const study::StreamedRanking ranked(study, options, 0, render, kReportRows);
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

}  // namespace

void compare_study(std::ostream& out, const Study& study, const EvaluationOptions& options, OutputFormat format,
                   int top, const Provenance& provenance) {
  if (top < 0) throw std::invalid_argument("compare_study: top must be 0 (every variant) or positive, not " + std::to_string(top));
  Comparison head;  // what the writers need besides the variants
  head.study = study.name;
  head.source = study.source;
  head.ranking = study.ranking;
  head.deflection_rule = study.deflection_rule;
  if (format == OutputFormat::markdown || format == OutputFormat::html) {
    if (top > 0) throw std::invalid_argument("compare_study: the " + std::string(to_string(format)) +
                                             " report shows every variant; top applies to table, csv and json");
    return write_streamed_document(out, study, options, std::move(head), format, provenance);
  }
  const study::StreamedRanking ranked(study, options, static_cast<size_t>(top),
                                      report::streamed_row(study.ranking, study.deflection_rule, format));
  report::write_streamed_comparison(out, head, ranked, format);
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
