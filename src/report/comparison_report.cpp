// The ranked comparison as a table, CSV or JSON, and the JSON of one shard's results.
// A shard's JSON holds every field of its results with doubles written to round trip, so a
// merge ranks exactly the numbers a single run would have ranked (src/input/shard_reader.cpp
// reads it back).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "railmodal/comparison_report.hpp"
#include "railmodal/hunting.hpp"
#include "railmodal/study.hpp"
#include "report/comparison_rows.hpp"
#include "report/json_writer.hpp"
#include "report/streamed_comparison.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"
#include "shortest_text.hpp"
#include "study/metrics.hpp"

namespace railmodal {
namespace {

using report::JsonWriter;

using report::kKmh;

std::vector<double> periods(const VariantResult& r) {
  std::vector<double> out;
  for (const auto& m : r.modes)
    if (m.kind == "oscillatory") out.push_back(m.period_s);
  return out;
}

// The critical speeds in km/h (scale kKmh) or m/s (scale 1): the JSON gives both lists, as
// critical-speed's gives speeds_kmh and speeds_m_s (docs/input.md, "Names and units in outputs").
std::vector<double> critical_speeds(const VariantResult& r, double scale) {
  std::vector<double> out;
  for (const auto& c : r.critical_speeds) out.push_back(c.speed * scale);
  return out;
}

// A ranking value of `metric`: a number; +∞ the word the tables print for it ("none": no critical
// speed in the range; "unbounded": an undamped peak), as dynamic_deflection_ratio writes it; a
// hunting speed stable over the whole scan the scan's top, a number as the speeds are (the
// variant's hunting_speed_above_range says it is a bound); null only for no value (a failed
// variant, a vehicle without wheelsets for hunting_speed), so that the two never read alike.
void ranking_value(JsonWriter& j, const std::optional<double>& x, const std::string& metric) {
  if (x && std::isinf(*x) && *x > 0 && canonical_metric(metric) == "hunting_speed")
    j.value(HuntingOptions{}.max_speed);
  else if (x && std::isinf(*x) && *x > 0)
    j.value(study::infinite_word(metric));
  else
    j.value(x);  // null for none, and for NaN or −∞
}

void write_modes(JsonWriter& j, const VariantResult& r) {
  j.key("modes").begin_array();
  for (const auto& m : r.modes) {
    j.begin_object().member("divergence_rate_per_s", m.divergence_rate).member("frequency_hz", m.frequency_hz);
    j.member("kind", m.kind).member("name", m.name).member("period_s", m.period_s).end_object();
  }
  j.end_array();
}

// A source is written by its number in the scene from 1 (`source_index`), as critical-speed's
// JSON and the tables' "[1] rail_joints" number it; `source_kind` is its kind.
void write_critical_speeds(JsonWriter& j, const VariantResult& r) {
  j.key("critical_speeds").begin_array();
  for (const auto& c : r.critical_speeds) {
    j.begin_object().member("friction_stops", c.friction_stops).member("harmonic", c.harmonic);
    j.member("mode_name", c.mode_name).member("source_index", c.source + 1).member("source_kind", c.source_kind);
    j.member("speed_kmh", c.speed * kKmh).member("speed_m_s", c.speed).end_object();
  }
  j.end_array();
}

void write_deflections(JsonWriter& j, const VariantResult& r) {
  j.key("dynamic_deflections").begin_array();
  for (const auto& c : r.deflections) {
    j.begin_object().member("basis", c.basis).member("deflection_m", c.deflection).member("element", c.element);
    j.member("kept", c.kept()).member("permissible_m", c.permissible).member("source_index", c.source + 1);
    j.member("speed_kmh", c.speed * kKmh).member("speed_m_s", c.speed).member("stage", c.stage);
    j.member("unbounded", c.unbounded).end_object();
  }
  j.end_array();
}

void write_peaks(JsonWriter& j, const VariantResult& r) {
  j.key("peaks").begin_array();
  for (const auto& p : r.peaks) {
    j.begin_object().member("amplitude", p.amplitude).member("output", p.output).member("quantity", p.quantity);
    j.member("source_index", p.source + 1).member("speed_kmh", p.speed * kKmh).member("speed_m_s", p.speed);
    j.member("unbounded", p.unbounded).end_object();
  }
  j.end_array();
}

void write_ride(JsonWriter& j, const VariantResult& r) {
  j.key("ride").begin_array();
  for (const auto& o : r.ride) {
    j.begin_object().member("max_rms", o.max_rms).member("max_wz", o.max_wz).member("output", o.output);
    j.member("unbounded", o.unbounded).member("unit", o.unit).end_object();
  }
  j.end_array();
}

// Objective criterion k's metric ("" past the objective).
std::string criterion_metric(const Comparison& c, size_t k) {
  return k < c.ranking.objective.size() ? c.ranking.objective[k].metric : std::string();
}

// The objective is +∞ through its criteria: it takes the word of the first that is.
std::string objective_metric(const Comparison& c, const RankedVariant& v) {
  for (size_t k = 0; k < v.criteria.size(); ++k)
    if (v.criteria[k] && std::isinf(*v.criteria[k])) return criterion_metric(c, k);
  return "";
}

// What a comparison adds to a variant's results: its place in the ranking.
struct RankingMembers {
  const Comparison& comparison;
  const RankedVariant& variant;
};

// One variant's results, and with `ranked` its ranking, as one object whose members come in
// alphabetical order, as the files had them (json_writer.hpp). Optional members are written only
// when the study asks for them, so that a study without them writes what it always wrote.
void write_result(JsonWriter& j, const VariantResult& r, const RankingMembers* ranked) {
  std::optional<double> ratio;
  if (ranked && r.deflections_checked) ratio = metric_value(r, "dynamic_deflection_ratio");
  j.begin_object();
  if (ranked) {
    const RankedVariant& v = ranked->variant;
    j.key("criteria").begin_array();
    for (size_t k = 0; k < v.criteria.size(); ++k) ranking_value(j, v.criteria[k], criterion_metric(ranked->comparison, k));
    j.end_array();
    if (r.critical_speeds_evaluated) {  // absent, not empty, when the study asked for none
      write_critical_speeds(j, r);
      j.member("critical_speeds_kmh", critical_speeds(r, kKmh)).member("critical_speeds_m_s", critical_speeds(r, 1.0));
    }
    if (r.deflections_checked) {
      j.key("dynamic_deflection_ratio");
      ratio && std::isinf(*ratio) ? j.value("unbounded") : j.value(ratio);
    }
  } else {
    write_critical_speeds(j, r);
  }
  if (r.deflections_checked) write_deflections(j, r);
  j.key("failure");
  r.ok() ? j.value(nullptr) : j.value(r.failure);
  if (ranked) j.member("feasible", ranked->variant.feasible);
  if (r.hunting_speed && ranked) {
    // Stable over the whole scan: its top, a number, and the flag that it is a bound ("above
    // 500" in the tables, as `railmodal stability` says it; user audit 2026-11-28, F4).
    const bool above = std::isinf(*r.hunting_speed);
    const double speed = above ? HuntingOptions{}.max_speed : *r.hunting_speed;
    j.member("hunting_speed_above_range", above);
    j.member("hunting_speed_kmh", speed * kKmh).member("hunting_speed_m_s", speed);
  } else if (r.hunting_speed) {  // a shard: +∞ as "none", read back exactly (shard_reader)
    j.key("hunting_speed_kmh");
    std::isinf(*r.hunting_speed) ? j.value("none") : j.value(*r.hunting_speed * kKmh);
    j.key("hunting_speed_m_s");
    std::isinf(*r.hunting_speed) ? j.value("none") : j.value(*r.hunting_speed);
  }
  j.member("index", r.index);
  if (ranked && r.deflections_checked) {
    j.key("keeps_permissible_deflections");
    ratio ? j.value(*ratio <= 1.0) : j.value(nullptr);
  }
  if (r.ride_evaluated) j.member("max_nmv", r.max_nmv);
  // A partial N_MV says so beside its figure, as the ride's "partial" (absent when it is over
  // the lateral and vertical axes); shards carry it, so that a merge labels what one run would.
  if (!r.max_nmv_partial.empty()) j.member("max_nmv_partial", r.max_nmv_partial);
  j.member("metacentric_height_m", r.metacentric_height);
  write_modes(j, r);
  j.member("name", r.name);
  if (ranked) {
    j.key("objective");
    ranking_value(j, ranked->variant.objective, objective_metric(ranked->comparison, ranked->variant));
  }
  j.key("parameters").begin_array();
  for (const auto& [key, value] : r.parameters) j.begin_object().member("key", key).member("value", value).end_object();
  j.end_array();
  if (r.critical_speeds_evaluated) write_peaks(j, r);
  if (ranked) j.member("periods_s", periods(r)).member("rank", ranked->variant.rank);
  if (r.ride_evaluated) write_ride(j, r);
  j.key("static_deflections").begin_array();
  for (const auto& [body, deflection] : r.static_deflections)
    j.begin_object().member("body", body).member("deflection_m", deflection).end_object();
  j.end_array();
  if (ranked) j.member("violations", ranked->variant.violations);
  j.end_object();
}

void write_json(std::ostream& out, const Comparison& c, const std::vector<std::string>& notes = {}) {
  JsonWriter j(out);
  j.begin_object();
  if (!notes.empty()) j.member("notes", notes);  // the study's (Study::notes), once; absent without
  if (c.deflection_rule.active()) {
    j.key("permissible_dynamic_deflection").begin_object();
    j.member("rule", to_string(c.deflection_rule.book)).member("service", to_string(c.deflection_rule.service));
    j.end_object();
  }
  j.key("ranking").begin_object();
  j.key("constraints").begin_array();
  for (const auto& k : c.ranking.constraints)
    j.begin_object().member("max", k.max).member("metric", k.metric).member("min", k.min).end_object();
  j.end_array();
  j.member("method", c.ranking.weighted ? "weighted" : "lexicographic");
  j.key("objective").begin_array();
  for (const auto& k : c.ranking.objective)
    j.begin_object().member("goal", k.maximise ? "max" : "min").member("metric", k.metric).member("weight", k.weight).end_object();
  j.end_array();
  j.end_object();
  j.member("study", c.study);
  j.key("variants").begin_array();
  for (const RankedVariant& v : c.variants) {
    const RankingMembers ranked{c, v};
    write_result(j, v.result, &ranked);
  }
  j.end_array();
  j.end_object();
}

// A number in the table's cells to `decimals`, as report::fixed writes it; "none" for +∞, "-inf"
// for −∞, and "-" for NaN, the table's mark of a value not there (the CSV leaves it blank and
// JSON writes null).
std::string number(double x, int decimals) {
  if (std::isnan(x)) return "-";
  if (std::isinf(x)) return x > 0 ? "none" : "-inf";
  return report::fixed(x, decimals);
}

// The shortest text that reads back as the same double (CSV is for programs), appended to `text`;
// nothing for a non-finite value.
void append_exact(std::string* text, double x) {
  if (std::isfinite(x)) append_shortest_text(text, x);
}

const char* status(const RankedVariant& v) { return !v.result.ok() ? "failed" : v.feasible ? "yes" : "no"; }

// What a row needs of an objective criterion, worked out once per study rather than once per
// row (display_unit and infinite_is_unbounded look the metric up by its name).
struct CriterionColumn {
  double per_si;  // the display unit per SI unit
  std::string infinite;  // what +∞ reads as: "unbounded" (a peak), "above 500" (hunting), "none"
  std::string metric;
  int decimals;  // the table's (study::table_decimals)
  bool nmv;      // max_nmv: a partial one says what it covers, "0.76 (vertical only)", as the ride does
};

// The columns of a comparison's table and CSV, worked out once per study: each criterion; each
// metric a constraint names that no other column shows (the hunting speed a ride study is
// constrained by, say: a reader sees the value the constraint judges); the lowest critical
// speed only when the study computes critical speeds (variant_work_of), so that "none" never
// reads as "stable" where nothing was computed.
struct Columns {
  std::vector<CriterionColumn> criteria, constrained;
  bool critical_speeds = true;
  bool deflections = false;
  bool nmv = false;  // a column shows max_nmv: the CSV says what a partial one covers (max_nmv_partial)
};

CriterionColumn column_of(const std::string& metric) {
  return {study::display_unit(metric).per_si, study::infinite_word(metric), metric,
          study::table_decimals(metric), metric == "max_nmv"};
}

Columns columns_of(const Ranking& ranking, const DeflectionRule& rule) {
  Columns c;
  c.critical_speeds = variant_work_of(ranking, rule).critical_speeds;
  c.deflections = rule.active();
  for (const auto& k : ranking.objective) c.criteria.push_back(column_of(k.metric));
  const auto shown = [&](const std::string& metric) {
    if ((metric == "lowest_critical_speed" && c.critical_speeds) || metric == "static_deflection" ||
        (metric == "dynamic_deflection_ratio" && c.deflections))
      return true;  // a column of its own
    for (const auto* list : {&c.criteria, &c.constrained})
      for (const CriterionColumn& k : *list)
        if (k.metric == metric) return true;
    return false;
  };
  for (const auto& k : ranking.constraints)
    if (!shown(k.metric)) c.constrained.push_back(column_of(k.metric));
  c.nmv = shown("max_nmv");
  return c;
}

// metric_value(r, "lowest_critical_speed") and metric_value(r, "static_deflection")
// (study/metrics.cpp) without its look-up by name, which cost a row more than its numbers' text.
std::optional<double> lowest_critical_speed(const VariantResult& r) {
  if (!r.ok()) return std::nullopt;
  return r.critical_speeds.empty() ? std::numeric_limits<double>::infinity() : r.critical_speeds.front().speed;
}

// The mode of the lowest critical speed, the one a constraint on it binds: a column of its own
// could read as the bounce's where it is the pitch's (user audit 2026-11-28b, F8); "" for none.
const std::string& lowest_critical_mode(const VariantResult& r) {
  static const std::string none;
  return r.ok() && !r.critical_speeds.empty() ? r.critical_speeds.front().mode_name : none;
}

std::optional<double> body_deflection(const VariantResult& r) {
  if (!r.ok()) return std::nullopt;
  for (const auto& [body, deflection] : r.static_deflections)
    if (body == "body") return deflection;
  return std::nullopt;
}

// A variant's CSV row after its rank (a streamed ranking knows the rank only when it writes),
// appended to `row` field by field: numbers straight from to_chars, and only the fields that
// can hold any text (the name, the failure, the violations) looked at for quotes.
void append_csv_row(std::string* row, const Columns& columns, const RankedVariant& v) {
  const std::vector<CriterionColumn>& criteria = columns.criteria;
  const VariantResult& r = v.result;
  report::append_csv_field(row, r.name);
  *row += ',';
  *row += status(v);
  *row += ',';
  if (v.objective) append_exact(row, *v.objective);
  for (size_t k = 0; k < criteria.size(); ++k) {
    *row += ',';
    const std::optional<double> x = v.criteria.size() > k ? v.criteria[k] : std::nullopt;
    if (x && std::isinf(*x) && *x > 0) *row += criteria[k].infinite;  // as the constrained columns write it
    else if (x) append_exact(row, *x * criteria[k].per_si);
  }
  for (const CriterionColumn& k : columns.constrained) {
    *row += ',';
    const auto x = r.ok() ? metric_value(r, k.metric) : std::nullopt;
    if (x && std::isinf(*x) && *x > 0) *row += k.infinite;
    else if (x) append_exact(row, *x * k.per_si);
  }
  if (columns.critical_speeds) {
    *row += ',';
    if (const auto lowest = lowest_critical_speed(r)) append_exact(row, *lowest * kKmh);
    *row += ',';
    report::append_csv_field(row, lowest_critical_mode(r));
  }
  *row += ',';
  if (const auto deflection = body_deflection(r)) append_exact(row, *deflection * 1000.0);
  if (columns.deflections) {
    *row += ',';
    const auto ratio = r.ok() ? metric_value(r, "dynamic_deflection_ratio") : std::nullopt;
    if (ratio && std::isinf(*ratio)) *row += "unbounded";
    else if (ratio) append_exact(row, *ratio);
  }
  if (columns.nmv) {
    *row += ',';
    report::append_csv_field(row, r.max_nmv_partial);
  }
  *row += ',';
  size_t start = row->size();  // a list's items apart by a space, as the table has them
  for (const auto& m : r.modes)
    if (m.kind == "oscillatory") {
      if (row->size() > start) *row += ' ';
      append_exact(row, m.period_s);
    }
  if (columns.critical_speeds) {
    *row += ',';
    start = row->size();
    for (const auto& c : r.critical_speeds) {
      if (row->size() > start) *row += ' ';
      append_exact(row, c.speed * kKmh);
    }
  }
  *row += ',';
  report::append_csv_field(row, r.failure);
  *row += ',';
  std::string violations;
  for (const auto& w : v.violations) {
    if (!violations.empty()) violations += "; ";
    violations += w;
  }
  report::append_csv_field(row, violations);
}

std::string criterion_heading(const RankingCriterion& c) {
  const std::string unit = study::display_unit(c.metric).unit;
  return std::string(c.maximise ? "max " : "min ") + c.metric + (unit.empty() ? "" : " [" + unit + "]");
}

// For people: the metric as the docs name it and how it is ranked, "period of body bounce,
// maximised [s]" (the unit last, as in every table heading); CSV keeps the metric's name
// (criterion_heading).
std::string criterion_title(const RankingCriterion& c) {
  return study::title(c.metric) + (c.maximise ? ", maximised" : ", minimised") + study::table_unit_bracket(c.metric);
}

// The worst dynamic deflection against the permissible one, in % of it (the heading says so) to
// one decimal, and the verdict: "33.0 (within)", "130.2 (exceeds)".
std::string deflection_verdict(double ratio) {
  if (std::isinf(ratio)) return "unbounded (exceeds)";
  return number(100.0 * ratio, 1) + (ratio <= 1.0 ? " (within)" : " (exceeds)");
}

// The header: the table's names for people, the CSV's for programs (metric names, units in
// brackets, the extra columns).
std::vector<std::string> comparison_head(const Comparison& c, bool for_csv) {
  std::vector<std::string> head{"rank", "variant", "feasible"};
  if (for_csv) head.push_back("objective");
  for (const auto& k : c.ranking.objective) head.push_back(for_csv ? criterion_heading(k) : criterion_title(k));
  const Columns columns = columns_of(c.ranking, c.deflection_rule);
  for (const CriterionColumn& k : columns.constrained) {
    const std::string unit = study::display_unit(k.metric).unit;
    head.push_back(for_csv ? report::csv_heading(k.metric, unit) : study::title(k.metric) + study::table_unit_bracket(k.metric));
  }
  if (!for_csv) {
    if (columns.critical_speeds) head.push_back("lowest critical speed [km/h]");
    head.push_back("static deflection [mm]");
    if (columns.deflections) head.push_back("largest dynamic deflection [% of permissible]");
    head.push_back("periods [s]");
    return head;
  }
  if (columns.critical_speeds)
    for (const std::string& h : {report::csv_heading("lowest_critical_speed", "km/h"), std::string("lowest_critical_speed_mode")})
      head.push_back(h);
  head.push_back(report::csv_heading("static_deflection", "mm"));
  if (columns.deflections) head.push_back("dynamic_deflection_ratio");
  if (columns.nmv) head.push_back("max_nmv_partial");
  head.push_back(report::csv_heading("periods", "s"));
  if (columns.critical_speeds) head.push_back(report::csv_heading("critical_speeds", "km/h"));
  for (const char* h : {"failure", "violations"}) head.push_back(h);
  return head;
}

// A variant's row of comparison_rows (its rank is v.rank), the criteria's columns worked out
// once per study.
std::string shown_value(const CriterionColumn& k, const std::optional<double>& x, const VariantResult& r) {
  if (!x) return "-";
  if (std::isinf(*x) && *x > 0) return k.infinite;  // no critical speed in range, or above the hunting scan
  // Fixed decimals, so that a column's figures align at the point and differ by what matters
  // (study::table_figure, the notes' rule too).
  if (std::isnan(*x)) return "-";
  if (std::isinf(*x)) return "-inf";
  std::string text = study::table_figure(*x * k.per_si, k.decimals);
  if (k.nmv && !r.max_nmv_partial.empty()) text += " (" + r.max_nmv_partial + ")";
  return text;
}

std::vector<std::string> table_row(const Columns& columns, const RankedVariant& v) {
  const std::vector<CriterionColumn>& criteria = columns.criteria;
  const VariantResult& r = v.result;
  std::vector<std::string> row;
  row.reserve(7 + criteria.size() + columns.constrained.size());  // every column below: one allocation for the row, not five
  row.insert(row.end(), {std::to_string(v.rank), r.name, status(v)});
  for (size_t k = 0; k < criteria.size(); ++k)
    row.push_back(shown_value(criteria[k], v.criteria.size() > k ? v.criteria[k] : std::nullopt, r));
  for (const CriterionColumn& k : columns.constrained)
    row.push_back(shown_value(k, r.ok() ? metric_value(r, k.metric) : std::nullopt, r));
  if (columns.critical_speeds) {
    const auto lowest = lowest_critical_speed(r);
    const std::string& mode = lowest_critical_mode(r);
    row.push_back(!lowest ? "-" : number(*lowest * kKmh, 1) + (mode.empty() ? "" : " (" + mode + ")"));
  }
  const auto deflection = body_deflection(r);
  row.push_back(!deflection ? "-" : number(*deflection * 1000.0, 1));
  if (columns.deflections) {
    const auto ratio = r.ok() ? metric_value(r, "dynamic_deflection_ratio") : std::nullopt;
    row.push_back(!ratio ? "-" : deflection_verdict(*ratio));
  }
  std::string list;
  // Each item appended to the list as it is (a joined temporary per item was an allocation).
  for (double p : periods(r)) {
    if (!list.empty()) list += ' ';
    list += number(p, 3);
  }
  row.push_back(list);
  return row;
}

}  // namespace

std::vector<std::vector<std::string>> report::comparison_rows(const Comparison& c) {
  std::vector<std::vector<std::string>> rows{comparison_head(c, false)};
  const Columns columns = columns_of(c.ranking, c.deflection_rule);
  for (const RankedVariant& v : c.variants) rows.push_back(table_row(columns, v));
  return rows;
}

namespace {

// Display width: UTF-8 continuation bytes take no column.
size_t width(const std::string& s) {
  return static_cast<size_t>(std::count_if(s.begin(), s.end(), [](char ch) { return (static_cast<unsigned char>(ch) & 0xC0) != 0x80; }));
}

// The table's head: the study, the variants and how they are ranked.
void write_table_head(std::ostream& out, const Comparison& c, size_t count, size_t feasible) {
  out << "railmodal compare: " << c.study << "\n" << count << " variants, " << feasible << " feasible";
  if (!c.ranking.objective.empty()) {
    out << "; objective: ";
    for (size_t k = 0; k < c.ranking.objective.size(); ++k) {
      const auto& crit = c.ranking.objective[k];
      out << (k ? (c.ranking.weighted ? " + " : ", then ") : "") << study::title(crit.metric)
          << (crit.maximise ? " (maximised" : " (minimised");
      if (c.ranking.weighted) out << ", weight " << crit.weight;
      out << ")";
    }
  }
  out << "\n";
  for (const auto& k : c.ranking.constraints) {
    out << "constraint: " << study::title(k.metric);
    if (k.min) out << " >= " << study::shown(k.metric, *k.min);
    if (k.max) out << (k.min ? " and" : "") << " <= " << study::shown(k.metric, *k.max);
    out << "\n";
  }
  out << "\n";
}

// One pass over the table's rows in order (0 the heading, then the variants in rank order):
// each row's cells handed to `visit`, or with `notes` each variant's note alone (one cell, ""
// for none: why it failed, or what it violates; the heading has none and is not handed on).
using RowVisit = std::function<void(std::vector<std::string>&& row)>;
using TableRows = std::function<void(bool notes, const RowVisit& visit)>;

// The table: its rows in two passes (the column widths, then the lines), then a third for the
// notes under it. Passes rather than rows by number, so that a streamed ranking reads its kept
// rows from its file front to back (SpilledTexts::each_of) instead of one read a row.
void write_table_rows(std::ostream& out, const TableRows& rows) {
  std::vector<size_t> widths;
  rows(false, [&](std::vector<std::string>&& row) {
    widths.resize(std::max(widths.size(), row.size()), 0);
    for (size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], width(row[i]));
  });
  rows(false, [&](std::vector<std::string>&& row) {
    std::string line;
    for (size_t i = 0; i < row.size(); ++i) {
      const bool last = i + 1 == row.size();
      const bool right = i >= 3 && !last;  // numbers right-aligned
      const std::string pad(widths[i] - width(row[i]), ' ');
      line += right ? pad + row[i] : row[i] + (last ? "" : pad);
      if (!last) line += "  ";
    }
    out << line << "\n";
  });
  bool notes = false;
  rows(true, [&](std::vector<std::string>&& note) {
    if (note.front().empty()) return;
    if (!notes) out << "\n";
    notes = true;
    out << note.front() << "\n";
  });
}

// A variant's note under the table: why it failed, or the constraints it violates, for people;
// "" when it has none.
std::string table_note(const Ranking& ranking, const RankedVariant& v) {
  if (v.result.ok() && v.violations.empty()) return "";
  std::string note = v.result.name + ": ";
  if (!v.result.ok()) return note + "failed: " + v.result.failure;
  const auto words = study::violations(v.result, ranking, true);
  for (size_t k = 0; k < words.size(); ++k) note += (k ? "; " : "") + words[k];
  return note;
}

// The study's notes (Study::notes) after the table and its variants' notes, once.
void write_study_notes(std::ostream& out, const std::vector<std::string>& notes) {
  if (notes.empty()) return;
  out << "\n";
  for (const std::string& n : notes) out << n << "\n";
}

void write_table(std::ostream& out, const Comparison& c) {
  size_t feasible = 0;
  for (const auto& v : c.variants) feasible += v.feasible;
  write_table_head(out, c, c.variants.size(), feasible);
  const Columns columns = columns_of(c.ranking, c.deflection_rule);
  write_table_rows(out, [&](bool notes, const RowVisit& visit) {
    if (!notes) visit(comparison_head(c, false));
    for (const RankedVariant& v : c.variants)
      visit(notes ? std::vector<std::string>{table_note(c.ranking, v)} : table_row(columns, v));
  });
}

void write_csv_row(std::ostream& out, const std::vector<std::string>& row) {
  for (size_t i = 0; i < row.size(); ++i) {
    if (i > 0) out << ',';
    report::write_csv_field(out, row[i]);
  }
}

}  // namespace

