// What a study can rank by: metric names, their physical quantity (to read limits with
// units) and the unit reports show them in.
#pragma once

#include <string>

#include "input/units.hpp"

namespace railmodal::study {

/// The quantity a metric's values and limits have (after canonical_metric).
input::Quantity metric_quantity(const std::string& metric);

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
