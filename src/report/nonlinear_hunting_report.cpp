// The nonlinear-hunting report: what was simulated (the effects and their laws, the ramp and its
// disturbance), the nonlinear critical speed and its amplitude beside the linear one, the ramps at
// the stated and halved rates (the convergence check), the held confirmation, and the bifurcation
// curve (limit-cycle amplitude against speed), as a table, CSV, JSON, Markdown or HTML with the
// bifurcation plot. Quantities the result does not have are words or null, never inf or NaN.
#include "railmodal/nonlinear_hunting_report.hpp"

#include "railmodal/limit_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "report/csv_writer.hpp"
#include "report/document_table.hpp"
#include "report/json_writer.hpp"
#include "report/report_page.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace {

using report::fixed;
using report::JsonWriter;
using report::significant;
using report::Table;
using report::wrapped;
using report::write_text_table;

using report::kKmh;
constexpr double kMm = 1e3;   // m → mm
// Points of the stated ramp's curve the text formats list (the CSV and JSON carry every half cycle).
constexpr size_t kListedPoints = 12;

struct Page {
  const NonlinearHuntingResult& r;
  const NonlinearHuntingOptions& o;
  std::string vehicle;
  const Provenance& provenance;
  std::optional<double> linear;  // m/s
  const LimitCycleBranch* branch;  // the continuation, when asked for
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
  return "from " + shortest_text(o.start_speed * kKmh, 6) + " to " + shortest_text(o.end_speed * kKmh, 6) + " km/h at " +
         significant(o.ramp_rate, 4) + " m/s² and at half of it, every wheelset displaced laterally by " +
         mm(o.disturbance) + " at the start";
}

