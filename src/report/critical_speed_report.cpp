// The critical-speed report: Markdown, self-contained HTML with inline SVG, CSV, JSON.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/element_stiffness.hpp"
#include "railmodal/critical_speed_report.hpp"
#include "report/csv_writer.hpp"
#include "report/document_table.hpp"
#include "report/json_writer.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace {

using report::fixed;
using report::html_escape;
using report::significant;
using report::Table;
using report::is_rotation;
using report::Unit;
using report::unit_of;
using report::write_html_table;
using report::write_markdown_table;

using report::kKmh;

std::string source_label(const CriticalSpeedStudy& study, int s) {
  return "[" + std::to_string(s + 1) + "] " + study.scene.sources[s]->kind();
}

// The same in a chart's legend, with its wavelength (report::source_legend): a chart stands
// apart from the Sources table.
std::string source_legend(const CriticalSpeedStudy& study, int s) {
  return report::source_legend(s, study.scene.sources[s]->kind(), study.scene.sources[s]->wavelength());
}

// Round-off shown as what it is, in the Markdown and HTML reports (CSV and JSON keep every
// value): an amplitude or growth of at most 1e-12 of the largest the report gives the same
// output and quantity reads 0. A mode that does not move an output (by symmetry: the Su
// locomotive's frame pitch and its frame yaw) leaves it about 1e-16 of that largest, the
// round-off of a double-precision solve (9.354e-19 mrad beside 29.49 mrad); 1e-12 keeps four
// orders of headroom above it and hides nothing a 4-digit table could show of a real
// response. Per output and quantity, since outputs differ in unit (mm, mrad, m/s²).
class CriticalSpeedRoundOff {
 public:
  explicit CriticalSpeedRoundOff(const CriticalSpeedStudy& st) {
    for (const CriticalSpeed& r : st.critical_speeds) {
      if (!r.unbounded) note(r.output, ResponseQuantity::displacement, r.amplitude);
      note(r.output, ResponseQuantity::displacement, r.growth_per_half_period);
      for (const ResonanceAtOutput& o : r.outputs) {
        if (!o.unbounded) note(o.output, o.quantity, o.amplitude);
        note(o.output, o.quantity, o.growth_per_half_period);
      }
    }
    for (const AmplitudeCurve& c : st.curves)
      for (const double a : c.amplitudes) note(c.output, c.quantity, a);
    for (const auto& p : st.peaks) note(st.curves[p.curve].output, st.curves[p.curve].quantity, p.peak.amplitude);
  }
  /// `value`, or 0 when it is round-off beside the largest of its output and quantity.
  double shown(const std::string& output, ResponseQuantity quantity, double value) const {
    const auto largest = largest_.find(key(output, quantity));
    return largest != largest_.end() && std::abs(value) <= kRelative * largest->second ? 0.0 : value;
  }

 private:
  static constexpr double kRelative = 1e-12;
  static std::string key(const std::string& output, ResponseQuantity quantity) {
    return output + " " + to_string(quantity);
  }
  void note(const std::string& output, ResponseQuantity quantity, double value) {
    if (!std::isfinite(value)) return;
    double& largest = largest_[key(output, quantity)];
    largest = std::max(largest, std::abs(value));
  }
  std::map<std::string, double> largest_;
};

std::string amplitude_text(const CriticalSpeedStudy& study, const CriticalSpeedRoundOff& round_off,
                           const CriticalSpeed& r) {
  if (r.unbounded) return "unbounded";
  const Unit u = unit_of(study.system, r.output, ResponseQuantity::displacement);
  return significant(round_off.shown(r.output, ResponseQuantity::displacement, r.amplitude) * u.scale, 4) + " " +
         u.name;
}

std::string growth_text(const CriticalSpeedStudy& study, const CriticalSpeedRoundOff& round_off,
                        const CriticalSpeed& r) {
  const Unit u = unit_of(study.system, r.output, ResponseQuantity::displacement);
  return significant(round_off.shown(r.output, ResponseQuantity::displacement, r.growth_per_half_period) * u.scale,
                     3) +
         " " + u.name;
}

std::string friction_text(const CriticalSpeedStudy& study, const CriticalSpeed& r) {
  if (!(r.friction_decrement_per_half_period > 0.0)) return "no friction";
  const Unit u = unit_of(study.system, r.output, ResponseQuantity::displacement);
  const std::string decrement = significant(r.friction_decrement_per_half_period * u.scale, 3) + " " + u.name;
  if (r.friction_stops)
    return "stops it (2φf = " + decrement + "; needs " + significant(r.friction_threshold_scale, 3) + "× the input)";
  return "does not stop it (2φf = " + decrement + ")";
}

