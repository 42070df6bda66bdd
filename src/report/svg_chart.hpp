// A small line chart as inline SVG: axes with ticks, polylines, markers, reference lines.
// Shared by the HTML reports; no scripts, no external files. The SVG scales to the width of
// the page (a viewBox, width 100 %); the legend sits under the plot area, never over data;
// labels at the plot's edges are spread apart so that none overlaps another.
#pragma once

#include <string>
#include <vector>

namespace railmodal::report {

struct ChartSeries {
  std::string label;
  std::vector<double> x, y;  ///< NaN in y breaks the line
  bool dashed = false;
  bool markers_only = false;  ///< draw circles at the points instead of a line
  /// Index into the palette (12 colours: kChartColours); −1: the series' own position among the
  /// first 8 (a source's harmonics share one).
  int colour = -1;
  /// x where the series grows without limit (an undamped resonance): marked by a triangle at the
  /// top of the plot, and the automatic y range leaves out the points within 5 % of it.
  std::vector<double> unbounded_x;
  /// Per point, in [0, 1]: with markers_only, each point is a dot filled by its shade on a
  /// sequential scale (dark blue, 0, to yellow, 1) instead of the series' colour, which then
  /// only edges it; Chart::shade_key says what the shade stands for. Empty: no shading.
  std::vector<double> shade;
};

/// The palette's size, and its last two entries: a dark and a light grey, for a distinction
/// that is not one of a report's series (feasible or not).
constexpr int kChartColours = 12, kDarkGrey = 10, kLightGrey = 11;

struct ReferenceLine {
  std::string label;  ///< short, drawn at the line (right of the plot, or above it for a vertical line)
  double value = 0.0;
  bool vertical = false;  ///< x = value; otherwise y = value
  std::string key;        ///< what the label stands for, listed in the legend ("label  key"); "": not listed
  /// Drawn over the series, solid and dark, instead of dotted grey under them: a level that a
  /// dense trace would hide (a P95 over an acceleration history).
  bool over_data = false;
};

struct Chart {
  std::string id;  ///< unique within the page (names the plot's clip path); letters, digits, '-'
  std::string title, x_label, y_label;  ///< axis labels carry one unit each: "speed (km/h)"
  std::vector<ChartSeries> series;
  std::vector<ReferenceLine> lines;
  /// What the shades of the series stand for, as the legend says it beside a bar of the scale:
  /// "speed from 10 km/h (dark) to 500 km/h (light)". "": no scale in the legend.
  std::string shade_key;
  bool log_y = false;
  /// A logarithmic x axis (spectra against frequency): whole decades from the data's positive
  /// x unless x_min and x_max are given; points at x ≤ 0 are left out.
  bool log_x = false;
  double x_min = 0.0, x_max = 0.0;  ///< equal: from the data
  double y_min = 0.0, y_max = 0.0;  ///< equal: from the data
  int width = 1000, height = 400;   ///< of the viewBox, without the legend (which adds its rows)
};

std::string svg_chart(const Chart& chart);

/// Escapes &, <, > and quotes for HTML and SVG text.
std::string html_escape(const std::string& text);

}  // namespace railmodal::report
