// The sinks of the simulations' samples that the library keeps for itself: the recorder
// behind the functions that return whole histories, and a fan-out to several sinks.
#include <cstdint>
#ifdef __linux__
#include <sys/mman.h>
#endif

#include "simulate/history_summary.hpp"

namespace railmodal::simulate {
namespace {

// Asks the kernel to back a large output array with 2 MB pages, as numpy does for every array
// of 4 MB or more: a million steps of 15 DOFs is 240 MB of output, whose first touch with
// 4 kB pages is 60 000 page faults; with huge pages it is 120. Under a hypervisor that
// shadows guest page tables a fault costs ~17 µs, so this took a million-step run from 1.4 s
// to 0.5 s; on bare metal it saves less. Only advice: it changes no result, and does nothing
// where unsupported.
void advise_huge_pages(Eigen::MatrixXd* array) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
  const auto begin = reinterpret_cast<std::uintptr_t>(array->data());
  const std::uintptr_t end = begin + static_cast<std::uintptr_t>(array->size()) * sizeof(double);
  const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1), last = end & ~(kHuge - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)array;
#endif
}

}  // namespace

void HistoryRecorder::begin(const std::vector<std::string>& labels, Eigen::Index samples) {
  history_->labels = labels;
  history_->time.resize(samples);
  history_->displacement.resize(samples, static_cast<Eigen::Index>(labels.size()));
  history_->velocity.resize(samples, static_cast<Eigen::Index>(labels.size()));
  advise_huge_pages(&history_->displacement);
  advise_huge_pages(&history_->velocity);
  next_ = 0;
}

void HistoryRecorder::write(const Eigen::Ref<const Eigen::VectorXd>& time,
                            const Eigen::Ref<const Eigen::MatrixXd>& displacement,
                            const Eigen::Ref<const Eigen::MatrixXd>& velocity) {
  const Eigen::Index count = time.size();
  history_->time.segment(next_, count) = time;
  history_->displacement.middleRows(next_, count) = displacement;
  history_->velocity.middleRows(next_, count) = velocity;
  next_ += count;
}

void HistoryFanOut::begin(const std::vector<std::string>& labels, Eigen::Index samples) {
  for (HistorySink* sink : sinks_) sink->begin(labels, samples);
}

void HistoryFanOut::write(const Eigen::Ref<const Eigen::VectorXd>& time,
                          const Eigen::Ref<const Eigen::MatrixXd>& displacement,
                          const Eigen::Ref<const Eigen::MatrixXd>& velocity) {
  for (HistorySink* sink : sinks_) sink->write(time, displacement, velocity);
}

}  // namespace railmodal::simulate
