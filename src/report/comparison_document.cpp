// The design comparison as a document to hand in (docs/studies.md, "Reports"): Markdown, or one
// self-contained HTML page with inline SVG. It argues as the book does when it sets the Pullman,
// Fette and Egorov bogies side by side: why the winner wins, the ranked table, how each swept
// parameter moves the periods and the objective, and the response curves of the best designs
// against the base.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "railmodal/comparison_report.hpp"
#include "railmodal/critical_speed.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/response.hpp"
#include "railmodal/study.hpp"
#include "report/comparison_document.hpp"
#include "report/comparison_rows.hpp"
#include "report/document_table.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "response/curve_peaks.hpp"
#include "ride/nmv_scope.hpp"
#include "study/metrics.hpp"
#include "study/ranking.hpp"

namespace railmodal {
namespace {

using report::fixed;
using report::html_escape;
using report::significant;
using report::Table;

using report::kKmh;
constexpr size_t kChartPoints = 2000;  // points per sweep chart: larger studies are thinned
constexpr size_t kModeSeries = 6;   // periods plotted per sweep chart: the lowest modes
constexpr size_t kCurveCharts = 8;  // amplitude charts at most

// Text that is Markdown or HTML: names in bold, everything else escaped for HTML.
struct Writer {
  bool html;
  std::string text(const std::string& s) const { return html ? html_escape(s) : s; }
  std::string bold(const std::string& s) const { return html ? "<b>" + html_escape(s) + "</b>" : "**" + s + "**"; }
};

// A metric's value as the table shows it (study::shown_as_tabled), or the word for none or ±∞.
std::string metric_text(const std::string& metric, const std::optional<double>& x) {
  if (!x) return "–";
  if (std::isinf(*x) && *x > 0) {
    const std::string word = study::infinite_word(metric);
    return word == "none" ? "none in range" : study::infinite_text(metric);  // "above 500 km/h"
  }
  if (std::isinf(*x)) return "−∞";
  return study::shown_as_tabled(metric, *x);
}

// Two values of a metric set side by side, "0.567 s against 0.531 s": as the table shows them,
// with more decimals where two values that differ would read the same (study::shown_apart).
std::pair<std::string, std::string> metric_texts(const std::string& metric, const std::optional<double>& a,
                                                 const std::optional<double>& b) {
  if (a && b && std::isfinite(*a) && std::isfinite(*b)) return study::shown_apart(metric, *a, *b);
  return {metric_text(metric, a), metric_text(metric, b)};
}

// " (vertical only)" after a partial N_MV (ride::nmv_scope), as the table and the ride write it;
// "" after one over both axes.
std::string scope_suffix(const std::string& scope) { return scope.empty() ? "" : " (" + scope + ")"; }

// The same after the max_nmv of a variant (VariantResult::max_nmv_partial).
std::string scope_of(const std::string& metric, const VariantResult& r) {
  return metric == "max_nmv" ? scope_suffix(r.max_nmv_partial) : "";
}

// A criterion as docs/studies.md names its metric: "period of body bounce (maximised)".
std::string goal(const RankingCriterion& c) {
  return study::title(c.metric) + (c.maximise ? " (maximised)" : " (minimised)");
}

// ---- why the winner wins ------------------------------------------------------------------

// How the winner beats the runner-up: on the weighted objective, or on the first criterion
// where they differ (or that they tie on all).
std::string against_runner_up(const Comparison& c, const Writer& w, const RankedVariant& winner,
                              const RankedVariant& runner) {
  const auto& objective = c.ranking.objective;
  if (c.ranking.weighted)
    return w.text(" Its weighted objective is " + significant(winner.objective.value_or(NAN), 6) + " against " +
                  significant(runner.objective.value_or(NAN), 6) + " for the runner-up ") +
           w.bold(runner.result.name) + w.text(".");
  size_t k = 0;
  while (k < objective.size() && k < winner.criteria.size() && k < runner.criteria.size() &&
         winner.criteria[k] == runner.criteria[k])
    ++k;
  if (k < objective.size() && k < winner.criteria.size() && k < runner.criteria.size()) {
    const std::string& metric = objective[k].metric;
    const auto [ahead, behind] = metric_texts(metric, winner.criteria[k], runner.criteria[k]);
    return w.text(" It is ahead of the runner-up ") + w.bold(runner.result.name) +
           w.text(" on " + goal(objective[k]) + ": " + ahead + scope_of(metric, winner.result) + " against " + behind +
                  scope_of(metric, runner.result) +
                  (k > 0 ? " (the criteria before it tie)." : "."));
  }
  return w.text(" It ties with the runner-up ") + w.bold(runner.result.name) +
         w.text(" on every criterion and comes first in study order.");
}

// Whether `a` ranks behind `b` on the objective alone (constraints aside), as rank_entry
// (study/ranking.cpp) sorts: the weighted sum smaller first; else the first criterion where they
// differ, a missing value the worst.
bool behind_on_objective(const Ranking& ranking, const RankedVariant& a, const RankedVariant& b) {
  if (ranking.weighted) return a.objective && b.objective && *a.objective > *b.objective;
  const auto key = [](const std::optional<double>& x, bool maximise) -> double {
    if (!x || std::isnan(*x)) return INFINITY;
    return maximise ? -*x : *x;
  };
  for (size_t k = 0; k < ranking.objective.size() && k < a.criteria.size() && k < b.criteria.size(); ++k) {
    const double x = key(a.criteria[k], ranking.objective[k].maximise);
    const double y = key(b.criteria[k], ranking.objective[k].maximise);
    if (x != y) return x > y;
  }
  return false;
}

// The winner's objective against the base design's, and why the base is not in front.
std::string against_base(const Comparison& c, const Writer& w, const RankedVariant& winner,
                         const RankedVariant& base, size_t feasible) {
  const auto& objective = c.ranking.objective;
  std::string b = w.text("Against the base:");
  for (size_t k = 0; k < objective.size(); ++k) {
    const auto& mine = k < winner.criteria.size() ? winner.criteria[k] : std::nullopt;
    const auto& theirs = k < base.criteria.size() ? base.criteria[k] : std::nullopt;
    const std::string& metric = objective[k].metric;
    const auto [its, base_value] = metric_texts(metric, mine, theirs);
    b += w.text(std::string(k ? ";" : "") + " " + study::title(metric) + " " + its + scope_of(metric, winner.result) +
                " (base " + base_value + scope_of(metric, base.result) + ")");
  }
  b += w.text(".");
  if (!base.result.ok()) b += w.text(" The base itself failed: " + base.result.failure + ".");
  else if (!base.feasible && !base.violations.empty())
    b += w.text(" The base violates " + study::violations(base.result, c.ranking, true).front() + ".");
  // A winner worse than the base on what the study optimises wins on the constraints alone: said,
  // so that "period 0.456 s (base 0.589 s)" does not read as an improvement (user audit
  // 2026-11-28b, F6).
  if (base.result.ok() && !base.feasible && behind_on_objective(c.ranking, winner, base))
    b += w.text(feasible == 1 ? " The winner is worse than the base on the objective: it wins only as the one "
                                "feasible design."
                              : " The winner is worse than the base on the objective: it wins because the base is "
                                "infeasible.");
  return b;
}

// Who ranks first and why, and how it compares with the base design.
void add_winner(const Comparison& c, const Writer& w, const report::DocumentTally& tally,
                std::vector<std::string>* out) {
  const RankedVariant* base = comparison_base(c);
  const RankedVariant& winner = c.variants.front();
  std::string s = w.bold(winner.result.name) + w.text(" ranks first of " + std::to_string(tally.variants) +
                                                    " variants (" + std::to_string(tally.feasible) + " feasible).");
  const RankedVariant* runner = c.variants.size() > 1 && c.variants[1].feasible ? &c.variants[1] : nullptr;
  if (runner && !c.ranking.objective.empty()) s += against_runner_up(c, w, winner, *runner);
  // An infeasible runner-up (not the base, which has its own sentence) is drawn below with its
  // mark: what rules it out is said here.
  if (c.variants.size() > 1 && !runner && c.variants[1].result.ok() && !study::is_base(c.variants[1].result) &&
      !c.variants[1].violations.empty())
    s += w.text(" The runner-up ") + w.bold(c.variants[1].result.name) +
         w.text(" is infeasible: it violates " + study::violations(c.variants[1].result, c.ranking, true).front() + ".");
  out->push_back(s);
  if (base && &winner == base)
    out->push_back(w.text("The base design is best: no variant improves on it within the constraints."));
  else if (base && !c.ranking.objective.empty())
    out->push_back(against_base(c, w, winner, *base, tally.feasible));
}

// Whether an evaluated variant's value of the constraint's metric lies outside it.
bool violates(const VariantResult& r, const RankingConstraint& k) {
  const auto x = metric_value(r, k.metric);
  return !x || (k.min && *x < *k.min) || (k.max && *x > *k.max);
}

std::string constraint_sentence(const Writer& w, const RankingConstraint& k, size_t violating,
                                const report::DocumentTally& tally) {
  std::string bound;
  // The limits as the study gives them (study::shown's 6 significant digits), as the table's head.
  if (k.min) bound += " ≥ " + study::shown(k.metric, *k.min);
  if (k.max) bound += std::string(k.min ? " and" : "") + " ≤ " + study::shown(k.metric, *k.max);
  return w.text("Constraint " + study::title(k.metric) + bound + ": " + std::to_string(violating) + " of " +
                std::to_string(tally.variants - tally.failed) + " evaluated variants violate it.");
}

// Where a largest value over the scene's speeds lies at an end of their range, the largest may
// lie beyond it (user audit 2026-11-28b, F9a): said of a drawn design (its scene is in `curves`),
// "" otherwise. The ends are the scene's own speeds; 1e-9 relative allows the round-off of a grid
// built by steps, and is far below the 0.1 km/h a table shows.
std::string range_end(const ComparisonCurves& curves, int variant, double speed) {
  for (const DesignCurves& d : curves.designs) {
    if (d.variant != variant || d.study.curves.empty()) continue;
    const Scene& scene = d.study.scene;
    const double tolerance = 1e-9 * scene.max_speed;
    if (std::abs(speed - scene.max_speed) <= tolerance) return "the range's end: the largest may lie above it";
    if (std::abs(speed - scene.min_speed) <= tolerance) return "the range's start: the largest may lie below it";
  }
  return "";
}

// Whether the winner keeps the book's permissible dynamic deflections, and how closely.
std::string deflection_sentence(const VariantResult& r, const Writer& w, const ComparisonCurves& curves) {
  const VariantResult::DeflectionCheck* worst = nullptr;
  for (const auto& d : r.deflections)
    if (!worst || d.unbounded > worst->unbounded ||
        (d.unbounded == worst->unbounded && d.deflection / d.permissible > worst->deflection / worst->permissible))
      worst = &d;
  if (!worst) return w.text("No spring of the winner falls under the permissible-deflection rule.");
  if (worst->unbounded)
    return w.text("The winner exceeds the permissible dynamic deflection: a resonance that friction does not "
                  "stop stretches " + worst->element + " without limit at " +
                  fixed(worst->speed * kKmh, 1) + " km/h.");
  const std::string end = range_end(curves, r.index, worst->speed);
  return w.text(std::string(worst->kept() ? "The winner keeps" : "The winner exceeds") +
                " the permissible dynamic deflections: at worst " +
                fixed(100.0 * worst->deflection / worst->permissible, 1) + " % of the limit (" + worst->element + ", " +
                worst->basis + ") at " + fixed(worst->speed * kKmh, 1) + " km/h" +
                (end.empty() ? "" : ", " + end) + ".");
}

std::vector<std::string> verdict(const Comparison& c, const Writer& w, const report::DocumentTally& tally,
                                 const ComparisonCurves& curves) {
  std::vector<std::string> out;
  const size_t feasible = tally.feasible, failed = tally.failed;
  if (feasible == 0)
    out.push_back(w.text("No variant meets every constraint: the table ranks them all as infeasible."));
  else
    add_winner(c, w, tally, &out);
  for (size_t k = 0; k < c.ranking.constraints.size(); ++k)
    out.push_back(constraint_sentence(w, c.ranking.constraints[k], tally.violating.at(k), tally));
  if (c.deflection_rule.active() && feasible > 0 && c.variants.front().result.ok())
    out.push_back(deflection_sentence(c.variants.front().result, w, curves));
  if (failed > 0 && tally.failed_index)
    out.push_back(w.text(std::to_string(failed) + " variant" + (failed > 1 ? "s" : "") +
                         " could not be evaluated (first: ") +
                  w.bold(tally.failed_name) + w.text(", " + tally.failure + ")."));
  return out;
}

// ---- the ranked table -----------------------------------------------------------------------

Table ranked_table(const Comparison& c) {
  const auto rows = report::comparison_rows(c);
  Table t;
  t.headers = rows.front();
  for (size_t i = 0; i < t.headers.size(); ++i) t.numeric.push_back(i >= 3 && i + 1 < t.headers.size());
  for (size_t r = 1; r < rows.size() && r <= static_cast<size_t>(kReportRows); ++r) t.rows.push_back(rows[r]);
  return t;
}

std::string table_note(const report::DocumentTally& tally) {
  if (tally.variants <= static_cast<size_t>(kReportRows)) return "";
  return "The first " + std::to_string(kReportRows) + " of " + std::to_string(tally.variants) +
         " variants; every variant is in --format csv and json.";
}

// ---- swept parameters -------------------------------------------------------------------------

// A parameter value as a number and its unit as written ("40 mm" → 40, "mm"); nothing for a
// table, an array or a file name.
std::optional<std::pair<double, std::string>> numeric(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(x)) return std::nullopt;
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(' '));
  unit.erase(unit.find_last_not_of(' ') + 1);
  if (unit.find_first_of("[{\"=,") != std::string::npos) return std::nullopt;
  return std::make_pair(x, unit);
}

