// railmodal::compare_study: a study evaluated, ranked and written without holding its results
// (issue 19, item 2). Here, at the top of src/, because it joins an analysis (the streamed
// ranking, study/) and a writer (report/) that must not call each other's way.
#include <stdexcept>
#include <string>

#include "railmodal/comparison_report.hpp"
#include "report/streamed_comparison.hpp"
#include "study/streamed_ranking.hpp"

namespace railmodal {

void compare_study(std::ostream& out, const Study& study, const EvaluationOptions& options, OutputFormat format,
                   int top) {
  if (top < 0) throw std::invalid_argument("compare_study: top must be 0 (every variant) or positive, not " + std::to_string(top));
  Comparison head;  // what the writers need besides the variants
  head.study = study.name;
  head.source = study.source;
  head.ranking = study.ranking;
  head.deflection_rule = study.deflection_rule;
  const study::StreamedRanking ranked(study, options, static_cast<size_t>(top),
                                      report::streamed_row(study.ranking, study.deflection_rule, format));
  report::write_streamed_comparison(out, head, ranked, format);
}

}  // namespace railmodal