bool any_force_source(const CriticalSpeedStudy& study) {
  return std::any_of(study.scene.sources.begin(), study.scene.sources.end(),
                     [](const auto& s) { return s->kind() == "unbalance"; });
}


Table sources_table(const CriticalSpeedStudy& st) {
  Table t{{"#", "source", "fundamental wavelength Λ", "harmonics"}, {true, false, true, true}, {}};
  for (size_t s = 0; s < st.scene.sources.size(); ++s) {
    const auto& src = *st.scene.sources[s];
    t.rows.push_back({std::to_string(s + 1), src.description(), significant(src.wavelength(), 5) + " m",
                      src.harmonic_count() == 1 ? "1" : "1–" + std::to_string(src.harmonic_count())});
  }
  return t;
}

Table critical_speed_table(const CriticalSpeedStudy& st) {
  Table t{{"speed (km/h)", "source", "k", "mode", "f (Hz)", "output", "amplitude", "growth per half period if undamped", "leaf friction"},
          {true, false, true, false, true, false, true, true, false},
          {}};
  const CriticalSpeedRoundOff round_off(st);
  for (const auto& r : st.critical_speeds)
    t.rows.push_back({fixed(r.speed * kKmh, 1), source_label(st, r.source), std::to_string(r.harmonic),
                      std::to_string(r.mode) + " " + r.mode_name, fixed(r.frequency_hz, 3), r.output,
                      amplitude_text(st, round_off, r), growth_text(st, round_off, r), friction_text(st, r)});
  return t;
}

// Every requested output at every critical speed: its amplitude there, or its growth per half
// period (issue 17 item 7: the table above shows one output per mode).
Table outputs_table(const CriticalSpeedStudy& st) {
  Table t{{"speed (km/h)", "source", "k", "mode", "output", "amplitude", "growth per half period if undamped"},
          {true, false, true, false, false, true, true},
          {}};
  const CriticalSpeedRoundOff round_off(st);
  for (const auto& r : st.critical_speeds)
    for (const ResonanceAtOutput& o : r.outputs) {
      const Unit u = unit_of(st.system, o.output, o.quantity);
      const double amplitude = round_off.shown(o.output, o.quantity, o.amplitude);
      const double growth = round_off.shown(o.output, o.quantity, o.growth_per_half_period);
      t.rows.push_back({fixed(r.speed * kKmh, 1), source_label(st, r.source), std::to_string(r.harmonic),
                        std::to_string(r.mode) + " " + r.mode_name, o.output + " " + to_string(o.quantity),
                        o.unbounded ? "unbounded" : significant(amplitude * u.scale, 4) + " " + u.name,
                        significant(growth * u.scale, 3) + " " + u.name});
    }
  return t;
}

const char* const kOutputsNote =
    "Each output the scene requests, at each critical speed: unbounded where the resonant mode moves it (it then "
    "grows by the growth per half period), otherwise the steady amplitude of the rest of the response (growth 0 "
    "where no mode within 1 % of the resonance moves it; an output only such a near-coincident neighbour moves "
    "shows the neighbour's growth, with a large but finite amplitude).";

// What the curve is: the source's input times which transfer function.
std::string transfer_function(const CriticalSpeedStudy& st, const AmplitudeCurve& c) {
  const bool force = st.scene.sources[c.source]->kind() == "unbalance";
  switch (c.quantity) {
    case ResponseQuantity::displacement: return force ? "receptance × force" : "displacement transmissibility × input";
    case ResponseQuantity::velocity: return force ? "mobility × force" : "iω × transmissibility × input";
    case ResponseQuantity::acceleration: return force ? "accelerance × force" : "−ω² × transmissibility × input";
  }
  return "";
}