// A key the study sweeps, as the evaluated variants give it (first pass over their sweep points).
struct SweptParameter {
  std::string key, unit;
  std::string label;  ///< as the study names it (parameter_label)
  size_t points = 0;  ///< variants with a value of it (in `unit`)
  std::set<double> distinct;  ///< its distinct values, kept until there are more than kListedValues
  double lo = NAN, hi = NAN;  ///< the least and greatest value (the first written of equal ones)
};

constexpr size_t kListedValues = 12;  // more distinct values than this are binned (sweep_table)

// Keys that take at least two numeric values in one unit across the evaluated variants, in the
// order the variants first name them.
std::vector<SweptParameter> swept_parameters(const Study& study, const report::SweepPoints& points) {
  std::vector<SweptParameter> out;
  std::map<std::string, size_t> position;
  std::set<std::string> mixed;  // keys with other units or non-numeric values
  points([&](const report::SweepPoint& v) {
    for (const auto& [key, text] : v.parameters) {
      const auto value = numeric(text);
      if (!position.count(key)) {
        position[key] = out.size();
        SweptParameter p;
        p.key = key, p.unit = value ? value->second : "", p.label = study::parameter_label(study, key);
        out.push_back(std::move(p));
      }
      SweptParameter& p = out[position[key]];
      if (!value || value->second != p.unit) {
        mixed.insert(key);
        continue;
      }
      const double x = value->first;
      if (p.points++ == 0) p.lo = p.hi = x;
      if (x < p.lo) p.lo = x;
      if (x > p.hi) p.hi = x;
      if (p.distinct.size() <= kListedValues) p.distinct.insert(x);
    }
  });
  std::vector<SweptParameter> swept;
  for (SweptParameter& p : out)
    if (!mixed.count(p.key) && p.distinct.size() >= 2) swept.push_back(std::move(p));
  return swept;
}

