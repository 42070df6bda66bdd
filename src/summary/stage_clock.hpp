// Times the stages of an analysis into its AnalysisSummary.
#pragma once

#include <chrono>
#include <string>
#include <utility>

#include "railmodal/summary.hpp"

namespace railmodal {

/// Starts timing on construction; each lap() ends the stage running since the last lap (or
/// construction) and appends it with its name. Stages are consecutive, so they never overlap.
class StageClock {
 public:
  explicit StageClock(AnalysisSummary* summary) : summary_(summary), start_(Clock::now()) {}
  void lap(std::string stage) {
    const Clock::time_point now = Clock::now();
    summary_->stages.push_back({std::move(stage), std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  using Clock = std::chrono::steady_clock;
  AnalysisSummary* summary_;
  Clock::time_point start_;
};

}  // namespace railmodal