Table curve_peak_table(const CriticalSpeedStudy& st) {
  Table t{{"source", "output", "transfer function", "peak", "at (km/h)", "solves to refine"},
          {false, false, false, true, true, true},
          {}};
  for (size_t k = 0; k < st.curves.size(); ++k) {
    const auto& c = st.curves[k];
    const Unit u = unit_of(st.system, c.output, c.quantity);
    std::string unbounded;
    for (size_t i = 0; i < c.speeds.size(); ++i)
      if (c.unbounded[i]) unbounded += (unbounded.empty() ? "" : ", ") + fixed(c.speeds[i] * kKmh, 1);
    const std::string label = c.output + " " + to_string(c.quantity);
    if (!unbounded.empty())
      t.rows.push_back({source_label(st, c.source), label, transfer_function(st, c), "unbounded", unbounded, "—"});
    bool any = !unbounded.empty();
    for (const auto& p : st.peaks)
      if (p.curve == static_cast<int>(k)) {
        any = true;
        t.rows.push_back({source_label(st, c.source), label, transfer_function(st, c),
                          significant(p.peak.amplitude * u.scale, 5) + " " + u.name,
                          fixed(p.peak.speed * kKmh, 2), std::to_string(p.peak.evaluations)});
      }
    // The largest value may sit at an end of the range rather than at a peak (beside an
    // undamped resonance the grid's largest value only measures how close it came).
    if (c.amplitudes.empty() || !unbounded.empty()) continue;
    const size_t i = std::max_element(c.amplitudes.begin(), c.amplitudes.end()) - c.amplitudes.begin();
    if (!any || i == 0 || i + 1 == c.amplitudes.size())
      t.rows.push_back({source_label(st, c.source), label, transfer_function(st, c),
                        significant(c.amplitudes[i] * u.scale, 5) + " " + u.name,
                        fixed(c.speeds[i] * kKmh, 2) + (i == 0 || i + 1 == c.amplitudes.size() ? " (range end)" : ""),
                        "—"});
  }
  return t;
}

Table bodies_table(const CriticalSpeedStudy& st) {
  Table t{{"body", "mass (kg)", "I roll (kg·m²)", "I pitch (kg·m²)", "I yaw (kg·m²)"}, {false, true, true, true, true}, {}};
  for (const Body& b : st.system.vehicle.bodies)
    t.rows.push_back({b.name, significant(b.mass, 5), significant(b.inertia.x(), 4), significant(b.inertia.y(), 4),
                      significant(b.inertia.z(), 4)});
  return t;
}

// Every element with what the scene's motions feel of it: vertical (with its static load and
// deflection, and leaf friction), and, where the vehicle has any, lateral stiffness (swing
// hangers at their static load included), roll/pitch/yaw stiffness and viscous dampers.
Table elements_table(const CriticalSpeedStudy& st) {
  const Vehicle& v = st.system.vehicle;
  const std::vector<double>& loads = st.system.element_loads;
  bool lateral = false, rotational = false, dampers = false;
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    lateral = lateral || model::lateral_stiffness(e, loads[k]) > 0.0;
    rotational = rotational || e.rotational_stiffness.cwiseAbs().maxCoeff() > 0.0;
    dampers = dampers || e.vertical_damping > 0.0 || e.lateral_damping > 0.0;
  }
  Table t{{"element", "between", "vertical stiffness (kN/m)", "static load (kN)", "static deflection (mm)", "leaf friction φ"},
          {false, false, true, true, true, true},
          {}};
  if (lateral) t.headers.push_back("lateral stiffness (kN/m)"), t.numeric.push_back(true);
  if (rotational) t.headers.push_back("roll / pitch / yaw stiffness (kN·m/rad)"), t.numeric.push_back(true);
  if (dampers) t.headers.push_back("dampers vertical / lateral (kN·s/m)"), t.numeric.push_back(true);
  auto value = [](double x, int digits) { return x > 0.0 ? significant(x / 1e3, digits) : std::string("—"); };
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    const double kz = series_stiffness(e.vertical_stages);
    double phi = 0.0;
    for (const auto& s : e.vertical_stages) phi = std::max(phi, s.relative_friction);
    std::vector<std::string> row{e.name, (e.lower.empty() ? "track" : e.lower) + " – " + e.upper, value(kz, 5),
                                 significant(loads[k] / 1e3, 5), kz > 0.0 ? fixed(loads[k] / kz * 1e3, 2) : "—",
                                 phi > 0.0 ? significant(phi, 3) : "—"};
    if (lateral) row.push_back(value(model::lateral_stiffness(e, loads[k]), 5));
    if (rotational)
      row.push_back(e.rotational_stiffness.cwiseAbs().maxCoeff() > 0.0
                        ? value(e.rotational_stiffness.x(), 4) + " / " + value(e.rotational_stiffness.y(), 4) + " / " +
                              value(e.rotational_stiffness.z(), 4)
                        : "—");
    if (dampers)
      row.push_back(e.vertical_damping > 0.0 || e.lateral_damping > 0.0
                        ? value(e.vertical_damping, 4) + " / " + value(e.lateral_damping, 4)
                        : "—");
    t.rows.push_back(row);
  }
  return t;
}

