// The nonlinear-hunting report: what was simulated (the effects and their laws, the ramp and its
// disturbance), the nonlinear critical speed and its amplitude beside the linear one, the ramps at
// the stated and halved rates (the convergence check), the held confirmation, and the bifurcation
// curve (limit-cycle amplitude against speed), as a table, CSV, JSON, Markdown or HTML with the
// bifurcation plot. Quantities the result does not have are words or null, never inf or NaN.
#include "railmodal/nonlinear_hunting_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "report/document_table.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"

namespace railmodal {

namespace {

using report::fixed;
using report::significant;
using report::Table;

constexpr double kKmh = 3.6;  // m/s → km/h
constexpr double kMm = 1e3;   // m → mm
// Points of the stated ramp's curve the text formats list (the CSV and JSON carry every half cycle).
constexpr size_t kListedPoints = 12;

struct Page {
  const NonlinearHuntingResult& r;
  const NonlinearHuntingOptions& o;
  std::string vehicle;
  const Provenance& provenance;
  std::optional<double> linear;  // m/s
};

bool has_effect(const NonlinearHuntingOptions& o, NonlinearEffect e) {
  return std::find(o.effects.begin(), o.effects.end(), e) != o.effects.end();
}

std::string speed_text(double speed) { return fixed(speed * kKmh, 2) + " km/h (" + fixed(speed, 3) + " m/s)"; }
std::string mm(double length) { return fixed(length * kMm, 2) + " mm"; }

std::string effects_text(const NonlinearHuntingOptions& o) {
  std::string text;
  if (has_effect(o, NonlinearEffect::creep_saturation)) {
    text += "creep_saturation (Shen–Hedrick–Elkins, μ = " + significant(o.friction_coefficient, 4) + ", wheel load " +
            (o.wheel_load ? significant(*o.wheel_load / 1e3, 4) + " kN" : std::string("half the axle load")) +
            (o.contact_angle > 0.0 ? ", contact angle " + significant(o.contact_angle, 4) + " rad" : std::string()) +
            ")";
  }
  if (has_effect(o, NonlinearEffect::flange_contact)) {
    text += std::string(text.empty() ? "" : "; ") + "flange_contact (clearance " + mm(o.flange_clearance) +
            ", stiffness " + significant(o.flange_stiffness / 1e6, 4) + " MN/m)";
  }
  return text.empty() ? "none: Kalker's linear creep law and no flange (the answer is the linear critical speed)"
                      : text;
}

std::string ramp_text(const NonlinearHuntingOptions& o) {
  return "from " + fixed(o.start_speed * kKmh, 1) + " to " + fixed(o.end_speed * kKmh, 1) + " km/h at " +
         significant(o.ramp_rate, 4) + " m/s² and at half of it, every wheelset displaced laterally by " +
         mm(o.disturbance) + " at the start";
}

std::string verdict_text(const NonlinearHuntingResult& r) {
  switch (r.verdict) {
    case NonlinearHuntingVerdict::limit_cycle_dies_out:
      return "a hunting limit cycle was established and died out on the way down: the nonlinear critical speed "
             "is the lowest speed at which it survives.";
    case NonlinearHuntingVerdict::survives_to_end_speed:
      return "the limit cycle still lives at the end speed: the nonlinear critical speed is below it (none is "
             "invented). Lower end_speed.";
    case NonlinearHuntingVerdict::no_limit_cycle_at_start:
      return "the disturbance died out at once: no limit cycle at the start speed for this disturbance. Start "
             "above the linear critical speed, or with a larger disturbance (on the flange).";
    case NonlinearHuntingVerdict::unbounded_growth:
      return "the amplitude grew past amplitude_bound: without saturation or flange nothing bounds the hunting "
             "above the linear critical speed.";
  }
  return "";
}

std::string optional_speed(const std::optional<double>& v) { return v ? speed_text(*v) : "none"; }

std::string check_value(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e9) return fixed(value, 0);
  return significant(value, 2);
}

std::string checks_text(const NonlinearHuntingResult& r) {
  std::string text;
  for (const Check& c : r.summary.checks) {
    text += (text.empty() ? "" : "; ") + c.name + " " + check_value(c.value);
    if (std::isfinite(c.limit)) text += " (limit " + check_value(c.limit) + (c.passed ? ")" : ", FAILED)");
  }
  return text.empty() ? "none recorded" : text;
}

std::string convergence_text(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  std::string text = std::string(to_string(r.convergence)) + ": ";
  switch (r.convergence) {
    case NonlinearConvergence::converged:
      if (p.o.hold_periods == 0)
        return text + "halving the ramp rate moved the critical speed by less than " + fixed(p.o.tolerance, 3) +
               " m/s (no holds asked for: the ramp's answer is the result).";
      return text + "the held critical speed is bracketed to within " + fixed(p.o.tolerance, 3) +
             " m/s and a hold twice as long keeps its cycle; halving the ramp rate moved the ramp's answer by " +
             fixed(r.convergence_difference, 3) + " m/s" +
             (r.convergence_difference <= p.o.tolerance ? "" : ", more than that: the ramp lags, the holds do not") +
             ".";
    case NonlinearConvergence::not_converged:
      return text + "the two ramp rates disagree, or the holds did not bracket or confirm the answer: read the "
                    "figure as an estimate (a slower ramp, a longer hold_periods, or a wider hold_margin).";
    case NonlinearConvergence::not_applicable:
      return text + "both ramp rates agree that there is no critical speed to converge.";
  }
  return text;
}

const char* const kCannotShow =
    "What the ramp-down shows: the stable hunting limit cycle the disturbance falls onto, followed down in speed to "
    "where it stops existing (a fold of the branch, or the Hopf point when the branch is supercritical). What it "
    "cannot show: the unstable limit cycle of a subcritical branch (the threshold amplitude between decay to the "
    "centre and hunting), which no simulation converges onto and which needs numerical continuation of periodic "
    "orbits; it is not offered. The answer depends on the disturbance, and the watched wheelset is the one that "
    "moves most (docs/stability.md, \"What the ramp-down can and cannot show\").";

// ---- tables shared by the formats for people ----

Table result_table(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  Table t{{"quantity", "value"}, {false, false}, {}};
  t.rows.push_back({"verdict", to_string(r.verdict)});
  t.rows.push_back({"nonlinear critical speed", optional_speed(r.critical_speed)});
  t.rows.push_back({"limit-cycle amplitude there", r.critical_speed ? mm(r.amplitude) : "none"});
  t.rows.push_back({"watched wheelset", "wheelset " + std::to_string(r.stated_rate.watched_wheelset + 1) +
                                            " of the vehicle file (the one that moves most)"});
  if (p.linear) t.rows.push_back({"linear critical speed", speed_text(*p.linear)});
  t.rows.push_back({"convergence", to_string(r.convergence)});
  return t;
}

std::string ramp_speed(const RampDown& d) { return d.critical_speed ? fixed(*d.critical_speed * kKmh, 2) : "none"; }

Table ramps_table(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  Table t{{"ramp", "rate (m/s²)", "verdict", "critical speed (km/h)", "amplitude (mm)", "half cycles", "steps"},
          {false, true, false, true, true, true, true},
          {}};
  for (const RampDown* d : {&r.stated_rate, &r.halved_rate})
    t.rows.push_back({d == &r.stated_rate ? "stated" : "halved", significant(d->ramp_rate, 4), to_string(d->verdict),
                      ramp_speed(*d), d->critical_speed ? fixed(d->amplitude * kMm, 2) : "none",
                      std::to_string(d->curve.size()), std::to_string(d->steps)});
  return t;
}

Table convergence_table(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  Table t{{"check", "value", "limit"}, {false, true, true}, {}};
  const bool both = std::isfinite(r.convergence_difference);
  t.rows.push_back({"critical speed moved by halving the ramp rate (km/h)",
                    both ? fixed(r.convergence_difference * kKmh, 3) : "none (a rate has no critical speed)",
                    fixed(p.o.tolerance * kKmh, 3)});
  t.rows.push_back({"ramps extrapolated to a zero rate, Richardson (km/h)",
                    r.richardson_critical_speed ? fixed(*r.richardson_critical_speed * kKmh, 2) : "none", "reported"});
  const HeldCriticalSpeed& h = r.hold;
  if (!h.holds.empty()) {
    t.rows.push_back({"lowest held speed whose cycle survives (km/h)",
                      h.lowest_surviving ? fixed(*h.lowest_surviving * kKmh, 3) : "none", ""});
    t.rows.push_back(
        {"highest held speed below it whose cycle dies (km/h)", h.highest_dying ? fixed(*h.highest_dying * kKmh, 3) : "none", ""});
    t.rows.push_back({"bracket of the held critical speed (km/h)",
                      h.lowest_surviving && h.highest_dying ? fixed((*h.lowest_surviving - *h.highest_dying) * kKmh, 3)
                                                            : "none",
                      fixed(p.o.tolerance * kKmh, 3)});
    t.rows.push_back({"cycle kept through a hold of " + std::to_string(2 * p.o.hold_periods) + " periods",
                      h.doubled_hold_survives ? "yes" : "no", "yes"});
  }
  return t;
}

Table holds_table(const NonlinearHuntingResult& r) {
  Table t{{"speed (km/h)", "survives", "start amplitude (mm)", "end amplitude (mm)", "periods"},
          {true, false, true, true, true},
          {}};
  for (const SpeedHold& h : r.hold.holds)
    t.rows.push_back({fixed(h.speed * kKmh, 3), h.survives ? "yes" : "no", fixed(h.start_amplitude * kMm, 2),
                      fixed(h.end_amplitude * kMm, 2), std::to_string(h.periods)});
  return t;
}

// About kListedPoints half cycles of the stated ramp, evenly spaced in speed, and the branch end.
Table curve_table(const NonlinearHuntingResult& r) {
  Table t{{"speed (km/h)", "amplitude (mm)"}, {true, true}, {}};
  const auto& c = r.stated_rate.curve;
  if (c.empty()) return t;
  const double top = c.front().speed, bottom = c.back().speed;
  const double spacing = (top - bottom) / static_cast<double>(kListedPoints - 1);
  double next = top;
  for (size_t i = 0; i < c.size(); ++i) {
    if (c[i].speed <= next + 1e-12 || i + 1 == c.size()) {
      t.rows.push_back({fixed(c[i].speed * kKmh, 2), fixed(c[i].amplitude * kMm, 3)});
      next = c[i].speed - spacing;
    }
  }
  return t;
}

// ---- table (text) ----

size_t width_of(const std::string& text) {
  return static_cast<size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

std::string wrapped(const std::string& text) {
  std::string out, line;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    if (!line.empty() && width_of(line) + 1 + width_of(word) > 100) out += line + "\n", line.clear();
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

void write_text_table(std::ostream& out, const Table& t) {
  std::vector<size_t> width(t.headers.size());
  for (size_t c = 0; c < t.headers.size(); ++c) width[c] = width_of(t.headers[c]);
  for (const auto& row : t.rows)
    for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], width_of(row[c]));
  for (size_t k = 0; k <= t.rows.size(); ++k) {
    const auto& cells = k == 0 ? t.headers : t.rows[k - 1];
    std::string text;
    for (size_t c = 0; c < cells.size(); ++c) {
      const std::string fill(width[c] - width_of(cells[c]), ' ');
      text += "  " + (t.numeric[c] ? fill + cells[c] : cells[c] + fill);
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out << text << "\n";
  }
}

void write_table(std::ostream& out, const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  out << "railmodal hunting: " << p.vehicle << "\n";
  out << wrapped("effects: " + effects_text(p.o)) << "\n" << wrapped("ramp: " + ramp_text(p.o)) << "\n\n";
  out << wrapped("verdict: " + std::string(to_string(r.verdict)) + ": " + verdict_text(r)) << "\n\n";
  write_text_table(out, result_table(p));
  out << "\nramps:\n";
  write_text_table(out, ramps_table(p));
  out << "\nconvergence:\n";
  write_text_table(out, convergence_table(p));
  out << wrapped(convergence_text(p)) << "\n";
  if (!r.hold.holds.empty()) {
    out << "\nholds of the speed (in the order held; the doubled hold last):\n";
    write_text_table(out, holds_table(r));
  }
  out << "\nlimit cycle on the way down (stated rate; every half cycle in csv and json):\n";
  write_text_table(out, curve_table(r));
  out << "\n" << wrapped(kCannotShow) << "\n";
  out << "\n" << wrapped("checks: " + checks_text(r)) << "\n" << wrapped("method: " + r.summary.method) << "\n";
}

// ---- Markdown ----

void write_markdown(std::ostream& out, const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  out << "# Nonlinear hunting: " << p.vehicle << "\n\n";
  out << "Effects: " << effects_text(p.o) << ".\n\nRamp: " << ramp_text(p.o) << ".\n\n";
  out << "**Verdict: " << to_string(r.verdict) << "**: " << verdict_text(r) << "\n\n";
  report::write_markdown_table(out, result_table(p));
  out << "\n## Ramps\n\n";
  report::write_markdown_table(out, ramps_table(p));
  out << "\n## Convergence\n\n";
  report::write_markdown_table(out, convergence_table(p));
  out << "\n" << convergence_text(p) << "\n\n";
  if (!r.hold.holds.empty()) {
    out << "## Holds of the speed\n\n";
    report::write_markdown_table(out, holds_table(r));
    out << "\n";
  }
  out << "## Limit cycle on the way down\n\n";
  report::write_markdown_table(out, curve_table(r));
  out << "\n" << kCannotShow << "\n\n## Checks\n\n" << checks_text(r) << ".\n\nMethod: " << r.summary.method
      << ".\n\n";
  out << report::provenance_line("hunting", p.provenance) << "\n";
}

// ---- HTML ----

report::Chart bifurcation_chart(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  report::Chart chart;
  chart.id = "bifurcation";
  chart.title = "Limit-cycle amplitude against speed";
  chart.x_label = "speed (km/h)";
  chart.y_label = "amplitude (mm)";
  for (const RampDown* d : {&r.stated_rate, &r.halved_rate}) {
    report::ChartSeries s;
    s.label = (d == &r.stated_rate ? "ramp at " : "ramp at half the rate, ") + significant(d->ramp_rate, 4) + " m/s²";
    s.markers_only = true;
    for (const LimitCyclePoint& q : d->curve) {
      s.x.push_back(q.speed * kKmh);
      s.y.push_back(q.amplitude * kMm);
    }
    chart.series.push_back(std::move(s));
  }
  if (r.critical_speed)
    chart.lines.push_back({"nonlinear", *r.critical_speed * kKmh, true, "critical speed (held)"});
  if (p.linear) chart.lines.push_back({"linear", *p.linear * kKmh, true, "critical speed (Hopf point)"});
  if (std::find(p.o.effects.begin(), p.o.effects.end(), NonlinearEffect::flange_contact) != p.o.effects.end())
    chart.lines.push_back({"flange", p.o.flange_clearance * kMm, false, "clearance"});
  chart.x_min = p.o.end_speed * kKmh;
  chart.x_max = p.o.start_speed * kKmh;
  return chart;
}

void write_html(std::ostream& out, const Page& p) {
  using report::html_escape;
  const NonlinearHuntingResult& r = p.r;
  report::write_html_head(out, "Nonlinear hunting: " + p.vehicle);
  out << "<h1>Nonlinear hunting: " << html_escape(p.vehicle) << "</h1>\n";
  out << "<p>Effects: " << html_escape(effects_text(p.o)) << ".</p>\n<p>Ramp: " << html_escape(ramp_text(p.o))
      << ".</p>\n";
  const bool found = r.verdict == NonlinearHuntingVerdict::limit_cycle_dies_out;
  out << "<p class=" << (found ? "ok" : "bad") << "><b>Verdict: " << to_string(r.verdict) << "</b>: "
      << html_escape(verdict_text(r)) << "</p>\n";
  report::write_html_table(out, result_table(p));
  out << "<h2>Bifurcation plot</h2>\n" << report::svg_chart(bifurcation_chart(p));
  out << "<p class=note>One point per half cycle of the watched wheelset's lateral motion: its largest |y| and the "
         "speed at its peak, the speed falling from right to left. Where the points fall away the limit cycle is "
         "lost; the held confirmation places that speed (nonlinear). The linear critical speed is where the "
         "centred running loses stability (amplitude 0).</p>\n";
  out << "<h2>Ramps</h2>\n";
  report::write_html_table(out, ramps_table(p));
  out << "<h2>Convergence</h2>\n";
  report::write_html_table(out, convergence_table(p));
  out << "<p>" << html_escape(convergence_text(p)) << "</p>\n";
  if (!r.hold.holds.empty()) {
    out << "<h2>Holds of the speed</h2>\n";
    report::write_html_table(out, holds_table(r));
  }
  out << "<p class=note>" << html_escape(kCannotShow) << "</p>\n";
  out << "<h2>Checks</h2>\n<p>" << html_escape(checks_text(r)) << ".</p>\n<p class=note>Method: "
      << html_escape(r.summary.method) << ".</p>\n";
  report::write_html_footer(out, "hunting", p.provenance);
}

// ---- CSV and JSON ----

// The bifurcation data: every half cycle of both ramps.
void write_csv(std::ostream& out, const NonlinearHuntingResult& r) {
  using report::csv_heading;
  out << "ramp," << csv_heading("ramp_rate", "m/s^2") << ",half_cycle," << csv_heading("speed", "km/h") << ","
      << csv_heading("amplitude", "mm") << "\n";
  for (const RampDown* d : {&r.stated_rate, &r.halved_rate})
    for (size_t i = 0; i < d->curve.size(); ++i)
      out << (d == &r.stated_rate ? "stated," : "halved,") << significant(d->ramp_rate, 10) << "," << i + 1 << ","
          << significant(d->curve[i].speed * kKmh, 10) << "," << significant(d->curve[i].amplitude * kMm, 10) << "\n";
}

nlohmann::json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json speed_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }
nlohmann::json kmh_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v * kKmh) : nlohmann::json(nullptr);
}

