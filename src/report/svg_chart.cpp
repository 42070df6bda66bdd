#include "report/svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

namespace railmodal::report {

namespace {

const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};

const char* colour_of(const Chart& chart, size_t k) {
  constexpr size_t n = sizeof(kColours) / sizeof(kColours[0]);
  const int chosen = chart.series[k].colour;
  return kColours[(chosen >= 0 ? static_cast<size_t>(chosen) : k) % n];
}

std::string number(double v) {
  std::ostringstream out;
  out << std::setprecision(4) << v;
  return out.str();
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
    for (double x : s.x) x0 = std::min(x0, x), x1 = std::max(x1, x);
  if (!(x1 > x0)) x0 -= 1.0, x1 += 1.0;
  return {x0, x1};
}

// The y range: the chart's, or that of the finite data and horizontal lines, from 0 with 5 %
// headroom, or in whole decades (at most eight) on a log axis.
std::pair<double, double> y_range(const Chart& chart) {
  double y0 = chart.y_min, y1 = chart.y_max;
  if (y1 > y0) return {y0, y1};
  y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
  for (const auto& s : chart.series)
    for (double y : s.y)
      if (std::isfinite(y) && (!chart.log_y || y > 0.0)) y0 = std::min(y0, y), y1 = std::max(y1, y);
  for (const auto& l : chart.lines)
    if (!l.vertical) y0 = std::min(y0, l.value), y1 = std::max(y1, l.value);
  if (!std::isfinite(y0)) y0 = chart.log_y ? 1e-6 : 0.0, y1 = chart.log_y ? 1.0 : 1.0;
  if (chart.log_y) {
    y0 = std::pow(10.0, std::floor(std::log10(y0)));
    y1 = std::pow(10.0, std::ceil(std::log10(y1)));
    if (y1 / y0 > 1e8) y0 = y1 / 1e8;  // keep eight decades: deep antiresonances would flatten the rest
  } else {
    if (y0 > 0.0) y0 = 0.0;
    y1 += 0.05 * (y1 - y0);
  }
  if (!(y1 > y0)) y1 = y0 + 1.0;
  return {y0, y1};
}

// The plot area inside the margins (axis labels left, line labels and legend room right), and
// the map from data to it.
struct Plot {
  double left = 78, right = 250, top = 34, bottom = 48;
  double width, height;  // of the plot area
  double x0, x1, y0, y1;
  bool log_y;