Table modes_table(const CriticalSpeedStudy& st) {
  Table t{{"#", "mode", "kind", "f (Hz)", "T (s)"}, {true, false, false, true, true}, {}};
  for (const Mode& m : st.modes.modes) {
    const bool osc = m.kind == ModeKind::oscillatory;
    t.rows.push_back({std::to_string(m.index), m.name, to_string(m.kind), osc ? fixed(m.frequency_hz, 4) : "—",
                      osc ? fixed(m.period_s, 4) : "—"});
  }
  return t;
}

std::string friction_model_note(const CriticalSpeedStudy& st) {
  if (!has_leaf_friction(st.system)) return "No leaf-spring friction in this vehicle.";
  if (st.scene.friction_reference_amplitude > 0.0)
    return "Leaf friction: as the scene asks, also an EQUIVALENT VISCOUS damping c = 4R·s/(πωX) for a spring "
           "stretch amplitude X = " + significant(st.scene.friction_reference_amplitude * 1e3, 4) +
           " mm — an approximation of Coulomb friction whose amplitudes depend on that choice.";
  return "Leaf friction: Coulomb, in the resonance criterion only (the amplitudes are those of the frictionless "
         "linear model).";
}

// "Critical speed" also names the onset of hunting (docs/stability.md), which a kinematic-hunting
// source's resonances are not: every report of such a scene says which one it gives.
const char* const kKinematicHuntingNote =
    "these critical speeds are resonances to a kinematic (forced) input, the wheelsets' hunting motion at "
    "V/Λ; the stability critical speed, where hunting sets in, is what `railmodal stability` computes "
    "(docs/stability.md)";

// The notes every format writes: what the modes leave out (ModalResult::notes, as `modes`
// prints them; none for the book's wagons), and which critical speed a hunting source's are.
std::vector<std::string> report_notes(const CriticalSpeedStudy& st) {
  std::vector<std::string> notes = st.modes.notes;
  if (std::any_of(st.scene.sources.begin(), st.scene.sources.end(),
                  [](const auto& s) { return s->kind() == "hunting"; }))
    notes.push_back(kKinematicHuntingNote);
  // The random track has no line spectrum, so no critical speed: said, as `ride` says which
  // periodic sources it leaves out (user audit 2026-11-27c, F4).
  if (st.scene.irregularity)
    notes.push_back("the scene's random track irregularity has no critical speeds (a broad spectrum, not a line): "
                    "railmodal ride takes it");
  return notes;
}

const char* const kCriticalSpeedNote =
    "Amplitude: steady amplitude of the output at the critical speed; unbounded where nothing damps the mode "
    "(no viscous damping): the amplitude then grows by the growth per half period (the book's secular solutions "
    "(168d), (274)). Where dampers keep the amplitude finite, the growth is what the resonance would gain per half "
    "period without them: the figure friction is weighed against, not a growth of this vehicle. Leaf friction: Den Hartog's criterion — friction stops the resonance when the growth per half "
    "period does not exceed the friction decrement 2φf (two-axle digest (169a) without its static term); the "
    "factor is how much larger the source amplitude would have to be for the resonance to grow.";

// ---- Markdown -------------------------------------------------------------------------------

