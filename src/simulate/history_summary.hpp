// The summary both simulation paths give their history.
#pragma once

#include <string>

#include "railmodal/simulation.hpp"

namespace railmodal::simulate {

/// Moves `summary` (its stages timed) into history->summary with the analysis, the method and
/// the checks every history gets: its samples are finite, and how many there are.
void summarise_history(TimeHistory* history, AnalysisSummary summary, std::string analysis, std::string method);

}  // namespace railmodal::simulate
