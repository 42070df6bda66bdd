// The summary both simulation paths give their history, and the sinks the library keeps for itself.
#pragma once

#include <string>
#include <utility>

#include "railmodal/simulation.hpp"

namespace railmodal::simulate {

/// Moves `summary` (its stages timed) into history->summary with the analysis, the method and
/// the checks every history gets: its samples are finite, and how many there are.
void summarise_history(TimeHistory* history, Eigen::Index samples, bool finite, AnalysisSummary summary,
                       std::string analysis, std::string method);

/// A sink that keeps every sample in a TimeHistory: what the simulations return when given no
/// sink of their own.
class HistoryRecorder final : public HistorySink {
 public:
  explicit HistoryRecorder(TimeHistory* history) : history_(history) {}
  void begin(const std::vector<std::string>& labels, Eigen::Index samples) override;
  void write(const Eigen::Ref<const Eigen::VectorXd>& time, const Eigen::Ref<const Eigen::MatrixXd>& displacement,
             const Eigen::Ref<const Eigen::MatrixXd>& velocity) override;

 private:
  TimeHistory* history_;
  Eigen::Index next_ = 0;
};

/// The history that `simulate(sink)` returns with every sample it gave `sink` kept in it: what
/// the simulations that take no sink return.
template <class Simulate>
TimeHistory recorded(Simulate&& simulate) {
  TimeHistory samples;
  HistoryRecorder recorder(&samples);
  TimeHistory result = simulate(static_cast<HistorySink&>(recorder));
  result.time = std::move(samples.time);
  result.displacement = std::move(samples.displacement);
  result.velocity = std::move(samples.velocity);
  return result;
}

/// Passes every block to each of `sinks` in turn.
class HistoryFanOut final : public HistorySink {
 public:
  explicit HistoryFanOut(std::vector<HistorySink*> sinks) : sinks_(std::move(sinks)) {}
  void begin(const std::vector<std::string>& labels, Eigen::Index samples) override;
  void write(const Eigen::Ref<const Eigen::VectorXd>& time, const Eigen::Ref<const Eigen::MatrixXd>& displacement,
             const Eigen::Ref<const Eigen::MatrixXd>& velocity) override;

 private:
  std::vector<HistorySink*> sinks_;
};

}  // namespace railmodal::simulate