void write_markdown(std::ostream& out, const CriticalSpeedStudy& st, const Provenance& provenance) {
  out << "# Critical speeds: " << st.system.vehicle.name << "\n\n";
  out << "Scene **" << st.scene.name << "** (`" << st.scene.source << "`), vehicle `" << st.scene.vehicle_file
      << "`, " << to_string(st.scene.dofs) << " degrees of freedom (" << st.system.size() << "), speeds "
      << shortest_text(st.scene.min_speed * kKmh, 6) << "–" << shortest_text(st.scene.max_speed * kKmh, 6) << " km/h.\n\n";
  out << friction_model_note(st) << "\n\n";
  for (const std::string& note : report_notes(st)) out << "Note: " << note << ".\n\n";
  out << "## Sources\n\n";
  write_markdown_table(out, sources_table(st));
  out << "A harmonic k of a source runs at f = k·V/Λ; a mode of frequency f resonates at V = Λ·f/k.\n\n";
  out << "## Critical speeds\n\n";
  if (st.critical_speeds.empty()) {
    out << "No source harmonic meets a natural frequency in the speed range.\n\n";
  } else {
    write_markdown_table(out, critical_speed_table(st));
    out << kCriticalSpeedNote << "\n\n";
    out << "### Every output at each critical speed\n\n";
    write_markdown_table(out, outputs_table(st));
    out << kOutputsNote << "\n\n";
  }
  out << "## Amplitude against speed\n\n"
      << (any_force_source(st) ? "Force sources: receptance times the source's force (∝ V²). " : "")
      << "Displacement sources: the source amplitude times the displacement transmissibility; the sum over the "
         "source's harmonics. Damped peaks are refined by golden-section search to 1e-6 of their speed; "
         "the curves themselves are in the HTML (`--format html`) and JSON reports.\n\n";
  write_markdown_table(out, curve_peak_table(st));
  out << "## Model summary\n\n### Bodies\n\n";
  write_markdown_table(out, bodies_table(st));
  out << "### Elements\n\n";
  write_markdown_table(out, elements_table(st));
  out << "### Modes\n\n";
  write_markdown_table(out, modes_table(st));
  out << "---\n\nWritten by " << report::provenance_line("critical-speed", provenance) << "\n";
}

// ---- HTML -----------------------------------------------------------------------------------

// Up to the highest excitation frequency in the range (or the lowest mode, if higher):
// natural frequencies no source reaches would squash the ones that matter. But no higher
// than 1.3 times the highest natural frequency: a flat's sixth harmonic at 160 km/h reaches
// 89 Hz and would press every mode and crossing of a 1–5 Hz wagon onto the axis.
double campbell_top_frequency(const CriticalSpeedStudy& st) {
  double f_top = 0.0, f_lowest = INFINITY, f_highest = 0.0;
  for (const auto& src : st.scene.sources)
    f_top = std::max(f_top, src->frequency_hz(st.scene.max_speed, src->harmonic_count()));
  for (const Mode& m : st.modes.modes)
    if (m.kind == ModeKind::oscillatory) f_lowest = std::min(f_lowest, m.frequency_hz), f_highest = std::max(f_highest, m.frequency_hz);
  if (std::isfinite(f_lowest)) f_top = std::min(std::max(f_top, f_lowest), 1.3 * f_highest);
  return f_top;
}

// Each source's harmonics as lines f = kV/Λ, the fundamental solid and labelled, the higher
// harmonics dashed, all in the source's colour.
void add_excitation_lines(const CriticalSpeedStudy& st, report::Chart* c) {
  for (size_t s = 0; s < st.scene.sources.size(); ++s) {
    const auto& src = *st.scene.sources[s];
    for (int k = 1; k <= src.harmonic_count(); ++k) {
      report::ChartSeries line;
      line.label = k > 1 ? "" : source_legend(st, static_cast<int>(s)) + (src.harmonic_count() == 1 ? "" : " (k = 1…" + std::to_string(src.harmonic_count()) + ")");
      line.dashed = k > 1;
      line.colour = static_cast<int>(s);  // every harmonic in its source's colour, as the legend shows
      for (double V : {st.scene.min_speed, st.scene.max_speed}) {
        line.x.push_back(V * kKmh);
        line.y.push_back(src.frequency_hz(V, k));
      }
      c->series.push_back(line);
    }
  }
}

// Campbell diagram: excitation lines f = kV/Λ against the natural frequencies.
report::Chart campbell_chart(const CriticalSpeedStudy& st) {
  report::Chart c;
  c.id = "campbell";
  c.title = "Campbell diagram: excitation frequencies against speed";
  c.x_label = "speed (km/h)";
  c.y_label = "frequency (Hz)";
  c.x_min = st.scene.min_speed * kKmh;
  c.x_max = st.scene.max_speed * kKmh;
  c.y_min = 0.0;
  c.y_max = 1.1 * std::max(campbell_top_frequency(st), 1e-3);
  // Each natural frequency is labelled by its mode's number at the plot's edge, the name in the
  // legend: whole names collide where modes lie close (the bogies' bounce and pitch pairs).
  for (const Mode& m : st.modes.modes)
    if (m.kind == ModeKind::oscillatory && m.frequency_hz <= c.y_max)
      c.lines.push_back(
          {std::to_string(m.index), m.frequency_hz, false, m.name + ", " + fixed(m.frequency_hz, 2) + " Hz"});
  add_excitation_lines(st, &c);
  report::ChartSeries hits;
  hits.label = "critical speeds";
  hits.markers_only = true;
  hits.colour = static_cast<int>(st.scene.sources.size());  // a colour no source line has
  for (const auto& r : st.critical_speeds) {
    hits.x.push_back(r.speed * kKmh);
    hits.y.push_back(r.frequency_hz);
  }
  c.series.push_back(hits);
  return c;
}

