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

/// A metric as docs/studies.md describes it, for headings a user reads: "period of body
/// bounce", "lowest critical speed", "largest dynamic deflection / permissible" (the metric's
/// name, "period:body bounce", stays in CSV and JSON, where programs read it).
std::string title(const std::string& metric);
/// title and the display unit: "period of body bounce (s)".
std::string heading(const std::string& metric);

/// A value with its display unit, "80 mm", "0.47", or "unbounded" / "none" for +∞.
std::string shown(const std::string& metric, double si);

}  // namespace railmodal::study