void write_comparison(std::ostream& out, const Comparison& comparison, OutputFormat format) {
  switch (format) {
    case OutputFormat::table: write_table(out, comparison); break;
    case OutputFormat::csv: {
      write_csv_row(out, comparison_head(comparison, true));
      out << "\n";
      const Columns columns = columns_of(comparison.ranking, comparison.deflection_rule);
      std::string row;
      for (const RankedVariant& v : comparison.variants) {
        row = std::to_string(v.rank) + ',';
        append_csv_row(&row, columns, v);
        out << row << "\n";
      }
      break;
    }
    case OutputFormat::json: write_json(out, comparison); break;
    default:
      throw std::invalid_argument(report::unwritten_format("write_comparison", "table, csv or json", format) +
                                  " (the markdown and html reports need the study: write_comparison_report)");
  }
}

namespace {

// A cell appended to cells kept as one text: its length, ':' and its bytes (a name may hold any
// character).
void append_packed(std::string* text, std::string_view cell) {
  char length[24];
  text->append(length, std::to_chars(length, length + sizeof length, cell.size()).ptr);
  *text += ':';
  text->append(cell);
}

std::vector<std::string> unpacked(std::string_view text) {
  std::vector<std::string> cells;
  for (size_t at = 0; at < text.size();) {
    const size_t colon = text.find(':', at);
    const size_t length = std::stoul(std::string(text.substr(at, colon - at)));
    cells.emplace_back(text.substr(colon + 1, length));
    at = colon + 1 + length;
  }
  return cells;
}

// A variant's JSON object as it stands in the comparison's "variants" array, with its rank
// left out: "<where the rank goes>:<text>", the place zero-padded to kRankPlaceDigits so that
// the text is written after it in its place, not copied behind it.
constexpr size_t kRankPlaceDigits = 9;

std::string json_object(const Comparison& head, const RankedVariant& v) {
  std::string kept(kRankPlaceDigits, '0');
  kept += ":    ";  // the object's indentation as an element of "variants", two levels deep
  const size_t object = kept.size() - 4;
  {
    JsonWriter j(&kept, 2, 2);
    const RankingMembers ranked{head, v};
    write_result(j, v.result, &ranked);
  }
  // One member a line: the rank member is the only line of the object that reads so.
  const std::string_view rank = "\n      \"rank\": 0";
  const size_t at = kept.rfind(rank) + rank.size() - 1;
  kept.erase(at, 1);
  const std::string place = std::to_string(at - object);
  kept.replace(kRankPlaceDigits - place.size(), place.size(), place);
  return kept;
}

void write_streamed_json(std::ostream& out, const Comparison& head, const study::StreamedRanking& ranked,
                         const std::vector<std::string>& notes) {
  std::ostringstream document;
  write_json(document, head, notes);
  const std::string text = document.str();
  const std::string empty = "\"variants\": []";
  const size_t at = text.find(empty) + empty.size() - 1;  // before the closing bracket
  if (ranked.shown() == 0) {
    out << text;
    return;
  }
  out << text.substr(0, at);
  ranked.each_text([&](size_t rank, std::string_view kept) {
    const size_t colon = kept.find(':');
    const size_t split = std::stoul(std::string(kept.substr(0, colon)));
    out << (rank == 1 ? "\n" : ",\n");
    out.write(kept.data() + colon + 1, static_cast<std::streamsize>(split));
    out << rank;
    out.write(kept.data() + colon + 1 + split, static_cast<std::streamsize>(kept.size() - colon - 1 - split));
  });
  out << "\n  " << text.substr(at);
}

}  // namespace

