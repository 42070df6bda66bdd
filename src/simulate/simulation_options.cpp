// The rules a SimulationOptions keeps on either path, and what every history's summary checks.
#include <cmath>
#include <limits>
#include <string>

#include "railmodal/simulation.hpp"
#include "require_valid.hpp"
#include "simulate/history_summary.hpp"

namespace railmodal {

bool SimulationOptions::is_valid(std::string* why) const {
  if (!(duration > 0.0) || !(time_step > 0.0) || !std::isfinite(duration))
    return invalid(why, "duration and time step must be positive");
  if (!(tolerance > 0.0) || !(event_tolerance > 0.0))
    return invalid(why, "tolerance and event tolerance must be positive");
  if (final_speed < 0.0 || !std::isfinite(final_speed))
    return invalid(why, "a final speed must be positive, and needs sources to run over");
  return true;
}

double resolvable_event_tolerance(double duration) { return std::numeric_limits<double>::epsilon() * duration; }

namespace simulate {

void summarise_history(TimeHistory* history, Eigen::Index samples, bool finite, AnalysisSummary summary,
                       std::string analysis, std::string method) {
  summary.analysis = std::move(analysis);
  summary.method = std::move(method);
  summary.checks.push_back({"samples that are not finite", finite ? 0.0 : 1.0, 0.0, finite});
  summary.checks.push_back({"samples", static_cast<double>(samples), std::numeric_limits<double>::infinity(), true});
  history->summary = std::move(summary);
}

}  // namespace simulate
}  // namespace railmodal
