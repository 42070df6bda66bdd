// Metrics of a variant result, by name (docs/studies.md, "Ranking").
#include "study/metrics.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>

#include "railmodal/hunting.hpp"
#include "railmodal/study.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

// The metrics are read per variant (the ranking's constraints and criteria, a report's rows):
// they are looked at through views, so that naming a metric builds no string.
bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// canonical_metric without a copy: a view of a literal or of `metric` itself.
std::string_view canonical(std::string_view metric) {
  if (metric == "critical_speed") return "lowest_critical_speed";
  if (metric == "bounce_period") return "period:body bounce";
  if (metric == "pitch_period") return "period:body pitch";
  if (metric == "bounce_critical_speed") return "critical_speed:body bounce";
  return metric;
}

// "peak:<dof>:<quantity>" → dof and quantity (views of `metric`); false when it is not of that form.
bool split_peak(std::string_view metric, std::string_view* dof, std::string_view* quantity) {
  if (!starts_with(metric, "peak:")) return false;
  const size_t colon = metric.rfind(':');
  if (colon <= 5) return false;
  *dof = metric.substr(5, colon - 5);
  *quantity = metric.substr(colon + 1);
  return !dof->empty() && (*quantity == "displacement" || *quantity == "velocity" || *quantity == "acceleration");
}

// The ride's RMS metrics, one for each quantity a ride output can be (ride.hpp, unit_of), each
// in that quantity's SI unit: a force's RMS is never shown as an acceleration.
struct RmsMetric {
  std::string_view prefix;
  const char* unit;       // metric_unit's spelling
  const char* ride_unit;  // unit_of's spelling
  const char* title;      // title's words before the output's name
};
constexpr RmsMetric kRmsMetrics[] = {{"rms_acceleration:", "m/s^2", "m/s²", "largest RMS acceleration at "},
                                     {"rms_velocity:", "m/s", "m/s", "largest RMS of "},
                                     {"rms_displacement:", "m", "m", "largest RMS of "},
                                     {"rms_force:", "N", "N", "largest RMS of "}};

// The RMS metric `metric` is (with an output named after its prefix), or null.
const RmsMetric* rms_metric(std::string_view metric) {
  for (const RmsMetric& m : kRmsMetrics)
    if (metric.size() > m.prefix.size() && starts_with(metric, m.prefix)) return &m;
  return nullptr;
}

// The ride's metrics: the largest Wz or N_MV over outputs (points) and speeds, or the largest RMS
// of a named output; +∞ where the ride is unbounded; none without a ride.
std::optional<double> ride_metric(const VariantResult& r, std::string_view metric) {
  if (!r.ride_evaluated) return std::nullopt;
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  if (metric == "max_nmv") return r.max_nmv;
  if (metric == "max_wz") {
    std::optional<double> largest;
    for (const auto& o : r.ride)
      if (o.unbounded) largest = kUnbounded;
      else if (o.max_wz) largest = std::max(largest.value_or(*o.max_wz), *o.max_wz);
    return largest;
  }
  const std::string_view output = metric.substr(rms_metric(metric)->prefix.size());
  for (const auto& o : r.ride)
    if (o.output == output) return o.unbounded ? kUnbounded : o.max_rms;
  return std::nullopt;
}

bool is_ride_metric(std::string_view metric) {
  return metric == "max_wz" || metric == "max_nmv" || rms_metric(metric);
}

// The vehicle's own speed (critical and hunting speeds: m/s, shown in km/h), as against a
// vibration's velocity (a peak or an RMS, m/s shown as m/s).
bool is_vehicle_speed(std::string_view metric) {
  return metric == "lowest_critical_speed" || metric == "hunting_speed" || starts_with(metric, "critical_speed:");
}

bool is_rotation(std::string_view dof) {
  for (const std::string_view m : {".roll", ".pitch", ".yaw"})
    if (dof.size() > m.size() && dof.substr(dof.size() - m.size()) == m) return true;
  return false;
}

}  // namespace

std::string canonical_metric(const std::string& metric) { return std::string(canonical(metric)); }

bool is_metric(const std::string& name) {
  const std::string_view metric = canonical(name);
  std::string_view dof, quantity;
  return metric == "lowest_critical_speed" || metric == "hunting_speed" || metric == "static_deflection" ||
         metric == "metacentric_height" || metric == "dynamic_deflection_ratio" ||
         (starts_with(metric, "dynamic_deflection_ratio:") && metric.size() > 25) ||
         (starts_with(metric, "period:") && metric.size() > 7) ||
         (starts_with(metric, "critical_speed:") && metric.size() > 15) ||
         (starts_with(metric, "static_deflection:") && metric.size() > 18) || split_peak(metric, &dof, &quantity) ||
         is_ride_metric(metric);
}

