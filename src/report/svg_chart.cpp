#include "report/svg_chart.hpp"
#include "report/text_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <tuple>
#include <utility>

namespace railmodal::report {

namespace {

// The first kAutomaticColours go round for series without a colour of their own; the rest only
// when a report chooses them (ChartSeries::colour), so that a colour can mean one thing across a
// report's charts: olive and grey, then a dark and a light grey.
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
                                "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f", "#333333", "#aaaaaa"};
constexpr size_t kAutomaticColours = 8;

// Within this fraction of an unbounded x the response of an undamped mode is at least
// 1/(1 − 0.95²) ≈ 10 times its quasi-static value: such points only measure how close the
// grid came to the resonance, and would set the axis to an arbitrary height.
constexpr double kNearUnbounded = 0.05;

constexpr double kLegendRow = 18;  // height of a legend row

const char* colour_of(const Chart& chart, size_t k) {
  constexpr size_t n = sizeof(kColours) / sizeof(kColours[0]);
  const int chosen = chart.series[k].colour;
  return chosen >= 0 ? kColours[static_cast<size_t>(chosen) % n] : kColours[k % kAutomaticColours];
}

// A sequential scale for ChartSeries::shade, from dark blue through teal and green to yellow
// (the end points and midpoints of matplotlib's viridis, interpolated linearly in sRGB): its
// lightness rises monotonically, so the order of the shades reads without the colours.
std::string shade_colour(double t) {
  static const double stops[][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
  const int k = std::min(static_cast<int>(t), 3);
  char text[8];
  int rgb[3];
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<int>(std::lround(stops[k][c] + (t - k) * (stops[k + 1][c] - stops[k][c])));
  std::snprintf(text, sizeof text, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return text;
}

// The width of `text` in the chart's sans-serif at `font_size`: 0.6 em a character (UTF-8
// continuation bytes take none), a little more than the average glyph, so estimates err wide.
double text_width(const std::string& text, double font_size) {
  const auto characters = std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; });
  return 0.6 * font_size * static_cast<double>(characters);
}

// Tick values at 1, 2, 5 × 10ⁿ covering [lo, hi].
std::vector<double> linear_ticks(double lo, double hi) {
  const double span = hi - lo;
  const double raw = span / 6.0;
  const double base = std::pow(10.0, std::floor(std::log10(raw)));
  double step = base;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * base) {
      step = m * base;
      break;
    }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * span; t += step) ticks.push_back(std::abs(t) < 1e-12 * span ? 0.0 : t);
  return ticks;
}

// The x range: the chart's, or the data's (widened by 1 each way where it is a point).
std::pair<double, double> x_range(const Chart& chart) {
  double x0 = chart.x_min, x1 = chart.x_max;
  if (x1 > x0) return {x0, x1};
  x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
  for (const auto& s : chart.series)
    for (double x : s.x)
      if (!chart.log_x || x > 0.0) x0 = std::min(x0, x), x1 = std::max(x1, x);
  if (chart.log_x) {
    if (!std::isfinite(x0)) return {1.0, 10.0};
    x0 = std::pow(10.0, std::floor(std::log10(x0) + 1e-9));
    x1 = std::pow(10.0, std::ceil(std::log10(x1) - 1e-9));
    if (!(x1 > x0)) x1 = 10.0 * x0;
    return {x0, x1};
  }
  if (!(x1 > x0)) x0 -= 1.0, x1 += 1.0;
  return {x0, x1};
}

bool near_unbounded(const ChartSeries& s, double x) {
  return std::any_of(s.unbounded_x.begin(), s.unbounded_x.end(),
                     [x](double u) { return std::abs(x - u) <= kNearUnbounded * std::abs(u); });
}