// Calls visit(parameter, value) for each point a variant gives the swept parameters, in the
// order of its parameters.
template <typename Visit>
void for_each_swept(const report::SweepPoint& v, const std::vector<SweptParameter>& swept, const Visit& visit) {
  for (const auto& [key, text] : v.parameters)
    for (size_t k = 0; k < swept.size(); ++k)
      if (swept[k].key == key) visit(k, numeric(text)->first);
}

// A name with its unit: "f [mm]" in a table heading (as the text tables and CSV write it), "f
// (mm)" on a chart's axis.
std::string labelled(const std::string& name, const std::string& unit, bool table) {
  if (unit.empty()) return name;
  return name + (table ? " [" + unit + "]" : " (" + unit + ")");
}

// The parameter as the study names it, with the unit its values are written in: "f (mm)".
std::string axis_label(const SweptParameter& p, bool table) { return labelled(p.label, p.unit, table); }

// A sweep's heading: its label, and the key path it sets (for the reader who looks it up).
std::string parameter_heading(const SweptParameter& p, const Writer& w) {
  return w.text(p.label + ": ") + (w.html ? "<code>" + html_escape(p.key) + "</code>" : "`" + p.key + "`");
}

// The mode names whose periods are plotted: the lowest oscillatory modes of the reference.
std::vector<std::string> period_modes(const VariantResult& reference) {
  std::vector<std::string> names;
  for (const auto& m : reference.modes)
    if (m.kind == "oscillatory" && names.size() < kModeSeries &&
        std::find(names.begin(), names.end(), m.name) == names.end())
      names.push_back(m.name);
  return names;
}

std::optional<double> period_of(const report::SweepPoint& v, const std::string& mode) {
  for (const auto& [name, period] : v.periods)
    if (name == mode) return period;
  return std::nullopt;
}

// The value each variant is ranked by first: the weighted sum or the first criterion (SI).
std::optional<double> ranked_value(const RankedVariant& v, const Ranking& ranking) {
  if (ranking.weighted) return v.objective;
  return v.criteria.empty() ? std::nullopt : v.criteria.front();
}

// A ratio to a permissible value is shown in per cent of it, as the tables say it.
bool is_ratio(const std::string& metric) { return study::title(metric).find("/ permissible") != std::string::npos; }

// The axis (and column) of the value ranked first, its unit at the end: "period of body bounce
// (s)", "largest dynamic deflection (% of permissible)" ("[s]", "[% of permissible]" in a table).
std::string ranked_label(const Ranking& ranking, bool table) {
  if (ranking.objective.empty()) return "";
  if (ranking.weighted) return labelled("weighted objective", "weights × SI values", table);
  const std::string& metric = ranking.objective.front().metric;
  if (is_ratio(metric))
    return labelled(study::title(metric).substr(0, study::title(metric).find(" / ")), "% of permissible", table);
  return labelled(study::title(metric), study::display_unit(metric).unit, table);
}

double ranked_scale(const Ranking& ranking) {
  if (ranking.weighted || ranking.objective.empty()) return 1.0;
  const std::string& metric = ranking.objective.front().metric;
  return is_ratio(metric) ? 100.0 : study::display_unit(metric).per_si;
}

// Room for the points: 5 % beyond the extreme values, so none sits on the frame (the legend is
// drawn under the plot and needs none).
void frame_points(report::Chart* chart) {
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (const auto& s : chart->series)
    for (size_t i = 0; i < s.x.size(); ++i)
      x_lo = std::min(x_lo, s.x[i]), x_hi = std::max(x_hi, s.x[i]), y_lo = std::min(y_lo, s.y[i]), y_hi = std::max(y_hi, s.y[i]);
  if (!(x_lo < x_hi) || !(y_lo <= y_hi)) return;  // no points, or one value: the chart's own range
  chart->x_min = x_lo - 0.05 * (x_hi - x_lo);
  chart->x_max = x_hi + 0.05 * (x_hi - x_lo);
  chart->y_min = y_lo >= 0.0 ? 0.0 : y_lo - 0.05 * (y_hi - y_lo);
  chart->y_max = y_hi + 0.05 * (y_hi - chart->y_min);
  if (!(chart->y_min < chart->y_max)) chart->y_min = chart->y_max = 0.0;  // all zero: automatic
}

// One swept parameter's charts: the periods, and the value ranked first (feasible and not).
struct SweepCharts {
  report::Chart periods, objective;
  std::vector<report::ChartSeries> modes;  ///< one per plotted mode
  report::ChartSeries feasible, infeasible;
  size_t stride = 1, seen = 0;  ///< every stride-th point is plotted; points met so far
};

