// Times the stages of an analysis into its AnalysisSummary.
#pragma once

#include <chrono>
#include <string>

#include "railmodal/summary.hpp"

namespace railmodal {

/// Starts timing on construction; each lap() ends the stage running since the last lap (or
/// construction) and appends it with its name. Stages are consecutive, so they never overlap.
/// With a null summary (an out-parameter the caller did not pass) it reads no clock and builds
/// no strings: peak and deflection refinement run an analysis per golden-section step.
class StageClock {
 public:
  explicit StageClock(AnalysisSummary* summary)
      : summary_(summary), start_(summary ? Clock::now() : Clock::time_point{}) {
    if (summary_) summary_->stages.reserve(kStages);  // the laps of an analysis: one allocation, not three
  }
  void lap(const char* stage) {
    if (!summary_) return;
    const Clock::time_point now = Clock::now();
    summary_->stages.push_back({stage, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr size_t kStages = 8;  // room for the laps an analysis usually times
  AnalysisSummary* summary_;
  Clock::time_point start_;
};

}  // namespace railmodal