// The y range: the chart's, or that of the finite data (away from unbounded points) and
// horizontal lines, from 0 with 5 % headroom, or in whole decades (at most eight) on a log axis.
std::pair<double, double> y_range(const Chart& chart) {
  double y0 = chart.y_min, y1 = chart.y_max;
  if (y1 > y0) return {y0, y1};
  y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
  for (const auto& s : chart.series)
    for (size_t i = 0; i < s.y.size(); ++i)
      if (std::isfinite(s.y[i]) && (!chart.log_y || s.y[i] > 0.0) && !near_unbounded(s, s.x[i]))
        y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
  for (const auto& l : chart.lines)
    if (!l.vertical) y0 = std::min(y0, l.value), y1 = std::max(y1, l.value);
  if (!std::isfinite(y0)) y0 = chart.log_y ? 1e-6 : 0.0, y1 = chart.log_y ? 1.0 : 1.0;
  if (chart.log_y) {
    y0 = std::pow(10.0, std::floor(std::log10(y0)));
    y1 = std::pow(10.0, std::ceil(std::log10(y1)));
    if (y1 / y0 > 1e8) y0 = y1 / 1e8;  // keep eight decades: deep antiresonances would flatten the rest
  } else {
    const double margin = 0.05 * (std::max(y1, 0.0) - std::min(y0, 0.0));  // no curve on the frame
    y0 = y0 > 0.0 ? 0.0 : y0 - margin;
    y1 += margin;
  }
  if (!(y1 > y0)) y1 = y0 + 1.0;
  return {y0, y1};
}

// One entry of the legend under the plot: a swatch and its text.
struct LegendEntry {
  enum class Swatch { line, dashed, circle, reference, unbounded, shade } swatch;
  const char* colour;
  std::string text;
};

std::vector<LegendEntry> legend_entries(const Chart& chart) {
  std::vector<LegendEntry> entries;
  bool unbounded = false;
  for (size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& s = chart.series[k];
    unbounded = unbounded || !s.unbounded_x.empty();
    if (s.label.empty()) continue;
    const auto swatch = s.markers_only ? LegendEntry::Swatch::circle
                        : s.dashed     ? LegendEntry::Swatch::dashed
                                       : LegendEntry::Swatch::line;
    entries.push_back({swatch, colour_of(chart, k), s.label});
  }
  if (unbounded)
    entries.push_back(
        {LegendEntry::Swatch::unbounded, "#444", "unbounded: an undamped resonance, the curve leaves the plot"});
  for (const auto& l : chart.lines)
    if (!l.key.empty())
      entries.push_back({l.over_data ? LegendEntry::Swatch::dashed : LegendEntry::Swatch::reference,
                         l.over_data ? "#111" : "#888", l.label + "  " + l.key});
  if (!chart.shade_key.empty()) entries.push_back({LegendEntry::Swatch::shade, "#444", chart.shade_key});
  return entries;
}

constexpr double kLegendFont = 11;
double entry_width(const LegendEntry& e) { return 34 + text_width(e.text, kLegendFont) + 16; }

// Rows of the legend (each a list of entries) filling `width` left to right.
std::vector<std::vector<size_t>> flow_legend(const std::vector<LegendEntry>& entries, double width) {
  std::vector<std::vector<size_t>> rows;
  double used = width;
  for (size_t k = 0; k < entries.size(); ++k) {
    if (rows.empty() || used + entry_width(entries[k]) > width) rows.emplace_back(), used = 0;
    rows.back().push_back(k);
    used += entry_width(entries[k]);
  }
  return rows;
}

// The plot area inside the margins (tick labels and axis labels left and below, line labels
// right and above, the legend below the x axis), and the map from data to it.
struct Plot {
  double left = 78, right = 20, top = 34, bottom = 48;
  double width, height;  // of the plot area
  double x0, x1, y0, y1;
  bool log_y, log_x;
  std::vector<LegendEntry> legend;
  std::vector<std::vector<size_t>> legend_rows;

  explicit Plot(const Chart& chart) : log_y(chart.log_y), log_x(chart.log_x), legend(legend_entries(chart)) {
    for (const auto& l : chart.lines) {
      if (!l.label.empty() && l.vertical) top = 50;  // room for the labels above the plot
      if (!l.label.empty() && !l.vertical) right = std::max(right, 20 + text_width(l.label, 11));
    }
    for (const auto& s : chart.series)
      if (!s.unbounded_x.empty()) top = 56;  // room for the marks and their words
    width = chart.width - left - right;
    height = chart.height - top - bottom;
    std::tie(x0, x1) = x_range(chart);
    std::tie(y0, y1) = y_range(chart);
    legend_rows = flow_legend(legend, width);
  }
  double legend_top() const { return top + height + bottom; }
  double legend_height() const { return legend_rows.empty() ? 0.0 : kLegendRow * legend_rows.size() + 8; }
  double X(double x) const {
    if (log_x) return left + (std::log10(std::max(x, x0)) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) * width;
    return left + (x - x0) / (x1 - x0) * width;
  }
  double Y(double y) const {
    if (log_y) {
      const double v = std::log10(std::max(y, y0));
      return top + height - (v - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) * height;
    }
    return top + height - (y - y0) / (y1 - y0) * height;
  }
};

