// The charts of every HTML page, read as a reader's eye would: each SVG is parsed, and its plot
// must have axes with tick labels and one unit per axis label, scale to the page's width, keep
// its legend off every plotted point, and set no label over another. Checked on every bundled
// example's page (tests/golden/expected/**/*.html, which the golden tests hold byte for byte
// to what railmodal writes) and on charts made to provoke collisions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "hunting_results.hpp"
#include "railmodal/hunting_report.hpp"
#include "report/svg_chart.hpp"

namespace railmodal::report {
namespace {

struct Box {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

struct Label {
  std::string text;
  Box box;
  bool rotated;
};

struct ParsedSvg {
  std::string width;  ///< the width attribute
  double view_width = 0, view_height = 0;
  Box plot{0, 0, 0, 0};
  std::vector<Box> other_rects;                   ///< legend boxes: rects outside the plot's clip path
  std::vector<std::pair<double, double>> points;  ///< plotted data points inside the plot area
  std::vector<Label> labels;
};

// Plain string search: std::regex recurses per character and overflows the stack on a
// polyline of 4000 points.
std::string attribute(const std::string& attributes, const std::string& name) {
  const std::string start = " " + name + "=\"";
  const size_t at = (" " + attributes).find(start);
  if (at == std::string::npos) return "";
  const size_t begin = at + start.size() - 1;  // in `attributes`, which lacks the leading space
  return attributes.substr(begin, attributes.find('"', begin) - begin);
}

double number(const std::string& attributes, const std::string& name) {
  const std::string text = attribute(attributes, name);
  return text.empty() ? 0.0 : std::stod(text);
}

size_t characters(const std::string& text) {
  std::string plain = std::regex_replace(text, std::regex("&[a-z]+;"), "x");
  return static_cast<size_t>(std::count_if(plain.begin(), plain.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

// The box a text takes: 0.55 em a character (the average advance of a sans-serif; digits are
// 0.55 em in DejaVu Sans and Liberation Sans), from 0.75 em above the baseline to 0.2 em below.
Label label_of(const std::string& attributes, const std::string& text) {
  const double size = attribute(attributes, "font-size").empty() ? 12.0 : number(attributes, "font-size");
  const double width = 0.55 * size * static_cast<double>(characters(text));
  double x = number(attributes, "x");
  const std::string anchor = attribute(attributes, "text-anchor");
  if (anchor == "middle") x -= width / 2;
  if (anchor == "end") x -= width;
  const double y = number(attributes, "y");
  return {text, {x, y - 0.75 * size, x + width, y + 0.2 * size}, !attribute(attributes, "transform").empty()};
}

// The plot area is the rectangle of the clip path the data are drawn in.
ParsedSvg parse(const std::string& svg) {
  ParsedSvg out;
  std::istringstream view(attribute(svg.substr(0, svg.find('>')), "viewBox"));
  double ignored;
  view >> ignored >> ignored >> out.view_width >> out.view_height;
  out.width = attribute(svg.substr(0, svg.find('>')), "width");
  bool in_clip = false, in_data = false;
  for (size_t open = svg.find('<'); open != std::string::npos; open = svg.find('<', open + 1)) {
    const size_t close = svg.find('>', open);
    const bool closing = svg[open + 1] == '/';
    const size_t name_begin = open + (closing ? 2 : 1);
    const size_t name_end = svg.find_first_of(" />", name_begin);
    const std::string name = svg.substr(name_begin, name_end - name_begin);
    const std::string a = svg.substr(name_end, close - name_end);
    if (name == "clipPath") in_clip = !closing;
    if (name == "g") in_data = !closing && !attribute(a, "clip-path").empty();
    if (closing) continue;
    if (name == "rect") {
      const Box b{number(a, "x"), number(a, "y"), number(a, "x") + number(a, "width"),
                  number(a, "y") + number(a, "height")};
      if (in_clip)
        out.plot = b;
      else
        out.other_rects.push_back(b);
    } else if (name == "circle" && in_data) {
      out.points.push_back({number(a, "cx"), number(a, "cy")});
    } else if (name == "polyline" && in_data) {
      std::istringstream pts(attribute(a, "points"));
      double x, y;
      char comma;
      while (pts >> x >> comma >> y) out.points.push_back({x, y});
    } else if (name == "text") {
      const size_t begin = close + 1;
      out.labels.push_back(label_of(a, svg.substr(begin, svg.find("</text>", begin) - begin)));
    }
  }
  // The frame drawn over the clip path's rectangle is no legend; points outside the plot are clipped.
  const Box plot = out.plot;
  out.other_rects.erase(
      std::remove_if(out.other_rects.begin(), out.other_rects.end(),
                     [&](const Box& b) { return b.x0 == plot.x0 && b.y0 == plot.y0 && b.x1 == plot.x1; }),
      out.other_rects.end());
  out.points.erase(std::remove_if(out.points.begin(), out.points.end(),
                                  [&](const auto& p) { return !plot.contains(p.first, p.second); }),
                   out.points.end());
  return out;
}

std::vector<std::string> svgs_of(const std::string& page) {
  std::vector<std::string> out;
  for (size_t at = page.find("<svg"); at != std::string::npos; at = page.find("<svg", at + 1))
    out.push_back(page.substr(at, page.find("</svg>", at) + 6 - at));
  return out;
}

// One unit, in parentheses or brackets at the end: "speed (km/h)", not "displacement [mm, mrad]".
bool has_one_unit(const std::string& label) {
  return std::regex_search(label, std::regex(R"((\([^(),]+\)|\[[^\[\],]+\])$)"));
}

// Every finding on one chart, as lines; empty when it reads well.
std::string problems(const std::string& svg) {
  const ParsedSvg p = parse(svg);
  std::ostringstream found;
  if (p.width != "100%") found << "width is '" << p.width << "', not 100 % of the page\n";
  if (!(p.plot.x1 > p.plot.x0)) found << "no plot area\n";
  int x_ticks = 0, y_ticks = 0;
  const Label* y_label = nullptr;
  const Label* x_label = nullptr;
  for (const Label& l : p.labels) {
    if (l.rotated)
      y_label = &l;
    else if (l.box.y0 > p.plot.y1 && l.box.y1 < p.plot.y1 + 22)
      ++x_ticks;
    else if (l.box.x1 <= p.plot.x0 && l.box.y0 >= p.plot.y0 - 8 && l.box.y1 <= p.plot.y1 + 8)
      ++y_ticks;
    else if (l.box.y0 > p.plot.y1 + 22 && l.box.y1 < p.plot.y1 + 48 && !x_label)
      x_label = &l;
  }
  if (x_ticks < 2 || y_ticks < 2) found << "axes without ticks (" << x_ticks << " on x, " << y_ticks << " on y)\n";
  if (!x_label || !has_one_unit(x_label->text))
    found << "x axis label '" << (x_label ? x_label->text : "") << "' has not one unit\n";
  if (!y_label || !has_one_unit(y_label->text))
    found << "y axis label '" << (y_label ? y_label->text : "") << "' has not one unit\n";
  for (const Box& legend : p.other_rects)
    for (const auto& [x, y] : p.points)
      if (legend.contains(x, y)) {
        found << "a legend box covers the data point (" << x << ", " << y << ")\n";
        break;
      }
  for (size_t i = 0; i < p.labels.size(); ++i) {
    const Label& a = p.labels[i];
    if (a.rotated) continue;
    if (a.box.x0 < 0 || a.box.x1 > p.view_width) found << "label '" << a.text << "' runs off the chart\n";
    for (size_t j = i + 1; j < p.labels.size(); ++j)
      if (!p.labels[j].rotated && a.box.overlaps(p.labels[j].box))
        found << "labels '" << a.text << "' and '" << p.labels[j].text << "' overlap\n";
  }
  return found.str();
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SvgStructure, EveryChartOfEveryBundledPageReadsWell) {
  const std::filesystem::path golden =
      std::filesystem::path(RAILMODAL_DATA_DIR) / ".." / "tests" / "golden" / "expected";
  int pages = 0, charts = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(golden)) {
    if (entry.path().extension() != ".html") continue;
    ++pages;
    for (const std::string& svg : svgs_of(read(entry.path()))) {
      ++charts;
      EXPECT_EQ(problems(svg), "") << entry.path().lexically_relative(golden) << ", chart " << charts;
    }
  }
  EXPECT_GE(pages, 19);  // every critical-speed scene, simulation scene and study has a page
  EXPECT_GT(charts, pages);
}

// Eight natural frequencies within 2 % of each other (the labels' natural places overlap) and a
// curve through the top-left corner, where a legend drawn inside the plot would sit.
TEST(SvgStructure, CrowdedLabelsAreSpreadAndTheLegendCoversNoPoint) {
  Chart c;
  c.id = "crowded";
  c.title = "crowded";
  c.x_label = "speed (km/h)";
  c.y_label = "frequency (Hz)";
  ChartSeries s;
  s.label = "a source with a long name that fills a legend row";
  for (double x = 0; x <= 100; x += 1) s.x.push_back(x), s.y.push_back(10.0 - 0.09 * x);
  c.series.push_back(s);
  for (int k = 0; k < 8; ++k)
    c.lines.push_back({std::to_string(k + 1), 5.0 + 0.01 * k, false, "mode " + std::to_string(k + 1)});
  for (int k = 0; k < 6; ++k) c.lines.push_back({"mode " + std::to_string(k + 1), 50.0 + 0.1 * k, true, ""});
  EXPECT_EQ(problems(svg_chart(c)), "");
}

// An undamped resonance: the points beside it do not set the axis, and it is marked.
TEST(SvgStructure, UnboundedCurvesAreClippedAndMarked) {
  Chart c;
  c.id = "unbounded";
  c.x_label = "speed (km/h)";
  c.y_label = "amplitude (mm)";
  c.log_y = true;
  ChartSeries s;
  s.label = "undamped";
  for (double x = 10; x <= 90; x += 1) {
    s.x.push_back(x);
    s.y.push_back(x == 50 ? NAN : 1.0 / std::abs(1.0 - (x / 50) * (x / 50)));  // 1/|1 − r²|: 25 at r = 0.98
  }
  s.unbounded_x = {50};
  c.series.push_back(s);
  const std::string svg = svg_chart(c);
  EXPECT_EQ(problems(svg), "");
  // Outside ±5 % the transmissibility stays below 1/(1 − 0.95²) = 10.3 (8.6 on this grid): the
  // axis ends at the decade 10, not at the 100 the grid's nearest points would ask for (x ticks:
  // 20, 40, 60, 80).
  EXPECT_NE(svg.find(">10</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">100</text>"), std::string::npos);
  EXPECT_NE(svg.find("class=\"unbounded\""), std::string::npos);
  EXPECT_NE(svg.find(">unbounded</text>"), std::string::npos);
}

// The hunting report's charts (root locus shaded by speed, ζ against speed with its marks,
// critical speed against conicity) on results built by hand: every verdict and a design curve.
TEST(SvgStructure, HuntingStabilityChartsReadWell) {
  for (const HuntingResult& r : {test::conicity_result(), test::unstable_at_lowest_result(), test::stable_result(),
                                 test::zero_conicity_result()}) {
    std::ostringstream page;
    write_hunting_stability(page, r, OutputFormat::html);
    const std::vector<std::string> charts = svgs_of(page.str());
    ASSERT_GE(charts.size(), 2u);
    for (const std::string& svg : charts) EXPECT_EQ(problems(svg), "") << to_string(r.verdict);
    // The root locus: every branch's points as dots shaded dark to light (the first speed's
    // dot is the scale's dark end, the last its light end), and the scale in the legend.
    const std::string& locus = charts[1];
    EXPECT_NE(locus.find("fill=\"#440154\""), std::string::npos);
    EXPECT_NE(locus.find("fill=\"#fde725\""), std::string::npos);
    EXPECT_NE(locus.find("dots: speed from 10 km/h (dark) to 500 km/h (light)"), std::string::npos);
  }
}

// The damping chart marks the critical speed and the threshold: vertical and horizontal lines
// labelled at the plot's edge.
TEST(SvgStructure, HuntingDampingChartMarksTheCriticalSpeedAndThreshold) {
  std::ostringstream page;
  write_hunting_stability(page, test::two_interval_result(), OutputFormat::html);
  const std::string damping = svgs_of(page.str()).front();
  for (const char* label : {"V crit 200.0", "ζ = 5 %", "ζ = 0", "V at ζ = 5 %"})
    EXPECT_NE(damping.find(std::string(">") + label + "</text>"), std::string::npos) << label;
}

}  // namespace
}  // namespace railmodal::report