namespace {
// Metrics read from the scene's critical-speed study (its critical speeds, its amplitude curves,
// the deflection checks made on them).
bool reads_critical_speeds(std::string_view metric) {
  std::string_view dof, quantity;
  return metric == "lowest_critical_speed" || starts_with(metric, "critical_speed:") ||
         starts_with(metric, "dynamic_deflection_ratio") || split_peak(metric, &dof, &quantity);
}
}  // namespace

bool study::metric_reads_critical_speeds(const std::string& name) { return reads_critical_speeds(canonical(name)); }

bool metric_needs_scene(const std::string& name) {
  const std::string_view metric = canonical(name);
  return reads_critical_speeds(metric) || is_ride_metric(metric);
}

VariantWork variant_work_of(const Ranking& ranking, const DeflectionRule& rule) {
  VariantWork work;
  // A study that ranks nothing lists every variant's figures: all of them are computed.
  if (ranking.objective.empty() && ranking.constraints.empty()) return work;
  work.critical_speeds = rule.active();
  work.ride = false;
  const auto see = [&](const std::string& name) {
    const std::string_view metric = canonical(name);
    work.critical_speeds = work.critical_speeds || reads_critical_speeds(metric);
    work.ride = work.ride || is_ride_metric(metric);
  };
  for (const RankingCriterion& c : ranking.objective) see(c.metric);
  for (const RankingConstraint& c : ranking.constraints) see(c.metric);
  return work;
}

bool ride_rms_only(const Study& study) {
  bool rms = false, more = false;
  const auto see = [&](const std::string& name) {
    const std::string_view metric = canonical(name);
    if (!is_ride_metric(metric)) return;
    (rms_metric(metric) ? rms : more) = true;
  };
  for (const RankingCriterion& c : study.ranking.objective) see(c.metric);
  for (const RankingConstraint& c : study.ranking.constraints) see(c.metric);
  return rms && !more;
}

std::optional<double> metric_value(const VariantResult& r, const std::string& name) {
  const std::string_view metric = canonical(name);
  if (!r.ok()) return std::nullopt;
  // Not asked for is not "none in range": no value (Python's None), not +inf.
  if (reads_critical_speeds(metric) && !r.critical_speeds_evaluated) return std::nullopt;
  if (metric == "lowest_critical_speed")
    return r.critical_speeds.empty() ? std::numeric_limits<double>::infinity() : r.critical_speeds.front().speed;
  if (starts_with(metric, "critical_speed:")) {
    for (const auto& c : r.critical_speeds)  // ascending
      if (c.mode_name == metric.substr(15)) return c.speed;
    return std::numeric_limits<double>::infinity();
  }
  if (starts_with(metric, "period:")) {
    const std::string_view mode = metric.substr(7);
    for (const auto& m : r.modes)
      if (m.name == mode && m.kind == "oscillatory") return m.period_s;
    return std::nullopt;
  }
  if (metric == "static_deflection" || starts_with(metric, "static_deflection:")) {
    const std::string_view body = metric == "static_deflection" ? std::string_view("body") : metric.substr(18);
    for (const auto& [name_of_body, deflection] : r.static_deflections)
      if (name_of_body == body) return deflection;
    return std::nullopt;
  }
  if (metric == "metacentric_height") return r.metacentric_height;
  if (metric == "hunting_speed") return r.hunting_speed;
  if (is_ride_metric(metric)) return ride_metric(r, metric);
  if (metric == "dynamic_deflection_ratio" || starts_with(metric, "dynamic_deflection_ratio:")) {
    // The worst check (of the named element); +∞ for an unbounded resonance. No value when
    // nothing was checked.
    const std::string_view element = metric.size() > 25 ? metric.substr(25) : std::string_view();
    std::optional<double> worst;
    for (const auto& c : r.deflections) {
      if (!element.empty() && c.element != element) continue;
      const double ratio = c.unbounded ? std::numeric_limits<double>::infinity() : c.deflection / c.permissible;
      if (!std::isnan(ratio)) worst = std::max(worst.value_or(ratio), ratio);
    }
    return worst;
  }
  std::string_view dof, quantity;
  if (split_peak(metric, &dof, &quantity)) {
    std::optional<double> largest;
    for (const auto& p : r.peaks)
      if (p.output == dof && p.quantity == quantity) {
        const double a = p.unbounded ? std::numeric_limits<double>::infinity() : p.amplitude;
        largest = std::max(largest.value_or(a), a);
      }
    return largest;
  }
  return std::nullopt;
}

bool metric_is_vehicle_speed(const std::string& metric) { return is_vehicle_speed(canonical(metric)); }

