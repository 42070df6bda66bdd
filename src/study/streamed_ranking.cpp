// The streamed ranking: keys in memory, texts in a temporary file (or the best k in memory).
// A variant's key and text depend on the variant alone and land in its own slot (or, for the
// best k, in a set ordered by key and study order), so the output is the same whatever the
// thread count.
#include "study/streamed_ranking.hpp"

#include <stdlib.h>  // mkstemp
#include <unistd.h>  // unlink

#include <algorithm>
#include <cerrno>
#include <atomic>
#include <cstdlib>
#include <iterator>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "study/parallel_evaluation.hpp"
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

// The best `top` texts seen so far, under a lock: a new one enters when it beats the worst kept.
class BestKept {
 public:
  explicit BestKept(size_t top) : top_(top) {}
  void offer(Key key, std::string text) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (best_.size() == top_ && !(key < std::prev(best_.end())->first)) return;
    best_.emplace(std::move(key), std::move(text));
    if (best_.size() > top_) best_.erase(std::prev(best_.end()));
  }
  std::vector<std::string> in_order() {
    std::vector<std::string> texts;
    for (auto& entry : best_) texts.push_back(std::move(entry.second));
    return texts;
  }

 private:
  size_t top_;
  std::mutex mutex_;
  std::multimap<Key, std::string> best_;  // keys are unique (their positions are)
};

// The directory for the texts: TMPDIR, as other programs use it, or /tmp.
std::string temporary_directory() {
  const char* dir = std::getenv("TMPDIR");
  return dir && *dir ? dir : "/tmp";
}

// A file in `directory` that no other process sees and that goes when it is closed (or the
// process ends): unlinked as soon as it is open.
std::FILE* anonymous_file(const std::string& directory) {
  std::string path = directory + "/railmodal-ranking-XXXXXX";
  const int fd = mkstemp(path.data());
  if (fd < 0) return nullptr;
  unlink(path.c_str());
  std::FILE* file = fdopen(fd, "w+b");
  if (!file) close(fd);
  return file;
}

}  // namespace

StreamedRanking::StreamedRanking(const Study& study, const EvaluationOptions& options, size_t top, const Render& render) {
  if (options.shards != 1)
    throw std::invalid_argument("a streamed ranking ranks the whole study: shards must be 1, not " +
                                std::to_string(options.shards));
  const Ranking& ranking = study.ranking;
  const size_t stride = 1 + (ranking.objective.empty() ? 0 : ranking.weighted ? 1 : ranking.objective.size());
  std::vector<double> keys;  // top == 0: `stride` values a variant, by position
  BestKept best(top);
  std::mutex mutex;  // the spill file, the mode names
  std::set<std::string> modes;
  bool evaluated = false;
  std::atomic<size_t> feasible{0};
  unsigned long long spilled = 0;
  bool spill_failed = false;  // a full disk, say: thrown once the threads have stopped
  if (top == 0) {
    spill_.reset(anonymous_file(temporary_directory()));
    if (!spill_)
      throw std::system_error(errno, std::generic_category(),
                              "the ranking of a whole study keeps its rows in a temporary file, and none could be "
                              "opened in " + temporary_directory() +
                              " (set TMPDIR to a writable directory, or keep the best K only with --top K)");
  }
  study::evaluate_each(
      study, options,
      [&](size_t count) {
        size_ = count;
        if (top == 0) keys.resize(count * stride), offsets_.resize(count), lengths_.resize(count);
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
        if (top > 0) return best.offer({std::move(key), k}, std::move(text));
        std::copy(key.begin(), key.end(), keys.begin() + static_cast<std::ptrdiff_t>(k * stride));
        const std::lock_guard<std::mutex> lock(mutex);
        spill_failed = spill_failed || std::fwrite(text.data(), 1, text.size(), spill_.get()) != text.size();
        offsets_[k] = spilled;
        lengths_[k] = static_cast<unsigned>(text.size());
        spilled += text.size();
      });
  // A full disk shows at the write or only at the flush: both before a byte of the output.
  if (!spill_failed && top == 0) spill_failed = std::fflush(spill_.get()) != 0 || std::ferror(spill_.get()) != 0;
  if (spill_failed)
    throw std::system_error(errno ? errno : EIO, std::generic_category(),
                            "the ranking of a whole study could not write its temporary file in " +
                                temporary_directory() + " (free space there, set TMPDIR, or use --top K)");
  check_mode_names(study, modes, evaluated);
  feasible_ = feasible;
  if (top > 0) {
    kept_ = best.in_order();
    for (size_t i = 0; i < kept_.size(); ++i) order_.push_back(i);
    return;
  }
  order_.resize(size_);
  for (size_t i = 0; i < size_; ++i) order_[i] = i;
  const auto key_of = [&](size_t k) { return keys.begin() + static_cast<std::ptrdiff_t>(k * stride); };
  std::sort(order_.begin(), order_.end(), [&](size_t a, size_t b) {
    const bool less = std::lexicographical_compare(key_of(a), key_of(a) + stride, key_of(b), key_of(b) + stride);
    const bool greater = std::lexicographical_compare(key_of(b), key_of(b) + stride, key_of(a), key_of(a) + stride);
    return less || (!greater && a < b);
  });
}

std::string StreamedRanking::text(size_t rank) const {
  if (rank < 1 || rank > order_.size()) throw std::out_of_range("a streamed ranking has no rank " + std::to_string(rank));
  const size_t k = order_[rank - 1];
  if (!spill_) return kept_[k];
  std::string text(lengths_[k], '\0');
  if (fseeko(spill_.get(), static_cast<off_t>(offsets_[k]), SEEK_SET) != 0 ||
      std::fread(text.data(), 1, text.size(), spill_.get()) != text.size())
    throw std::system_error(errno ? errno : EIO, std::generic_category(),
                            "the ranking of a whole study could not read back its temporary file");
  return text;
}

}  // namespace railmodal::study