study::StreamedRanking::Render report::streamed_row(const Ranking& ranking, const DeflectionRule& rule,
                                                   OutputFormat format) {
  switch (format) {
    case OutputFormat::table:
      return [ranking, columns = columns_of(ranking, rule)](const RankedVariant& v) {
        const std::vector<std::string> cells = table_row(columns, v);
        std::string text;
        for (size_t i = 1; i < cells.size(); ++i) append_packed(&text, cells[i]);  // the rank is not known yet
        append_packed(&text, table_note(ranking, v));
        return text;
      };
    case OutputFormat::csv:
      return [columns = columns_of(ranking, rule)](const RankedVariant& v) {
        std::string row;
        row.reserve(384);  // a row of the benchmark study is about 300 bytes: one allocation
        append_csv_row(&row, columns, v);
        return row;
      };
    case OutputFormat::json:
      return [head = std::make_shared<Comparison>(Comparison{"", "", ranking, rule, {}, {}})](const RankedVariant& v) {
        return json_object(*head, v);
      };
    default:
      throw std::invalid_argument(report::unwritten_format("streamed_row", "table, csv or json", format));
  }
}

void report::write_streamed_comparison(std::ostream& out, const Comparison& head, const study::StreamedRanking& ranked,
                                       OutputFormat format, const std::vector<std::string>& notes) {
  switch (format) {
    case OutputFormat::table: {
      write_table_head(out, head, ranked.size(), ranked.feasible());
      // A kept row: its cells after the rank, then its note; read in rank order, a pass at a time.
      write_table_rows(out, [&](bool notes, const RowVisit& visit) {
        if (!notes) visit(comparison_head(head, false));
        ranked.each_text([&](size_t rank, std::string_view text) {
          std::vector<std::string> cells = unpacked(text);
          if (notes) return visit({std::move(cells.back())});
          cells.pop_back();
          cells.insert(cells.begin(), std::to_string(rank));
          visit(std::move(cells));
        });
      });
      write_study_notes(out, notes);
      break;
    }
    case OutputFormat::csv:
      write_csv_row(out, comparison_head(head, true));
      out << "\n";
      ranked.each_text([&](size_t rank, std::string_view text) { out << rank << "," << text << "\n"; });
      break;
    case OutputFormat::json: write_streamed_json(out, head, ranked, notes); break;
    default:
      throw std::invalid_argument(report::unwritten_format("write_streamed_comparison", "table, csv or json", format));
  }
}