void write_sweep_charts(std::ostream& out, const Comparison& c, const std::vector<SweptParameter>& swept,
                        const VariantResult& reference, const report::SweepPoints& points) {
  const std::vector<std::string> modes = period_modes(reference);
  std::vector<SweepCharts> charts(swept.size());
  for (size_t k = 0; k < swept.size(); ++k) {
    const SweptParameter& p = swept[k];
    SweepCharts& chart = charts[k];
    chart.stride = (p.points + kChartPoints - 1) / kChartPoints;
    chart.periods.id = "sweep-periods-" + std::to_string(k + 1);
    chart.periods.title = "Periods against " + p.label;
    chart.periods.x_label = axis_label(p, false);
    chart.periods.y_label = "period (s)";
    // A colour means one thing throughout the report: the variants of the amplitude charts take
    // the first kReportBest + 1 (base first), the modes those after them, feasibility two greys.
    for (size_t m = 0; m < modes.size(); ++m) {
      report::ChartSeries series;
      series.label = modes[m];
      series.markers_only = true;
      series.colour = static_cast<int>(kReportBest + 1 + m);
      chart.modes.push_back(series);
    }
    chart.objective.id = "sweep-objective-" + std::to_string(k + 1);
    chart.objective.title = c.ranking.weighted ? "Weighted objective against " + p.label
                            : c.ranking.objective.empty()
                                ? ""
                                : "Objective against " + p.label + ": " + goal(c.ranking.objective.front());
    chart.objective.x_label = axis_label(p, false);
    chart.objective.y_label = ranked_label(c.ranking, false);
    chart.feasible.label = "feasible", chart.infeasible.label = "infeasible";
    chart.feasible.markers_only = chart.infeasible.markers_only = true;
    chart.feasible.colour = report::kDarkGrey, chart.infeasible.colour = report::kLightGrey;
  }
  points([&](const report::SweepPoint& v) {
    for_each_swept(v, swept, [&](size_t k, double x) {
      SweepCharts& chart = charts[k];
      if (chart.seen++ % chart.stride != 0) return;
      for (size_t m = 0; m < modes.size(); ++m)
        if (const auto T = period_of(v, modes[m])) chart.modes[m].x.push_back(x), chart.modes[m].y.push_back(*T);
      const auto& y = v.ranked;
      if (c.ranking.objective.empty() || !y || !std::isfinite(*y)) return;
      report::ChartSeries& s = v.feasible ? chart.feasible : chart.infeasible;
      s.x.push_back(x);
      s.y.push_back(*y * ranked_scale(c.ranking));
    });
  });
  for (size_t k = 0; k < swept.size(); ++k) {
    SweepCharts& chart = charts[k];
    for (report::ChartSeries& s : chart.modes)
      if (!s.x.empty()) chart.periods.series.push_back(std::move(s));
    frame_points(&chart.periods);
    out << "<h3>" << parameter_heading(swept[k], Writer{true}) << "</h3>\n" << report::svg_chart(chart.periods);
    if (!c.ranking.objective.empty()) {
      for (auto* s : {&chart.feasible, &chart.infeasible})
        if (!s->x.empty()) chart.objective.series.push_back(std::move(*s));
      frame_points(&chart.objective);
      if (!chart.objective.series.empty()) out << report::svg_chart(chart.objective);
    }
    if (chart.stride > 1)
      out << "<p class=note>Every " << chart.stride << "th of " << swept[k].points << " variants is plotted.</p>\n";
  }
}

// Markdown cannot draw: the same as a table over the parameter's values (each value, or ten
// equal bins when a sample spreads them out).
struct Range {
  double min = INFINITY, max = -INFINITY;
  void add(double x) { min = std::min(min, x), max = std::max(max, x); }
  std::string text(int digits) const {
    if (!(min <= max)) return "–";
    return min == max ? significant(min, digits) : significant(min, digits) + "–" + significant(max, digits);
  }
};

struct SweepRow {
  int variants = 0, feasible = 0;
  Range objective;
  std::vector<Range> periods;
};

// A swept parameter's table being filled: its bins (or values) and their rows.
struct SweepTable {
  bool binned = false;
  double lo = 0.0, hi = 0.0;
  int bins = 0;
  std::vector<double> values;  ///< the distinct values, unbinned
  std::vector<SweepRow> rows;
  int bin_of(double x) const {
    if (!binned) return static_cast<int>(std::lower_bound(values.begin(), values.end(), x) - values.begin());
    return std::min(bins - 1, static_cast<int>((x - lo) / (hi - lo) * bins));
  }
};

std::vector<Table> sweep_tables(const Comparison& c, const std::vector<SweptParameter>& swept,
                                const VariantResult& reference, const report::SweepPoints& points) {
  std::vector<std::string> modes = period_modes(reference);
  if (modes.size() > 3) modes.resize(3);
  std::vector<SweepTable> tables(swept.size());
  for (size_t k = 0; k < swept.size(); ++k) {
    const SweptParameter& p = swept[k];
    SweepTable& t = tables[k];
    t.binned = p.distinct.size() > kListedValues;
    t.lo = p.lo, t.hi = p.hi;
    t.bins = t.binned ? 10 : static_cast<int>(p.distinct.size());
    t.values.assign(p.distinct.begin(), p.distinct.end());
    t.rows.assign(t.bins, SweepRow{0, 0, {}, std::vector<Range>(modes.size())});
  }
  points([&](const report::SweepPoint& v) {
    for_each_swept(v, swept, [&](size_t k, double x) {
      SweepRow& row = tables[k].rows[tables[k].bin_of(x)];
      ++row.variants;
      row.feasible += v.feasible;
      if (const auto& y = v.ranked; y && std::isfinite(*y)) row.objective.add(*y * ranked_scale(c.ranking));
      for (size_t m = 0; m < modes.size(); ++m)
        if (const auto T = period_of(v, modes[m])) row.periods[m].add(*T);
    });
  });
  std::vector<Table> out;
  for (size_t k = 0; k < swept.size(); ++k) {
    const SweepTable& s = tables[k];
    Table t;
    t.headers = {axis_label(swept[k], true), "variants", "feasible"};
    if (!c.ranking.objective.empty()) t.headers.push_back(ranked_label(c.ranking, true));
    for (const auto& m : modes) t.headers.push_back("T " + m + " [s]");
    t.numeric.assign(t.headers.size(), true);
    for (int b = 0; b < s.bins; ++b) {
      if (s.rows[b].variants == 0) continue;
      const std::string value = s.binned ? significant(s.lo + (s.hi - s.lo) * b / s.bins, 4) + "–" +
                                               significant(s.lo + (s.hi - s.lo) * (b + 1) / s.bins, 4)
                                         : significant(s.values[b], 6);
      std::vector<std::string> cells{value, std::to_string(s.rows[b].variants), std::to_string(s.rows[b].feasible)};
      if (!c.ranking.objective.empty()) cells.push_back(s.rows[b].objective.text(4));
      for (const Range& r : s.rows[b].periods) cells.push_back(r.text(4));
      t.rows.push_back(cells);
    }
    out.push_back(std::move(t));
  }
  return out;
}