std::string verdict_text(const NonlinearHuntingResult& r) {
  switch (r.verdict) {
    case NonlinearHuntingVerdict::limit_cycle_dies_out:
      return "a hunting limit cycle was established and died out on the way down: the nonlinear critical speed "
             "is the lowest speed at which it survives.";
    case NonlinearHuntingVerdict::survives_to_end_speed:
      if (r.collapsing_at_end_speed)
        return "the oscillation had not died out by the end speed, but it was collapsing there: it may not be a "
               "limit cycle at all (below).";
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

// A speed difference in km/h, with three decimals (the tolerance's 0.05 m/s is 0.180 km/h).
std::string kmh_difference(double speed) { return fixed(speed * kKmh, 3) + " km/h"; }

std::string convergence_text(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  std::string text = std::string(to_string(r.convergence)) + ": ";
  switch (r.convergence) {
    case NonlinearConvergence::converged: {
      if (p.o.hold_periods == 0)
        return text + "halving the ramp rate moved the critical speed by " + kmh_difference(r.convergence_difference) +
               ", within the tolerance " + kmh_difference(p.o.tolerance) +
               " (no holds asked for: the ramp's answer is the result).";
      const HeldCriticalSpeed& h = r.hold;
      return text + "the held critical speed lies between " + fixed(*h.highest_dying * kKmh, 3) + " km/h (dies) and " +
             fixed(*h.lowest_surviving * kKmh, 3) + " km/h (survives), a bracket of " +
             kmh_difference(*h.lowest_surviving - *h.highest_dying) + " within the tolerance " +
             kmh_difference(p.o.tolerance) + ", and a hold twice as long keeps its cycle; halving the ramp rate moved "
             "the ramp's answer by " + kmh_difference(r.convergence_difference) +
             (r.convergence_difference <= p.o.tolerance ? "" : ", more than the tolerance: the ramp lags, the holds do not") +
             ".";
    }
    case NonlinearConvergence::not_converged:
      return text + nonlinear_hunting_warning(r, p.o) + " Read the figures as an estimate, not an answer.";
    case NonlinearConvergence::not_applicable:
      return text + "both ramp rates agree that there is no critical speed to converge.";
  }
  return text;
}

// The summary's checks for people: speeds in km/h (the JSON keeps them in m/s, the unit in the
// name, as every JSON does).
AnalysisSummary checks_in_kmh(const AnalysisSummary& summary) {
  AnalysisSummary shown = summary;
  for (Check& c : shown.checks) {
    const std::size_t at = c.name.find(", m/s");
    if (at == std::string::npos) continue;
    c.name.replace(at, 5, ", km/h");
    c.value *= kKmh;
    if (std::isfinite(c.limit)) c.limit *= kKmh;
  }
  return shown;
}

const char* const kEstimate =
    "The figures below are an estimate, not an answer: the run exits 6 (docs/stability.md, \"When the answer is "
    "not converged\").";

const char* const kCannotShow =
    "What the ramp-down shows: the stable hunting limit cycle the disturbance falls onto, followed down in speed to "
    "where it stops existing (a fold of the branch, or the Hopf point when the branch is supercritical). What it "
    "cannot show: the unstable limit cycle of a subcritical branch (the threshold amplitude between decay to the "
    "centre and hunting), which no simulation converges onto and which needs numerical continuation of periodic "
    "orbits: railmodal hunting --continuation follows it. The answer depends on the disturbance, and the watched wheelset is the one that "
    "moves most (docs/stability.md, \"What the ramp-down can and cannot show\").";
// The same, when the continuation was asked for and follows below.
const char* const kCannotShowButContinued =
    "What the ramp-down shows: the stable hunting limit cycle the disturbance falls onto, followed down in speed to "
    "where it stops existing (a fold of the branch, or the Hopf point when the branch is supercritical). What it "
    "cannot show: the unstable limit cycle of a subcritical branch (the threshold amplitude between decay to the "
    "centre and hunting), which no simulation converges onto: the continuation below follows it. The answer depends "
    "on the disturbance, and the watched wheelset is the one that moves most (docs/stability.md, \"What the "
    "ramp-down can and cannot show\").";

const char* cannot_show(const Page& p) { return p.branch ? kCannotShowButContinued : kCannotShow; }

// ---- tables shared by the formats for people ----

Table result_table(const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  Table t{{"quantity", "value"}, {false, false}, {}};
  t.rows.push_back({"verdict", to_string(r.verdict)});
  const bool estimate = r.convergence == NonlinearConvergence::not_converged && r.critical_speed;
  t.rows.push_back({"nonlinear critical speed",
                    optional_speed(r.critical_speed) + (estimate ? ", not converged: an estimate" : "")});
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

// ---- the continuation (only with --continuation) ----

std::string branch_text(const LimitCycleBranch& b) {
  switch (b.kind) {
    case LimitCycleBranchKind::subcritical:
      return std::string("subcritical: the branch leaves the Hopf point towards lower speeds with unstable limit "
                         "cycles (the threshold between decay and hunting)") +
             (b.fold ? "; it turns at the fold, " + speed_text(b.fold->speed) + " at " + mm(b.fold->amplitude) +
                           ", into the stable hunting cycle: below the fold no limit cycle exists (the nonlinear "
                           "critical speed)."
                     : b.folds.empty() ? "; it ended before turning: no fold found."
                                       : "; it turns, but with the same stability on both sides of every turn (no "
                                         "exchange of stability): no fold into the stable cycle found.");
    case LimitCycleBranchKind::supercritical:
      return "supercritical: the branch leaves the Hopf point towards higher speeds with stable limit cycles; no "
             "fold below it: the nonlinear critical speed is the linear one.";
    case LimitCycleBranchKind::no_hopf_point:
      return "no Hopf point: the centred running does not lose stability between the end and the start speed; no "
             "branch to continue.";
    case LimitCycleBranchKind::undetermined:
      return "undetermined: the corrector failed before the branch's direction was seen (" + b.failure + ").";
    case LimitCycleBranchKind::neutral:
      return "neutral: orbits of every amplitude sit at the Hopf speed (a linear law): no limit cycle bounds the "
             "hunting above it, none exists below it.";
  }
  return "";
}

Table branch_summary_table(const LimitCycleBranch& b) {
  Table t{{"quantity", "value"}, {false, false}, {}};
  t.rows.push_back({"branch", to_string(b.kind)});
  t.rows.push_back({"Hopf point", b.hopf_speed ? speed_text(*b.hopf_speed) + ", " + fixed(b.hopf_frequency, 3) + " Hz"
                                               : std::string("none")});
  t.rows.push_back({"fold (nonlinear critical speed)",
                    b.fold ? speed_text(b.fold->speed) + ", " + mm(b.fold->amplitude) : std::string("none")});
  t.rows.push_back({"watched wheelset", "wheelset " + std::to_string(b.watched_wheelset + 1)});
  t.rows.push_back({"continuation ended", std::string(to_string(b.end)) + (b.failure.empty() ? "" : ": " + b.failure)});
  t.rows.push_back(
      {"orbits, one-period integrations", std::to_string(b.points.size()) + ", " + std::to_string(b.flows)});
  return t;
}

Table branch_table(const LimitCycleBranch& b) {
  Table t{{"speed (km/h)", "amplitude (mm)", "period (s)", "stability", "largest |multiplier|", "residual"},
          {true, true, true, false, true, true},
          {}};
  for (const LimitCycleBranchPoint& q : b.points)
    t.rows.push_back({fixed(q.speed * kKmh, 3), fixed(q.amplitude * kMm, 3), fixed(q.period, 4),
                      q.stable ? "stable" : "unstable", significant(q.largest_multiplier, 6),
                      significant(q.residual, 2)});
  return t;
}

// ---- table (text) ----

void write_table(std::ostream& out, const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  out << "railmodal hunting: " << p.vehicle << "\n";
  out << wrapped("effects: " + effects_text(p.o)) << "\n" << wrapped("ramp: " + ramp_text(p.o)) << "\n\n";
  out << wrapped("verdict: " + std::string(to_string(r.verdict)) + ": " + verdict_text(r)) << "\n\n";
  if (r.convergence == NonlinearConvergence::not_converged)
    out << wrapped("NOT CONVERGED: " + nonlinear_hunting_warning(r, p.o) + " " + kEstimate) << "\n\n";
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
  out << "\n" << wrapped(cannot_show(p)) << "\n";
  if (p.branch) {
    out << "\ncontinuation of the limit cycles (shooting, pseudo-arclength in speed from the Hopf point):\n";
    out << wrapped(branch_text(*p.branch)) << "\n\n";
    write_text_table(out, branch_summary_table(*p.branch));
    out << "\n";
    write_text_table(out, branch_table(*p.branch));
    out << wrapped("continuation checks: " + report::checks_text(p.branch->summary)) << "\n";
  }
  out << "\n" << wrapped("checks: " + report::checks_text(checks_in_kmh(r.summary))) << "\n"
      << wrapped("method: " + r.summary.method)
      << "\n";
}

// ---- Markdown ----

void write_markdown(std::ostream& out, const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  out << "# Nonlinear hunting: " << p.vehicle << "\n\n";
  out << "Effects: " << effects_text(p.o) << ".\n\nRamp: " << ramp_text(p.o) << ".\n\n";
  out << "**Verdict: " << to_string(r.verdict) << "**: " << verdict_text(r) << "\n\n";
  if (r.convergence == NonlinearConvergence::not_converged)
    out << "**Not converged**: " << nonlinear_hunting_warning(r, p.o) << " " << kEstimate << "\n\n";
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
  out << "\n" << cannot_show(p) << "\n\n";
  if (p.branch) {
    out << "## Continuation of the limit cycles\n\n" << branch_text(*p.branch) << "\n\n";
    report::write_markdown_table(out, branch_summary_table(*p.branch));
    out << "\n";
    report::write_markdown_table(out, branch_table(*p.branch));
    out << "\nContinuation checks: " << report::checks_text(p.branch->summary) << ".\n\n";
  }
  out << "## Checks\n\n" << report::checks_text(checks_in_kmh(r.summary))
      << ".\n\nMethod: " << r.summary.method << ".\n\n";
  out << report::provenance_line("hunting", p.provenance) << "\n";
}

// ---- HTML ----

// The branch as two series, stable solid and unstable dashed, broken by NaN where the other
// holds; where the stability changes both pass through the fold between (or, without one, the
// later point), so the curve is unbroken.
void add_branch(report::Chart& chart, const LimitCycleBranch& b) {
  report::ChartSeries stable, unstable;
  stable.label = "continuation: stable limit cycles";
  unstable.label = "continuation: unstable limit cycles";
  unstable.dashed = true;
  const auto add = [&](const LimitCycleBranchPoint& q, bool in_stable, bool in_unstable) {
    const double nan = std::nan("");
    stable.x.push_back(q.speed * kKmh);
    stable.y.push_back(in_stable ? q.amplitude * kMm : nan);
    unstable.x.push_back(q.speed * kKmh);
    unstable.y.push_back(in_unstable ? q.amplitude * kMm : nan);
  };
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const LimitCycleBranchPoint& q = b.points[i];
    if (i > 0 && b.points[i - 1].stable != q.stable) {
      const LimitCycleBranchPoint* junction = &q;
      for (const LimitCycleBranchPoint& f : b.folds)
        if ((f.amplitude - b.points[i - 1].amplitude) * (f.amplitude - q.amplitude) <= 0.0) junction = &f;
      add(*junction, true, true);
      if (junction == &q) continue;
    }
    add(q, q.stable, !q.stable);
  }
  chart.series.push_back(std::move(stable));
  chart.series.push_back(std::move(unstable));
}

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
  if (p.branch) add_branch(chart, *p.branch);
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
  if (r.convergence == NonlinearConvergence::not_converged)
    out << "<p class=bad><b>Not converged</b>: " << html_escape(nonlinear_hunting_warning(r, p.o)) << " "
        << html_escape(kEstimate) << "</p>\n";
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
  out << "<p class=note>" << html_escape(cannot_show(p)) << "</p>\n";
  if (p.branch) {
    out << "<h2>Continuation of the limit cycles</h2>\n<p>" << html_escape(branch_text(*p.branch)) << "</p>\n";
    report::write_html_table(out, branch_summary_table(*p.branch));
    report::write_html_table(out, branch_table(*p.branch));
    out << "<p class=note>Continuation checks: " << html_escape(report::checks_text(p.branch->summary)) << ".</p>\n";
  }
  out << "<h2>Checks</h2>\n<p>" << html_escape(report::checks_text(checks_in_kmh(r.summary))) << ".</p>\n<p class=note>Method: "
      << html_escape(r.summary.method) << ".</p>\n";
  report::write_html_footer(out, "hunting", p.provenance);
}

// ---- CSV and JSON ----

// The bifurcation data: every half cycle of both ramps.
// With the continuation, its orbits follow as rows of ramp "continuation" (no rate; half_cycle
// is the orbit's number along the branch) with four more columns, empty for the ramps' rows.
void write_csv(std::ostream& out, const NonlinearHuntingResult& r, const LimitCycleBranch* branch) {
  using report::csv_heading;
  report::CsvWriter csv(out);
  csv.field("ramp").field(csv_heading("ramp_rate", "m/s²")).field("half_cycle").field(csv_heading("speed", "km/h"));
  csv.field(csv_heading("amplitude", "mm"));
  if (branch)
    csv.field("stable").field(csv_heading("period", "s")).field("largest_multiplier").field("newton_residual");
  csv.end_row();
  for (const RampDown* d : {&r.stated_rate, &r.halved_rate})
    for (size_t i = 0; i < d->curve.size(); ++i) {
      csv.field(d == &r.stated_rate ? "stated" : "halved").field(d->ramp_rate).field(i + 1)
          .field(d->curve[i].speed * kKmh).field(d->curve[i].amplitude * kMm);
      if (branch) csv.field("").field("").field("").field("");
      csv.end_row();
    }
  if (!branch) return;
  for (size_t i = 0; i < branch->points.size(); ++i) {
    const LimitCycleBranchPoint& q = branch->points[i];
    csv.field("continuation").field("").field(i + 1).field(q.speed * kKmh).field(q.amplitude * kMm).field(q.stable)
        .field(q.period).field(q.largest_multiplier).field(q.residual).end_row();
  }
}

// Every object's members in the alphabetical order nlohmann::json's std::map gave them (the file
// is the same from run to run); a number that is not finite, or a speed not found, is null.
std::optional<double> kmh(const std::optional<double>& v) { return v ? std::optional<double>(*v * kKmh) : v; }
std::optional<double> if_found(const std::optional<double>& speed, double x) {
  return speed ? std::optional<double>(x) : std::nullopt;
}

void write_ramp(JsonWriter& j, const RampDown& d) {
  j.begin_object().member("amplitude_m", if_found(d.critical_speed, d.amplitude));
  j.member("critical_speed_kmh", kmh(d.critical_speed)).member("critical_speed_m_s", d.critical_speed);
  j.key("curve").begin_object().key("amplitude_m").begin_array();
  for (const LimitCyclePoint& q : d.curve) j.value(q.amplitude);
  j.end_array().key("speed_kmh").begin_array();
  for (const LimitCyclePoint& q : d.curve) j.value(q.speed * kKmh);
  j.end_array().key("speed_m_s").begin_array();
  for (const LimitCyclePoint& q : d.curve) j.value(q.speed);
  j.end_array().end_object();
  j.member("ramp_rate_m_s2", d.ramp_rate).member("steps", d.steps).member("verdict", to_string(d.verdict));
  j.member("watched_wheelset", d.watched_wheelset).end_object();
}

void write_options(JsonWriter& j, const NonlinearHuntingOptions& o) {
  j.begin_object().member("amplitude_bound_m", o.amplitude_bound).key("creep_saturation");
  if (has_effect(o, NonlinearEffect::creep_saturation))
    j.begin_object().member("contact_angle_rad", o.contact_angle).member("friction_coefficient", o.friction_coefficient)
        .member("law", "shen_hedrick_elkins").member("wheel_load_n", o.wheel_load).end_object();
  else
    j.value(nullptr);
  j.member("disturbance_m", o.disturbance).key("effects").begin_array();
  for (NonlinearEffect e : o.effects) j.value(to_string(e));
  j.end_array().member("end_speed_kmh", o.end_speed * kKmh).member("end_speed_m_s", o.end_speed);
  j.member("extinction_amplitude_m", o.extinction_amplitude);
  j.key("flange_contact");
  if (has_effect(o, NonlinearEffect::flange_contact))
    j.begin_object().member("clearance_m", o.flange_clearance).member("stiffness_n_per_m", o.flange_stiffness).end_object();
  else
    j.value(nullptr);
  j.member("hold_margin_m_s", o.hold_margin).member("hold_periods", o.hold_periods);
  j.member("ramp_rate_m_s2", o.ramp_rate).member("start_speed_kmh", o.start_speed * kKmh);
  j.member("start_speed_m_s", o.start_speed).member("tolerance_m_s", o.tolerance);
  j.end_object();
}

void write_branch_point(JsonWriter& j, const LimitCycleBranchPoint& q) {
  j.begin_object().member("amplitude_m", q.amplitude).member("largest_multiplier", q.largest_multiplier);
  j.member("newton_residual", q.residual).member("period_s", q.period).member("speed_kmh", q.speed * kKmh);
  j.member("speed_m_s", q.speed).member("stable", q.stable).end_object();
}

void write_branch(JsonWriter& j, const LimitCycleBranch& b) {
  j.begin_object().member("end", to_string(b.end)).member("failure", b.failure).key("fold");
  if (b.fold)
    write_branch_point(j, *b.fold);
  else
    j.value(nullptr);
  j.key("folds").begin_array();
  for (const LimitCycleBranchPoint& q : b.folds) write_branch_point(j, q);
  j.end_array().member("hopf_frequency_hz", if_found(b.hopf_speed, b.hopf_frequency));
  j.member("hopf_speed_kmh", kmh(b.hopf_speed)).member("hopf_speed_m_s", b.hopf_speed);
  j.member("kind", to_string(b.kind)).member("one_period_integrations", b.flows).key("points").begin_array();
  for (const LimitCycleBranchPoint& q : b.points) write_branch_point(j, q);
  j.end_array().member("watched_wheelset", b.watched_wheelset).end_object();
}

void write_json(std::ostream& out, const Page& p) {
  const NonlinearHuntingResult& r = p.r;
  JsonWriter j(out);
  j.begin_object().member("amplitude_m", if_found(r.critical_speed, r.amplitude)).member("analysis", "nonlinear");
  j.member("collapsing_at_end_speed", r.collapsing_at_end_speed);
  if (p.branch) {
    j.key("continuation");
    write_branch(j, *p.branch);
  }
  j.member("converged", r.converged).member("convergence", to_string(r.convergence));
  j.member("convergence_difference_m_s", r.convergence_difference);
  j.member("critical_speed_kmh", kmh(r.critical_speed)).member("critical_speed_m_s", r.critical_speed);
  j.key("hold").begin_object().member("doubled_hold_survives", r.hold.doubled_hold_survives);
  j.member("highest_dying_kmh", kmh(r.hold.highest_dying)).member("highest_dying_m_s", r.hold.highest_dying);
  j.key("holds").begin_array();
  for (const SpeedHold& h : r.hold.holds)
    j.begin_object().member("end_amplitude_m", h.end_amplitude).member("periods", h.periods)
        .member("rate_change_error", h.rate_change_error).member("rate_change_per_period", h.rate_change_per_period)
        .member("rate_error", h.rate_error).member("rate_per_period", h.rate_per_period)
        .member("speed_kmh", h.speed * kKmh).member("speed_m_s", h.speed).member("start_amplitude_m", h.start_amplitude)
        .member("steps", h.steps).member("survives", h.survives).member("undecided", h.undecided).end_object();
  j.end_array().member("lowest_surviving_kmh", kmh(r.hold.lowest_surviving));
  j.member("lowest_surviving_m_s", r.hold.lowest_surviving).end_object();
  j.member("linear_critical_speed_kmh", kmh(p.linear)).member("linear_critical_speed_m_s", p.linear);
  // Why the answer is an estimate (the text under the verdict), null when it is not one.
  j.key("not_converged_reason");
  if (r.convergence == NonlinearConvergence::not_converged) j.value(nonlinear_hunting_warning(r, p.o));
  else j.value(nullptr);
  j.key("options");
  write_options(j, p.o);
  j.member("ramp_too_fast", r.ramp_too_fast);
  j.key("ramps").begin_array();
  write_ramp(j, r.stated_rate);
  write_ramp(j, r.halved_rate);
  j.end_array().member("richardson_critical_speed_kmh", kmh(r.richardson_critical_speed));
  j.member("richardson_critical_speed_m_s", r.richardson_critical_speed);
  j.key("summary").begin_object().member("analysis", r.summary.analysis).key("checks").begin_array();
  for (const Check& c : r.summary.checks)
    j.begin_object().member("limit", c.limit).member("name", c.name).member("passed", c.passed)
        .member("value", c.value).end_object();
  j.end_array().member("method", r.summary.method).end_object();
  j.member("vehicle", p.vehicle).member("verdict", to_string(r.verdict)).end_object();
}

}  // namespace