// One chart per output and quantity, all sources on it: amplitude on a log scale, with a
// dotted vertical line and a mark at the top at each unbounded speed. `k` numbers the chart
// (from 0).
report::Chart amplitude_chart(const CriticalSpeedStudy& st, const std::string& label, ResponseQuantity quantity,
                              size_t k) {
  const Unit u = unit_of(st.system, label, quantity);
  report::Chart c;
  c.id = "curve-" + std::to_string(k + 1);
  c.title = label + " " + to_string(quantity);
  c.x_label = "speed (km/h)";
  c.y_label = std::string(to_string(quantity)) + " amplitude (" + u.name + ")";
  c.log_y = true;
  c.x_min = st.scene.min_speed * kKmh;
  c.x_max = st.scene.max_speed * kKmh;
  for (const auto& curve : st.curves) {
    if (curve.output != label || curve.quantity != quantity) continue;
    report::ChartSeries s;
    s.label = source_legend(st, curve.source);
    for (size_t i = 0; i < curve.speeds.size(); ++i) {
      s.x.push_back(curve.speeds[i] * kKmh);
      s.y.push_back(curve.unbounded[i] ? NAN : curve.amplitudes[i] * u.scale);
      if (curve.unbounded[i]) {
        c.lines.push_back({"", curve.speeds[i] * kKmh, true, ""});
        s.unbounded_x.push_back(curve.speeds[i] * kKmh);
      }
    }
    c.series.push_back(s);
  }
  return c;
}

void write_html(std::ostream& out, const CriticalSpeedStudy& st, const Provenance& provenance) {
  const Vehicle& v = st.system.vehicle;
  report::write_html_head(out, "Critical speeds: " + v.name);
  out << "<h1>Critical speeds: " << html_escape(v.name) << "</h1>\n<p>Scene <b>" << html_escape(st.scene.name)
      << "</b> (<code>" << html_escape(st.scene.source) << "</code>), vehicle <code>" << html_escape(st.scene.vehicle_file)
      << "</code>, " << to_string(st.scene.dofs) << " degrees of freedom (" << st.system.size() << "), speeds "
      << shortest_text(st.scene.min_speed * kKmh, 6) << "–" << shortest_text(st.scene.max_speed * kKmh, 6) << " km/h.</p>\n";

  out << "<p>" << html_escape(friction_model_note(st)) << "</p>\n";
  for (const std::string& note : report_notes(st)) out << "<p class=note>Note: " << html_escape(note) << ".</p>\n";
  out << "<h2>Sources</h2>\n";
  write_html_table(out, sources_table(st));
  out << "<h2>Critical speeds</h2>\n";
  if (st.critical_speeds.empty()) {
    out << "<p>No source harmonic meets a natural frequency in the speed range.</p>\n";
  } else {
    write_html_table(out, critical_speed_table(st));
    out << "<p class=note>" << html_escape(kCriticalSpeedNote) << "</p>\n";
    out << "<h3>Every output at each critical speed</h3>\n";
    write_html_table(out, outputs_table(st));
    out << "<p class=note>" << html_escape(kOutputsNote) << "</p>\n";
  }
  out << "<h2>Campbell diagram</h2>\n"
      << report::svg_chart(campbell_chart(st))
      << "<p class=note>Solid: the fundamental of each source; dashed: its higher harmonics. Dotted horizontal "
         "lines: natural frequencies, numbered as the modes (the legend names them). Circles: the critical speeds of "
         "the table.</p>\n";

  out << "<h2>Amplitude against speed</h2>\n<p class=note>"
      << (any_force_source(st) ? "Force sources: receptance times the source's force (∝ V²). " : "")
      << "Displacement sources: the source amplitude times the displacement transmissibility. Sum over the "
         "source's harmonics (the bound of the peak of their sum). Logarithmic scale; a dotted vertical line and a "
         "triangle at the top mark each unbounded (undamped) resonance, where the curve leaves the plot: the "
         "axis ends at the largest amplitude found away from them.</p>\n";
  std::vector<std::pair<std::string, ResponseQuantity>> outputs;
  for (const auto& c : st.curves)
    if (std::find(outputs.begin(), outputs.end(), std::make_pair(c.output, c.quantity)) == outputs.end())
      outputs.push_back({c.output, c.quantity});
  for (size_t k = 0; k < outputs.size(); ++k)
    out << report::svg_chart(amplitude_chart(st, outputs[k].first, outputs[k].second, k));

  out << "<h2>Peaks</h2>\n";
  write_html_table(out, curve_peak_table(st));
  out << "<h2>Model summary</h2>\n";
  write_html_table(out, bodies_table(st));
  write_html_table(out, elements_table(st));
  write_html_table(out, modes_table(st));
  report::write_html_footer(out, "critical-speed", provenance);
}