// ---- response curves of the best designs ------------------------------------------------------

struct CurveKey {
  int source;
  std::string output;
  ResponseQuantity quantity;
  bool operator==(const CurveKey& o) const { return source == o.source && output == o.output && quantity == o.quantity; }
};

const AmplitudeCurve* find_curve(const CriticalSpeedStudy& st, const CurveKey& key, int* index) {
  for (size_t i = 0; i < st.curves.size(); ++i)
    if (CurveKey{st.curves[i].source, st.curves[i].output, st.curves[i].quantity} == key) {
      *index = static_cast<int>(i);
      return &st.curves[i];
    }
  return nullptr;
}

std::vector<CurveKey> curve_keys(const std::vector<DesignCurves>& sets) {
  std::vector<CurveKey> keys;
  if (sets.empty()) return keys;
  for (const AmplitudeCurve& curve : sets.front().study.curves)
    if (keys.size() < kCurveCharts) keys.push_back({curve.source, curve.output, curve.quantity});
  return keys;
}

// A curve's title, its source named with its wavelength (report::source_legend) when the drawn
// designs share it; a study that sweeps it (the rail length) says it is each variant's own.
std::string curve_title(const std::vector<DesignCurves>& sets, const CurveKey& key) {
  const ExcitationSource& source = *sets.front().study.scene.sources.at(key.source);
  const bool shared = std::all_of(sets.begin(), sets.end(), [&](const DesignCurves& s) {
    const auto& sources = s.study.scene.sources;
    return static_cast<size_t>(key.source) < sources.size() &&
           sources[key.source]->wavelength() == source.wavelength();
  });
  std::string kind = source.kind();
  std::replace(kind.begin(), kind.end(), '_', ' ');
  const std::string name = shared ? report::source_legend(key.source, source.kind(), source.wavelength())
                                  : "[" + std::to_string(key.source + 1) + "] " + kind + ", Λ of each variant";
  return name + ": " + key.output + " " + to_string(key.quantity);
}

// The largest response on the grid and at the refined peaks (response::largest_response, as a
// variant's peak summary finds it); unbounded when the grid met an undamped resonance.
std::string peak_text(const CriticalSpeedStudy& st, const CurveKey& key) {
  int index = 0;
  if (!find_curve(st, key, &index)) return "–";
  const response::LargestResponse peak = response::largest_response(st, static_cast<size_t>(index));
  if (peak.unbounded) return "unbounded";
  const report::Unit u = report::unit_of(st.system, key.output, key.quantity);
  return significant(peak.amplitude * u.scale, 4) + " " + u.name + " at " + fixed(peak.speed * kKmh, 1) + " km/h";
}

Table peak_table(const std::vector<DesignCurves>& sets, const std::vector<CurveKey>& keys) {
  Table t;
  t.headers = {"variant"};
  for (const CurveKey& k : keys) t.headers.push_back(curve_title(sets, k) + ": peak");
  t.numeric.assign(t.headers.size(), true);
  t.numeric.front() = false;
  for (const DesignCurves& s : sets) {
    std::vector<std::string> row{s.label};
    for (const CurveKey& k : keys) row.push_back(peak_text(s.study, k));
    t.rows.push_back(row);
  }
  return t;
}

// The designs the curves and their tables show, as many as there are: "the base and the best 2
// variants by rank, feasible or not (an infeasible one marked so)". The text once said "the best
// 3" where one was drawn (user audit 2026-11-28b, F5).
std::string drawn_designs(const std::vector<DesignCurves>& sets) {
  const size_t best = static_cast<size_t>(std::count_if(sets.begin(), sets.end(), [](const DesignCurves& s) { return !s.base; }));
  const bool base = best < sets.size();
  if (best == 0) return "the base alone";
  const std::string variants = best == 1 ? "the best variant" : "the best " + std::to_string(best) + " variants";
  return (base ? "the base and " : "") + variants + " by rank, feasible or not (an infeasible one marked so)";
}

// What the peaks and curves leave out of a design with leaf friction, as critical-speed's note
// says it (friction_model_note there), "" when no design drawn has any: with Coulomb friction in
// the resonance criterion only, "unbounded" beside "friction stops it" in the same report read as
// a contradiction (user audit 2026-11-28b, F6).
std::string friction_caption(const std::vector<DesignCurves>& sets) {
  for (const DesignCurves& s : sets) {
    if (s.study.curves.empty() || !has_leaf_friction(s.study.system)) continue;
    if (const double x = s.study.scene.friction_reference_amplitude; x > 0.0)
      return " Leaf friction: as the scene asks, an equivalent viscous damping for a spring stretch amplitude of " +
             significant(x * 1e3, 4) + " mm, an approximation whose peaks depend on that choice.";
    return " Leaf friction: Coulomb, in the resonance criterion only: these amplitudes are those of the "
           "frictionless linear model, so a resonance reads unbounded here even where friction stops it (the "
           "critical-speed report says which; the permissible deflections below take friction).";
  }
  return "";
}

void write_curve_charts(std::ostream& out, const std::vector<DesignCurves>& sets, const std::vector<CurveKey>& keys) {
  for (size_t k = 0; k < keys.size(); ++k) {
    const CriticalSpeedStudy& first = sets.front().study;
    const report::Unit u = report::unit_of(first.system, keys[k].output, keys[k].quantity);
    report::Chart chart;
    chart.id = "curves-" + std::to_string(k + 1);
    chart.title = curve_title(sets, keys[k]);
    chart.x_label = "speed (km/h)";
    chart.y_label = std::string(to_string(keys[k].quantity)) + " amplitude (" + u.name + ")";
    chart.log_y = true;
    chart.x_min = INFINITY;
    chart.x_max = -INFINITY;
    for (size_t v = 0; v < sets.size(); ++v) {
      const DesignCurves& s = sets[v];
      int index = 0;
      const AmplitudeCurve* curve = find_curve(s.study, keys[k], &index);
      if (!curve) continue;
      report::ChartSeries series;
      series.label = s.label;
      series.dashed = s.base;
      series.colour = static_cast<int>(v);  // the variant's own colour in every chart, a curve missing or not
      for (size_t i = 0; i < curve->speeds.size(); ++i) {
        series.x.push_back(curve->speeds[i] * kKmh);
        series.y.push_back(curve->unbounded[i] ? NAN : curve->amplitudes[i] * u.scale);
        if (curve->unbounded[i]) series.unbounded_x.push_back(curve->speeds[i] * kKmh);
      }
      chart.x_min = std::min(chart.x_min, s.study.scene.min_speed * kKmh);
      chart.x_max = std::max(chart.x_max, s.study.scene.max_speed * kKmh);
      chart.series.push_back(series);
    }
    out << report::svg_chart(chart);
  }
}

