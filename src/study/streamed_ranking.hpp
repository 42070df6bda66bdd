// A study evaluated and ranked without holding its results (issue 19, item 2): per variant only
// its sort key stays in memory, and the text a report writes of it waits in a temporary file
// until the ranking is known; a report that shows only the best k keeps only their texts.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "railmodal/study.hpp"
#include "study/spilled_texts.hpp"

namespace railmodal::study {

class StreamedRanking {
 public:
  /// What a report keeps of a variant: its text, from the result and its ranking entry
  /// (feasible, violations, criteria, objective; the rank is not known yet and is 0).
  using Render = std::function<std::string(const RankedVariant&)>;

  /// Hands every result of a whole study to `sink` with its position (its index in the study),
  /// each exactly once, after telling `prepare` how many there are; the sink may be called
  /// from several threads at once. Evaluating the study is one source; shard files are another.
  using Sink = std::function<void(size_t position, VariantResult&& result)>;
  using Source = std::function<void(const std::function<void(size_t count)>& prepare, const Sink& sink)>;

  /// Ranks the results `source` gives (the study evaluated on its threads, or shard files) as
  /// rank_variants ranks them: the same order whatever order they come in. `render` is called
  /// as the source hands each on (concurrently, from its threads), once per variant. With `top`
  /// > 0 only the texts of the best `top` variants are kept. With `keep` > 0 the best `keep`
  /// variants are kept whole (best()), and the base design (base()). Throws what the source
  /// throws, and as rank_variants for a metric naming a mode no variant has.
  StreamedRanking(const Study& study, const Source& source, size_t top, const Render& render, size_t keep = 0);

  size_t size() const { return size_; }          ///< variants ranked
  size_t feasible() const { return feasible_; }  ///< evaluated and within every constraint
  size_t shown() const { return order_.size(); }  ///< variants whose text is kept: size(), or top
  /// The texts of ranks 1 ... shown() handed to `visit` with their rank, in rank order, read
  /// from the temporary file in a few sequential passes (SpilledTexts::each_of) rather than one
  /// read a rank.
  void each_text(const std::function<void(size_t rank, std::string_view text)>& visit) const;
  /// The text of the variant at `position` in the study (0 ... size() − 1); only without `top`.
  std::string text_at(size_t position) const;
  /// The best `keep` variants whole, in rank order, their ranks set (fewer if the study is smaller).
  const std::vector<RankedVariant>& best() const { return best_; }
  /// The base design whole with its rank (comparison_base), if `keep` > 0 and the study has one.
  const RankedVariant* base() const { return base_ ? &*base_ : nullptr; }

 private:
  size_t size_ = 0, feasible_ = 0;
  std::vector<size_t> order_;          ///< variant positions in rank order (top: into kept_)
  std::vector<std::string> kept_;      ///< top > 0: the texts of the best, by position in order_
  std::unique_ptr<SpilledTexts> spill_;       ///< top == 0: every text, by position
  std::vector<RankedVariant> best_;           ///< keep > 0: the best, whole
  std::optional<RankedVariant> base_;         ///< keep > 0: the base design, whole
};

}  // namespace railmodal::study