const char* metric_unit(const std::string& name) {
  const std::string_view metric = canonical(name);
  if (is_vehicle_speed(metric)) return "m/s";
  if (starts_with(metric, "period:")) return "s";
  if (starts_with(metric, "dynamic_deflection_ratio") || metric == "max_wz" || metric == "max_nmv") return "";
  if (const RmsMetric* rms = rms_metric(metric)) return rms->unit;
  std::string_view dof, quantity;
  if (split_peak(metric, &dof, &quantity)) {
    const bool rotation = is_rotation(dof);
    if (quantity == "displacement") return rotation ? "rad" : "m";
    if (quantity == "velocity") return rotation ? "rad/s" : "m/s";
    return rotation ? "rad/s^2" : "m/s^2";
  }
  return "m";  // static deflections, metacentric height
}

namespace study {

bool names_ride(const std::string& metric) { return is_ride_metric(canonical(metric)); }

std::string ride_output_of(const std::string& metric) {
  const RmsMetric* rms = rms_metric(metric);
  return rms ? metric.substr(rms->prefix.size()) : std::string();
}

std::string rms_ride_unit(const std::string& metric) {
  const RmsMetric* rms = rms_metric(metric);
  return rms ? rms->ride_unit : "";
}

std::string rms_metric_for(const std::string& ride_unit) {
  for (const RmsMetric& m : kRmsMetrics)
    if (ride_unit == m.ride_unit) return std::string(m.prefix);
  return "";
}

DisplayUnit display_unit(const std::string& metric) {
  // Critical speeds in km/h, as the book gives them; peak and RMS velocities stay in m/s.
  if (is_vehicle_speed(canonical(metric))) return {"km/h", 3.6};
  const char* si = metric_unit(metric);
  if (std::string_view(si) == "m") return {"mm", 1000.0};
  // Reports write a unit as every report does (docs/input.md, "Names and units in outputs"):
  // metric_unit's "m/s^2" is the API's ASCII spelling.
  if (std::string_view(si) == "m/s^2") return {"m/s²", 1.0};
  if (std::string_view(si) == "rad/s^2") return {"rad/s²", 1.0};
  return {si, 1.0};
}

bool infinite_is_unbounded(const std::string& metric) {
  const std::string_view m = canonical(metric);
  return starts_with(m, "peak:") || starts_with(m, "dynamic_deflection") || is_ride_metric(m);
}

std::string hunting_scan_top_kmh() {
  // The range a study's hunting speed is scanned over is HuntingOptions' default
  // (hunting_options_of), so its top is the bound `railmodal stability` prints as "above 500".
  return shortest_text(HuntingOptions{}.max_speed * 3.6, 6);
}

std::string infinite_word(const std::string& metric) {
  if (infinite_is_unbounded(metric)) return "unbounded";
  // Stable over the whole scan is not "no result" (user audit 2026-11-28, F4): the words and
  // number `railmodal stability` prints.
  if (canonical(metric) == "hunting_speed") return "above " + hunting_scan_top_kmh();
  return "none";
}

std::string title(const std::string& metric) {
  const std::string m(canonical(metric));
  std::string_view dof, quantity;
  if (m == "lowest_critical_speed") return "lowest critical speed";
  if (m == "hunting_speed") return "linear hunting speed";
  if (m == "static_deflection") return "static deflection of the body";
  if (m == "metacentric_height") return "metacentric height";
  if (m == "dynamic_deflection_ratio") return "largest dynamic deflection / permissible";
  if (starts_with(m, "critical_speed:")) return "critical speed of " + m.substr(15);
  if (starts_with(m, "period:")) return "period of " + m.substr(7);
  if (starts_with(m, "static_deflection:")) return "static deflection of " + m.substr(18);
  if (starts_with(m, "dynamic_deflection_ratio:")) return "dynamic deflection of " + m.substr(25) + " / permissible";
  if (split_peak(m, &dof, &quantity)) return "peak " + std::string(quantity) + " of " + std::string(dof);
  if (m == "max_wz") return "largest Sperling Wz of the ride";
  if (m == "max_nmv") return "largest N_MV (estimate) of the ride";
  if (const RmsMetric* rms = rms_metric(m))
    return rms->title + m.substr(rms->prefix.size());
  return metric;
}

std::string unit_bracket(const std::string& metric) {
  const std::string unit = display_unit(metric).unit;
  return unit.empty() ? "" : " [" + unit + "]";
}

std::string heading(const std::string& metric) { return title(metric) + unit_bracket(metric); }

std::string table_unit_bracket(const std::string& metric) {
  const std::string bracket = unit_bracket(metric);
  return bracket.empty() ? " [–]" : bracket;
}

int table_decimals(const std::string& name) {
  const std::string_view metric = canonical(name);
  if (is_vehicle_speed(metric)) return 1;                     // km/h, as the lowest critical speed column
  if (starts_with(metric, "period:")) return 3;               // s, as the periods column
  if (starts_with(metric, "dynamic_deflection_ratio")) return 3;
  if (metric == "max_wz" || metric == "max_nmv") return 2;  // Wz's and N_MV's scales step by 0.5 and 1
  const std::string_view unit = display_unit(name).unit;
  std::string_view dof, quantity;
  const bool response = rms_metric(metric) || split_peak(metric, &dof, &quantity);
  if (unit == "mm") return response ? 2 : 1;  // a vibration's mm against a static deflection's tens
  if (unit == "N") return 0;
  if (unit == "m/s" || unit == "rad/s") return 4;
  if (unit == "rad") return 5;
  return 3;  // m/s², rad/s²
}

std::string shown(const std::string& metric, double si, int digits) {
  if (std::isinf(si) && si > 0) return infinite_text(metric);
  const DisplayUnit u = display_unit(metric);
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, si * u.per_si);
  return std::string(text) + (*u.unit ? std::string(" ") + u.unit : std::string());
}

