// How reports show a study's metrics: the unit of each (railmodal::metric_unit gives the SI
// one) and its values.
#pragma once

#include <string>

namespace railmodal::study {

/// The unit a report shows a metric in and the factor from SI: km/h, mm, s, ...
struct DisplayUnit {
  const char* unit;
  double per_si;
};
DisplayUnit display_unit(const std::string& metric);

/// Whether +∞ of this metric is an unbounded response (peaks, dynamic deflections) rather
/// than "none in range" (critical speeds).
bool infinite_is_unbounded(const std::string& metric);

/// A value with its display unit, "80 mm", "0.47", or "unbounded" / "none" for +∞.
std::string shown(const std::string& metric, double si);

}  // namespace railmodal::study