nlohmann::json ramp_json(const RampDown& d) {
  nlohmann::json speeds = nlohmann::json::array(), amplitudes = nlohmann::json::array();
  for (const LimitCyclePoint& q : d.curve) {
    speeds.push_back(q.speed);
    amplitudes.push_back(q.amplitude);
  }
  return {{"ramp_rate_m_s2", d.ramp_rate},
          {"verdict", to_string(d.verdict)},
          {"critical_speed_m_s", speed_json(d.critical_speed)},
          {"critical_speed_kmh", kmh_json(d.critical_speed)},
          {"amplitude_m", d.critical_speed ? nlohmann::json(d.amplitude) : nlohmann::json(nullptr)},
          {"steps", d.steps},
          {"watched_wheelset", d.watched_wheelset},
          {"curve", {{"speed_m_s", speeds}, {"amplitude_m", amplitudes}}}};
}

nlohmann::json options_json(const NonlinearHuntingOptions& o) {
  nlohmann::json effects = nlohmann::json::array();
  for (NonlinearEffect e : o.effects) effects.push_back(to_string(e));
  nlohmann::json j = {{"effects", effects},
                      {"start_speed_m_s", o.start_speed},
                      {"end_speed_m_s", o.end_speed},
                      {"ramp_rate_m_s2", o.ramp_rate},
                      {"disturbance_m", o.disturbance},
                      {"tolerance_m_s", o.tolerance},
                      {"hold_periods", o.hold_periods},
                      {"hold_margin_m_s", o.hold_margin},
                      {"extinction_amplitude_m", o.extinction_amplitude},
                      {"amplitude_bound_m", o.amplitude_bound}};
  j["creep_saturation"] = has_effect(o, NonlinearEffect::creep_saturation)
                              ? nlohmann::json{{"law", "shen_hedrick_elkins"},
                                               {"friction_coefficient", o.friction_coefficient},
                                               {"wheel_load_n", speed_json(o.wheel_load)},
                                               {"contact_angle_rad", o.contact_angle}}
                              : nlohmann::json(nullptr);
  j["flange_contact"] = has_effect(o, NonlinearEffect::flange_contact)
                            ? nlohmann::json{{"clearance_m", o.flange_clearance}, {"stiffness_n_m", o.flange_stiffness}}
                            : nlohmann::json(nullptr);
  return j;
}