  explicit Plot(const Chart& chart) : log_y(chart.log_y) {
    width = chart.width - left - right;
    height = chart.height - top - bottom;
    std::tie(x0, x1) = x_range(chart);
    std::tie(y0, y1) = y_range(chart);
  }
  double X(double x) const { return left + (x - x0) / (x1 - x0) * width; }
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
  for (double t : linear_ticks(p.x0, p.x1)) {
    s << "<line x1=\"" << p.X(t) << "\" y1=\"" << p.top << "\" x2=\"" << p.X(t) << "\" y2=\"" << p.top + p.height
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << p.X(t) << "\" y=\"" << p.top + p.height + 16
      << "\" text-anchor=\"middle\">" << number(t) << "</text>\n";
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
      << number(t) << "</text>\n";
  const double H = chart.height;
  s << "<text x=\"" << p.left + p.width / 2 << "\" y=\"" << H - 10 << "\" text-anchor=\"middle\">"
    << html_escape(chart.x_label) << "</text>\n";
  s << "<text transform=\"translate(16," << p.top + p.height / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << html_escape(chart.y_label) << "</text>\n";
}

void write_reference_lines(std::ostream& s, const Chart& chart, const Plot& p) {
  for (const auto& l : chart.lines) {
    if (l.vertical)
      s << "<line x1=\"" << p.X(l.value) << "\" y1=\"" << p.top << "\" x2=\"" << p.X(l.value) << "\" y2=\""
        << p.top + p.height;
    else
      s << "<line x1=\"" << p.left << "\" y1=\"" << p.Y(l.value) << "\" x2=\"" << p.left + p.width << "\" y2=\""
        << p.Y(l.value);
    s << "\" stroke=\"#888\" stroke-dasharray=\"2,3\"/>\n";
  }
}

// One series: circles, or polylines broken where a value is missing (or not positive on a log axis).
void write_series(std::ostream& s, const Chart& chart, size_t k, const Plot& p) {
  const auto& series = chart.series[k];
  const char* colour = colour_of(chart, k);
  if (series.markers_only) {
    for (size_t i = 0; i < series.x.size(); ++i)
      if (std::isfinite(series.y[i]))
        s << "<circle cx=\"" << p.X(series.x[i]) << "\" cy=\"" << p.Y(series.y[i])
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
  for (size_t i = 0; i < series.x.size(); ++i) {
    if (!std::isfinite(series.y[i]) || (chart.log_y && !(series.y[i] > 0.0))) {
      flush();
      continue;
    }
    std::ostringstream point;
    point << std::fixed << std::setprecision(1) << p.X(series.x[i]) << "," << p.Y(series.y[i]) << " ";
    points += point.str();
  }
  flush();
}

// Labels of horizontal lines at the right edge, of vertical lines above the plot, each pushed
// apart where lines lie closer than a text line (a label's width).
void write_line_labels(std::ostream& s, const Chart& chart, const Plot& p) {
  std::vector<std::pair<double, std::string>> labels;
  for (const auto& l : chart.lines)
    if (!l.vertical && !l.label.empty() && l.value >= p.y0 && l.value <= p.y1)
      labels.push_back({p.Y(l.value) + 4, l.label});
  std::sort(labels.begin(), labels.end());
  for (size_t k = 1; k < labels.size(); ++k) labels[k].first = std::max(labels[k].first, labels[k - 1].first + 12);
  for (const auto& [y, text] : labels)
    s << "<text x=\"" << p.left + p.width + 6 << "\" y=\"" << y << "\" fill=\"#555\" font-size=\"11\">"
      << html_escape(text) << "</text>\n";
  std::vector<std::pair<double, std::string>> tops;
  for (const auto& l : chart.lines)
    if (l.vertical && !l.label.empty() && l.value >= p.x0 && l.value <= p.x1) tops.push_back({p.X(l.value), l.label});
  std::sort(tops.begin(), tops.end());
  for (size_t k = 1; k < tops.size(); ++k)
    tops[k].first = std::max(tops[k].first, tops[k - 1].first + 3 + 6.2 * static_cast<double>(tops[k - 1].second.size()));
  for (const auto& [x, text] : tops)
    s << "<text x=\"" << x << "\" y=\"" << p.top - 4 << "\" fill=\"#555\" font-size=\"10\">" << html_escape(text)
      << "</text>\n";
}

// Legend in the plot's top-left corner, on a white card.
void write_legend(std::ostream& s, const Chart& chart, const Plot& p) {
  std::vector<size_t> named;
  for (size_t k = 0; k < chart.series.size(); ++k)
    if (!chart.series[k].label.empty()) named.push_back(k);
  if (named.empty()) return;
  size_t longest = 0;
  for (size_t k : named) longest = std::max(longest, chart.series[k].label.size());
  s << "<rect x=\"" << p.left + 8 << "\" y=\"" << p.top + 8 << "\" width=\"" << 40 + 6.2 * longest << "\" height=\""
    << 16 * named.size() + 8 << "\" fill=\"#fff\" fill-opacity=\"0.9\" stroke=\"#ccc\"/>\n";
  double ly = p.top + 20;
  for (size_t k : named) {
    const char* colour = colour_of(chart, k);
    if (chart.series[k].markers_only)
      s << "<circle cx=\"" << p.left + 24 << "\" cy=\"" << ly << "\" r=\"4\" fill=\"none\" stroke=\"" << colour
        << "\" stroke-width=\"2\"/>";
    else
      s << "<line x1=\"" << p.left + 14 << "\" y1=\"" << ly << "\" x2=\"" << p.left + 34 << "\" y2=\"" << ly
        << "\" stroke=\"" << colour << "\" stroke-width=\"2\""
        << (chart.series[k].dashed ? " stroke-dasharray=\"6,4\"" : "") << "/>";
    s << "<text x=\"" << p.left + 40 << "\" y=\"" << ly + 4 << "\" font-size=\"11\">"
      << html_escape(chart.series[k].label) << "</text>\n";
    ly += 16;
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
  const double W = chart.width, H = chart.height;
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s << "<text x=\"" << p.left << "\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << html_escape(chart.title)
    << "</text>\n";
  s << "<rect x=\"" << p.left << "\" y=\"" << p.top << "\" width=\"" << p.width << "\" height=\"" << p.height
    << "\" fill=\"#fff\" stroke=\"#444\"/>\n";
  write_axes(s, chart, p);
  s << "<clipPath id=\"plot-" << chart.id << "\"><rect x=\"" << p.left << "\" y=\"" << p.top << "\" width=\""
    << p.width << "\" height=\"" << p.height << "\"/></clipPath>\n<g clip-path=\"url(#plot-" << chart.id << ")\">\n";
  write_reference_lines(s, chart, p);
  for (size_t k = 0; k < chart.series.size(); ++k) write_series(s, chart, k, p);
  s << "</g>\n";
  write_line_labels(s, chart, p);
  write_legend(s, chart, p);
  s << "</svg>\n";
  return s.str();
}

}  // namespace railmodal::report