// ---- the ranked ride metric against speed ------------------------------------------------------

// The ride metric the study ranks by: its first in the objective, else in the constraints; "".
std::string ranked_ride_metric(const Ranking& ranking) {
  for (const RankingCriterion& c : ranking.objective)
    if (study::names_ride(c.metric)) return c.metric;
  for (const RankingConstraint& c : ranking.constraints)
    if (study::names_ride(c.metric)) return c.metric;
  return "";
}

// What the ride metric is at one speed (the metric is its largest over the speeds).
std::string ride_metric_at_speed_title(const std::string& metric) {
  if (metric == "max_nmv") return "N_MV (estimate) at the worst floor point";
  if (metric == "max_wz") return "Sperling Wz of the worst output";
  return "RMS of " + study::ride_output_of(metric);
}

// The ride metric at one speed, SI, and what an N_MV there covers (ride::nmv_scope: "vertical
// only" when its floor point has no lateral or no vertical output; "" otherwise).
struct RideMetricAtSpeed {
  double value = NAN;
  std::string scope;
};

// The metric at each of the ride's speeds, as study/metrics.cpp takes its largest: N_MV the
// largest over the floor points (the first of equals, as VariantResult::max_nmv_partial), Wz over
// the outputs, an RMS of its output; NaN where unbounded (an undamped mode the track excites) or
// absent.
std::vector<RideMetricAtSpeed> ride_metric_at_speeds(const RideResult& ride, const std::string& metric) {
  std::vector<RideMetricAtSpeed> out;
  const std::string output = study::ride_output_of(metric);
  for (const RideAtSpeed& at : ride.speeds) {
    double v = NAN;
    std::string scope;
    if (metric == "max_nmv") {
      for (const RideComfortAtPoint& c : at.comfort)
        if (std::isnan(v) || c.nmv_estimate > v) v = c.nmv_estimate, scope = ride::nmv_scope(c);
    } else {
      bool unbounded = false;
      for (size_t i = 0; i < ride.outputs.size(); ++i) {
        const RideOutputAtSpeed& o = at.outputs[i];
        if (metric == "max_wz") {
          unbounded = unbounded || o.unbounded;
          if (o.sperling_wz) v = std::isnan(v) ? *o.sperling_wz : std::max(v, *o.sperling_wz);
        } else if (ride.outputs[i].name == output) {
          unbounded = o.unbounded;
          v = o.rms;
        }
      }
      if (unbounded) v = NAN;
    }
    out.push_back({v, scope});
  }
  return out;
}

// One row per design: the metric at each ride speed, in the metric's display unit; a partial
// N_MV says what it covers, "0.76 (vertical only)", as the ride's tables and compare's ranked
// table write it.
Table ride_table(const std::vector<DesignCurves>& sets, const std::string& metric) {
  Table t;
  t.headers = {"variant"};
  const DesignCurves* first = nullptr;
  for (const DesignCurves& s : sets)
    if (s.ride && !first) first = &s;
  for (const RideAtSpeed& at : first->ride->speeds) t.headers.push_back(significant(at.speed * kKmh, 6) + " km/h");
  t.numeric.assign(t.headers.size(), true);
  t.numeric.front() = false;
  for (const DesignCurves& s : sets) {
    if (!s.ride) continue;
    std::vector<std::string> row{s.label};
    for (const RideMetricAtSpeed& at : ride_metric_at_speeds(*s.ride, metric))
      row.push_back(std::isnan(at.value) ? "unbounded"
                                         : study::shown_as_tabled(metric, at.value) + scope_suffix(at.scope));
    t.rows.push_back(row);
  }
  return t;
}

void write_ride_chart(std::ostream& out, const std::vector<DesignCurves>& sets, const std::string& metric) {
  const study::DisplayUnit u = study::display_unit(metric);
  report::Chart chart;
  chart.id = "ride-1";
  chart.title = ride_metric_at_speed_title(metric);
  chart.x_label = "speed (km/h)";
  // A dimensionless index (Wz, N_MV) says so, as the ride report's "Wz (–)" does.
  chart.y_label = ride_metric_at_speed_title(metric) + " (" + (*u.unit ? u.unit : "–") + ")";
  for (size_t v = 0; v < sets.size(); ++v) {
    const DesignCurves& s = sets[v];
    if (!s.ride) continue;
    report::ChartSeries series;
    series.label = s.label;
    series.dashed = s.base;
    series.colour = static_cast<int>(v);
    const std::vector<RideMetricAtSpeed> values = ride_metric_at_speeds(*s.ride, metric);
    for (size_t i = 0; i < values.size(); ++i) {
      series.x.push_back(s.ride->speeds[i].speed * kKmh);
      series.y.push_back(values[i].value * u.per_si);
      if (std::isnan(values[i].value)) series.unbounded_x.push_back(s.ride->speeds[i].speed * kKmh);
    }
    chart.series.push_back(series);
  }
  out << report::svg_chart(chart);
}

bool any_ride(const std::vector<DesignCurves>& sets) {
  return std::any_of(sets.begin(), sets.end(), [](const DesignCurves& s) { return s.ride.has_value(); });
}

// ---- permissible dynamic deflections ------------------------------------------------------------

std::string rule_text(const DeflectionRule& rule) {
  std::string s;
  if (rule.book == DeflectionRule::Book::korotkevich)
    s = std::string("Korotkevich's limits for ") + to_string(rule.service) + " cars (springs digest §5)";
  else if (rule.book == DeflectionRule::Book::lehner)
    s = std::string("Lehner's limits for ") + to_string(rule.service) + " cars (springs digest §5)";
  if (!rule.element_limits.empty()) s += std::string(s.empty() ? "L" : ", with l") + "imits the study sets on named elements";
  return s + ". Each check is the largest dynamic deflection over every source and speed of the scene against "
             "its limit. A resonance that leaf friction does not stop is unbounded; otherwise friction is "
             "linearised at the limit itself, so the ratio decides, and with friction the deflection behind it is "
             "not the amplitude the spring reaches (docs/studies.md, \"Permissible dynamic deflections\").";
}