// ---- CSV and JSON ---------------------------------------------------------------------------

// The unit of an output's amplitude: m or rad per its DOF, per s or s² for velocity or acceleration.
std::string output_unit(const std::string& output, ResponseQuantity quantity) {
  const std::string unit = report::displacement_unit(output);
  if (unit.empty() || quantity == ResponseQuantity::displacement) return unit;
  return unit + (quantity == ResponseQuantity::velocity ? "/s" : "/s²");
}

// The per-output columns' names, "<dof>.<quantity>_amplitude [unit]" and
// "…_growth_per_half_period [unit]" (SI, rad-based), from the first row (every row has the same outputs).
std::string output_columns(const CriticalSpeedStudy& st) {
  std::string header;
  if (st.critical_speeds.empty()) return header;
  for (const ResonanceAtOutput& o : st.critical_speeds.front().outputs) {
    const std::string name = o.output + "." + to_string(o.quantity);
    const std::string unit = output_unit(o.output, o.quantity);
    header += "," + report::csv_field(report::csv_heading(name + "_amplitude", unit)) + "," +
              report::csv_field(report::csv_heading(name + "_growth_per_half_period", unit));
  }
  return header;
}

void write_csv(std::ostream& out, const CriticalSpeedStudy& st) {
  // The amplitudes are of each row's output, m for a translation and rad for a roll, pitch or
  // yaw: the row's unit is in its output_unit column, which the three headings name.
  using report::csv_heading;
  report::CsvWriter csv(out);
  for (const std::string& note : report_notes(st)) csv.line("# note: " + note);  // as `modes` writes them
  csv.line(csv_heading("speed", "km/h") + ",source_kind,source_index,harmonic,mode,mode_name," +
           csv_heading("frequency", "Hz") + ",output,output_unit," + csv_heading("amplitude", "output_unit") +
           ",unbounded," + csv_heading("growth_per_half_period", "output_unit") + "," +
           csv_heading("friction_decrement_per_half_period", "output_unit") +
           ",friction_stops,friction_threshold_scale" + output_columns(st));
  // An unbounded amplitude is a blank field.
  const auto amplitude = [&csv](double value, bool unbounded) -> report::CsvWriter& {
    return unbounded ? csv.blank() : csv.field(value);
  };
  for (const auto& r : st.critical_speeds) {
    csv.field(r.speed * kKmh).field(r.source_kind).field(r.source + 1).field(r.harmonic).field(r.mode);
    csv.field(r.mode_name).field(r.frequency_hz).field(r.output).field(report::displacement_unit(r.output));
    amplitude(r.amplitude, r.unbounded).field(r.unbounded).field(r.growth_per_half_period);
    csv.field(r.friction_decrement_per_half_period).field(r.friction_stops).field(r.friction_threshold_scale);
    // Each output: its amplitude (blank where unbounded) and its growth per half period.
    for (const ResonanceAtOutput& o : r.outputs) amplitude(o.amplitude, o.unbounded).field(o.growth_per_half_period);
    csv.end_row();
  }
}

