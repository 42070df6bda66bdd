// The ranked comparison as a table, CSV or JSON, and the JSON of one shard's results.
// A shard's JSON holds every field of its results with doubles written to round trip, so a
// merge ranks exactly the numbers a single run would have ranked (src/input/shard_reader.cpp
// reads it back).
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "railmodal/comparison_report.hpp"
#include "railmodal/study.hpp"
#include "report/comparison_rows.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"
#include "shortest_text.hpp"
#include "study/metrics.hpp"

namespace railmodal {
namespace {

using nlohmann::json;

constexpr double kKmh = 3.6;  // km/h per m/s

json optional_number(const std::optional<double>& x) {
  return x && std::isfinite(*x) ? json(*x) : json(nullptr);
}

std::vector<double> periods(const VariantResult& r) {
  std::vector<double> out;
  for (const auto& m : r.modes)
    if (m.kind == "oscillatory") out.push_back(m.period_s);
  return out;
}

std::vector<double> critical_speeds_kmh(const VariantResult& r) {
  std::vector<double> out;
  for (const auto& c : r.critical_speeds) out.push_back(c.speed * kKmh);
  return out;
}

json result_json(const VariantResult& r) {
  json j;
  j["index"] = r.index;
  j["name"] = r.name;
  j["parameters"] = json::array();
  for (const auto& [key, value] : r.parameters) j["parameters"].push_back({{"key", key}, {"value", value}});
  j["failure"] = r.ok() ? json(nullptr) : json(r.failure);
  j["modes"] = json::array();
  for (const auto& m : r.modes)
    j["modes"].push_back({{"name", m.name}, {"kind", m.kind}, {"frequency_hz", m.frequency_hz}, {"period_s", m.period_s},
                          {"divergence_rate_per_s", m.divergence_rate}});
  j["static_deflections"] = json::array();
  for (const auto& [body, deflection] : r.static_deflections)
    j["static_deflections"].push_back({{"body", body}, {"deflection_m", deflection}});
  j["metacentric_height_m"] = optional_number(r.metacentric_height);
  j["critical_speeds"] = json::array();
  for (const auto& c : r.critical_speeds)
    j["critical_speeds"].push_back({{"speed_m_s", c.speed}, {"speed_kmh", c.speed * kKmh}, {"source", c.source},
                                    {"source_kind", c.source_kind}, {"harmonic", c.harmonic}, {"mode_name", c.mode_name},
                                    {"friction_stops", c.friction_stops}});
  j["peaks"] = json::array();
  for (const auto& p : r.peaks)
    j["peaks"].push_back({{"source", p.source}, {"output", p.output}, {"quantity", p.quantity}, {"amplitude", p.amplitude},
                          {"speed_m_s", p.speed}, {"unbounded", p.unbounded}});
  // Only when the study asks for it (a study without it writes what it always wrote); +∞, stable
  // over the whole range, is "none".
  if (r.hunting_speed) j["hunting_speed_m_s"] = std::isinf(*r.hunting_speed) ? json("none") : json(*r.hunting_speed);
  // Only for a scene with a ride (a study without one writes what it always wrote).
  if (r.ride_evaluated) {
    j["ride"] = json::array();
    for (const auto& o : r.ride)
      j["ride"].push_back({{"output", o.output}, {"unit", o.unit}, {"max_rms", o.max_rms},
                           {"max_sperling_wz", optional_number(o.max_wz)}, {"unbounded", o.unbounded}});
    j["max_nmv"] = optional_number(r.max_nmv);
  }
  if (r.deflections_checked) {
    j["dynamic_deflections"] = json::array();
    for (const auto& c : r.deflections)
      j["dynamic_deflections"].push_back({{"element", c.element}, {"stage", c.stage}, {"basis", c.basis},
                                          {"permissible_m", c.permissible}, {"deflection_m", c.deflection},
                                          {"speed_m_s", c.speed}, {"source", c.source}, {"unbounded", c.unbounded},
                                          {"kept", c.kept()}});
  }
  return j;
}

json ranking_json(const Ranking& ranking) {
  json j;
  j["method"] = ranking.weighted ? "weighted" : "lexicographic";
  j["constraints"] = json::array();
  for (const auto& c : ranking.constraints)
    j["constraints"].push_back({{"metric", c.metric}, {"min", optional_number(c.min)}, {"max", optional_number(c.max)}});
  j["objective"] = json::array();
  for (const auto& c : ranking.objective)
    j["objective"].push_back({{"metric", c.metric}, {"goal", c.maximise ? "max" : "min"}, {"weight", c.weight}});
  return j;
}

// A ranking value: a number; +∞ the word the tables print for it ("none": no critical speed in the
// range, a design stable throughout; "unbounded": an undamped peak), as hunting_speed_m_s and
// dynamic_deflection_ratio write it; null only for no value (a failed variant, a vehicle without
// wheelsets for hunting_speed), so that the two never read alike.
json ranking_value(const std::optional<double>& x, bool peak) {
  if (x && std::isinf(*x) && *x > 0) return peak ? "unbounded" : "none";
  return optional_number(x);
}

void write_json(std::ostream& out, const Comparison& c) {
  json j;
  j["study"] = c.study;
  j["ranking"] = ranking_json(c.ranking);
  if (c.deflection_rule.active())
    j["permissible_dynamic_deflection"] = {{"rule", to_string(c.deflection_rule.book)},
                                           {"service", to_string(c.deflection_rule.service)}};
  j["variants"] = json::array();
  for (const RankedVariant& v : c.variants) {
    json row = result_json(v.result);
    row["rank"] = v.rank;
    row["feasible"] = v.feasible;
    row["violations"] = v.violations;
    // The objective is +∞ through its criteria: it takes the word of the first that is.
    bool peak = false, infinite_seen = false;
    row["criteria"] = json::array();
    for (size_t k = 0; k < v.criteria.size(); ++k) {
      const bool unbounded =
          k < c.ranking.objective.size() && study::infinite_is_unbounded(c.ranking.objective[k].metric);
      if (!infinite_seen && v.criteria[k] && std::isinf(*v.criteria[k])) peak = unbounded, infinite_seen = true;
      row["criteria"].push_back(ranking_value(v.criteria[k], unbounded));
    }
    row["objective"] = ranking_value(v.objective, peak);
    row["periods_s"] = periods(v.result);
    row["critical_speeds_kmh"] = critical_speeds_kmh(v.result);
    if (v.result.deflections_checked) {
      const auto ratio = metric_value(v.result, "dynamic_deflection_ratio");
      row["dynamic_deflection_ratio"] = ratio && std::isinf(*ratio) ? json("unbounded") : optional_number(ratio);
      row["keeps_permissible_deflections"] = ratio ? json(*ratio <= 1.0) : json(nullptr);
    }
    j["variants"].push_back(row);
  }
  out << j.dump(2) << "\n";
}

std::string number(double x, const char* format = "%.4f") {
  if (!std::isfinite(x)) return x > 0 ? "none" : "-inf";
  char text[64];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

// Shortest text that reads back as the same double (CSV is for programs).
std::string exact(double x) {
  return std::isfinite(x) ? shortest_text(x) : std::string();
}

std::string status(const RankedVariant& v) { return !v.result.ok() ? "failed" : v.feasible ? "yes" : "no"; }

std::string criterion_heading(const RankingCriterion& c) {
  const std::string unit = study::display_unit(c.metric).unit;
  return std::string(c.maximise ? "max " : "min ") + c.metric + (unit.empty() ? "" : " [" + unit + "]");
}

// For people: the metric as the docs name it and how it is ranked, "period of body bounce,
// maximised [s]" (the unit last, as in every table heading); CSV keeps the metric's name
// (criterion_heading).
std::string criterion_title(const RankingCriterion& c) {
  return study::title(c.metric) + (c.maximise ? ", maximised" : ", minimised") + study::unit_bracket(c.metric);
}

// The worst dynamic deflection against the permissible one, in words, to one decimal: "33.0 %
// of permissible (within)", "130.2 % of permissible (exceeds)".
std::string deflection_verdict(double ratio) {
  if (std::isinf(ratio)) return "unbounded (exceeds)";
  return number(100.0 * ratio, "%.1f") + " % of permissible" + (ratio <= 1.0 ? " (within)" : " (exceeds)");
}

std::optional<double> body_deflection(const VariantResult& r) { return metric_value(r, "static_deflection"); }

// The header: the table's names for people, the CSV's for programs (metric names, units in
// brackets, the extra columns).
std::vector<std::string> comparison_head(const Comparison& c, bool for_csv) {
  std::vector<std::string> head{"rank", "variant", "feasible"};
  if (for_csv) head.push_back("objective");
  for (const auto& k : c.ranking.objective) head.push_back(for_csv ? criterion_heading(k) : criterion_title(k));
  const bool deflections = c.deflection_rule.active();
  if (!for_csv) {
    for (const char* h : {"lowest critical speed [km/h]", "static deflection [mm]"}) head.push_back(h);
    if (deflections) head.push_back("largest dynamic deflection");
    head.push_back("periods [s]");
    return head;
  }
  head.push_back(report::csv_heading("lowest_critical_speed", "km/h"));
  head.push_back(report::csv_heading("static_deflection", "mm"));
  if (deflections) head.push_back("dynamic_deflection_ratio");
  head.push_back(report::csv_heading("periods", "s"));
  head.push_back(report::csv_heading("critical_speeds", "km/h"));
  for (const char* h : {"failure", "violations"}) head.push_back(h);
  return head;
}

}  // namespace

std::vector<std::vector<std::string>> report::comparison_rows(const Comparison& c, bool for_csv) {
  std::vector<std::vector<std::string>> rows;
  const std::vector<std::string> head = comparison_head(c, for_csv);
  const bool deflections = c.deflection_rule.active();
  rows.push_back(head);
  for (const RankedVariant& v : c.variants) {
    const VariantResult& r = v.result;
    std::vector<std::string> row{std::to_string(v.rank), r.name, status(v)};
    if (for_csv) row.push_back(v.objective ? exact(*v.objective) : "");
    for (size_t k = 0; k < c.ranking.objective.size(); ++k) {
      const auto& x = v.criteria.size() > k ? v.criteria[k] : std::nullopt;
      const double scale = study::display_unit(c.ranking.objective[k].metric).per_si;
      const bool peak = study::infinite_is_unbounded(c.ranking.objective[k].metric);
      if (!x) row.push_back(for_csv ? "" : "-");
      else if (for_csv) row.push_back(exact(*x * scale));
      else if (std::isinf(*x) && *x > 0) row.push_back(peak ? "unbounded" : "none");  // no critical speed in range
      else row.push_back(number(*x * scale, "%.4g"));
    }
    const auto lowest = r.ok() ? metric_value(r, "lowest_critical_speed") : std::nullopt;
    row.push_back(!lowest ? (for_csv ? "" : "-") : for_csv ? exact(*lowest * kKmh) : number(*lowest * kKmh, "%.1f"));
    const auto deflection = body_deflection(r);
    row.push_back(!deflection ? (for_csv ? "" : "-") : for_csv ? exact(*deflection * 1000.0) : number(*deflection * 1000.0, "%.1f"));
    if (deflections) {
      const auto ratio = r.ok() ? metric_value(r, "dynamic_deflection_ratio") : std::nullopt;
      if (!ratio) row.push_back(for_csv ? "" : "-");
      else if (for_csv) row.push_back(std::isinf(*ratio) ? "unbounded" : exact(*ratio));
      else row.push_back(deflection_verdict(*ratio));
    }
    std::string list;
    for (double p : periods(r)) list += (list.empty() ? "" : " ") + (for_csv ? exact(p) : number(p, "%.3f"));
    row.push_back(list);
    if (for_csv) {
      std::string speeds, violations;
      for (double s : critical_speeds_kmh(r)) speeds += (speeds.empty() ? "" : " ") + exact(s);
      for (const auto& w : v.violations) violations += (violations.empty() ? "" : "; ") + w;
      row.push_back(speeds);
      row.push_back(r.failure);
      row.push_back(violations);
    }
    rows.push_back(row);
  }
  return rows;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char ch : s) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

// Display width: UTF-8 continuation bytes take no column.
size_t width(const std::string& s) {
  return static_cast<size_t>(std::count_if(s.begin(), s.end(), [](char ch) { return (static_cast<unsigned char>(ch) & 0xC0) != 0x80; }));
}

void write_table(std::ostream& out, const Comparison& c) {
  size_t feasible = 0;
  for (const auto& v : c.variants) feasible += v.feasible;
  out << "railmodal compare: " << c.study << "\n" << c.variants.size() << " variants, " << feasible << " feasible";
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
  const auto rows = report::comparison_rows(c, false);
  std::vector<size_t> widths(rows.front().size(), 0);
  for (const auto& row : rows)
    for (size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], width(row[i]));
  for (const auto& row : rows) {
    std::string line;
    for (size_t i = 0; i < row.size(); ++i) {
      const bool last = i + 1 == row.size();
      const bool right = i >= 3 && !last;  // numbers right-aligned
      const std::string pad(widths[i] - width(row[i]), ' ');
      line += right ? pad + row[i] : row[i] + (last ? "" : pad);
      if (!last) line += "  ";
    }
    out << line << "\n";
  }
  bool notes = false;
  for (const auto& v : c.variants) {
    if (v.result.ok() && v.violations.empty()) continue;
    if (!notes) out << "\n";
    notes = true;
    out << v.result.name << ": ";
    if (!v.result.ok()) {
      out << "failed: " << v.result.failure << "\n";
    } else {
      const auto words = study::violations(v.result, c.ranking, true);
      for (size_t k = 0; k < words.size(); ++k) out << (k ? "; " : "") << words[k];
      out << "\n";
    }
  }
}

}  // namespace