std::string infinite_text(const std::string& metric) {
  const std::string word = infinite_word(metric);
  return canonical(metric) == "hunting_speed" ? word + " km/h" : word;
}

std::string table_figure(double shown, int decimals) {
  char text[400];  // %.<decimals>f below 1e9, %.<decimals>e above: well within for decimals ≤ 17
  const bool small = shown != 0.0 && std::abs(shown) < std::pow(10.0, 1 - decimals);
  const auto format = small ? std::chars_format::general
                            : std::abs(shown) >= 1e9 ? std::chars_format::scientific : std::chars_format::fixed;
  const char* end = std::to_chars(text, text + sizeof text, shown, format, small ? 2 : decimals).ptr;
  const char* first = text;
  // A negative figure that rounds to zero (and −0) is written without its sign.
  if (*first == '-' && std::all_of(first + 1, end, [](char c) { return c == '0' || c == '.'; })) ++first;
  return std::string(first, end);
}

namespace {

// The value to `decimals` with its display unit, or the word for +∞.
std::string tabled(const std::string& metric, double si, int decimals) {
  if (std::isinf(si) && si > 0) return infinite_text(metric);
  const DisplayUnit u = display_unit(metric);
  return table_figure(si * u.per_si, decimals) + (*u.unit ? std::string(" ") + u.unit : std::string());
}

// The decimals past the table's that shown_apart adds at most: a double has 17 significant digits.
constexpr int kMoreDecimals = 17;

}  // namespace

std::string shown_as_tabled(const std::string& metric, double si) { return tabled(metric, si, table_decimals(metric)); }

std::pair<std::string, std::string> shown_apart(const std::string& metric, double a_si, double b_si) {
  int decimals = table_decimals(metric);
  std::pair<std::string, std::string> texts{tabled(metric, a_si, decimals), tabled(metric, b_si, decimals)};
  for (const int last = decimals + kMoreDecimals; a_si != b_si && texts.first == texts.second && decimals < last;) {
    ++decimals;
    texts = {tabled(metric, a_si, decimals), tabled(metric, b_si, decimals)};
  }
  return texts;
}

std::vector<std::string> violations(const VariantResult& r, const Ranking& ranking, bool for_people) {
  std::vector<std::string> out;
  // A value against its limit: for programs both to 6 significant digits; for people the value
  // as the table shows it (more decimals where it would read as the limit), the limit as given.
  // A partial N_MV says what it covers, as the table does.
  const auto against = [&](const std::string& metric, double value, double limit) {
    if (!for_people) return shown(metric, value) + (value < limit ? " < " : " > ") + shown(metric, limit);
    const std::string scope = metric == "max_nmv" && !r.max_nmv_partial.empty() ? " (" + r.max_nmv_partial + ")" : "";
    return shown_apart(metric, value, limit).first + scope + (value < limit ? " < " : " > ") + shown(metric, limit);
  };
  for (const RankingConstraint& c : ranking.constraints) {
    // The metric's name is copied only for a constraint the result breaks (rank_entry asks
    // every variant, and most keep every constraint).
    const auto name = [&] { return for_people ? title(c.metric) : c.metric; };
    const std::optional<double> value = metric_value(r, c.metric);
    if (!value && r.deflections_checked && starts_with(c.metric, "dynamic_deflection_ratio"))
      out.push_back("no " + name() + ": no spring of this variant falls under the deflection rule");
    else if (!value)
      out.push_back("no " + name());
    else if (c.min && *value < *c.min)
      out.push_back(name() + " " + against(c.metric, *value, *c.min));
    else if (c.max && *value > *c.max)
      out.push_back(name() + " " + against(c.metric, *value, *c.max));
  }
  return out;
}

}  // namespace study
}  // namespace railmodal