// Members in alphabetical order, as the files had them (json_writer.hpp).
void write_json_critical_speed(report::JsonWriter& j, const CriticalSpeed& r) {
  const std::optional<double> none;
  j.begin_object();
  j.member("amplitude", r.unbounded ? none : std::optional<double>(r.amplitude));
  j.member("frequency_hz", r.frequency_hz);
  j.member("friction_decrement_per_half_period", r.friction_decrement_per_half_period);
  j.member("friction_stops", r.friction_stops);
  j.member("friction_threshold_scale", r.friction_threshold_scale);  // null when infinite
  j.member("growth_per_half_period", r.growth_per_half_period);
  j.member("harmonic", r.harmonic).member("mode", r.mode).member("mode_name", r.mode_name);
  j.member("output", r.output);
  j.key("outputs").begin_array();
  for (const ResonanceAtOutput& o : r.outputs) {
    j.begin_object();
    j.member("amplitude", o.unbounded ? none : std::optional<double>(o.amplitude));
    j.member("growth_per_half_period", o.growth_per_half_period);
    j.member("output", o.output).member("quantity", to_string(o.quantity)).member("unbounded", o.unbounded);
    j.end_object();
  }
  j.end_array();
  j.member("source_index", r.source + 1).member("source_kind", r.source_kind);
  j.member("speed_kmh", r.speed * kKmh).member("speed_m_s", r.speed).member("unbounded", r.unbounded);
  j.end_object();
}

void write_json_curve(report::JsonWriter& j, const CriticalSpeedStudy& st, const AmplitudeCurve& c) {
  const std::optional<double> none;
  j.begin_object();
  j.key("amplitudes").begin_array();
  for (size_t i = 0; i < c.speeds.size(); ++i) j.value(c.unbounded[i] ? none : std::optional<double>(c.amplitudes[i]));
  j.end_array();
  j.member("output", c.output);
  j.key("phases_deg").begin_array();
  for (size_t i = 0; i < c.speeds.size(); ++i)
    j.value(c.unbounded[i] || c.phases_deg.empty() ? none : std::optional<double>(c.phases_deg[i]));
  j.end_array();
  j.member("quantity", to_string(c.quantity)).member("source_index", c.source + 1);
  j.key("speeds_kmh").begin_array();
  for (double v : c.speeds) j.value(v * kKmh);
  j.end_array();
  j.key("speeds_m_s").begin_array();
  for (double v : c.speeds) j.value(v);
  j.end_array();
  j.member("transfer_function", transfer_function(st, c));
  j.member("unit", is_rotation(st.system, c.output) ? "rad-based SI" : "SI (m, m/s, m/s²)");
  j.end_object();
}

void write_json(std::ostream& out, const CriticalSpeedStudy& st) {
  report::JsonWriter j(out);
  j.begin_object();
  j.key("critical_speeds").begin_array();
  for (const auto& r : st.critical_speeds) write_json_critical_speed(j, r);
  j.end_array();
  j.key("curves").begin_array();
  for (const auto& c : st.curves) write_json_curve(j, st, c);
  j.end_array();
  j.key("dofs").begin_array();
  for (const auto& d : st.system.dofs) j.value(d.label);
  j.end_array();
  j.key("modes").begin_array();
  for (const Mode& m : st.modes.modes) {
    j.begin_object();
    j.member("frequency_hz", m.kind == ModeKind::oscillatory ? std::optional<double>(m.frequency_hz) : std::nullopt);
    j.member("index", m.index).member("kind", to_string(m.kind)).member("name", m.name);
    j.end_object();
  }
  j.end_array();
  // Absent without a note (the book's wagons over joints): their files stay.
  if (const std::vector<std::string> notes = report_notes(st); !notes.empty()) j.member("notes", notes);
  j.member("scene", st.scene.name);
  j.key("sources").begin_array();
  for (size_t s = 0; s < st.scene.sources.size(); ++s) {
    const auto& src = *st.scene.sources[s];
    j.begin_object();
    j.member("description", src.description()).member("harmonics", src.harmonic_count());
    j.member("index", s + 1).member("kind", src.kind()).member("wavelength_m", src.wavelength());
    j.end_object();
  }
  j.end_array();
  j.member("vehicle", st.system.vehicle.name);
  j.end_object();
}

}  // namespace

void write_critical_speed_report(std::ostream& out, const CriticalSpeedStudy& study, OutputFormat format,
                                 const Provenance& provenance) {
  switch (format) {
    case OutputFormat::markdown: write_markdown(out, study, provenance); break;
    case OutputFormat::html: write_html(out, study, provenance); break;
    case OutputFormat::csv: write_csv(out, study); break;
    case OutputFormat::json: write_json(out, study); break;
    default:
      throw std::invalid_argument(
          report::unwritten_format("write_critical_speed_report", "markdown, html, csv or json", format));
  }
}

}  // namespace railmodal
