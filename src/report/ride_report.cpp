// The ride report: per output and speed the RMS, the EN 12299 weighted RMS and its estimated
// 95th percentile, Sperling's Wz and the dominant modes, N_MV per floor point; as a text table,
// CSV (one row per speed, units in the column heads), JSON (unit-suffixed keys), Markdown, or
// HTML with SVG plots (input and output PSDs log–log with the natural frequencies marked, the
// indices against speed, and for a time-domain run the weighted acceleration with its 5 s
// windows and the FFT checks). Figures a result does not have (an unbounded RMS, an index of a
// force) are words or blank or null, never inf or NaN; the indices a result solved with
// RideOptions::rms_only skipped (RideResult::rms_only) have no column, member or chart at all.
#include "railmodal/ride_report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <charconv>
#include <cstdio>

#include "report/csv_writer.hpp"
#include "report/document_table.hpp"
#include "report/json_lines.hpp"
#include "report/json_writer.hpp"
#include "report/report_page.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "ride/nmv_scope.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

using report::fixed;
using report::JsonWriter;
using report::significant;
using report::Table;
using report::write_text_table;
using ride::nmv_scope;

using report::kKmh;
// Modes named per output: the largest shares, down to this one.
constexpr size_t kDominantModes = 3;
constexpr double kSmallestShownShare = 0.05;

struct Page {
  const RideResult& r;
  std::string title;
  const Provenance& provenance;
  const RideSimulationResult* simulated;
  const RideFftChecks* checks;
};

// ---- units and words ----


// A speed in km/h for CSV and JSON: m/s × 3.6 to 15 significant digits, so that a speed given as
// "150 km/h" (41.666… m/s) is 150 and not 150.00000000000003, the product's round-off; any speed
// written with up to 15 digits comes back as written (speed_m_s keeps the exact value).
double kmh_value(double speed) {
  const std::string text = shortest_text(speed * kKmh, 15);
  double value = speed * kKmh;
  std::from_chars(text.data(), text.data() + text.size(), value);  // locale-free, as to_chars wrote it
  return value;
}

// A ride speed, as the user gave it ("100 km/h", "12.5 km/h"): every report prints a speed it was
// given in this form and a speed it computed at the precision it has (docs/input.md, "Names and
// units in outputs").
std::string kmh(double speed) { return shortest_text(speed * kKmh, 6) + " km/h"; }
// Four significant digits with their trailing zeros ("0.1500", not "0.15"), so that a column
// reads at one precision; from 1000 on, whole units.
std::string value_text(double v) {
  if (std::abs(v) >= 1000.0) return fixed(v, 0);
  char text[32];
  std::snprintf(text, sizeof text, "%#.4g", v);
  std::string t = text;
  if (!t.empty() && t.back() == '.') t.pop_back();
  return t;
}
std::string optional_text(const std::optional<double>& v) { return v ? value_text(*v) : "–"; }

// A floor point as people read it: the name its acceleration outputs share once their axis is
// taken off ("floor over front bogie, vertical" and "…, lateral" give "floor over front bogie"),
// or their names joined by " / ", then its body and coordinates: "floor over front bogie: body
// (9.5, 0, 0.3675) m". The reports say the frame once (kFloorPointNote).
std::string point_text(const RideComfortAtPoint& c, const std::vector<RideOutput>& outputs) {
  std::string name;
  std::vector<std::string> names;
  for (const RideOutput& o : outputs) {
    if (o.kind != RideOutput::Kind::point || o.quantity != ResponseQuantity::acceleration || o.body != c.body ||
        (o.point - c.point).norm() > 1e-9)  // the tolerance the ride groups a point's axes by
      continue;
    std::string n = o.name;
    const std::string axis = std::string(", ") + to_string(o.axis);
    if (n.size() > axis.size() && n.compare(n.size() - axis.size(), std::string::npos, axis) == 0)
      n.resize(n.size() - axis.size());
    if (std::find(names.begin(), names.end(), n) != names.end()) continue;
    name += (names.empty() ? "" : " / ") + n;
    names.push_back(n);
  }
  const std::string where = c.body + " (" + significant(c.point.x(), 4) + ", " + significant(c.point.y(), 4) + ", " +
                            significant(c.point.z(), 4) + ") m";
  return name.empty() ? where : name + ": " + where;
}

// Modes are numbered from 1 in every report (the table, the marks on the spectra).
std::string mode_number(size_t index) { return std::to_string(index + 1); }

std::string mode_name(const RideResult& r, int mode) {
  return mode >= 0 && static_cast<size_t>(mode) < r.modes.size()
             ? r.modes[mode].name + " (" + fixed(r.modes[mode].frequency_hz, 2) + " Hz)"
             : "mode " + mode_number(static_cast<size_t>(mode));
}

// A share of an output's variance as a whole percentage, "39 %"; "" where it rounds to 0 %.
std::string percent(double share) {
  const std::string text = fixed(100.0 * share, 0);
  return text == "0" ? std::string() : text + " %";
}