// The checks of the base and the best variants: one row per limit (basis), for the element
// that comes closest to it (or exceeds it most), with how many elements share that limit.
Table deflection_table(const Comparison& c, const ComparisonCurves& curves) {
  Table t;
  t.headers = {"variant", "limit", "permissible", "worst element", "its largest dynamic deflection", "at", "verdict"};
  t.numeric = {false, false, true, false, true, true, false};
  std::vector<const RankedVariant*> shown;
  if (const RankedVariant* base = comparison_base(c)) shown.push_back(base);
  for (const RankedVariant* v : best_designs(c, kReportBest)) shown.push_back(v);
  auto ratio = [](const VariantResult::DeflectionCheck& d) { return d.unbounded ? INFINITY : d.deflection / d.permissible; };
  for (const RankedVariant* v : shown) {
    const VariantResult& r = v->result;
    if (!r.ok()) continue;
    // An infeasible design says so, as its curves' legend does (comparison_curves).
    const std::string name = r.name + (v->feasible ? "" : " (infeasible)");
    if (r.deflections.empty()) t.rows.push_back({name, "no spring the rule limits", "–", "–", "–", "–", "–"});
    std::vector<std::string> bases;
    for (const auto& d : r.deflections)
      if (std::find(bases.begin(), bases.end(), d.basis) == bases.end()) bases.push_back(d.basis);
    for (const std::string& basis : bases) {
      const VariantResult::DeflectionCheck* worst = nullptr;
      int count = 0;
      for (const auto& d : r.deflections)
        if (d.basis == basis) {
          ++count;
          if (!worst || ratio(d) > ratio(*worst)) worst = &d;
        }
      const std::string stage = worst->stage.empty() ? "" : " (" + worst->stage + " stage)";
      const std::string end = worst->unbounded ? "" : range_end(curves, r.index, worst->speed);
      t.rows.push_back({name, basis, fixed(worst->permissible * 1000.0, 1) + " mm",
                        worst->element + stage + (count > 1 ? ", worst of " + std::to_string(count) : ""),
                        worst->unbounded
                            ? "unbounded: a resonance friction does not stop"
                            : fixed(100.0 * worst->deflection / worst->permissible, 1) + " % of permissible",
                        fixed(worst->speed * kKmh, 1) + " km/h, source " + std::to_string(worst->source + 1) +
                            (end.empty() ? "" : " (" + end + ")"),
                        worst->kept() ? "within the limit" : "exceeds the limit"});
    }
  }
  return t;
}

// ---- the documents ------------------------------------------------------------------------------

std::string ranking_text(const Comparison& c) {
  if (c.ranking.objective.empty()) return "No objective: the variants keep study order, feasible first.";
  std::string s = c.ranking.weighted ? "Weighted objective: minimise " : "Lexicographic objective: ";
  for (size_t k = 0; k < c.ranking.objective.size(); ++k) {
    const RankingCriterion& crit = c.ranking.objective[k];
    if (c.ranking.weighted)
      s += std::string(k ? " + " : "") + significant(crit.weight, 6) + " × " + (crit.maximise ? "(−" : "") +
           study::title(crit.metric) + (crit.maximise ? ")" : "");
    else
      s += std::string(k ? ", then " : "") + goal(crit);
  }
  return s + ".";
}

const VariantResult* reference_result(const Comparison& c) {
  if (const RankedVariant* base = comparison_base(c); base && base->result.ok()) return &base->result;
  for (const RankedVariant& v : c.variants)
    if (v.result.ok()) return &v.result;
  return nullptr;
}

void write_markdown(std::ostream& out, const Study& study, const Comparison& c, const report::DocumentTally& tally,
                    const report::SweepPoints& points, const ComparisonCurves& curves, const Provenance& provenance) {
  const Writer w{false};
  out << "# Design comparison: " << c.study << "\n\nStudy `" << study.source << "`, " << tally.variants
      << " variants. " << ranking_text(c) << "\n\n## Why the winner wins\n\n";
  for (const std::string& s : verdict(c, w, tally, curves)) out << "- " << s << "\n";
  out << "\n## Ranked variants\n\n";
  report::write_markdown_table(out, ranked_table(c));
  if (const std::string note = table_note(tally); !note.empty()) out << note << "\n\n";
  const std::vector<SweptParameter> swept = swept_parameters(study, points);
  const VariantResult* reference = reference_result(c);
  if (!swept.empty() && reference) {
    out << "## Swept parameters\n\nRanges over the variants at each value: the periods of the lowest modes and "
           "the value ranked first. The plots are in the HTML report (`--format html`).\n\n";
    const std::vector<Table> tables = sweep_tables(c, swept, *reference, points);
    for (size_t k = 0; k < swept.size(); ++k) {
      out << "### " << parameter_heading(swept[k], w) << "\n\n";
      report::write_markdown_table(out, tables[k]);
    }
  }
  const std::vector<DesignCurves>& sets = curves.designs;
  if (const std::vector<CurveKey> keys = curve_keys(sets); !keys.empty()) {
    out << "## Peak responses of the best variants\n\nThe largest amplitude of each output over the speed range, "
           "for " << drawn_designs(sets) << "; the curves are in the HTML report." << friction_caption(sets) << "\n\n";
    report::write_markdown_table(out, peak_table(sets, keys));
  }
  if (const std::string metric = ranked_ride_metric(c.ranking); !metric.empty() && any_ride(sets)) {
    out << "## " << ride_metric_at_speed_title(metric) << " against speed\n\nAt each speed of the scene's ride, "
           "for " << drawn_designs(sets) << " (" << study::title(metric)
        << " is the largest over these speeds); the chart is in the HTML report.\n\n";
    report::write_markdown_table(out, ride_table(sets, metric));
  }
  if (c.deflection_rule.active()) {
    out << "## Permissible dynamic deflections\n\n" << rule_text(c.deflection_rule) << "\n\n";
    report::write_markdown_table(out, deflection_table(c, curves));
  }
  for (const std::string& n : curves.notes) out << n << "\n\n";
  for (const std::string& n : study.notes) out << n << "\n\n";  // the periods' notes, once
  out << "---\n\nWritten by " << report::provenance_line("compare", provenance) << "\n";
}

