// The variants of a shard on several threads. Each result depends only on its variant and
// lands in its own slot, so the output is the same whatever the number of threads.
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "railmodal/study.hpp"

namespace railmodal {

std::vector<VariantResult> evaluate_study(const Study& study, const EvaluationOptions& options) {
  if (options.shards < 1 || options.shard < 1 || options.shard > options.shards)
    throw std::invalid_argument("shard must be K/N with 1 <= K <= N");
  std::vector<int> indices;
  for (int i = 0; i < static_cast<int>(study.variants.size()); ++i)
    if (in_shard(i, options.shard, options.shards)) {
      if (!study.variants[i].read)
        throw std::invalid_argument("variant " + std::to_string(i + 1) + " ('" + study.variants[i].name +
                                    "') was not read: load the study with this shard");
      indices.push_back(i);
    }
  std::vector<VariantResult> results(indices.size());
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, static_cast<int>(indices.size())));

  std::atomic<size_t> next{0};
  std::mutex progress_mutex;
  size_t done = 0;
  auto work = [&] {
    for (size_t k = next++; k < indices.size(); k = next++) {
      try {
        results[k] = evaluate_variant(study.variants[indices[k]], indices[k], study.deflection_rule);
      } catch (const std::exception& e) {  // evaluate_variant keeps design failures; this is a bug
        results[k].index = indices[k];
        results[k].name = study.variants[indices[k]].name;
        results[k].parameters = study.variants[indices[k]].parameters;
        results[k].failure = std::string("internal error: ") + e.what();
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
  return results;
}

}  // namespace railmodal