// "body pitch (1.29 Hz) 124 %; body bounce (1.07 Hz) 39 %; cross terms −63 %": the largest
// shares of the variance, then the modes not named together and the cross terms, so that the
// percentages add up to 100 % before each is rounded (semicolons: mode names have commas). Each mode's share is the
// variance of its term alone; the cross terms Σ_{j≠k}∫Re(H_jH_k*)G df are negative where two
// modes' terms partly cancel at the output, and then one mode's share exceeds 100 %. A
// suspension force's direct track term alone comes first; what is left beside it is named so.
std::string dominant_modes(const RideResult& r, const RideOutputAtSpeed& o) {
  const double variance = o.rms * o.rms;
  if (!(variance > 0.0) || (o.modes.empty() && !(o.direct_variance > 0.0))) return "–";  // no shares given
  std::vector<std::string> parts;
  double rest = o.cross_term_variance;  // σ² − Σ_j var_j
  if (o.direct_variance > 0.0) {
    parts.push_back("direct track term " + fixed(100.0 * o.direct_variance / variance, 0) + " %");
    rest -= o.direct_variance;
  }
  double others = 0.0;  // the modes not named
  for (size_t k = 0; k < o.modes.size(); ++k) {
    if (k < kDominantModes && (k == 0 || o.modes[k].share >= kSmallestShownShare))
      parts.push_back(mode_name(r, o.modes[k].mode) + " " + fixed(100.0 * o.modes[k].share, 0) + " %");
    else
      others += o.modes[k].share;
  }
  if (const std::string p = percent(others); !p.empty()) parts.push_back("other modes " + p);
  // Without modal shares (the creep contact) the rest is the vehicle's whole response with its
  // cross term against the direct one.
  const char* rest_name = o.modes.empty() ? "response and cross terms " : "cross terms ";
  if (const std::string p = percent(rest / variance); !p.empty()) parts.push_back(rest_name + p);
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text;
}

std::string input_name(const RideResult& r, size_t k) {
  return k < r.inputs.size() ? r.inputs[k] : "input " + std::to_string(k + 1);
}

