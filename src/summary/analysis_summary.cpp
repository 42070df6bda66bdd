#include <cstdio>
#include <string>

#include "railmodal/summary.hpp"

namespace railmodal {

namespace {

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g s", s);
  return text;
}

}  // namespace

double AnalysisSummary::total_seconds() const {
  double total = 0.0;
  for (const StageTiming& s : stages) total += s.seconds;
  return total;
}

bool AnalysisSummary::passed() const {
  for (const Check& c : checks)
    if (!c.passed) return false;
  return true;
}

std::string AnalysisSummary::brief() const {
  int failed = 0;
  for (const Check& c : checks) failed += c.passed ? 0 : 1;
  std::string line = analysis + " by " + method + ": " + std::to_string(checks.size() - failed) + " of " +
                     std::to_string(checks.size()) + " checks passed; " + seconds(total_seconds());
  for (size_t i = 0; i < stages.size(); ++i)
    line += (i == 0 ? " (" : ", ") + stages[i].stage + " " + seconds(stages[i].seconds);
  return stages.empty() ? line : line + ")";
}

}  // namespace railmodal
