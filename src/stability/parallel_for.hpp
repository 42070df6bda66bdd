// Independent tasks over an index range on several threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace railmodal::stability {

/// The worker count for `threads` (0: the hardware's), never more than `tasks`, at least 1.
inline int worker_count(int threads, int tasks) {
  const int wanted = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  return std::max(1, std::min(wanted, tasks));
}

/// Calls task(i) for i = 0 … count−1 on `threads` workers. Each task writes only its own
/// slot, so the results do not depend on the thread count or the order tasks ran in; when
/// tasks throw, the exception of the lowest index is rethrown (again independent of threads).
template <class Task>
void parallel_for(int count, int threads, const Task& task) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(std::max(count, 0)));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        errors[static_cast<size_t>(i)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < worker_count(threads, count); ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace railmodal::stability