std::string capitalised(std::string word) {
  if (!word.empty()) word[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
  return word;
}

// ---- the tables (text, Markdown, HTML) ----

// RMS only (rms_only): the first four columns.
Table indices_table(const RideResult& r, const RideAtSpeed& at) {
  Table t;
  const bool every_index = !r.rms_only;
  t.headers = {"output", "unit", "RMS", "weighted RMS [m/s²]"};
  t.numeric = {false, false, true, true};
  if (every_index) {
    t.headers.insert(t.headers.end(), {"P95 estimate [m/s²]", "Wz", "dominant modes"});
    t.numeric.insert(t.numeric.end(), {true, true, false});
  }
  for (size_t i = 0; i < r.outputs.size() && i < at.outputs.size(); ++i) {
    const RideOutputAtSpeed& o = at.outputs[i];
    std::vector<std::string> row{r.outputs[i].name, unit_of(r.outputs[i])};
    if (o.unbounded) {
      row.insert(row.end(), {"unbounded", "–"});
      if (every_index) row.insert(row.end(), {"–", "–", "see the notes"});
    } else {
      row.insert(row.end(), {value_text(o.rms), optional_text(o.weighted_rms)});
      if (every_index)
        row.insert(row.end(), {optional_text(o.p95_estimate), o.sperling_wz ? fixed(*o.sperling_wz, 2) : "–",
                               dominant_modes(r, o)});
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

// The N_MV as people read it: "0.76 (vertical only)" for a partial one.
std::string nmv_text(const RideComfortAtPoint& c) {
  const std::string scope = nmv_scope(c);
  return fixed(c.nmv_estimate, 2) + (scope.empty() ? "" : " (" + scope + ")");
}

Table comfort_table(const std::vector<RideComfortAtPoint>& comfort, const std::vector<RideOutput>& outputs,
                    const std::string& heading) {
  Table t;
  t.headers = {"floor point", heading, "axes without an output"};
  t.numeric = {false, true, false};
  for (const RideComfortAtPoint& c : comfort) {
    std::string missing;
    for (RideAxis a : c.missing_axes) missing += (missing.empty() ? "" : ", ") + std::string(to_string(a));
    t.rows.push_back({point_text(c, outputs), nmv_text(c), missing.empty() ? "–" : missing + " (taken as 0)"});
  }
  return t;
}

Table modes_table(const RideResult& r) {
  Table t;
  t.headers = {"mode", "name", "frequency [Hz]"};
  t.numeric = {true, false, true};
  for (size_t k = 0; k < r.modes.size(); ++k)
    t.rows.push_back({mode_number(k), r.modes[k].name, fixed(r.modes[k].frequency_hz, 3)});
  return t;
}

Table simulated_table(const RideSimulationResult& s) {
  Table t;
  t.headers = {"output", "unit", "RMS", "weighted RMS [m/s²]", "P95 of the windows [m/s²]", "Wz", "windows"};
  t.numeric = {false, false, true, true, true, true, true};
  for (size_t i = 0; i < s.outputs.size() && i < s.histories.size(); ++i) {
    const RideHistory& h = s.histories[i];
    t.rows.push_back({s.outputs[i].name, unit_of(s.outputs[i]), value_text(h.rms), optional_text(h.weighted_rms),
                      optional_text(h.p95), h.sperling_wz ? fixed(*h.sperling_wz, 2) : "–",
                      std::to_string(h.window_rms.size())});
  }
  return t;
}

Table checks_table(const RideFftChecks& c, const RideSimulationResult& s) {
  Table t;
  t.headers = {"check", "value"};
  t.numeric = {false, true};
  t.rows.push_back({"(a) exact: largest bin error of the steady state against H·X",
                    c.exact_bin_error ? significant(*c.exact_bin_error, 3) : "not run (not periodic, or not linear)"});
  t.rows.push_back({"(b) Welch PSD bins of the realisation outside the 95 % band (expected about 5 %)",
                    fixed(100.0 * c.fraction_outside_band, 1) + " %"});
  for (size_t i = 0; i < c.rms_difference.size() && i < s.outputs.size(); ++i)
    t.rows.push_back({"(c) RMS, simulated against spectral: " + s.outputs[i].name,
                      fixed(100.0 * c.rms_difference[i], 2) + " %"});
  return t;
}

// "; track RMS over each band: ORE B176 low, vertical level 2.36 mm, …" (RideResult::input_rms).
std::string track_rms_text(const RideResult& r) {
  std::string text;
  for (size_t k = 0; k < r.input_rms.size() && k < r.inputs.size(); ++k)
    text += (k ? ", " : "; track RMS over each band: ") + r.inputs[k] + " " + significant(1000.0 * r.input_rms[k], 3) +
            " mm";
  return text;
}

// Whether the grid error estimate measured anything: some output has a bounded RMS at some speed.
// With none (every output unbounded) it is 0 by default, not an estimate, and the reports say so.
std::string grid_error_text(const RideResult& r) {
  if (r.rms_only) return "; RMS and weighted RMS only (no grid error estimate)";
  if (!has_grid_error_estimate(r)) return "; no grid error estimate (no output has a bounded RMS)";
  return "; grid error estimate " + significant(100.0 * r.grid_error_estimate, 2) + " % of an RMS";
}

std::string method_text(const RideResult& r) {
  if (r.frequencies.size() == 0)
    return "No frequency-domain ride: the track is a geometry file, which has no spectrum; the time-domain run below "
           "is the result";
  return "S_out(f) = Σ_c |H_c(f)|² G_c(f) over " + std::to_string(r.frequencies.size()) + " frequencies from " +
         (r.frequencies.size() ? significant(r.frequencies[0], 3) + " to " +
                                     significant(r.frequencies[r.frequencies.size() - 1], 3) + " Hz"
                               : std::string("–")) +
         grid_error_text(r) +
         "; friction: " +
         (r.friction_treatment.empty() ? std::string("none in the vehicle") : r.friction_treatment) + track_rms_text(r);
}

constexpr const char* kEstimateNote =
    "P95 estimate: the 95th percentile of the 5 s weighted RMS values estimated from the spectrum, not measured. "
    "N_MV = 6·√(P95x² + P95y² + P95z²) (EN 12299) from those estimates. Wz: Sperling's index from the B-weighted "
    "RMS (filter form). Dominant modes: each mode's share is the variance of its term alone over the output's "
    "variance; the modes not named and the cross terms between the terms follow, so that the percentages add up "
    "to 100 %. Cross terms are negative where two terms partly cancel at the output, and then one share exceeds "
    "100 % (a suspension force, which also follows the track directly, shows this most: the share of its direct "
    "track term alone comes first).";

// The time-domain notes with those that differ only in the output they begin with ("floor at
// mid-car, vertical: P95 over the 36 complete windows …") written once, naming how many.
std::vector<std::string> run_notes(const RideSimulationResult& s) {
  std::vector<std::string> notes;
  std::vector<std::pair<std::string, size_t>> shared;  // text after the output's name, outputs
  for (const std::string& n : s.notes) {
    const auto named = std::find_if(s.outputs.begin(), s.outputs.end(),
                                    [&](const RideOutput& o) { return n.rfind(o.name + ": ", 0) == 0; });
    if (named == s.outputs.end()) {
      notes.push_back(n);
      continue;
    }
    const std::string text = n.substr(named->name.size() + 2);
    const auto seen = std::find_if(shared.begin(), shared.end(), [&](const auto& t) { return t.first == text; });
    if (seen == shared.end()) shared.push_back({text, 1});
    else ++seen->second;
  }
  for (const auto& [text, count] : shared)
    notes.push_back(count == 1 ? text : capitalised(text) + " (" + std::to_string(count) + " outputs)");
  return notes;
}

constexpr const char* kFloorPointNote =
    "Floor points: named by their outputs, then the body and the point (x, y, z) in m in the vehicle frame (x "
    "forward, y to the left, z up from the plane of the axles, on the track centre line).";

// Whether the report has an N_MV table, whose floor points kFloorPointNote explains.
bool has_floor_points(const RideResult& r, const RideSimulationResult* simulated) {
  return std::any_of(r.speeds.begin(), r.speeds.end(), [](const RideAtSpeed& at) { return !at.comfort.empty(); }) ||
         (simulated && !simulated->comfort.empty());
}

constexpr const char* kCheckNote =
    "(c) is read against the scatter of a realisation's RMS, a few per cent for minutes of track (docs/ride.md, "
    "\"The FFT checks\"), not as pass or fail; (a) is exact to round-off for a linear vehicle.";

// Markdown and HTML write the same sections; `kind` says how a table is written.
enum class Document { markdown, html };

void write_table(std::ostream& out, const Table& t, Document d) {
  if (d == Document::markdown) report::write_markdown_table(out, t);
  else report::write_html_table(out, t);
}

// ---- the charts (HTML) ----

std::vector<double> to_vector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

report::ChartSeries series(const std::string& label, std::vector<double> x, std::vector<double> y) {
  report::ChartSeries s;
  s.label = label;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

std::vector<report::ReferenceLine> mode_lines(const RideResult& r) {
  std::vector<report::ReferenceLine> lines;
  for (size_t k = 0; k < r.modes.size(); ++k)
    if (r.frequencies.size() && r.modes[k].frequency_hz >= r.frequencies[0] &&
        r.modes[k].frequency_hz <= r.frequencies[r.frequencies.size() - 1])
      lines.push_back({mode_number(k), r.modes[k].frequency_hz, true, ""});  // the modes table names them
  return lines;
}

report::Chart input_chart(const RideResult& r, size_t speed) {
  report::Chart c;
  c.id = "input-psd";
  c.title = "Track input at " + kmh(r.speeds[speed].speed);
  c.x_label = "frequency (Hz)";
  c.y_label = "PSD [m²/Hz]";  // brackets: a unit with parentheses in it reads as one
  c.log_x = c.log_y = true;
  const auto f = to_vector(r.frequencies);
  for (size_t k = 0; k < r.speeds[speed].input_psd.size(); ++k)
    c.series.push_back(series(input_name(r, k), f, to_vector(r.speeds[speed].input_psd[k])));
  c.lines = mode_lines(r);
  return c;
}

// The unit of a PSD of values in `unit`: "m²/Hz", "(m/s²)²/Hz", "N²/Hz".
std::string psd_unit(const std::string& unit) {
  return (unit.find('/') == std::string::npos ? unit + "²" : "(" + unit + ")²") + "/Hz";
}

// What outputs in `unit` are, for a chart's title.
std::string quantity_word(const std::string& unit) {
  return unit == "m/s²" ? "acceleration" : unit == "m/s" ? "velocity" : unit == "N" ? "force" : "displacement";
}

// The outputs charted together: one unit along one axis ("vertical acceleration").
struct Group {
  std::string unit;
  RideAxis axis;
};

std::vector<Group> groups_of(const RideResult& r) {
  std::vector<Group> groups;
  for (const RideOutput& o : r.outputs)
    if (std::none_of(groups.begin(), groups.end(),
                     [&](const Group& g) { return g.unit == unit_of(o) && g.axis == o.axis; }))
      groups.push_back({unit_of(o), o.axis});
  return groups;
}

// The output PSDs of one group at one speed.
report::Chart output_chart(const RideResult& r, size_t speed, const Group& g, int id) {
  report::Chart c;
  c.id = "output-psd-" + std::to_string(id);
  c.title = capitalised(to_string(g.axis)) + " " + quantity_word(g.unit) + " spectra at " + kmh(r.speeds[speed].speed);
  c.x_label = "frequency (Hz)";
  c.y_label = "PSD [" + psd_unit(g.unit) + "]";
  c.log_x = c.log_y = true;
  const auto f = to_vector(r.frequencies);
  for (size_t i = 0; i < r.outputs.size(); ++i) {
    const RideOutputAtSpeed& o = r.speeds[speed].outputs[i];
    if (unit_of(r.outputs[i]) != g.unit || r.outputs[i].axis != g.axis || o.unbounded ||
        o.psd.size() != r.frequencies.size())
      continue;
    c.series.push_back(series(r.outputs[i].name, f, to_vector(o.psd)));
  }
  c.lines = mode_lines(r);
  return c;
}

// An index against speed, one series per output that has it.
report::Chart index_chart(const RideResult& r, RideAxis axis, const std::string& id, const std::string& title,
                          const std::string& y_label, std::optional<double> (*index)(const RideOutputAtSpeed&)) {
  report::Chart c;
  c.id = id + "-" + to_string(axis);
  c.title = title;
  c.x_label = "speed (km/h)";
  c.y_label = y_label;
  for (size_t i = 0; i < r.outputs.size(); ++i) {
    if (r.outputs[i].axis != axis) continue;
    report::ChartSeries s;
    s.label = r.outputs[i].name;
    bool any = false;
    for (const RideAtSpeed& at : r.speeds) {
      const auto v = at.outputs[i].unbounded ? std::nullopt : index(at.outputs[i]);
      s.x.push_back(at.speed * kKmh);
      s.y.push_back(v ? *v : std::nan(""));
      any = any || v.has_value();
    }
    if (any) c.series.push_back(s);
  }
  return c;
}

// The RMS against speed of a group's outputs, for those without comfort indices (forces,
// deflections, displacements and velocities), which the index charts do not show: every
// requested output then has a chart against speed (the audit of 2026-11-27).
report::Chart rms_chart(const RideResult& r, const Group& g, int id) {
  report::Chart c;
  c.id = "rms-" + std::to_string(id);
  c.title = std::string("RMS against speed, ") + to_string(g.axis) + " " + quantity_word(g.unit);
  c.x_label = "speed (km/h)";
  c.y_label = "RMS (" + g.unit + ")";
  for (size_t i = 0; i < r.outputs.size(); ++i) {
    if (unit_of(r.outputs[i]) != g.unit || r.outputs[i].axis != g.axis) continue;
    report::ChartSeries s;
    s.label = r.outputs[i].name;
    bool any = false;
    for (const RideAtSpeed& at : r.speeds) {
      s.x.push_back(at.speed * kKmh);
      s.y.push_back(at.outputs[i].unbounded ? std::nan("") : at.outputs[i].rms);
      any = any || !at.outputs[i].unbounded;
    }
    if (any) c.series.push_back(s);
  }
  return c;
}

std::optional<double> weighted_of(const RideOutputAtSpeed& o) { return o.weighted_rms; }
std::optional<double> wz_of(const RideOutputAtSpeed& o) { return o.sperling_wz; }

// The floor points with an N_MV at some speed, in the order the speeds first give them. A point
// whose axis is unbounded at a speed has no N_MV there and is left out of that speed's list, so
// the lists of two speeds need not match by position: columns and series go by the point.
std::vector<const RideComfortAtPoint*> comfort_points(const RideResult& r) {
  std::vector<const RideComfortAtPoint*> points;
  for (const RideAtSpeed& at : r.speeds)
    for (const RideComfortAtPoint& c : at.comfort)
      if (std::none_of(points.begin(), points.end(), [&](const RideComfortAtPoint* p) {
            return p->body == c.body && p->point == c.point;
          }))
        points.push_back(&c);
  return points;
}

// The N_MV of `point` at one speed, or null where it has none (an unbounded axis).
const RideComfortAtPoint* comfort_at(const RideAtSpeed& at, const RideComfortAtPoint& point) {
  for (const RideComfortAtPoint& c : at.comfort)
    if (c.body == point.body && c.point == point.point) return &c;
  return nullptr;
}

report::Chart nmv_chart(const RideResult& r) {
  report::Chart c;
  c.id = "nmv";
  c.title = "EN 12299 mean comfort N_MV per floor point, from the P95 estimates";
  c.x_label = "speed (km/h)";
  c.y_label = "N_MV estimate (–)";
  if (r.speeds.empty()) return c;
  for (const RideComfortAtPoint* point : comfort_points(r)) {
    report::ChartSeries s;
    const std::string scope = nmv_scope(*point);
    s.label = point_text(*point, r.outputs) + (scope.empty() ? "" : " (" + scope + ")");
    for (const RideAtSpeed& at : r.speeds)
      if (const RideComfortAtPoint* c = comfort_at(at, *point))
        s.x.push_back(at.speed * kKmh), s.y.push_back(c->nmv_estimate);
    c.series.push_back(s);
  }
  return c;
}

// The weighted acceleration of a time-domain run and its window RMS values as steps.
report::Chart history_chart(const RideSimulationResult& s, size_t i, double window) {
  report::Chart c;
  c.id = "history-" + std::to_string(i);
  // EN 12299 weights vertical acceleration by Wb, lateral and longitudinal by Wd.
  c.title = std::string(s.outputs[i].axis == RideAxis::vertical ? "Wb" : "Wd") +
            "-weighted acceleration and its " + significant(window, 3) + " s RMS values: " + s.outputs[i].name;
  c.x_label = "time (s)";
  c.y_label = "weighted acceleration (m/s²)";
  const RideHistory& h = s.histories[i];
  report::ChartSeries trace = series("weighted acceleration", {}, {});
  // At most some 4000 points drawn: every k-th sample (the page stays small; the JSON has the
  // window values).
  const size_t n = std::min<size_t>(h.weighted.size(), s.time.size());
  const size_t every = std::max<size_t>(1, n / 4000);
  for (size_t k = 0; k < n; k += every) trace.x.push_back(s.time[k]), trace.y.push_back(h.weighted[k]);
  c.series.push_back(trace);
  report::ChartSeries windows = series("RMS of each " + significant(window, 3) + " s window", {}, {});
  const double t0 = s.time.size() ? s.time[0] : 0.0;
  for (Eigen::Index w = 0; w < h.window_rms.size(); ++w) {
    windows.x.push_back(t0 + w * window), windows.y.push_back(h.window_rms[w]);
    windows.x.push_back(t0 + (w + 1) * window), windows.y.push_back(h.window_rms[w]);
  }
  c.series.push_back(windows);
  // Over the trace: under it, the dense history hid the level (the audit of 2026-11-27).
  if (h.p95) c.lines.push_back({"P95", *h.p95, false, "the 95th percentile of the window RMS values", true});
  return c;
}

// ---- the documents ----

void write_speed_sections(std::ostream& out, const Page& p, Document d) {
  const RideResult& r = p.r;
  const bool md = d == Document::markdown;
  for (size_t s = 0; s < r.speeds.size(); ++s) {
    const RideAtSpeed& at = r.speeds[s];
    out << (md ? "\n## " : "<h2>") << "At " << kmh(at.speed) << (md ? "\n\n" : "</h2>\n");
    write_table(out, indices_table(r, at), d);
    if (!at.comfort.empty()) {
      out << (md ? "\n" : "");
      write_table(out, comfort_table(at.comfort, r.outputs, "N_MV (estimate)"), d);
    }
  }
}

void write_time_domain(std::ostream& out, const Page& p, Document d) {
  if (!p.simulated) return;
  const bool md = d == Document::markdown;
  const RideSimulationResult& s = *p.simulated;
  out << (md ? "\n## Time-domain run\n\n" : "<h2>Time-domain run</h2>\n");
  // What was run and how (track, speed, duration, step) comes before the figures.
  for (const std::string& n : run_notes(s))
    out << (md ? "- " : "<p class=note>") << (md ? n : report::html_escape(n)) << (md ? "\n" : "</p>\n");
  out << (md ? "\n" : "");
  write_table(out, simulated_table(s), d);
  if (!s.comfort.empty()) {
    out << (md ? "\n" : "");
    write_table(out, comfort_table(s.comfort, s.outputs, "N_MV"), d);
  }
  if (d == Document::html)
    for (size_t i = 0; i < s.outputs.size() && i < s.histories.size(); ++i)
      if (s.histories[i].weighted.size() > 0) out << report::svg_chart(history_chart(s, i, s.window));
  if (p.checks) {
    out << (md ? "\n### FFT checks\n\n" : "<h3>FFT checks</h3>\n");
    write_table(out, checks_table(*p.checks, s), d);
    out << (md ? "\n" : "<p class=note>") << (md ? kCheckNote : report::html_escape(kCheckNote))
        << (md ? "\n" : "</p>\n");
  }
}

void write_markdown(std::ostream& out, const Page& p) {
  const RideResult& r = p.r;
  out << "# Ride: " << p.title << "\n\n" << method_text(r) << ".\n";
  if (!r.modes.empty()) {
    out << "\n## Modes\n\n";
    report::write_markdown_table(out, modes_table(r));
  }
  write_speed_sections(out, p, Document::markdown);
  if (!r.speeds.empty() && !r.rms_only) out << "\n" << kEstimateNote << "\n";
  if (has_floor_points(r, p.simulated)) out << "\n" << kFloorPointNote << "\n";
  for (const std::string& n : r.notes) out << "\n- " << n << "\n";
  write_time_domain(out, p, Document::markdown);
}

void write_html(std::ostream& out, const Page& p) {
  const RideResult& r = p.r;
  using report::html_escape;
  report::write_html_head(out, "Ride: " + p.title);
  out << "<h1>Ride: " << html_escape(p.title) << "</h1>\n<p>" << html_escape(method_text(r)) << ".</p>\n";
  for (const std::string& n : r.notes) out << "<p class=note>" << html_escape(n) << "</p>\n";
  // Against speed only when there are speeds to draw a line through; one speed is its table.
  if (r.speeds.size() > 1) {
    out << "<h2>Indices against speed</h2>\n";
    // One chart per axis, so that each holds a few floor points.
    for (RideAxis axis : {RideAxis::vertical, RideAxis::lateral, RideAxis::longitudinal}) {
      const std::string along = to_string(axis);
      const report::Chart weighted =
          index_chart(r, axis, "weighted-rms", "EN 12299 weighted RMS, " + along + " (W" +
                                                   (axis == RideAxis::vertical ? "b" : "d") + ")",
                      "weighted RMS (m/s²)", weighted_of);
      if (weighted.series.empty()) continue;
      out << report::svg_chart(weighted);
      const report::Chart wz = index_chart(r, axis, "wz", "Sperling's ride index Wz, " + along, "Wz (–)", wz_of);
      if (!wz.series.empty()) out << report::svg_chart(wz);
    }
    if (!comfort_points(r).empty()) out << report::svg_chart(nmv_chart(r));
    const std::vector<Group> groups = groups_of(r);
    for (size_t g = 0; g < groups.size(); ++g) {
      if (groups[g].unit == "m/s²") continue;  // point accelerations: the index charts above
      const report::Chart c = rms_chart(r, groups[g], static_cast<int>(g));
      if (!c.series.empty()) out << report::svg_chart(c);
    }
  }
  if (!r.speeds.empty()) {
    // The spectra at the highest speed: the one a ride is signed off at.
    const size_t top = r.speeds.size() - 1;
    out << "<h2>Spectra at " << html_escape(kmh(r.speeds[top].speed)) << "</h2>\n";
    if (!r.speeds[top].input_psd.empty()) out << report::svg_chart(input_chart(r, top));
    const std::vector<Group> groups = groups_of(r);
    for (size_t g = 0; g < groups.size(); ++g) {
      const report::Chart c = output_chart(r, top, groups[g], static_cast<int>(g));
      if (!c.series.empty()) out << report::svg_chart(c);
    }
    out << "<p class=note>Dotted vertical lines: the natural frequencies of the modes (numbered as in the table "
           "below).</p>\n";
  }
  if (!r.modes.empty()) {
    out << "<h2>Modes</h2>\n";
    report::write_html_table(out, modes_table(r));
  }
  write_speed_sections(out, p, Document::html);
  if (!r.speeds.empty() && !r.rms_only) out << "<p class=note>" << html_escape(kEstimateNote) << "</p>\n";
  if (has_floor_points(r, p.simulated)) out << "<p class=note>" << html_escape(kFloorPointNote) << "</p>\n";
  write_time_domain(out, p, Document::html);
  report::write_html_footer(out, "ride", p.provenance);
}

void write_text(std::ostream& out, const Page& p) {
  const RideResult& r = p.r;
  out << "Ride: " << p.title << "\n" << method_text(r) << "\n";
  if (!r.modes.empty()) {
    out << "\nModes:\n";
    write_text_table(out, modes_table(r));
  }
  for (const RideAtSpeed& at : r.speeds) {
    out << "\nAt " << kmh(at.speed) << ":\n";
    write_text_table(out, indices_table(r, at));
    if (!at.comfort.empty()) write_text_table(out, comfort_table(at.comfort, r.outputs, "N_MV (estimate)"));
  }
  const bool estimated = !r.speeds.empty() && !r.rms_only;
  if (estimated) out << "\n" << kEstimateNote << "\n";
  if (has_floor_points(r, p.simulated)) out << (estimated ? "" : "\n") << kFloorPointNote << "\n";
  for (const std::string& n : r.notes) out << "Note: " << n << "\n";
  if (p.simulated) {
    out << "\nTime-domain run:\n";
    for (const std::string& n : run_notes(*p.simulated)) out << "  " << n << "\n";
    write_text_table(out, simulated_table(*p.simulated));
    if (!p.simulated->comfort.empty()) write_text_table(out, comfort_table(p.simulated->comfort, p.simulated->outputs, "N_MV"));
    if (p.checks) {
      out << "FFT checks:\n";
      write_text_table(out, checks_table(*p.checks, *p.simulated));
      out << "  " << kCheckNote << "\n";
    }
  }
}

// ---- CSV and JSON ----

// A number that is not finite is a blank field.
void finite_field(report::CsvWriter& csv, double v) { std::isfinite(v) ? void(csv.field(v)) : void(csv.blank()); }
void optional_field(report::CsvWriter& csv, const std::optional<double>& v) {
  v ? finite_field(csv, *v) : void(csv.blank());
}

// Whether an output has the comfort indices (weighted RMS, P95, Wz): a point's acceleration.
bool has_comfort_indices(const RideOutput& o) {
  return o.kind == RideOutput::Kind::point && o.quantity == ResponseQuantity::acceleration;
}

// One row per speed: for each output its RMS and, for a floor acceleration, its weighted RMS,
// P95 estimate and Wz, each column headed with its unit; then N_MV per floor point. An unbounded
// RMS is the word, its other columns blank. RMS only (rms_only): the RMS and weighted RMS
// columns, no P95, Wz or N_MV column (a CSV has no place for the note; the headings say what
// there is).
void write_csv(std::ostream& out, const RideResult& r) {
  using report::csv_heading;
  report::CsvWriter csv(out);
  const bool every_index = !r.rms_only;
  csv.field(csv_heading("speed", "km/h"));
  for (const RideOutput& o : r.outputs) {
    csv.field(csv_heading(o.name + " rms", unit_of(o)));
    if (has_comfort_indices(o)) csv.field(csv_heading(o.name + " weighted rms", "m/s²"));
    if (has_comfort_indices(o) && every_index)
      csv.field(csv_heading(o.name + " p95 estimate", "m/s²")).field(o.name + " sperling wz");
  }
  const std::vector<const RideComfortAtPoint*> points = comfort_points(r);
  for (const RideComfortAtPoint* c : points) {
    const std::string scope = nmv_scope(*c);
    csv.field("nmv estimate " + (scope.empty() ? "" : "(" + scope + ") ") + point_text(*c, r.outputs));
  }
  csv.end_row();
  for (const RideAtSpeed& at : r.speeds) {
    finite_field(csv, kmh_value(at.speed));
    for (size_t i = 0; i < r.outputs.size() && i < at.outputs.size(); ++i) {
      const RideOutputAtSpeed& o = at.outputs[i];
      const bool comfort = has_comfort_indices(r.outputs[i]);
      if (o.unbounded) {
        csv.field("unbounded");
        if (comfort) csv.blank();
        if (comfort && every_index) csv.blank().blank();
        continue;
      }
      finite_field(csv, o.rms);
      if (comfort) optional_field(csv, o.weighted_rms);
      if (comfort && every_index) {
        optional_field(csv, o.p95_estimate);
        optional_field(csv, o.sperling_wz);
      }
    }
    for (const RideComfortAtPoint* point : points) {
      const RideComfortAtPoint* c = comfort_at(at, *point);
      if (c) finite_field(csv, c->nmv_estimate);
      else csv.field("unbounded");  // an axis there is unbounded at this speed (the notes say which)
    }
    csv.end_row();
  }
}

// The spectra behind the RMS (write_ride_spectra): one row per speed and frequency of the grid,
// long rather than wide so that another tool plots an output against frequency by filtering on
// the speed column; the inputs' PSDs first, then the outputs', each heading with its unit²/Hz.
// A value not there (an unbounded output's, or a spectrum not kept) is a blank field.
void write_spectra_csv(std::ostream& out, const RideResult& r) {
  using report::csv_heading;
  report::CsvWriter csv(out);
  csv.field(csv_heading("speed", "km/h")).field(csv_heading("frequency", "Hz"));
  const size_t inputs = r.speeds.empty() ? r.inputs.size() : r.speeds.front().input_psd.size();
  for (size_t k = 0; k < inputs; ++k) csv.field(csv_heading(input_name(r, k) + " input psd", "m²/Hz"));
  for (const RideOutput& o : r.outputs) csv.field(csv_heading(o.name + " psd", psd_unit(unit_of(o))));
  csv.end_row();
  const Eigen::Index n = r.frequencies.size();
  for (const RideAtSpeed& at : r.speeds)
    for (Eigen::Index b = 0; b < n; ++b) {
      finite_field(csv, kmh_value(at.speed));
      csv.field(r.frequencies[b]);
      for (size_t k = 0; k < inputs; ++k)
        k < at.input_psd.size() && at.input_psd[k].size() == n ? finite_field(csv, at.input_psd[k][b]) : void(csv.blank());
      for (size_t i = 0; i < r.outputs.size(); ++i) {
        const bool kept = i < at.outputs.size() && !at.outputs[i].unbounded && at.outputs[i].psd.size() == n;
        kept ? finite_field(csv, at.outputs[i].psd[b]) : void(csv.blank());
      }
      csv.end_row();
    }
}

// Every inner object's members in the alphabetical order nlohmann::json's std::map gave them
// (the names' prefixes fix the order whatever the unit suffix); a number that is not finite is
// null (JsonWriter).
void write_values(JsonWriter& j, const Eigen::VectorXd& v) {
  j.begin_array();
  for (Eigen::Index k = 0; k < v.size(); ++k) j.value(v[k]);
  j.end_array();
}

void write_point(JsonWriter& j, const Eigen::Vector3d& p) {
  j.key("point_m").begin_array().value(p.x()).value(p.y()).value(p.z()).end_array();
}

void write_output(JsonWriter& j, const RideOutput& o) {
  j.begin_object().member("axis", to_string(o.axis));
  if (o.kind == RideOutput::Kind::point) {
    j.member("body", o.body);
    // An acceleration's frame: an accelerometer on the body (with g·φ) or the track's (inertial).
    if (o.quantity == ResponseQuantity::acceleration) j.member("frame", to_string(o.frame));
    j.member("kind", to_string(o.kind)).member("name", o.name);
    write_point(j, o.point);
    j.member("quantity", to_string(o.quantity));
  } else {
    j.member("element", o.element).member("kind", to_string(o.kind)).member("name", o.name);
  }
  j.member("unit", unit_of(o)).end_object();
}

void write_comfort(JsonWriter& j, const std::vector<RideComfortAtPoint>& comfort, const char* key) {
  j.begin_array();
  for (const RideComfortAtPoint& c : comfort) {
    j.begin_object().member("body", c.body).key("missing_axes").begin_array();
    for (RideAxis x : c.missing_axes) j.value(to_string(x));
    j.end_array().member(key, c.nmv_estimate);
    // A partial N_MV says so beside its figure (absent for one over the lateral and vertical axes).
    if (const std::string scope = nmv_scope(c); !scope.empty()) j.member("partial", scope);
    write_point(j, c.point);
    j.end_object();
  }
  j.end_array();
}

// RMS only (rms_only): no comfort, modes, variance, P95 or Wz member.
void write_at_speed(JsonWriter& j, const RideResult& r, const RideAtSpeed& at) {
  const bool every_index = !r.rms_only;
  j.begin_object();
  if (every_index) {
    j.key("comfort");
    write_comfort(j, at.comfort, "nmv_estimate");
  }
  j.key("inputs").begin_array();
  for (size_t k = 0; k < at.input_psd.size(); ++k) {
    j.begin_object().member("name", input_name(r, k)).key("psd_m2_per_hz");
    write_values(j, at.input_psd[k]);
    j.end_object();
  }
  j.end_array().key("outputs").begin_array();
  for (size_t i = 0; i < r.outputs.size() && i < at.outputs.size(); ++i) {
    const RideOutputAtSpeed& o = at.outputs[i];
    const RideOutput& out = r.outputs[i];
    j.begin_object();
    if (o.unbounded) {
      j.member("name", out.name).member("unbounded", true).end_object();
      continue;
    }
    if (every_index) {
      // Σ modes' share + direct_share + cross_term_share = 1, the shares the text's percentages
      // give (dominant_modes): cross_term_variance is σ² − Σ modes' variances, the direct track
      // term included, so the cross terms' share is what is left of it without that term.
      const double variance = o.rms * o.rms;
      j.member("cross_term_share", variance > 0.0 ? (o.cross_term_variance - o.direct_variance) / variance : 0.0);
      j.member("cross_term_variance", o.cross_term_variance);
      j.member("direct_share", variance > 0.0 ? o.direct_variance / variance : 0.0);
      j.member("direct_variance", o.direct_variance).key("modes").begin_array();
      for (const ModalContribution& m : o.modes)
        // 1-based, as the reports' tables number the modes
        j.begin_object().member("mode", m.mode + 1).member("share", m.share).member("variance", m.variance)
            .end_object();
      j.end_array();
    }
    j.member("name", out.name);
    if (every_index) j.member("p95_estimate_m_s2", o.p95_estimate);
    if (o.psd.size() > 0) {
      j.key("psd");
      write_values(j, o.psd);
    }
    j.member("rms", o.rms);
    if (every_index) j.member("sperling_wz", o.sperling_wz);
    j.member("unbounded", false).member("unit", unit_of(out));
    j.member("weighted_rms_m_s2", o.weighted_rms).end_object();
  }
  j.end_array().member("speed_kmh", kmh_value(at.speed)).member("speed_m_s", at.speed).end_object();
}

void write_summary(JsonWriter& j, const AnalysisSummary& s) {
  j.begin_object().member("analysis", s.analysis).key("checks").begin_array();
  for (const Check& c : s.checks) {
    j.begin_object().member("limit", c.limit).member("name", c.name).key("passed");
    // a figure reported without a bound neither passes nor fails
    std::isfinite(c.limit) ? j.value(c.passed) : j.value(nullptr);
    j.member("value", c.value).end_object();
  }
  j.end_array().member("method", s.method).end_object();
}

void write_simulated(JsonWriter& j, const RideSimulationResult& s, const RideFftChecks* c) {
  j.begin_object().key("comfort");
  write_comfort(j, s.comfort, "nmv");
  j.member("duration_s", s.time.size() > 1 ? s.time[s.time.size() - 1] - s.time[0] : 0.0);
  if (c) {
    j.key("fft_checks").begin_object().member("exact_bin_error", c->exact_bin_error);
    j.member("fraction_outside_band", c->fraction_outside_band).member("rms_difference", c->rms_difference);
    j.key("summary");
    write_summary(j, c->summary);
    j.end_object();
  }
  j.member("notes", s.notes).key("outputs").begin_array();
  for (size_t i = 0; i < s.outputs.size() && i < s.histories.size(); ++i) {
    const RideHistory& h = s.histories[i];
    j.begin_object().member("name", s.outputs[i].name).member("p95_m_s2", h.p95);
    j.member("rms", h.rms).member("sperling_wz", h.sperling_wz).member("unit", unit_of(s.outputs[i]));
    j.member("weighted_rms_m_s2", h.weighted_rms).key("window_rms_m_s2");
    write_values(j, h.window_rms);
    j.end_object();
  }
  j.end_array().end_object();
}

// One member a line, and each speed on a line of its own (its spectra are most of the document):
// readable and diffable without one number a line (json_lines.hpp).
void write_json(std::ostream& out, const Page& p) {
  using report::write_line_member;
  const RideResult& r = p.r;
  write_line_member(out, "title", [&](JsonWriter& j) { j.value(p.title); }, true);
  write_line_member(out, "friction_treatment", [&](JsonWriter& j) { j.value(r.friction_treatment); });
  // RMS only (rms_only): no grid error estimate, and a member that says so.
  if (r.rms_only) write_line_member(out, "rms_only", [&](JsonWriter& j) { j.value(true); });
  else if (!has_grid_error_estimate(r)) write_line_member(out, "grid_error_estimate", [&](JsonWriter& j) { j.value(nullptr); });
  else write_line_member(out, "grid_error_estimate", [&](JsonWriter& j) { j.value(r.grid_error_estimate); });
  write_line_member(out, "notes", [&](JsonWriter& j) { j.value(r.notes); });
  write_line_member(out, "track_rms", [&](JsonWriter& j) {
    j.begin_array();
    for (size_t k = 0; k < r.input_rms.size() && k < r.inputs.size(); ++k)
      j.begin_object().member("name", r.inputs[k]).member("rms_m", r.input_rms[k]).end_object();
    j.end_array();
  });
  write_line_member(out, "summary", [&](JsonWriter& j) { write_summary(j, r.summary); });
  write_line_member(out, "modes", [&](JsonWriter& j) {
    j.begin_array();
    for (const RideMode& m : r.modes)
      j.begin_object().member("frequency_hz", m.frequency_hz).member("name", m.name).end_object();
    j.end_array();
  });
  write_line_member(out, "outputs", [&](JsonWriter& j) {
    j.begin_array();
    for (const RideOutput& o : r.outputs) write_output(j, o);
    j.end_array();
  });
  write_line_member(out, "time_domain", [&](JsonWriter& j) {
    p.simulated ? write_simulated(j, *p.simulated, p.checks) : void(j.value(nullptr));
  });
  write_line_member(out, "frequencies_hz", [&](JsonWriter& j) { write_values(j, r.frequencies); });
  report::write_last_line_array(out, "speeds", r.speeds,
                                [&](JsonWriter& j, const RideAtSpeed& at) { write_at_speed(j, r, at); });
}

}  // namespace

void write_ride(std::ostream& out, const RideResult& result, OutputFormat format, const RideSimulationResult* simulated,
                const RideFftChecks* checks) {
  write_ride(out, result, format, "", Provenance{}, simulated, checks);
}

void write_ride(std::ostream& out, const RideResult& result, OutputFormat format, const std::string& title,
                const Provenance& provenance, const RideSimulationResult* simulated, const RideFftChecks* checks) {
  const Page page{result, title.empty() ? std::string("vehicle") : title, provenance, simulated, checks};
  report::write_in_format(
      format, "write_ride", [&] { write_text(out, page); }, [&] { write_csv(out, result); },
      [&] { write_json(out, page); }, [&] { write_markdown(out, page); }, [&] { write_html(out, page); });
}

void write_ride_spectra(std::ostream& out, const RideResult& result) { write_spectra_csv(out, result); }

}  // namespace railmodal