// Ticks and grid, and the axis labels.
void write_axes(std::ostream& s, const Chart& chart, const Plot& p) {
  std::vector<double> xticks;
  if (chart.log_x) {
    for (double d = std::log10(p.x0); d <= std::log10(p.x1) + 1e-9; d += 1.0) xticks.push_back(std::pow(10.0, d));
  } else {
    xticks = linear_ticks(p.x0, p.x1);
  }
  for (double t : xticks) {
    s << "<line x1=\"" << p.X(t) << "\" y1=\"" << p.top << "\" x2=\"" << p.X(t) << "\" y2=\"" << p.top + p.height
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << p.X(t) << "\" y=\"" << p.top + p.height + 16
      << "\" text-anchor=\"middle\">" << significant(t, 4) << "</text>\n";
  }
  std::vector<double> yticks;
  if (chart.log_y) {
    for (double d = std::log10(p.y0); d <= std::log10(p.y1) + 1e-9; d += 1.0) yticks.push_back(std::pow(10.0, d));
  } else {
    yticks = linear_ticks(p.y0, p.y1);
  }
  for (double t : yticks)
    s << "<line x1=\"" << p.left << "\" y1=\"" << p.Y(t) << "\" x2=\"" << p.left + p.width << "\" y2=\"" << p.Y(t)
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << p.left - 6 << "\" y=\"" << p.Y(t) + 4 << "\" text-anchor=\"end\">"
      << significant(t, 4) << "</text>\n";
  s << "<text class=\"x-label\" x=\"" << p.left + p.width / 2 << "\" y=\"" << p.top + p.height + 38
    << "\" text-anchor=\"middle\">" << html_escape(chart.x_label) << "</text>\n";
  s << "<text class=\"y-label\" transform=\"translate(16," << p.top + p.height / 2
    << ") rotate(-90)\" text-anchor=\"middle\">" << html_escape(chart.y_label) << "</text>\n";
}

// The lines under the series (over_data false), or those over them (true).
void write_reference_lines(std::ostream& s, const Chart& chart, const Plot& p, bool over_data) {
  for (const auto& l : chart.lines) {
    if (l.over_data != over_data) continue;
    if (l.vertical)
      s << "<line x1=\"" << p.X(l.value) << "\" y1=\"" << p.top << "\" x2=\"" << p.X(l.value) << "\" y2=\""
        << p.top + p.height;
    else
      s << "<line x1=\"" << p.left << "\" y1=\"" << p.Y(l.value) << "\" x2=\"" << p.left + p.width << "\" y2=\""
        << p.Y(l.value);
    s << (over_data ? "\" stroke=\"#111\" stroke-width=\"2\" stroke-dasharray=\"6,4\"/>\n"
                    : "\" stroke=\"#888\" stroke-dasharray=\"2,3\"/>\n");
  }
}

// A polyline's points, "x,y " to a tenth of a unit of the viewBox, decimated: consecutive points
// in one column of the plot (a unit of the viewBox wide, about a pixel) are written as the
// column's first, lowest, highest and last point, in their order. The line then covers the same
// pixels, every peak and trough is kept (the highest and lowest point of its column), and a
// curve of 10⁴ speeds is not 10⁴ points of SVG (issue 19 item 3).
class ColumnDecimator {
 public:
  explicit ColumnDecimator(std::string& points) : points_(points) {}
  void add(double x, double y) {
    const double column = std::floor(x);
    if (!column_.empty() && column != std::floor(column_.front().first)) finish();
    column_.push_back({x, y});
  }
  // Writes the column's points (also before a break in the line).
  void finish() {
    if (column_.empty()) return;
    size_t low = 0, high = 0;
    for (size_t k = 1; k < column_.size(); ++k) {
      if (column_[k].second > column_[low].second) low = k;  // SVG's y runs down: lowest on the page
      if (column_[k].second < column_[high].second) high = k;
    }
    size_t kept[4] = {0, std::min(low, high), std::max(low, high), column_.size() - 1};
    for (size_t k = 0; k < 4; ++k)
      if (k == 0 || kept[k] != kept[k - 1]) write(column_[kept[k]]);
    column_.clear();
  }