std::string nonlinear_hunting_warning(const NonlinearHuntingResult& r, const NonlinearHuntingOptions& o) {
  if (r.convergence != NonlinearConvergence::not_converged) return "";
  std::vector<std::string> why;
  const std::string rate = significant(o.ramp_rate, 4) + " m/s²";
  const HeldCriticalSpeed& h = r.hold;
  if (r.stated_rate.verdict != r.halved_rate.verdict)
    why.push_back(std::string("the ramp at ") + rate + " ends " + to_string(r.stated_rate.verdict) + ", the one at " +
                  "half of it " + to_string(r.halved_rate.verdict) + ": lower ramp_rate");
  if (r.ramp_too_fast)
    why.push_back("the ramp at " + rate + " lost the limit cycle at " + fixed(*r.stated_rate.critical_speed * kKmh, 2) +
                  " km/h, more than hold_margin (" + fixed(o.hold_margin * kKmh, 2) + " km/h) above a held speed " +
                  "whose cycle survives (" + fixed(*h.lowest_surviving * kKmh, 2) + " km/h): the ramp is too fast "
                  "for its answer (it dragged the cycle down before the cycle settled on its branch); lower "
                  "ramp_rate, to " + significant(o.ramp_rate / 10.0, 4) + " m/s² or less");
  if (r.collapsing_at_end_speed) {
    const auto& c = r.stated_rate.curve;
    const double fall = 1.0 - c[c.size() - 2].amplitude / c[c.size() - 3].amplitude;
    why.push_back("the ramp at " + rate + " ended while the cycle collapsed (its last whole half cycle fell by " +
                  fixed(100.0 * fall, 1) + " %, a cycle on its branch by under 0.5 %): whether a cycle survives at " +
                  "end_speed is not known; lower ramp_rate (a ramp too fast for the cycle to settle drags it down " +
                  "over a long stretch of speed) or end_speed");
  }
  if (r.verdict == NonlinearHuntingVerdict::limit_cycle_dies_out && o.hold_periods > 0) {
    if (!h.lowest_surviving)
      why.push_back("no held speed near the ramp's answer kept its cycle: lower ramp_rate or widen hold_margin");
    else if (!h.highest_dying)
      why.push_back("every held speed down to " + fixed(*h.lowest_surviving * kKmh, 2) +
                    " km/h kept its cycle: the held critical speed is below it, not bracketed; widen hold_margin " +
                    "or lower ramp_rate");
    else if (*h.lowest_surviving - *h.highest_dying > o.tolerance)
      why.push_back("the held critical speed is bracketed to " +
                    kmh_difference(*h.lowest_surviving - *h.highest_dying) + ", over the tolerance " +
                    kmh_difference(o.tolerance));
    if (h.lowest_surviving && !h.doubled_hold_survives)
      why.push_back("the lowest surviving held speed lost its cycle in a hold twice as long: a longer hold_periods");
  } else if (r.verdict == NonlinearHuntingVerdict::limit_cycle_dies_out) {
    why.push_back("halving the ramp rate moved its answer by " + kmh_difference(r.convergence_difference) +
                  ", over the tolerance " + kmh_difference(o.tolerance) + ": lower ramp_rate");
  }
  std::string text;
  for (const std::string& w : why) text += (text.empty() ? "" : "; ") + w;
  if (text.empty()) text = "the confirmation did not converge";
  return text + ".";
}

void write_nonlinear_hunting(std::ostream& out, const NonlinearHuntingResult& result,
                             const NonlinearHuntingOptions& options, OutputFormat format, const std::string& vehicle,
                             const Provenance& provenance, std::optional<double> linear_critical_speed,
                             const LimitCycleBranch* continuation) {
  const Page page{result, options, vehicle.empty() ? std::string("vehicle") : vehicle, provenance,
                  linear_critical_speed, continuation};
  report::write_in_format(
      format, "write_nonlinear_hunting", [&] { write_table(out, page); }, [&] { write_csv(out, result, continuation); },
      [&] { write_json(out, page); }, [&] { write_markdown(out, page); }, [&] { write_html(out, page); });
}

}  // namespace railmodal
