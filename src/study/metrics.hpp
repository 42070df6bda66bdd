// How reports show a study's metrics: the unit of each (railmodal::metric_unit gives the SI
// one) and its values.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal::study {

/// Whether the metric is one of the ride's (max_wz, max_nmv, rms_<quantity>:<output>).
bool names_ride(const std::string& metric);
/// The ride output a metric names ("rms_acceleration:<output>" → the output), or "".
std::string ride_output_of(const std::string& metric);
/// The unit (as railmodal::unit_of spells it: "m/s²", "m/s", "m", "N") of the ride outputs an
/// RMS metric (rms_acceleration:, rms_velocity:, rms_displacement:, rms_force:) may name, or "".
std::string rms_ride_unit(const std::string& metric);
/// The RMS metric's prefix for an output of that unit ("N" → "rms_force:"), or "".
std::string rms_metric_for(const std::string& ride_unit);

/// The unit a report shows a metric in and the factor from SI: km/h, mm, s, ...
struct DisplayUnit {
  const char* unit;
  double per_si;
};
DisplayUnit display_unit(const std::string& metric);

/// Whether +∞ of this metric is an unbounded response (peaks, dynamic deflections) rather
/// than "none in range" (critical speeds).
bool infinite_is_unbounded(const std::string& metric);

/// What a table cell writes for +∞ of the metric: "unbounded" (infinite_is_unbounded), "above
/// 500" for a hunting speed stable over the whole scan (its top in km/h, as `railmodal
/// stability` prints it), "none" for no critical speed in range.
std::string infinite_word(const std::string& metric);
/// infinite_word with the display unit where it has a number: "above 500 km/h".
std::string infinite_text(const std::string& metric);
/// The top of the speeds a study's hunting speed is scanned over, in km/h as text ("500").
std::string hunting_scan_top_kmh();

/// Whether the metric reads the scene's critical-speed study (critical speeds, peaks, dynamic
/// deflections): it needs a periodic source.
bool metric_reads_critical_speeds(const std::string& metric);

/// A metric as docs/studies.md describes it, for headings a user reads: "period of body
/// bounce", "lowest critical speed", "largest dynamic deflection / permissible" (the metric's
/// name, "period:body bounce", stays in CSV and JSON, where programs read it).
std::string title(const std::string& metric);
/// title and the display unit as table headings write it: "period of body bounce [s]".
std::string heading(const std::string& metric);
/// The display unit as table headings write it, " [s]", or "" for a ratio.
std::string unit_bracket(const std::string& metric);

/// The decimals a table shows the metric with, in its display unit: one step a reader can
/// act on, the same for every row so that a column's figures align at the point (km/h to 0.1,
/// periods to 1 ms, ratios to 0.001, Wz and N_MV to 0.01, ...). CSV and JSON keep every digit.
int table_decimals(const std::string& metric);

/// A figure in its display unit as a table prints it: `decimals` after the point (those of
/// table_decimals), or two significant digits for one too small to show two that way (a peak of
/// 0.004 m/s² is not "0.000"); from 1e9 on in scientific notation; never "-0.0". NaN and ±∞ as
/// std::to_chars writes them.
std::string table_figure(double shown, int decimals);

/// A value for people (the notes under a comparison's table, its document's sentences), as its
/// table column shows it, with the display unit: "79.3 km/h", "0.76"; "unbounded" or "none" for
/// +∞. One rule with the tables (user audit 2026-11-27c, F13: notes had 4 significant digits).
std::string shown_as_tabled(const std::string& metric, double si);

/// Two values of a metric for people (a variant against another, a value against its limit),
/// each as shown_as_tabled shows it but to as many more decimals as it takes for two values that
/// differ not to read the same ("89.97 km/h" against 90, not "90.0 km/h").
std::pair<std::string, std::string> shown_apart(const std::string& metric, double a_si, double b_si);

/// The display unit as a table heading writes it, " [s]", or " [–]" for a ratio or an index
/// (Wz, N_MV): every figure column says what it is in.
std::string table_unit_bracket(const std::string& metric);

/// A value with its display unit, "80 mm", "0.47", or "unbounded" / "none" for +∞, to
/// `digits` significant digits (6 for programs, 4 for people).
std::string shown(const std::string& metric, double si, int digits = 6);

/// How a result breaks the ranking's constraints, one text each (none when it keeps them).
/// For programs (CSV, JSON) with the metric's name and 6 significant digits, "critical_speed:body
/// bounce 79.3089 km/h < 90 km/h"; for people with its title, the value as the table shows it
/// (shown_apart from the limit) and the limit as given (6 significant digits), "critical speed of
/// body bounce 79.3 km/h < 90 km/h".
std::vector<std::string> violations(const VariantResult& r, const Ranking& ranking, bool for_people);

/// What a report calls the parameter `key` (as StudyParameter names it): the label the study
/// gives it in a sweep ("f"), or else the last part of its key path ("static_deflection").
/// Defined in src/load_study.cpp, which holds the study's plan.
std::string parameter_label(const Study& study, const std::string& key);

}  // namespace railmodal::study
