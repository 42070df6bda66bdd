// A study evaluated and ranked without holding its results (issue 19, item 2): per variant only
// its sort key stays in memory, and the text a report writes of it waits in a temporary file
// until the ranking is known; a report that shows only the best k keeps only their texts.
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::study {

class StreamedRanking {
 public:
  /// What a report keeps of a variant: its text, from the result and its ranking entry
  /// (feasible, violations, criteria, objective; the rank is not known yet and is 0).
  using Render = std::function<std::string(const RankedVariant&)>;

  /// Evaluates the whole study (options.shards must be 1) and ranks it as
  /// rank_variants(study, evaluate_study(study, options)) would: the same order whatever the
  /// thread count. `render` is called from the worker threads, concurrently, once per variant.
  /// With `top` > 0 only the texts of the best `top` variants are kept. Throws as
  /// evaluate_study, and as rank_variants for a metric naming a mode no variant has.
  StreamedRanking(const Study& study, const EvaluationOptions& options, size_t top, const Render& render);

  size_t size() const { return size_; }          ///< variants ranked
  size_t feasible() const { return feasible_; }  ///< evaluated and within every constraint
  size_t shown() const { return order_.size(); }  ///< variants whose text is kept: size(), or top
  /// The text of the variant ranked `rank` (1 ... shown()).
  std::string text(size_t rank) const;

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  size_t size_ = 0, feasible_ = 0;
  std::vector<size_t> order_;          ///< variant positions in rank order (top: into kept_)
  std::vector<std::string> kept_;      ///< top > 0: the texts of the best, by position in order_
  std::unique_ptr<std::FILE, Closer> spill_;  ///< top == 0: every text, one after another
  std::vector<unsigned long long> offsets_;   ///< top == 0: where each variant's text starts
  std::vector<unsigned> lengths_;             ///< top == 0: its length
};

}  // namespace railmodal::study