void write_html(std::ostream& out, const Study& study, const Comparison& c, const report::DocumentTally& tally,
                const report::SweepPoints& points, const ComparisonCurves& curves, const Provenance& provenance) {
  const Writer w{true};
  report::write_html_head(out, "Design comparison: " + c.study);
  out << "<h1>Design comparison: " << html_escape(c.study) << "</h1>\n<p>Study <code>" << html_escape(study.source)
      << "</code>, " << tally.variants << " variants. " << html_escape(ranking_text(c)) << "</p>\n";
  out << "<h2>Why the winner wins</h2>\n<ul>\n";
  for (const std::string& s : verdict(c, w, tally, curves)) out << "<li>" << s << "</li>\n";
  out << "</ul>\n<h2>Ranked variants</h2>\n";
  report::write_html_table(out, ranked_table(c));
  if (const std::string note = table_note(tally); !note.empty()) out << "<p class=note>" << html_escape(note) << "</p>\n";
  const std::vector<SweptParameter> swept = swept_parameters(study, points);
  const VariantResult* reference = reference_result(c);
  if (!swept.empty() && reference) {
    out << "<h2>Swept parameters</h2>\n<p class=note>Each evaluated variant is a point: the periods of the "
           "lowest modes and the value ranked first against each parameter the study varies (points at one value "
           "differ in the other parameters). Colours: each mode its own, feasible dark grey, infeasible light grey; "
           "the variants of the amplitude charts below take colours of their own.</p>\n";
    write_sweep_charts(out, c, swept, *reference, points);
  }
  const std::vector<DesignCurves>& sets = curves.designs;
  if (const std::vector<CurveKey> keys = curve_keys(sets); !keys.empty()) {
    out << "<h2>Amplitude against speed: the best variants over the base</h2>\n<p class=note>Drawn: "
        << html_escape(drawn_designs(sets))
        << ", the base dashed. Each curve sums its source's harmonics; logarithmic scale; gaps are undamped "
           "resonances (unbounded)."
        << html_escape(friction_caption(sets)) << "</p>\n";
    write_curve_charts(out, sets, keys);
    report::write_html_table(out, peak_table(sets, keys));
  }
  if (const std::string metric = ranked_ride_metric(c.ranking); !metric.empty() && any_ride(sets)) {
    out << "<h2>" << html_escape(ride_metric_at_speed_title(metric)) << " against speed: the best variants over the "
           "base</h2>\n<p class=note>At each speed of the scene's ride, for "
        << html_escape(drawn_designs(sets)) << ", the base dashed. The ranked value (" << html_escape(study::title(metric))
        << ") is the largest over these speeds.</p>\n";
    write_ride_chart(out, sets, metric);
    report::write_html_table(out, ride_table(sets, metric));
  }
  if (c.deflection_rule.active()) {
    out << "<h2>Permissible dynamic deflections</h2>\n<p class=note>" << html_escape(rule_text(c.deflection_rule))
        << "</p>\n";
    report::write_html_table(out, deflection_table(c, curves));
  }
  for (const std::string& n : curves.notes) out << "<p class=note>" << html_escape(n) << "</p>\n";
  for (const std::string& n : study.notes) out << "<p class=note>" << html_escape(n) << "</p>\n";
  report::write_html_footer(out, "compare", provenance);
}

}  // namespace

report::SweepPoint report::sweep_point(const RankedVariant& v, const Ranking& ranking) {
  SweepPoint point;
  point.feasible = v.feasible;
  point.ranked = ranked_value(v, ranking);
  point.parameters = v.result.parameters;
  for (const auto& m : v.result.modes)
    if (m.kind == "oscillatory") point.periods.emplace_back(m.name, m.period_s);
  return point;
}

namespace {

// The bytes of a sweep point: sizes and numbers in this machine's representation (the file
// they go to is read back by the same process), strings as their size and bytes.
void put(std::string* bytes, const void* data, size_t size) { bytes->append(static_cast<const char*>(data), size); }
void put_size(std::string* bytes, size_t n) { put(bytes, &n, sizeof n); }
void put_double(std::string* bytes, double x) { put(bytes, &x, sizeof x); }
void put_text(std::string* bytes, const std::string& s) { put_size(bytes, s.size()), bytes->append(s); }

// Reads what put wrote, in order; std::invalid_argument past the end.
struct Reader {
  const std::string& bytes;
  size_t at = 0;
  void get(void* data, size_t size) {
    if (size > bytes.size() - at) throw std::invalid_argument("a sweep point's bytes end early");
    std::memcpy(data, bytes.data() + at, size);
    at += size;
  }
  size_t size() {
    size_t n = 0;
    get(&n, sizeof n);
    return n;
  }
  double number() {
    double x = 0.0;
    get(&x, sizeof x);
    return x;
  }
  std::string text() {
    std::string s(size(), '\0');
    get(s.data(), s.size());
    return s;
  }
};

}  // namespace

std::string report::to_bytes(const SweepPoint& point) {
  std::string bytes;
  put_size(&bytes, point.feasible ? 1 : 0);
  put_size(&bytes, point.ranked ? 1 : 0);
  put_double(&bytes, point.ranked.value_or(0.0));
  put_size(&bytes, point.parameters.size());
  for (const auto& [key, value] : point.parameters) put_text(&bytes, key), put_text(&bytes, value);
  put_size(&bytes, point.periods.size());
  for (const auto& [name, period] : point.periods) put_text(&bytes, name), put_double(&bytes, period);
  return bytes;
}

report::SweepPoint report::sweep_point_from_bytes(const std::string& bytes) {
  Reader in{bytes};
  SweepPoint point;
  point.feasible = in.size() != 0;
  const bool ranked = in.size() != 0;
  const double value = in.number();
  if (ranked) point.ranked = value;
  for (size_t n = in.size(), i = 0; i < n; ++i) {
    std::string key = in.text();
    point.parameters.emplace_back(std::move(key), in.text());
  }
  for (size_t n = in.size(), i = 0; i < n; ++i) {
    std::string name = in.text();
    point.periods.emplace_back(std::move(name), in.number());
  }
  return point;
}

void report::DocumentTally::add(const RankedVariant& v, const Ranking& ranking) {
  ++variants;
  feasible += v.feasible;
  violating.resize(ranking.constraints.size(), 0);
  if (!v.result.ok()) {
    ++failed;
    if (!failed_index || v.result.index < *failed_index)
      failed_index = v.result.index, failed_name = v.result.name, failure = v.result.failure;
    return;
  }
  for (size_t k = 0; k < ranking.constraints.size(); ++k) violating[k] += violates(v.result, ranking.constraints[k]);
}

void report::write_comparison_document(std::ostream& out, const Study& study, const Comparison& best,
                                       const DocumentTally& tally, const SweepPoints& points,
                                       const ComparisonCurves& curves, OutputFormat format,
                                       const Provenance& provenance) {
  DocumentTally counted = tally;
  counted.violating.resize(best.ranking.constraints.size(), 0);  // a study of no variant counts none
  switch (format) {
    case OutputFormat::markdown: write_markdown(out, study, best, counted, points, curves, provenance); break;
    case OutputFormat::html: write_html(out, study, best, counted, points, curves, provenance); break;
    default: throw std::invalid_argument("a comparison document is markdown or html, not " + std::string(to_string(format)));
  }
}

void write_comparison_report(std::ostream& out, const Study& study, const Comparison& comparison,
                             const ComparisonCurves& curves, OutputFormat format, const Provenance& provenance) {
  if (format != OutputFormat::markdown && format != OutputFormat::html)
    return write_comparison(out, comparison, format);
  report::DocumentTally tally;
  for (const RankedVariant& v : comparison.variants) tally.add(v, comparison.ranking);
  std::vector<const RankedVariant*> in_order;  // the evaluated variants in study order
  for (const RankedVariant& v : comparison.variants)
    if (v.result.ok()) in_order.push_back(&v);
  std::sort(in_order.begin(), in_order.end(), [](auto* a, auto* b) { return a->result.index < b->result.index; });
  const auto points = [&](const std::function<void(const report::SweepPoint&)>& visit) {
    for (const RankedVariant* v : in_order) visit(report::sweep_point(*v, comparison.ranking));
  };
  report::write_comparison_document(out, study, comparison, tally, points, curves, format, provenance);
}

}  // namespace railmodal
