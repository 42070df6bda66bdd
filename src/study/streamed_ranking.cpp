// The streamed ranking: keys in memory, texts in a temporary file (or the best k in memory).
// A variant's key and text depend on the variant alone and land in its own slot (or, for the
// best k, in a set ordered by key and study order), so the output is the same whatever the
// thread count.
#include "study/streamed_ranking.hpp"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <utility>

#include "study/ranking.hpp"

namespace railmodal::study {
namespace {

// One variant's sort key: rank_entry's, then the study order.
struct Key {
  std::vector<double> values;
  size_t position = 0;
  bool operator<(const Key& other) const {
    return values != other.values ? values < other.values : position < other.position;
  }
};

// The best `top` things (texts, or whole variants) seen so far, under a lock: a new one enters
// when it beats the worst kept.
template <typename T>
class BestKept {
 public:
  explicit BestKept(size_t top) : top_(top) {}
  void offer(const Key& key, T thing) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (best_.size() == top_ && !(key < std::prev(best_.end())->first)) return;
    best_.emplace(key, std::move(thing));
    if (best_.size() > top_) best_.erase(std::prev(best_.end()));
  }
  std::vector<T> in_order() {
    std::vector<T> things;
    for (auto& entry : best_) things.push_back(std::move(entry.second));
    return things;
  }

 private:
  size_t top_;
  std::mutex mutex_;
  std::multimap<Key, T> best_;  // keys are unique (their positions are)
};

}  // namespace

StreamedRanking::StreamedRanking(const Study& study, const Source& source, size_t top, const Render& render,
                                 size_t keep) {
  const Ranking& ranking = study.ranking;
  const size_t stride = 1 + (ranking.objective.empty() ? 0 : ranking.weighted ? 1 : ranking.objective.size());
  std::vector<double> keys;  // top == 0: `stride` values a variant, by position
  BestKept<std::string> best(top);
  BestKept<RankedVariant> kept(keep);
  std::mutex mutex;  // the mode names, the base
  std::set<std::string> modes;
  bool evaluated = false;
  std::atomic<size_t> feasible{0};
  if (top == 0)
    spill_ = std::make_unique<SpilledTexts>("the ranking of a whole study keeps its rows",
                                            keep > 0 ? "" : ", or keep the best K only with --top K");
  source(
      [&](size_t count) {
        size_ = count;
        if (top == 0) keys.resize(count * stride), spill_->resize(count);
      },
      [&](size_t k, VariantResult&& r) {
        RankedVariant v;
        std::vector<double> key = rank_entry(r, ranking, &v);
        v.result = std::move(r);
        if (v.result.ok() && v.feasible) ++feasible;
        std::string text = render(v);
        if (v.result.ok()) {
          const std::lock_guard<std::mutex> lock(mutex);
          evaluated = true;
          for (const auto& m : v.result.modes) modes.insert(m.name);
        }
        if (keep > 0 && is_base(v.result)) {
          const std::lock_guard<std::mutex> lock(mutex);
          base_ = v;
        }
        if (keep > 0) kept.offer({key, k}, std::move(v));
        if (top > 0) return best.offer({std::move(key), k}, std::move(text));
        std::copy(key.begin(), key.end(), keys.begin() + static_cast<std::ptrdiff_t>(k * stride));
        spill_->put(k, text);
      });
  if (spill_) spill_->finish();  // a full disk, say: thrown once the threads have stopped
  check_mode_names(study, modes, evaluated);
  feasible_ = feasible;
  best_ = kept.in_order();
  for (size_t i = 0; i < best_.size(); ++i) best_[i].rank = static_cast<int>(i) + 1;
  if (top > 0) {
    kept_ = best.in_order();
    for (size_t i = 0; i < kept_.size(); ++i) order_.push_back(i);
    return;
  }
  order_.resize(size_);
  for (size_t i = 0; i < size_; ++i) order_[i] = i;
  const auto key_of = [&](size_t k) { return keys.begin() + static_cast<std::ptrdiff_t>(k * stride); };
  // Lexicographic on the keys, then the study order, in one pass over the values: the first
  // values either way apart decide, the same order as two lexicographical_compare calls (less,
  // then greater) gave at twice the cost in the serial part.
  std::sort(order_.begin(), order_.end(), [&](size_t a, size_t b) {
    for (auto x = key_of(a), y = key_of(b), end = x + stride; x != end; ++x, ++y) {
      if (*x < *y) return true;
      if (*y < *x) return false;
    }
    return a < b;
  });
  if (base_) base_->rank = static_cast<int>(std::find(order_.begin(), order_.end(), size_t{0}) - order_.begin()) + 1;
}

void StreamedRanking::each_text(const std::function<void(size_t, std::string_view)>& visit) const {
  size_t rank = 0;
  if (spill_) return spill_->each_of(order_, [&](std::string_view text) { visit(++rank, text); });
  for (size_t k : order_) visit(++rank, kept_[k]);
}

std::string StreamedRanking::text_at(size_t k) const {
  if (!spill_) throw std::out_of_range("a streamed ranking of the best few keeps no study order");
  return spill_->at(k);
}

}  // namespace railmodal::study
