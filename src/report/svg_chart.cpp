#include "report/svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

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
  const double left = 78, right = 250, top = 34, bottom = 48;
  const double W = chart.width, H = chart.height;
  const double pw = W - left - right, ph = H - top - bottom;

  // Data ranges.
  double x0 = chart.x_min, x1 = chart.x_max, y0 = chart.y_min, y1 = chart.y_max;
  if (!(x1 > x0)) {
    x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    for (const auto& s : chart.series)
      for (double x : s.x) x0 = std::min(x0, x), x1 = std::max(x1, x);
    if (!(x1 > x0)) x0 -= 1.0, x1 += 1.0;
  }
  if (!(y1 > y0)) {
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
  }
  auto X = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double y) {
    if (chart.log_y) {
      const double v = std::log10(std::max(y, y0));
      return top + ph - (v - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) * ph;
    }
    return top + ph - (y - y0) / (y1 - y0) * ph;
  };

  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << html_escape(chart.title) << "</text>\n";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"#fff\" stroke=\"#444\"/>\n";
  // Ticks and grid.
  for (double t : linear_ticks(x0, x1)) {
    s << "<line x1=\"" << X(t) << "\" y1=\"" << top << "\" x2=\"" << X(t) << "\" y2=\"" << top + ph
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << X(t) << "\" y=\"" << top + ph + 16 << "\" text-anchor=\"middle\">"
      << number(t) << "</text>\n";
  }
  std::vector<double> yticks;
  if (chart.log_y) {
    for (double d = std::log10(y0); d <= std::log10(y1) + 1e-9; d += 1.0) yticks.push_back(std::pow(10.0, d));
  } else {
    yticks = linear_ticks(y0, y1);
  }
  for (double t : yticks)
    s << "<line x1=\"" << left << "\" y1=\"" << Y(t) << "\" x2=\"" << left + pw << "\" y2=\"" << Y(t)
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << left - 6 << "\" y=\"" << Y(t) + 4 << "\" text-anchor=\"end\">"
      << number(t) << "</text>\n";
  s << "<text x=\"" << left + pw / 2 << "\" y=\"" << H - 10 << "\" text-anchor=\"middle\">" << html_escape(chart.x_label)
    << "</text>\n";
  s << "<text transform=\"translate(16," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << html_escape(chart.y_label) << "</text>\n";
  s << "<clipPath id=\"plot-" << chart.id << "\"><rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw
    << "\" height=\"" << ph << "\"/></clipPath>\n<g clip-path=\"url(#plot-" << chart.id << ")\">\n";
  for (const auto& l : chart.lines) {
    if (l.vertical)
      s << "<line x1=\"" << X(l.value) << "\" y1=\"" << top << "\" x2=\"" << X(l.value) << "\" y2=\"" << top + ph;
    else
      s << "<line x1=\"" << left << "\" y1=\"" << Y(l.value) << "\" x2=\"" << left + pw << "\" y2=\"" << Y(l.value);
    s << "\" stroke=\"#888\" stroke-dasharray=\"2,3\"/>\n";
  }
  for (size_t k = 0; k < chart.series.size(); ++k) {
    const auto& series = chart.series[k];
    const char* colour = colour_of(chart, k);
    if (series.markers_only) {
      for (size_t i = 0; i < series.x.size(); ++i)
        if (std::isfinite(series.y[i]))
          s << "<circle cx=\"" << X(series.x[i]) << "\" cy=\"" << Y(series.y[i]) << "\" r=\"4\" fill=\"none\" stroke=\""
            << colour << "\" stroke-width=\"2\"/>\n";
      continue;
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
      std::ostringstream p;
      p << std::fixed << std::setprecision(1) << X(series.x[i]) << "," << Y(series.y[i]) << " ";
      points += p.str();
    }
    flush();
  }
  s << "</g>\n";
  // Labels of reference lines at the right edge, legend beside the plot.
  // Labels of horizontal lines, pushed apart where lines lie closer than a text line.
  std::vector<std::pair<double, std::string>> labels;
  for (const auto& l : chart.lines)
    if (!l.vertical && !l.label.empty() && l.value >= y0 && l.value <= y1) labels.push_back({Y(l.value) + 4, l.label});
  std::sort(labels.begin(), labels.end());
  for (size_t k = 1; k < labels.size(); ++k) labels[k].first = std::max(labels[k].first, labels[k - 1].first + 12);
  for (const auto& [y, text] : labels)
    s << "<text x=\"" << left + pw + 6 << "\" y=\"" << y << "\" fill=\"#555\" font-size=\"11\">" << html_escape(text)
      << "</text>\n";
  // Labels of vertical lines above the plot, pushed apart where lines lie closer than a label.
  std::vector<std::pair<double, std::string>> tops;
  for (const auto& l : chart.lines)
    if (l.vertical && !l.label.empty() && l.value >= x0 && l.value <= x1) tops.push_back({X(l.value), l.label});
  std::sort(tops.begin(), tops.end());
  for (size_t k = 1; k < tops.size(); ++k)
    tops[k].first = std::max(tops[k].first, tops[k - 1].first + 3 + 6.2 * static_cast<double>(tops[k - 1].second.size()));
  for (const auto& [x, text] : tops)
    s << "<text x=\"" << x << "\" y=\"" << top - 4 << "\" fill=\"#555\" font-size=\"10\">" << html_escape(text)
      << "</text>\n";
  // Legend in the plot's top-left corner, on a white card.
  std::vector<size_t> named;
  for (size_t k = 0; k < chart.series.size(); ++k)
    if (!chart.series[k].label.empty()) named.push_back(k);
  if (!named.empty()) {
    size_t longest = 0;
    for (size_t k : named) longest = std::max(longest, chart.series[k].label.size());
    s << "<rect x=\"" << left + 8 << "\" y=\"" << top + 8 << "\" width=\"" << 40 + 6.2 * longest << "\" height=\""
      << 16 * named.size() + 8 << "\" fill=\"#fff\" fill-opacity=\"0.9\" stroke=\"#ccc\"/>\n";
    double ly = top + 20;
    for (size_t k : named) {
      const char* colour = colour_of(chart, k);
      if (chart.series[k].markers_only)
        s << "<circle cx=\"" << left + 24 << "\" cy=\"" << ly << "\" r=\"4\" fill=\"none\" stroke=\"" << colour
          << "\" stroke-width=\"2\"/>";
      else
        s << "<line x1=\"" << left + 14 << "\" y1=\"" << ly << "\" x2=\"" << left + 34 << "\" y2=\"" << ly
          << "\" stroke=\"" << colour << "\" stroke-width=\"2\"" << (chart.series[k].dashed ? " stroke-dasharray=\"6,4\"" : "")
          << "/>";
      s << "<text x=\"" << left + 40 << "\" y=\"" << ly + 4 << "\" font-size=\"11\">"
        << html_escape(chart.series[k].label) << "</text>\n";
      ly += 16;
    }
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace railmodal::report