 private:
  void write(const std::pair<double, double>& point) {
    char text[64];
    char* end = std::to_chars(text, text + 30, point.first, std::chars_format::fixed, 1).ptr;
    *end++ = ',';
    end = std::to_chars(end, text + 62, point.second, std::chars_format::fixed, 1).ptr;
    *end++ = ' ';
    points_.append(text, end);
  }

  std::string& points_;
  std::vector<std::pair<double, double>> column_;
};

// A coordinate written to the chart's stream as the stream writes it (std::fixed, one decimal:
// printf's %.1f, which to_chars with that precision writes too), at a fraction of the stream's
// cost: a study's HTML report draws markers by the thousand (18 a variant in the benchmark study).
struct Coordinate {
  double value;
};

std::ostream& operator<<(std::ostream& s, Coordinate c) {
  char text[330];  // %.1f of the largest double: 309 digits, the point and one
  const char* end = std::to_chars(text, text + sizeof text, c.value, std::chars_format::fixed, 1).ptr;
  return s.write(text, end - text);
}

// One series: circles, or polylines broken where a value is missing (or not positive on a log
// axis). Points beyond the plot are clipped by the plot's clip path.
void write_series(std::ostream& s, const Chart& chart, size_t k, const Plot& p) {
  const auto& series = chart.series[k];
  const char* colour = colour_of(chart, k);
  if (series.markers_only && !series.shade.empty()) {
    for (size_t i = 0; i < series.x.size(); ++i)
      if (std::isfinite(series.x[i]) && std::isfinite(series.y[i]))
        s << "<circle cx=\"" << Coordinate{p.X(series.x[i])} << "\" cy=\"" << Coordinate{p.Y(series.y[i])} << "\" r=\"3\" fill=\""
          << shade_colour(i < series.shade.size() ? series.shade[i] : 0.0) << "\" stroke=\"" << colour
          << "\" stroke-width=\"0.6\"/>\n";
    return;
  }
  if (series.markers_only) {
    for (size_t i = 0; i < series.x.size(); ++i)
      if (std::isfinite(series.y[i]))
        s << "<circle cx=\"" << Coordinate{p.X(series.x[i])} << "\" cy=\"" << Coordinate{p.Y(series.y[i])}
          << "\" r=\"4\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n";
    return;
  }
  std::string points;
  auto flush = [&] {
    if (!points.empty())
      s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.6\""
        << (series.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"" << points << "\"/>\n";
    points.clear();
  };
  ColumnDecimator column(points);
  for (size_t i = 0; i < series.x.size(); ++i) {
    if (!std::isfinite(series.y[i]) || (chart.log_y && !(series.y[i] > 0.0)) || (chart.log_x && !(series.x[i] > 0.0))) {
      column.finish();
      flush();
      continue;
    }
    column.add(p.X(series.x[i]), p.Y(series.y[i]));
  }
  column.finish();
  flush();
}

// Starts for intervals of lengths `size` as near their `wanted` starts as they can be within
// [lo, hi] with `gap` between neighbours, in the order of their wanted starts. Where they do not
// all fit they run on past hi rather than overlap.
std::vector<double> spread(const std::vector<double>& wanted, const std::vector<double>& size, double lo, double hi,
                           double gap) {
  std::vector<size_t> order(wanted.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return wanted[a] < wanted[b]; });
  std::vector<double> at(wanted.size());
  double end = lo - gap;
  for (size_t i : order) at[i] = std::max(wanted[i], end + gap), end = at[i] + size[i];
  double start = hi + gap;  // push back from hi where the last ones ran past it
  for (auto i = order.rbegin(); i != order.rend(); ++i)
    at[*i] = std::min(at[*i], start - gap - size[*i]), start = at[*i];
  end = lo - gap;  // and forward again from lo where that pushed the first ones before it
  for (size_t i : order) at[i] = std::max(at[i], end + gap), end = at[i] + size[i];
  return at;
}