namespace {

// The shard's depth: its results' array holds each result two levels deep (object, array), laid
// out one space a level, as the shard files had it.
constexpr int kShardIndent = 1;
constexpr size_t kShardResultDepth = 2;

// A shard's document (write_shard) in one pass, its results written by `write_results` into the
// "results" array.
void write_shard_document(std::ostream& out, const Study& study, const EvaluationOptions& options,
                          const std::function<void(JsonWriter&)>& write_results, const Provenance& inputs) {
  JsonWriter j(out, kShardIndent);
  j.begin_object();
  j.member("format", "railmodal-compare-shard");
  if (!inputs.files.empty()) {
    j.key("inputs").begin_array();
    for (const InputFile& f : inputs.files) j.begin_object().member("digest", f.digest).member("path", f.path).end_object();
    j.end_array();
  }
  j.member("permissible_dynamic_deflection", to_string(study.deflection_rule));
  j.key("results").begin_array();
  write_results(j);
  j.end_array();
  j.member("shard", options.shard).member("shards", options.shards).member("study", study.name);
  j.member("variant_count", variant_count(study));
  j.end_object();
}

}  // namespace

std::string report::shard_result_json(const VariantResult& r) {
  std::string text;
  {
    JsonWriter j(&text, kShardIndent, kShardResultDepth);
    write_result(j, r, nullptr);
  }
  return text;
}

void report::write_streamed_shard(std::ostream& out, const Study& study, const EvaluationOptions& options,
                                  size_t count, const std::function<std::string(size_t)>& result_at,
                                  const Provenance& inputs) {
  write_shard_document(
      out, study, options,
      [&](JsonWriter& j) {
        for (size_t k = 0; k < count; ++k) j.raw(result_at(k));
      },
      inputs);
}

void write_shard(std::ostream& out, const Study& study, const EvaluationOptions& options,
                 const std::vector<VariantResult>& results, const Provenance& inputs) {
  write_shard_document(
      out, study, options,
      [&](JsonWriter& j) {
        for (const auto& r : results) write_result(j, r, nullptr);
      },
      inputs);
}

}  // namespace railmodal