void write_comparison(std::ostream& out, const Comparison& comparison, OutputFormat format) {
  switch (format) {
    case OutputFormat::table: write_table(out, comparison); break;
    case OutputFormat::csv:
      for (const auto& row : report::comparison_rows(comparison, true)) {
        for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csv_field(row[i]);
        out << "\n";
      }
      break;
    case OutputFormat::json: write_json(out, comparison); break;
    default:
      throw std::invalid_argument(report::unwritten_format("write_comparison", "table, csv or json", format) +
                                  " (the markdown and html reports need the study: write_comparison_report)");
  }
}

void write_shard(std::ostream& out, const Study& study, const EvaluationOptions& options,
                 const std::vector<VariantResult>& results, const Provenance& inputs) {
  json j;
  j["format"] = "railmodal-compare-shard";
  j["study"] = study.name;
  j["variant_count"] = study.variants.size();
  j["shard"] = options.shard;
  j["shards"] = options.shards;
  j["permissible_dynamic_deflection"] = to_string(study.deflection_rule);
  if (!inputs.files.empty()) {
    j["inputs"] = json::array();
    for (const InputFile& f : inputs.files) j["inputs"].push_back({{"path", f.path}, {"digest", f.digest}});
  }
  j["results"] = json::array();
  for (const auto& r : results) j["results"].push_back(result_json(r));
  out << j.dump(1) << "\n";
}

}  // namespace railmodal