// Over each unbounded x of each series, a triangle above the plot's top edge, where the curve
// leaves the plot, and the word "unbounded" above it where the words fit side by side (the
// legend explains the triangles either way).
void write_unbounded_marks(std::ostream& s, const Chart& chart, const Plot& p) {
  std::vector<double> marks;
  for (size_t k = 0; k < chart.series.size(); ++k)
    for (double u : chart.series[k].unbounded_x) {
      if (u < p.x0 || u > p.x1) continue;
      const double x = p.X(u);
      marks.push_back(x);
      s << "<path class=\"unbounded\" d=\"M" << x - 5 << "," << p.top - 2 << " L" << x + 5 << "," << p.top - 2 << " L"
        << x << "," << p.top - 11 << " Z\" fill=\"" << colour_of(chart, k) << "\"><title>unbounded at " << significant(u, 4)
        << "</title></path>\n";
    }
  // One word for each cluster of marks closer than a word's width (several designs at one speed).
  const double width = text_width("unbounded", 10);
  std::sort(marks.begin(), marks.end());
  std::vector<double> wanted;
  for (size_t k = 0, first = 0; k < marks.size(); ++k)
    if (k + 1 == marks.size() || marks[k + 1] - marks[first] > width)
      wanted.push_back((marks[first] + marks[k]) / 2 - width / 2), first = k + 1;
  // Words whose places would leave less than a word's gap between them read as one
  // ("unboundedunbounded", the audit of 2026-11-27): one word, centred on both, says it once.
  constexpr double kWordGap = 12;
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t k = 0; k + 1 < wanted.size(); ++k)
      if (wanted[k + 1] - wanted[k] < width + kWordGap) {
        wanted[k] = (wanted[k] + wanted[k + 1]) / 2;
        wanted.erase(wanted.begin() + static_cast<std::ptrdiff_t>(k) + 1);
        merged = true;
        break;
      }
  }
  if (wanted.empty() || (width + kWordGap) * static_cast<double>(wanted.size()) > p.width + 60) return;
  const std::vector<double> at =
      spread(wanted, std::vector<double>(wanted.size(), width), p.left - 30, chart.width - 4.0, kWordGap);
  for (double x : at)
    s << "<text class=\"mark-label\" x=\"" << x << "\" y=\"" << p.top - 14 << "\" fill=\"#555\" font-size=\"10\">"
      << "unbounded</text>\n";
}

// Labels of horizontal lines right of the plot, of vertical lines above it, spread apart so that
// none overlaps another, each joined to its line by a short leader.
void write_line_labels(std::ostream& s, const Chart& chart, const Plot& p) {
  std::vector<const ReferenceLine*> right, above;
  for (const auto& l : chart.lines) {
    if (l.label.empty()) continue;
    if (!l.vertical && l.value >= p.y0 && l.value <= p.y1) right.push_back(&l);
    if (l.vertical && l.value >= p.x0 && l.value <= p.x1) above.push_back(&l);
  }
  constexpr double kRow = 12;  // a label's height at font size 11
  std::vector<double> wanted, size;
  for (const auto* l : right) wanted.push_back(p.Y(l->value) - kRow / 2), size.push_back(kRow);
  std::vector<double> at = spread(wanted, size, p.top - 8, p.top + p.height + 8, 1);
  const double edge = p.left + p.width;
  for (size_t k = 0; k < right.size(); ++k)
    s << "<polyline class=\"leader\" fill=\"none\" stroke=\"#aaa\" points=\"" << edge << "," << p.Y(right[k]->value)
      << " " << edge + 6 << "," << at[k] + kRow / 2 << "\"/><text class=\"line-label\" x=\"" << edge + 8 << "\" y=\""
      << at[k] + kRow - 2 << "\" fill=\"#555\" font-size=\"11\">" << html_escape(right[k]->label) << "</text>\n";
  wanted.clear(), size.clear();
  for (const auto* l : above) {
    size.push_back(text_width(l->label, 10));
    wanted.push_back(p.X(l->value) - size.back() / 2);
  }
  at = spread(wanted, size, p.left - 30, chart.width - 4.0, 3);
  for (size_t k = 0; k < above.size(); ++k)
    s << "<polyline class=\"leader\" fill=\"none\" stroke=\"#aaa\" points=\"" << p.X(above[k]->value) << "," << p.top
      << " " << at[k] + size[k] / 2 << "," << p.top - 6 << "\"/><text class=\"line-label\" x=\"" << at[k] << "\" y=\""
      << p.top - 8 << "\" fill=\"#555\" font-size=\"10\">" << html_escape(above[k]->label) << "</text>\n";
}