void write_json(std::ostream& out, const Page& p) {
  using nlohmann::json;
  const NonlinearHuntingResult& r = p.r;
  json holds = json::array();
  for (const SpeedHold& h : r.hold.holds)
    holds.push_back({{"speed_m_s", h.speed},
                     {"survives", h.survives},
                     {"start_amplitude_m", h.start_amplitude},
                     {"end_amplitude_m", h.end_amplitude},
                     {"periods", h.periods},
                     {"steps", h.steps}});
  json checks = json::array();
  for (const Check& c : r.summary.checks)
    checks.push_back(
        {{"name", c.name}, {"value", number_or_null(c.value)}, {"limit", number_or_null(c.limit)}, {"passed", c.passed}});
  json j;  // nlohmann's object keeps its keys sorted: the file is the same from run to run
  j["vehicle"] = p.vehicle;
  j["analysis"] = "nonlinear";
  j["options"] = options_json(p.o);
  j["verdict"] = to_string(r.verdict);
  j["critical_speed_m_s"] = speed_json(r.critical_speed);
  j["critical_speed_kmh"] = kmh_json(r.critical_speed);
  j["amplitude_m"] = r.critical_speed ? json(r.amplitude) : json(nullptr);
  j["linear_critical_speed_m_s"] = speed_json(p.linear);
  j["linear_critical_speed_kmh"] = kmh_json(p.linear);
  j["convergence"] = to_string(r.convergence);
  j["converged"] = r.converged;
  j["convergence_difference_m_s"] = number_or_null(r.convergence_difference);
  j["richardson_critical_speed_m_s"] = speed_json(r.richardson_critical_speed);
  j["ramps"] = {ramp_json(r.stated_rate), ramp_json(r.halved_rate)};
  j["hold"] = {{"lowest_surviving_m_s", speed_json(r.hold.lowest_surviving)},
               {"highest_dying_m_s", speed_json(r.hold.highest_dying)},
               {"doubled_hold_survives", r.hold.doubled_hold_survives},
               {"holds", holds}};
  j["summary"] = {{"analysis", r.summary.analysis}, {"method", r.summary.method}, {"checks", checks}};
  out << j.dump(2) << "\n";
}

}  // namespace

void write_nonlinear_hunting(std::ostream& out, const NonlinearHuntingResult& result,
                             const NonlinearHuntingOptions& options, OutputFormat format, const std::string& vehicle,
                             const Provenance& provenance, std::optional<double> linear_critical_speed) {
  const Page page{result, options, vehicle.empty() ? std::string("vehicle") : vehicle, provenance,
                  linear_critical_speed};
  switch (format) {
    case OutputFormat::table:
      write_table(out, page);
      break;
    case OutputFormat::csv:
      write_csv(out, result);
      break;
    case OutputFormat::json:
      write_json(out, page);
      break;
    case OutputFormat::markdown:
      write_markdown(out, page);
      break;
    case OutputFormat::html:
      write_html(out, page);
      break;
    default:
      throw std::invalid_argument(
          report::unwritten_format("write_nonlinear_hunting", "table, csv, json, markdown or html", format));
  }
}

}  // namespace railmodal
