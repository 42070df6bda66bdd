// A small line chart as inline SVG: axes with ticks, polylines, markers, reference lines.
// Shared by the HTML reports; no scripts, no external files.
#pragma once

#include <string>
#include <vector>

namespace railmodal::report {

struct ChartSeries {
  std::string label;
  std::vector<double> x, y;  ///< NaN in y breaks the line
  bool dashed = false;
  bool markers_only = false;  ///< draw circles at the points instead of a line
  int colour = -1;  ///< index into the palette; −1: the series' own position (a source's harmonics share one)
};

struct ReferenceLine {
  std::string label;
  double value = 0.0;
  bool vertical = false;  ///< x = value; otherwise y = value
};

struct Chart {
  std::string id;  ///< unique within the page (names the plot's clip path); letters, digits, '-'
  std::string title, x_label, y_label;
  std::vector<ChartSeries> series;
  std::vector<ReferenceLine> lines;
  bool log_y = false;
  double x_min = 0.0, x_max = 0.0;  ///< equal: from the data
  double y_min = 0.0, y_max = 0.0;  ///< equal: from the data
  int width = 760, height = 380;
};

std::string svg_chart(const Chart& chart);

/// Escapes &, <, > and quotes for HTML and SVG text.
std::string html_escape(const std::string& text);

}  // namespace railmodal::report