void write_swatch(std::ostream& s, const LegendEntry& e, double x, double y) {
  using Swatch = LegendEntry::Swatch;
  switch (e.swatch) {
    case Swatch::circle:
      s << "<circle cx=\"" << x + 10 << "\" cy=\"" << y << "\" r=\"4\" fill=\"none\" stroke=\"" << e.colour
        << "\" stroke-width=\"2\"/>";
      break;
    case Swatch::shade:  // the scale, dark to light, in five steps
      for (int k = 0; k < 5; ++k)
        s << "<rect x=\"" << x + 4 * k << "\" y=\"" << y - 4 << "\" width=\"4\" height=\"8\" fill=\""
          << shade_colour(k / 4.0) << "\"/>";
      break;
    case Swatch::unbounded:
      s << "<path d=\"M" << x + 5 << "," << y + 4 << " L" << x + 15 << "," << y + 4 << " L" << x + 10 << "," << y - 5
        << " Z\" fill=\"" << e.colour << "\"/>";
      break;
    default:
      s << "<line x1=\"" << x << "\" y1=\"" << y << "\" x2=\"" << x + 20 << "\" y2=\"" << y << "\" stroke=\""
        << e.colour << "\" stroke-width=\"2\""
        << (e.swatch == Swatch::dashed      ? " stroke-dasharray=\"6,4\""
            : e.swatch == Swatch::reference ? " stroke-dasharray=\"2,3\""
                                            : "")
        << "/>";
  }
}

// The legend under the x axis, its entries in rows across the plot's width: outside the plot
// area, so it covers no curve, point or peak.
void write_legend(std::ostream& s, const Plot& p) {
  if (p.legend.empty()) return;
  const double top = p.legend_top();
  s << "<rect class=\"legend\" x=\"" << p.left << "\" y=\"" << top << "\" width=\"" << p.width << "\" height=\""
    << p.legend_height() << "\" fill=\"#fff\" stroke=\"#ccc\"/>\n";
  for (size_t r = 0; r < p.legend_rows.size(); ++r) {
    double x = p.left + 8;
    const double y = top + 4 + kLegendRow * (r + 0.5);
    for (size_t k : p.legend_rows[r]) {
      const LegendEntry& e = p.legend[k];
      write_swatch(s, e, x, y);
      s << "<text x=\"" << x + 26 << "\" y=\"" << y + 4 << "\" font-size=\"11\">" << html_escape(e.text) << "</text>\n";
      x += entry_width(e);
    }
  }
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string svg_chart(const Chart& chart) {
  const Plot p(chart);
  const double W = chart.width, H = p.legend_top() + p.legend_height() + (p.legend.empty() ? 0.0 : 6.0);
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << W << " " << H
    << "\" width=\"100%\" style=\"display:block;height:auto\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s << "<text x=\"" << p.left << "\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << html_escape(chart.title)
    << "</text>\n";
  s << "<rect class=\"plot\" x=\"" << p.left << "\" y=\"" << p.top << "\" width=\"" << p.width << "\" height=\""
    << p.height << "\" fill=\"#fff\" stroke=\"#444\"/>\n";
  write_axes(s, chart, p);
  s << "<clipPath id=\"plot-" << chart.id << "\"><rect x=\"" << p.left << "\" y=\"" << p.top << "\" width=\""
    << p.width << "\" height=\"" << p.height << "\"/></clipPath>\n<g clip-path=\"url(#plot-" << chart.id << ")\">\n";
  write_reference_lines(s, chart, p, false);
  for (size_t k = 0; k < chart.series.size(); ++k) write_series(s, chart, k, p);
  write_reference_lines(s, chart, p, true);
  s << "</g>\n";
  write_unbounded_marks(s, chart, p);
  write_line_labels(s, chart, p);
  write_legend(s, p);
  s << "</svg>\n";
  return s.str();
}

}  // namespace railmodal::report
