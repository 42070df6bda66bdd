// The hunting-stability report: the verdict, the linear critical speed, every unstable interval,
// the branches of the root locus and the contacts, as a table, CSV, JSON, Markdown or HTML with
// SVG plots (root locus, damping ratio against speed, critical speed against conicity).
// Quantities a result does not have (no critical speed, an infinite Klingel wavelength at zero
// conicity) are words or null, never inf or NaN.
#include "railmodal/hunting_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "report/document_table.hpp"
#include "report/json_lines.hpp"
#include "report/json_writer.hpp"
#include "report/number_text.hpp"
#include "report/report_page.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "shortest_text.hpp"
#include "stability/branch_naming.hpp"

namespace railmodal {

namespace {

using report::fixed;
using report::JsonWriter;
using report::significant;
using report::Table;
using report::wrapped;
using report::write_markdown_table;
using report::write_text_table;

using report::kKmh;

// Branches drawn each in a colour of their own (the palette has eight; the rest share the last).
constexpr size_t kColouredBranches = 7;

// The page's context: the vehicle's name, the input files.
struct Page {
  const HuntingResult& r;
  std::string vehicle;
  const Provenance& provenance;
};

// A speed the user gave (an end of --speeds, the grid's lowest and highest) in km/h as given, to at
// most 6 significant digits ("10", "72.5", "0.01"), as every report prints a given speed
// (docs/input.md, "Names and units in outputs"); computed speeds keep their own precision.
std::string given_kmh(double speed) { return shortest_text(speed * kKmh, 6); }
std::string kmh(double speed) { return given_kmh(speed) + " km/h"; }
std::string percent(double ratio) { return fixed(100.0 * ratio, 2) + " %"; }

double lowest_speed(const HuntingResult& r) { return r.speeds.empty() ? 0.0 : r.speeds.front(); }
double highest_speed(const HuntingResult& r) { return r.speeds.empty() ? 0.0 : r.speeds.back(); }

// The least of a branch's values over the grid and the index of the speed where it is (NaN
// skipped).
struct Least {
  double value = std::numeric_limits<double>::infinity();
  size_t at = 0;
};
Least least_of(const std::vector<double>& values) {
  Least l;
  for (size_t i = 0; i < values.size(); ++i)
    if (values[i] < l.value) l.value = values[i], l.at = i;
  return l;
}
Least least_damping(const HuntingBranch& b) { return least_of(b.damping_ratio); }
// The lowest MAC with the previous speed's eigenvector.
Least least_continuity(const HuntingBranch& b) { return least_of(b.continuity); }

// The branches in order of their least damping (the least damped first).
std::vector<size_t> by_least_damping(const HuntingResult& r) {
  std::vector<size_t> order(r.branches.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return least_damping(r.branches[a]).value < least_damping(r.branches[b]).value;
  });
  return order;
}

std::string range_text(const HuntingResult& r) {
  return given_kmh(lowest_speed(r)) + "–" + given_kmh(highest_speed(r)) + " km/h, " + std::to_string(r.speeds.size()) +
         " speeds";
}

// The number of the branch named `name` in the branch table ("#2"), "" for a name no branch has
// (a real root's group). Every mention of a branch cites it, so that one branch has one name
// wherever it appears (user audit 2026-11-27b, 1.4).
std::string branch_number(const HuntingResult& r, const std::string& name) {
  for (size_t k = 0; k < r.branches.size(); ++k)
    if (r.branches[k].name == name) return "#" + std::to_string(k + 1);
  return "";
}
// "#2 name", or the name alone when no branch has it.
std::string cited_branch(const HuntingResult& r, const std::string& name) {
  const std::string number = branch_number(r, name);
  return number.empty() ? name : number + " " + name;
}

// The frequencies a hunting frequency is held against: Klingel's V/Λ of a free wheelset, and for
// a vehicle on bogies the rigid bogie's V/Λ_b of the bogie that carries the hunting
// (HuntingCriticalSpeed::bogie_frequency_hz, ::bogie).
std::string kinematic_frequencies(const HuntingCriticalSpeed& c) {
  return "Klingel's V/Λ there: " + fixed(c.klingel_frequency_hz, 3) + " Hz" +
         (c.bogie_frequency_hz > 0.0
              ? "; V/Λ_b of '" + c.bogie + "' as a rigid bogie: " + fixed(c.bogie_frequency_hz, 3) + " Hz"
              : "");
}

// "#2 'name'", or 'name' when no branch has it: the branch in a sentence.
std::string quoted_branch(const HuntingResult& r, const std::string& name) {
  const std::string number = branch_number(r, name);
  return (number.empty() ? "" : number + " ") + "'" + name + "'";
}

// The critical speed with its frequency and the kinematic ones beside it.
std::string critical_text(const HuntingResult& r, const HuntingCriticalSpeed& c) {
  // A branch is named after its shape at the lowest speed; at the critical speed it may move
  // otherwise (the coach's branch 'body lateral/roll' hunts as its bogies): said after it.
  std::string branch = "branch " + quoted_branch(r, c.branch);
  // (Not when the motion is the branch's name but for its " (kinematic)" or " (2)".)
  const bool same = c.motion == c.branch || c.branch.rfind(c.motion + " (", 0) == 0;
  if (!c.motion.empty() && !same) branch += ", moving there as " + c.motion;
  return fixed(c.speed * kKmh, 2) + " km/h (" + significant(c.speed, 8) + " m/s): " + branch +
         ", hunting frequency " + fixed(c.frequency_hz, 3) + " Hz (" + kinematic_frequencies(c) + ")";
}

// Every wheelset at conicity 0: nothing couples lateral motion to yaw, so no speed makes it hunt
// (user audit 2026-11-28, F1: the verdict then says so rather than "above the range").
bool zero_conicity(const HuntingResult& r) {
  return !r.contacts.empty() &&
         std::all_of(r.contacts.begin(), r.contacts.end(), [](const ResolvedContact& c) { return c.conicity == 0.0; });
}

// The verdict in a sentence, with the critical speed or what stands in its place.
std::string verdict_text(const HuntingResult& r) {
  switch (r.verdict) {
    case HuntingVerdict::critical_speed_in_range:
      return r.critical ? "hunts above the linear critical speed " + critical_text(r, *r.critical) + "."
                        : "unstable within the range (no critical speed was refined).";
    case HuntingVerdict::stable_throughout:
      if (zero_conicity(r))
        return "neutrally stable at every speed from " + kmh(lowest_speed(r)) + " to " + kmh(highest_speed(r)) +
               ": at zero conicity the wheelsets have no kinematic coupling, so there is no hunting and no critical "
               "speed at any speed; the lateral and yaw motion nothing restrains neither grows nor decays (" +
               std::to_string(r.neutral_roots) + " rigid-body roots, neutral).";
      return "stable at every speed from " + kmh(lowest_speed(r)) + " to " + kmh(highest_speed(r)) +
             ": no critical speed in the range (it is above " + kmh(highest_speed(r)) + ", if there is one).";
    case HuntingVerdict::unstable_at_lowest_speed:
      return "already unstable at the lowest speed, " + kmh(lowest_speed(r)) +
             ": no critical speed is given (it is below the range, if the vehicle is stable at all).";
  }
  return "";
}

// What is unstable over an interval: its branch by number and name, or a real root's divergence.
std::string interval_cause(const HuntingResult& r, const UnstableInterval& u) {
  return u.divergence ? "divergence, " + u.branch : cited_branch(r, u.branch);
}

// One unstable interval, its open ends said, its branch by number and name.
std::string interval_text(const HuntingResult& r, const UnstableInterval& u) {
  const std::string from = u.from_lowest_speed ? "unstable at the lowest speed, " + kmh(u.from)
                                               : "from " + fixed(u.from * kKmh, 2) + " km/h";
  const std::string to =
      u.to_highest_speed ? "still unstable at the highest, " + kmh(u.to) : "to " + fixed(u.to * kKmh, 2) + " km/h";
  return from + ", " + to + " (" + interval_cause(r, u) + ")";
}

// The branches already at or below the threshold at the lowest speed, each with its ζ there:
// "'bogie 1 yaw' (ζ = 3.99 %), …" ("" when none).
std::string least_damped_at_lowest_speed(const HuntingResult& r) {
  std::string list;
  for (const std::string& name : r.below_threshold_at_lowest_speed) {
    list += (list.empty() ? "'" : ", '") + name + "'";
    for (const HuntingBranch& b : r.branches)
      if (b.name == name && !b.damping_ratio.empty())
        list += " (ζ = " + significant(100.0 * b.damping_ratio.front(), 3) + " %)";
  }
  return list;
}

std::string threshold_text(const HuntingResult& r) {
  if (!r.damping_threshold) return "";
  const std::string zeta = "ζ = " + significant(100.0 * *r.damping_threshold, 4) + " %";
  std::string text = "no branch damped more than " + zeta + " at a lower speed falls to it within the range.";
  if (r.threshold_speed)
    text = "branch " + quoted_branch(r, r.threshold_branch) + " falls to " + zeta + " at " + fixed(*r.threshold_speed * kKmh, 2) +
           " km/h, the lowest speed at which a branch damped more than that at a lower speed falls to it.";
  const std::string below = least_damped_at_lowest_speed(r);
  if (!below.empty())
    text += " Already at or below it at the lowest speed, " + kmh(lowest_speed(r)) +
            ", and so not what decides it: " + below + ".";
  return text;
}

const char* const kLinearNote =
    "Linear analysis: eigenvalues of the vehicle linearised about running straight and centred on its track, "
    "with linear (unsaturated) creep forces and no flange contact. Its critical speed is where small motions "
    "start to grow; the nonlinear critical speed, the lowest speed at which a limit cycle survives, may be lower: "
    "'railmodal hunting SCENE' computes it from a scene naming the effects (docs/stability.md).";

const char* const kBranchNote =
    "ζ = −Re λ/|λ|, f = Im λ/2π; f \"real\": the pair is two real (overdamped) roots at that speed, ζ 100 %, left "
    "out of the CSV there. Branches are followed from speed to speed by eigenvector continuity (MAC); where the "
    "lowest MAC falls below the tracking's threshold the branch veers: its name there is uncertain.";
// Under the verdict, for each check that failed: the run exits 6 (docs/stability.md).
const char* const kFailedNote =
    "The figures below are not an answer to sign off on: the run exits 6 (docs/stability.md)";

// ---- tables shared by every format for people ----

Table verdict_table(const HuntingResult& r) {
  Table t{{"quantity", "value"}, {false, false}, {}};
  t.rows.push_back({"verdict", to_string(r.verdict)});
  if (r.critical) {
    const HuntingCriticalSpeed& c = *r.critical;
    t.rows.push_back(
        {"linear critical speed", fixed(c.speed * kKmh, 2) + " km/h = " + significant(c.speed, 8) + " m/s"});
    t.rows.push_back({"hunting branch", cited_branch(r, c.branch)});
    t.rows.push_back({"what moves most at that speed", c.motion});
    t.rows.push_back({"hunting frequency", fixed(c.frequency_hz, 3) + " Hz"});
    t.rows.push_back({"Klingel's V/Λ at that speed", fixed(c.klingel_frequency_hz, 3) + " Hz"});
    if (c.bogie_frequency_hz > 0.0)
      t.rows.push_back({"V/Λ_b of '" + c.bogie + "' as a rigid bogie", fixed(c.bogie_frequency_hz, 3) + " Hz"});
    t.rows.push_back({"eigen-solves of the refinement", std::to_string(c.evaluations)});
  }
  if (r.damping_threshold) {
    const std::string zeta = "ζ = " + significant(100.0 * *r.damping_threshold, 4) + " %";
    t.rows.push_back({"speed at which a branch falls to " + zeta,
                      r.threshold_speed ? fixed(*r.threshold_speed * kKmh, 2) + " km/h (" + cited_branch(r, r.threshold_branch) + ")"
                                        : "none in the range"});
    if (!r.below_threshold_at_lowest_speed.empty())
      t.rows.push_back({"at or below " + zeta + " at the lowest speed", least_damped_at_lowest_speed(r)});
  }
  return t;
}

Table intervals_table(const HuntingResult& r) {
  Table t{{"from (km/h)", "to (km/h)", "branch"}, {true, true, false}, {}};
  for (const UnstableInterval& u : r.unstable_intervals)
    t.rows.push_back(
        {u.from_lowest_speed ? fixed(u.from * kKmh, 2) + " (unstable at the lowest speed)" : fixed(u.from * kKmh, 2),
         u.to_highest_speed ? fixed(u.to * kKmh, 2) + " (still unstable at the highest)" : fixed(u.to * kKmh, 2),
         interval_cause(r, u)});
  return t;
}

Table branches_table(const HuntingResult& r) {
  const std::string low = given_kmh(lowest_speed(r)), high = given_kmh(highest_speed(r));
  Table t{{"#", "branch", "f at " + low + " km/h (Hz)", "ζ at " + low + " km/h", "f at " + high + " km/h (Hz)",
           "ζ at " + high + " km/h", "least ζ", "at (km/h)", "lowest MAC", "tracking"},
          {true, false, true, true, true, true, true, true, true, false},
          {}};
  for (size_t k = 0; k < r.branches.size(); ++k) {
    const HuntingBranch& b = r.branches[k];
    if (b.damping_ratio.empty()) continue;
    const Least l = least_damping(b), mac = least_continuity(b);
    const bool veer_at = b.veers && mac.at < r.speeds.size();
    // A pair that is real or nearly real there (overdamped: stability::overdamped_root) does not
    // oscillate: "real", its ζ 100 % to the table's digits.
    const auto frequency = [&](size_t i) {
      return stability::overdamped_root(b.eigenvalues[i]) ? std::string("real") : fixed(b.frequency_hz[i], 3);
    };
    t.rows.push_back({std::to_string(k + 1), b.name, frequency(0), percent(b.damping_ratio.front()),
                      frequency(b.eigenvalues.size() - 1), percent(b.damping_ratio.back()), percent(l.value),
                      l.at < r.speeds.size() ? fixed(r.speeds[l.at] * kKmh, 1) : "—",
                      b.continuity.empty() ? "—" : fixed(mac.value, 3),
                      veer_at ? "VEERS near " + fixed(r.speeds[mac.at] * kKmh, 1) + " km/h" : "continuous"});
  }
  return t;
}

Table conicity_table(const HuntingResult& r) {
  // The rigid bogie's V/Λ_b beside Klingel's for a vehicle on bogies (0 at every point otherwise).
  const bool bogies = std::any_of(r.conicity_curve.begin(), r.conicity_curve.end(), [](const ConicityPoint& p) {
    return p.critical && p.critical->bogie_frequency_hz > 0.0;
  });
  Table t{{"conicity λ", "verdict", "critical speed (km/h)", "branch", "f (Hz)", "Klingel V/Λ (Hz)"},
          {true, false, true, false, true, true},
          {}};
  if (bogies) t.headers.push_back("rigid bogie V/Λ_b (Hz)"), t.numeric.push_back(true);
  for (const ConicityPoint& p : r.conicity_curve) {
    if (p.critical)
      t.rows.push_back({significant(p.conicity, 4), to_string(p.verdict), fixed(p.critical->speed * kKmh, 2),
                        p.critical->branch, fixed(p.critical->frequency_hz, 3),
                        fixed(p.critical->klingel_frequency_hz, 3)});
    else
      t.rows.push_back({significant(p.conicity, 4), to_string(p.verdict),
                        p.verdict == HuntingVerdict::stable_throughout
                            ? (p.conicity == 0.0 ? std::string("none (λ = 0: no kinematic coupling)")
                                                 : "above " + given_kmh(highest_speed(r)))
                            : "below " + given_kmh(lowest_speed(r)),
                        "—", "—", "—"});
    if (bogies)
      t.rows.back().push_back(p.critical && p.critical->bogie_frequency_hz > 0.0
                                  ? fixed(p.critical->bogie_frequency_hz, 3)
                                  : "—");
  }
  return t;
}

std::string wavelength_text(double wavelength) {
  return std::isfinite(wavelength) ? fixed(wavelength, 3) : "none (λ = 0: no kinematic oscillation)";
}

Table contacts_table(const HuntingResult& r) {
  Table t{{"wheelset", "W (kN)", "λ", "ε", "σ", "r0 (m)", "l0 (m)", "f11 (MN)", "f22 (MN)", "f23 (kN·m)", "f33 (N·m²)",
           "Hertz a × b (mm)", "Klingel Λ (m)"},
          {false, true, true, true, true, true, true, true, true, true, true, true, true},
          {}};
  for (const ResolvedContact& c : r.contacts)
    t.rows.push_back({c.body, significant(c.axle_load / 1e3, 5), significant(c.conicity, 4),
                      significant(c.contact_angle_parameter, 4), significant(c.roll_parameter, 4),
                      significant(c.rolling_radius, 4), significant(c.contact_half_spacing, 4),
                      significant(c.creep.f11 / 1e6, 4), significant(c.creep.f22 / 1e6, 4),
                      significant(c.creep.f23 / 1e3, 4), significant(c.creep.f33, 4),
                      c.ellipse ? fixed(c.ellipse->a * 1e3, 2) + " × " + fixed(c.ellipse->b * 1e3, 2) : "given",
                      wavelength_text(c.klingel_wavelength)});
  return t;
}

const char* const kContactsNote =
    "Per wheel: creep coefficients f11 (longitudinal), f22 (lateral), f23 (lateral–spin), f33 (spin); W the axle "
    "load, λ the equivalent conicity, ε and σ the contact-angle and roll parameters, r0 the rolling radius, l0 half "
    "the distance between the contact points, Λ = 2π√(r0·l0/λ) Klingel's kinematic wavelength; Hertz a × b: the "
    "contact ellipse when the coefficients were computed (\"given\": written in the vehicle file).";

// The rigid bogie's wavelength, said wherever V/Λ_b is printed (user audit 2026-11-28, F6: the
// creep-ratio form differs by 3.5 % on the coach from Rocard's √(1 + (a/l0)²), which the
// critical-speed command's rigid_bogie source uses).
const char* const kBogieNote =
    " Λ_b = Λ·√(1 + ā²f22/(l0²f11)): the kinematic wavelength of the bogie as a rigid frame (its wheelsets yawing "
    "together with no net creep force and moment), ā² the mean square of its axles' distances from their centre "
    "(a², a the half wheelbase, for two axles); Rocard's Λ·√(1 + (a/l0)²) when f11 = f22 (docs/stability.md).";

std::string contacts_note(const HuntingResult& r) {
  const auto bogie = [](const std::optional<HuntingCriticalSpeed>& c) { return c && c->bogie_frequency_hz > 0.0; };
  const bool shown = bogie(r.critical) || std::any_of(r.conicity_curve.begin(), r.conicity_curve.end(),
                                                       [&](const ConicityPoint& p) { return bogie(p.critical); });
  return std::string(kContactsNote) + (shown ? kBogieNote : "");
}

// ---- table (text) ----

void write_table(std::ostream& out, const Page& p) {
  const HuntingResult& r = p.r;
  out << "railmodal stability: " << p.vehicle << "\n";
  out << "speeds " << range_text(r) << "; " << r.dofs.size() << " degrees of freedom; " << r.branches.size()
      << " oscillatory branches\n\n";
  out << wrapped("verdict: " + std::string(to_string(r.verdict)) + ": " + verdict_text(r)) << "\n";
  for (const std::string& f : report::failed_checks(r.summary))
    out << wrapped("CHECK FAILED: " + f + ". " + kFailedNote) << "\n";
  if (r.critical) out << "  refined in " << r.critical->evaluations << " eigen-solves\n";
  if (r.damping_threshold) out << wrapped("damping threshold: " + threshold_text(r)) << "\n";
  out << "\nunstable speed intervals:";
  if (r.unstable_intervals.empty()) out << " none";
  out << "\n";
  for (const UnstableInterval& u : r.unstable_intervals) out << "  " << interval_text(r, u) << "\n";
  out << "\nbranches (least damped first at the highest speed):\n";
  write_text_table(out, branches_table(r));
  out << wrapped(kBranchNote) << "\n";
  if (!r.conicity_curve.empty()) {
    out << "\ncritical speed against conicity:\n";
    write_text_table(out, conicity_table(r));
  }
  out << "\ncontacts:\n";
  write_text_table(out, contacts_table(r));
  out << wrapped(contacts_note(r)) << "\n\n" << wrapped(kLinearNote) << "\n";
  out << "\n" << wrapped("checks: " + report::checks_text(r.summary)) << "\n"
      << wrapped("method: " + report::method_text(r.summary)) << "\n";
  for (const std::string& f : report::failed_checks(r.summary)) out << wrapped("warning: check failed: " + f) << "\n";
}

// ---- Markdown ----

void write_markdown(std::ostream& out, const Page& p) {
  const HuntingResult& r = p.r;
  out << "# Hunting stability: " << p.vehicle << "\n\n";
  out << "Speeds " << range_text(r) << "; " << r.dofs.size() << " degrees of freedom; " << r.branches.size()
      << " oscillatory branches.\n\n";
  out << "**Verdict: " << to_string(r.verdict) << "**: " << verdict_text(r) << "\n\n";
  for (const std::string& f : report::failed_checks(r.summary))
    out << "**Check failed:** " << f << ". " << kFailedNote << "\n\n";
  write_markdown_table(out, verdict_table(r));
  out << "## Unstable speed intervals\n\n";
  if (r.unstable_intervals.empty())
    out << "None: every branch is damped at every speed of the grid.\n\n";
  else
    write_markdown_table(out, intervals_table(r));
  out << "## Branches\n\n";
  write_markdown_table(out, branches_table(r));
  out << kBranchNote << " The root locus and ζ against speed are drawn in the HTML report (`--format html`); "
      << "the CSV and JSON hold each branch's eigenvalue at every speed (the root with Im λ > 0 of each "
      << "complex pair; the real roots, which do not oscillate, are left out).\n\n";
  if (!r.conicity_curve.empty()) {
    out << "## Critical speed against conicity\n\n";
    write_markdown_table(out, conicity_table(r));
  }
  out << "## Contacts\n\n";
  write_markdown_table(out, contacts_table(r));
  out << contacts_note(r) << "\n\n" << kLinearNote << "\n\n";
  out << "## Checks\n\n" << report::checks_text(r.summary) << ".\n\nMethod: " << report::method_text(r.summary)
      << ".\n\n";
  for (const std::string& f : report::failed_checks(r.summary)) out << "**Warning: check failed:** " << f << "\n\n";
  out << "---\n\nWritten by " << report::provenance_line("stability", p.provenance) << "\n";
}

// ---- HTML ----

// The branch's colour: its place among the least damped, the rest sharing the last colour.
int colour_of(const std::vector<size_t>& order, size_t branch) {
  const size_t place = static_cast<size_t>(std::find(order.begin(), order.end(), branch) - order.begin());
  return static_cast<int>(std::min(place, kColouredBranches));
}

std::string branch_label(const std::vector<size_t>& order, size_t branch, const HuntingResult& r) {
  const size_t place = static_cast<size_t>(std::find(order.begin(), order.end(), branch) - order.begin());
  if (place < kColouredBranches) return std::to_string(branch + 1) + " " + r.branches[branch].name;
  return place == kColouredBranches ? "more damped branches" : "";
}

// The root locus' extent: from the most damped point to the right of Re λ = 0, but no further
// left than −2 max Im λ (ζ ≈ 0.9): the creep damping, ∝ 1/V, throws the low-speed points of
// some branches far left (`cut` when it does).
struct LocusBounds {
  double left = 0.0, right = 0.0, top = 0.0;
  bool cut = false;
};
LocusBounds locus_bounds(const HuntingResult& r) {
  LocusBounds b;
  for (const HuntingBranch& branch : r.branches)
    for (const std::complex<double>& l : branch.eigenvalues)
      if (std::isfinite(l.real()) && std::isfinite(l.imag()))
        b.left = std::min(b.left, l.real()), b.right = std::max(b.right, l.real()), b.top = std::max(b.top, l.imag());
  b.cut = b.left < -2.0 * b.top;
  b.left = std::max(b.left, -2.0 * b.top);
  return b;
}

// Root locus: Im λ/2π against Re λ, each branch a thin line in its colour and its points shaded
// by speed (at most 60 a branch, evenly spaced: enough to read the direction of travel).
report::Chart root_locus_chart(const HuntingResult& r) {
  const std::vector<size_t> order = by_least_damping(r);
  report::Chart c;
  c.id = "root-locus";
  c.title = "Root locus: eigenvalues against speed";
  c.x_label = "real part Re λ (1/s)";
  c.y_label = "frequency Im λ/2π (Hz)";
  const LocusBounds bounds = locus_bounds(r);
  const double margin = 0.05 * std::max(bounds.right - bounds.left, 1e-9);
  c.x_min = bounds.left - margin;
  c.x_max = bounds.right + margin;
  c.y_min = 0.0;
  c.y_max = 1.05 * std::max(bounds.top / (2.0 * M_PI), 1e-6);
  const double span = highest_speed(r) - lowest_speed(r);
  c.shade_key = "dots: speed from " + kmh(lowest_speed(r)) + " (dark) to " + kmh(highest_speed(r)) + " (light)";
  c.lines.push_back({"Re λ = 0", 0.0, true, "the stability boundary: right of it a motion grows"});
  for (size_t k = 0; k < r.branches.size(); ++k) {
    const HuntingBranch& b = r.branches[k];
    report::ChartSeries line, dots;
    line.label = branch_label(order, k, r);
    line.colour = dots.colour = colour_of(order, k);
    dots.markers_only = true;
    const size_t step = std::max<size_t>(1, b.eigenvalues.size() / 60);
    for (size_t i = 0; i < b.eigenvalues.size(); ++i) {
      line.x.push_back(b.eigenvalues[i].real());
      line.y.push_back(b.eigenvalues[i].imag() / (2.0 * M_PI));
      if (i % step != 0 && i + 1 != b.eigenvalues.size()) continue;
      dots.x.push_back(line.x.back());
      dots.y.push_back(line.y.back());
      dots.shade.push_back(span > 0.0 && i < r.speeds.size() ? (r.speeds[i] - lowest_speed(r)) / span : 0.0);
    }
    c.series.push_back(line);
    c.series.push_back(dots);
  }
  return c;
}

// The zoomed panel of the root locus shows where the branches that matter near and cross
// Re λ = 0: on the full locus the strongly damped roots (on the Manchester coach, Re λ down to
// −600 1/s) set the scale and the crossing is a few pixels. The branches that matter are those
// unstable somewhere (their least ζ < 0), else the least-damped one; their points damped less
// than this are in the panel.
constexpr double kZoomDamping = 0.10;

// The extent of those points (with Re λ = 0 always in it); `any` is false when there are none,
// or when they already fill most of the full plot's width (no zoom needed).
struct ZoomBounds {
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  bool any = false;
  std::string branches;  // which, for the note: "the unstable branches" or the least-damped one's name
};
ZoomBounds zoom_bounds(const HuntingResult& r) {
  ZoomBounds z;
  std::vector<size_t> chosen;
  for (size_t k = 0; k < r.branches.size(); ++k)
    if (least_damping(r.branches[k]).value < 0.0) chosen.push_back(k);
  z.branches = chosen.size() == 1 ? "the unstable branch" : "the unstable branches";
  if (chosen.empty() && !r.branches.empty()) {
    chosen.push_back(by_least_damping(r).front());
    z.branches = "the least-damped branch, '" + r.branches[chosen.front()].name + "'";
  }
  z.bottom = std::numeric_limits<double>::infinity();
  for (size_t k : chosen) {
    const HuntingBranch& b = r.branches[k];
    for (size_t i = 0; i < b.eigenvalues.size() && i < b.damping_ratio.size(); ++i) {
      const std::complex<double> l = b.eigenvalues[i];
      if (!(b.damping_ratio[i] < kZoomDamping) || !std::isfinite(l.real()) || !std::isfinite(l.imag())) continue;
      z.any = true;
      z.left = std::min(z.left, l.real()), z.right = std::max(z.right, l.real());
      z.bottom = std::min(z.bottom, l.imag()), z.top = std::max(z.top, l.imag());
    }
  }
  const LocusBounds full = locus_bounds(r);
  if (z.any && z.left - z.right < 0.5 * (full.left - full.right)) z.any = false;  // wider than half the full plot
  return z;
}

// The root locus around Re λ = 0: the same branches, the axes cut to the points damped less than
// kZoomDamping of the branches that matter (the rest is clipped at the plot's edge).
report::Chart root_locus_zoom_chart(const HuntingResult& r, const ZoomBounds& z) {
  report::Chart c = root_locus_chart(r);
  c.id = "root-locus-zoom";
  c.title = "Root locus near the stability boundary (ζ < " + fixed(100.0 * kZoomDamping, 0) + " %)";
  const double width = std::max(z.right - z.left, 1e-9);
  c.x_min = z.left - 0.05 * width;
  c.x_max = z.right + 0.05 * width;
  const double bottom = z.bottom / (2.0 * M_PI), top = z.top / (2.0 * M_PI);
  const double height = std::max(top - bottom, 0.05 * std::max(top, 1e-6));
  c.y_min = std::max(0.0, bottom - 0.05 * height);
  c.y_max = top + 0.05 * height;
  return c;
}

// ζ against speed for every branch, with ζ = 0, the threshold, the critical speed and the
// threshold speed marked. ζ of the strongly damped branches (creep damping grows as 1/V at low
// speed) would squash the ones near zero: the axis ends at 60 %.
report::Chart damping_chart(const HuntingResult& r) {
  const std::vector<size_t> order = by_least_damping(r);
  report::Chart c;
  c.id = "damping";
  c.title = "Damping ratio of each branch against speed";
  c.x_label = "speed (km/h)";
  c.y_label = "damping ratio ζ (%)";
  c.x_min = lowest_speed(r) * kKmh;
  c.x_max = highest_speed(r) * kKmh;
  double lo = 0.0, hi = 0.0;
  for (const HuntingBranch& b : r.branches)
    for (double z : b.damping_ratio)
      if (std::isfinite(z)) lo = std::min(lo, 100.0 * z), hi = std::max(hi, 100.0 * z);
  const double threshold = r.damping_threshold ? 100.0 * *r.damping_threshold : 0.0;
  c.y_max = std::min(std::max({hi, threshold, 1.0}), 60.0) * 1.05;
  c.y_min = std::max(lo, -60.0);
  c.y_min -= 0.05 * (c.y_max - c.y_min);
  c.lines.push_back({"ζ = 0", 0.0, false, ""});
  if (r.damping_threshold)
    c.lines.push_back({"ζ = " + significant(threshold, 3) + " %", threshold, false, "the damping threshold asked for"});
  if (r.critical)
    c.lines.push_back({"V crit " + fixed(r.critical->speed * kKmh, 1), r.critical->speed * kKmh, true,
                       "the linear critical speed (km/h)"});
  if (r.threshold_speed)
    c.lines.push_back({"V at ζ = " + significant(threshold, 3) + " %", *r.threshold_speed * kKmh, true,
                       "where branch " + quoted_branch(r, r.threshold_branch) + " falls to the threshold"});
  for (size_t k = 0; k < r.branches.size(); ++k) {
    const HuntingBranch& b = r.branches[k];
    report::ChartSeries s;
    s.label = branch_label(order, k, r);
    s.colour = colour_of(order, k);
    s.dashed = colour_of(order, k) == static_cast<int>(kColouredBranches);
    for (size_t i = 0; i < b.damping_ratio.size() && i < r.speeds.size(); ++i) {
      s.x.push_back(r.speeds[i] * kKmh);
      s.y.push_back(std::isfinite(b.damping_ratio[i]) ? 100.0 * b.damping_ratio[i] : std::nan(""));
    }
    c.series.push_back(s);
  }
  return c;
}

// The vehicle's own equivalent conicities (its wheelsets', as used: the root locus and the
// critical speed above are at them), each once, in increasing order.
std::vector<double> own_conicities(const HuntingResult& r) {
  std::vector<double> out;
  for (const ResolvedContact& c : r.contacts) out.push_back(c.conicity);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The wheelsets whose conicity is λ, for the legend when they differ ("wheelset1, wheelset2").
std::string wheelsets_at(const HuntingResult& r, double conicity) {
  std::string out;
  for (const ResolvedContact& c : r.contacts)
    if (c.conicity == conicity) out += (out.empty() ? "" : ", ") + c.body;
  return out;
}

// Critical speed against conicity: the design curve, with the conicities stable over the whole
// range at the top of the range and those unstable at its lowest speed at the bottom (bounds,
// not values: each in a series of its own), and the vehicle's own conicity marked as the speed
// charts mark speeds (a vertical line, labelled), so that a reader sees where on the curve the
// vehicle stands.
report::Chart conicity_chart(const HuntingResult& r) {
  report::Chart c;
  c.id = "conicity";
  c.title = "Linear critical speed against equivalent conicity";
  c.x_label = "equivalent conicity λ (–)";
  c.y_label = "critical speed (km/h)";
  c.y_min = 0.0;
  c.y_max = highest_speed(r) * kKmh * 1.08;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const ConicityPoint& p : r.conicity_curve) lo = std::min(lo, p.conicity), hi = std::max(hi, p.conicity);
  const std::vector<double> own = own_conicities(r);
  for (double l : own) lo = std::min(lo, l), hi = std::max(hi, l);  // the mark always inside the axis
  const double margin = hi > lo ? 0.05 * (hi - lo) : 0.05;
  c.x_min = std::max(0.0, lo - margin);
  c.x_max = hi + margin;
  report::ChartSeries curve, stable, unstable;
  curve.label = "critical speed";
  stable.label = "stable over the whole range (drawn at its highest speed)";
  unstable.label = "unstable at the lowest speed (drawn at it)";
  stable.markers_only = unstable.markers_only = true;
  stable.colour = 2, unstable.colour = 1;
  report::ChartSeries points;
  points.markers_only = true;
  points.colour = 0;
  for (const ConicityPoint& p : r.conicity_curve) {
    curve.x.push_back(p.conicity);
    curve.y.push_back(p.critical ? p.critical->speed * kKmh : std::nan(""));
    if (p.critical) points.x.push_back(p.conicity), points.y.push_back(p.critical->speed * kKmh);
    if (p.verdict == HuntingVerdict::stable_throughout)
      stable.x.push_back(p.conicity), stable.y.push_back(highest_speed(r) * kKmh);
    if (p.verdict == HuntingVerdict::unstable_at_lowest_speed)
      unstable.x.push_back(p.conicity), unstable.y.push_back(lowest_speed(r) * kKmh);
  }
  c.lines.push_back({"range top", highest_speed(r) * kKmh, false, ""});
  for (double l : own)
    c.lines.push_back({"vehicle λ = " + significant(l, 4), l, true,
                       own.size() == 1 ? "the vehicle's own equivalent conicity (the root locus above is at it)"
                                       : "the equivalent conicity of " + wheelsets_at(r, l)});
  c.series.push_back(curve);
  c.series.push_back(points);
  if (!stable.x.empty()) c.series.push_back(stable);
  if (!unstable.x.empty()) c.series.push_back(unstable);
  return c;
}

void write_html(std::ostream& out, const Page& p) {
  using report::html_escape;
  const HuntingResult& r = p.r;
  report::write_html_head(out, "Hunting stability: " + p.vehicle);
  out << "<h1>Hunting stability: " << html_escape(p.vehicle) << "</h1>\n<p>Speeds " << html_escape(range_text(r))
      << "; " << r.dofs.size() << " degrees of freedom; " << r.branches.size() << " oscillatory branches.</p>\n";
  const bool stable = r.verdict == HuntingVerdict::stable_throughout;
  out << "<p class=" << (stable ? "ok" : "bad") << "><b>Verdict: " << to_string(r.verdict)
      << "</b>: " << html_escape(verdict_text(r)) << "</p>\n";
  for (const std::string& f : report::failed_checks(r.summary))
    out << "<p class=bad><b>Check failed:</b> " << html_escape(f + ". " + kFailedNote) << "</p>\n";
  report::write_html_table(out, verdict_table(r));
  out << "<h2>Unstable speed intervals</h2>\n";
  if (r.unstable_intervals.empty())
    out << "<p>None: every branch is damped at every speed of the grid.</p>\n";
  else
    report::write_html_table(out, intervals_table(r));
  out << "<h2>Damping ratio against speed</h2>\n" << report::svg_chart(damping_chart(r));
  // Say what the chart leaves out, when it does.
  bool cut = false;
  for (const HuntingBranch& b : r.branches)
    for (double z : b.damping_ratio) cut = cut || std::abs(z) > 0.6;
  if (r.branches.size() > kColouredBranches || cut)
    out << "<p class=note>"
        << (r.branches.size() > kColouredBranches
                ? "The " + std::to_string(kColouredBranches) + " least-damped branches in colour, the others dashed. "
                : std::string())
        << (cut ? "The axis is cut at ±60 %: creep damping grows as 1/V, so at low speed some branches are damped "
                  "far more."
                : "")
        << "</p>\n";
  out << "<h2>Root locus</h2>\n" << report::svg_chart(root_locus_chart(r));
  out << "<p class=note>Each branch from the lowest speed (dark dots) to the highest (light); a branch that crosses "
         "Re λ = 0 to the right becomes unstable there."
      << (locus_bounds(r).cut ? " The axis stops at Re λ = −2 max Im λ (ζ ≈ 0.9): points damped more than that lie "
                                "left of it."
                              : "")
      << "</p>\n";
  if (const ZoomBounds z = zoom_bounds(r); z.any) {
    out << "<h3>Near the stability boundary</h3>\n" << report::svg_chart(root_locus_zoom_chart(r, z));
    out << "<p class=note>The same root locus with the axes cut to the points of " << html_escape(z.branches)
        << " damped less than ζ = " << fixed(100.0 * kZoomDamping, 0) << " % (Re λ from " << significant(z.left, 3)
        << " to " << significant(z.right, 3) << " 1/s, f from " << fixed(z.bottom / (2.0 * M_PI), 2) << " to "
        << fixed(z.top / (2.0 * M_PI), 2)
        << " Hz): the other branches, and the more damped points, are drawn only where they pass through it.</p>\n";
  }
  out << "<h2>Branches</h2>\n";
  report::write_html_table(out, branches_table(r));
  out << "<p class=note>" << html_escape(kBranchNote) << "</p>\n";
  if (!r.conicity_curve.empty()) {
    out << "<h2>Critical speed against conicity</h2>\n" << report::svg_chart(conicity_chart(r));
    report::write_html_table(out, conicity_table(r));
  }
  out << "<h2>Contacts</h2>\n";
  report::write_html_table(out, contacts_table(r));
  out << "<p class=note>" << html_escape(contacts_note(r)) << "</p>\n<p class=note>" << html_escape(kLinearNote)
      << "</p>\n";
  out << "<h2>Checks</h2>\n<p>" << html_escape(report::checks_text(r.summary))
      << ".</p>\n<p class=note>Method: " << html_escape(report::method_text(r.summary)) << ".</p>\n";
  for (const std::string& f : report::failed_checks(r.summary))
    out << "<p class=bad><b>Warning: check failed:</b> " << html_escape(f) << "</p>\n";
  report::write_html_footer(out, "stability", p.provenance);
}

// ---- CSV and JSON ----

// A CSV number, the shortest text that reads back as the same double, or blank when it is not
// finite. std::to_chars (Ryu): the stream's setprecision(10) took 56 ms for a 1000-speed,
// 20-branch locus (20 000 rows), printf's %.10g 30 ms.
void csv_number(std::string* row, double value) {
  *row += ',';
  if (!std::isfinite(value)) return;
  char text[report::kNumberTextMax];
  row->append(text, report::write_number(text, value, report::NumberStyle::csv));
}

void write_csv(std::ostream& out, const HuntingResult& r) {
  using report::csv_heading;
  out << csv_heading("speed", "km/h") << ",branch," << csv_heading("eigenvalue_re", "1/s") << ","
      << csv_heading("eigenvalue_im", "1/s") << "," << csv_heading("frequency", "Hz") << ",damping_ratio,continuity\n";
  std::string row;
  for (const HuntingBranch& b : r.branches) {
    const std::string name = "," + report::csv_field(b.name);
    for (size_t i = 0; i < b.eigenvalues.size() && i < r.speeds.size(); ++i) {
      if (stability::overdamped_root(b.eigenvalues[i])) continue;  // overdamped there: not an oscillation
      row.clear();
      csv_number(&row, r.speeds[i] * kKmh);
      row.erase(0, 1);  // the first field has no comma before it
      row += name;
      csv_number(&row, b.eigenvalues[i].real());
      csv_number(&row, b.eigenvalues[i].imag());
      csv_number(&row, b.frequency_hz[i]);
      csv_number(&row, b.damping_ratio[i]);
      csv_number(&row, i < b.continuity.size() ? b.continuity[i] : 1.0);
      row += '\n';
      out << row;
    }
  }
}

// Every object's members in alphabetical order, as the files had them (json_writer.hpp); a
// number that is not finite is null (never inf or NaN in JSON).
// The member `branch_number`: the branch's place in `branches` (1 for the first), null for a
// name no branch has (a real root's).
void write_branch_number(JsonWriter& j, const HuntingResult& r, const std::string& name) {
  j.key("branch_number");
  for (size_t k = 0; k < r.branches.size(); ++k)
    if (r.branches[k].name == name) {
      j.value(static_cast<int>(k + 1));
      return;
    }
  j.value(nullptr);
}

// The critical speed; with `tracked` (the vehicle's own conicity, whose branches were followed
// over the grid) its branch's number too.
void write_critical(JsonWriter& j, const std::optional<HuntingCriticalSpeed>& c, const HuntingResult* tracked = nullptr) {
  if (!c) {
    j.value(nullptr);
    return;
  }
  const bool bogie = c->bogie_frequency_hz > 0.0;
  j.begin_object().key("bogie");
  if (bogie)
    j.value(c->bogie);
  else
    j.value(nullptr);
  j.member("bogie_frequency_hz", bogie ? std::optional<double>(c->bogie_frequency_hz) : std::optional<double>());
  j.member("branch", c->branch);
  if (tracked) write_branch_number(j, *tracked, c->branch);
  j.member("evaluations", c->evaluations);
  j.member("frequency_hz", c->frequency_hz).member("klingel_frequency_hz", c->klingel_frequency_hz);
  j.member("motion", c->motion).member("speed_kmh", c->speed * kKmh).member("speed_m_s", c->speed).end_object();
}

void write_contact(JsonWriter& j, const ResolvedContact& c) {
  j.begin_object().member("axle_load_n", c.axle_load).member("body", c.body).member("conicity", c.conicity);
  j.member("contact_angle_parameter", c.contact_angle_parameter);
  j.member("contact_half_spacing_m", c.contact_half_spacing);
  j.key("ellipse");
  if (c.ellipse)
    j.begin_object().member("a_m", c.ellipse->a).member("approach_m", c.ellipse->approach).member("b_m", c.ellipse->b)
        .member("max_pressure_pa", c.ellipse->max_pressure).end_object();
  else
    j.value(nullptr);
  j.member("f11_n", c.creep.f11).member("f22_n", c.creep.f22).member("f23_n_m", c.creep.f23);
  j.member("f33_n_m2", c.creep.f33).member("klingel_wavelength_m", c.klingel_wavelength);
  j.member("roll_parameter", c.roll_parameter).member("rolling_radius_m", c.rolling_radius).end_object();
}

// The analysis' checks, without the stage times (they vary from run to run); a limit of +∞
// (reported, not bounded) is null.
void write_summary(JsonWriter& j, const AnalysisSummary& s) {
  j.begin_object().member("analysis", s.analysis).key("checks").begin_array();
  for (const Check& c : s.checks)
    j.begin_object().member("limit", c.limit).member("name", c.name).member("passed", c.passed).member("value", c.value).end_object();
  j.end_array().member("method", s.method).end_object();
}

void write_branch(JsonWriter& j, const HuntingBranch& b) {
  j.begin_object().member("continuity", b.continuity).member("damping_ratio", b.damping_ratio);
  j.key("eigenvalue_im").begin_array();
  for (const auto& l : b.eigenvalues) j.value(l.imag());
  j.end_array().key("eigenvalue_re").begin_array();
  for (const auto& l : b.eigenvalues) j.value(l.real());
  j.end_array().member("frequency_hz", b.frequency_hz).member("name", b.name).member("veers", b.veers).end_object();
}

// The head's members one a line, in the order written here, each value compact on its line; then
// each branch on a line of its own (the eigenvalues of a 1000-speed locus are most of the document;
// json_lines.hpp).
void write_json(std::ostream& out, const Page& p) {
  using report::write_line_member;
  const HuntingResult& r = p.r;
  const std::optional<double> none;
  write_line_member(out, "vehicle", [&](JsonWriter& j) { j.value(p.vehicle); }, true);
  write_line_member(out, "analysis", [&](JsonWriter& j) { j.value("linear"); });
  write_line_member(out, "verdict", [&](JsonWriter& j) { j.value(to_string(r.verdict)); });
  write_line_member(out, "critical", [&](JsonWriter& j) { write_critical(j, r.critical, &r); });
  write_line_member(out, "summary", [&](JsonWriter& j) { write_summary(j, r.summary); });
  write_line_member(out, "unstable_intervals", [&](JsonWriter& j) {
    j.begin_array();
    for (const UnstableInterval& u : r.unstable_intervals) {
      j.begin_object().member("branch", u.branch);
      write_branch_number(j, r, u.branch);
      j.member("divergence", u.divergence).member("from_kmh", u.from * kKmh)
          .member("from_lowest_speed", u.from_lowest_speed).member("from_m_s", u.from)
          .member("to_highest_speed", u.to_highest_speed).member("to_kmh", u.to * kKmh).member("to_m_s", u.to)
          .end_object();
    }
    j.end_array();
  });
  write_line_member(out, "damping_threshold", [&](JsonWriter& j) { j.value(r.damping_threshold); });
  write_line_member(out, "threshold_speed_m_s", [&](JsonWriter& j) { j.value(r.threshold_speed); });
  write_line_member(out, "threshold_speed_kmh", [&](JsonWriter& j) {
    j.value(r.threshold_speed ? std::optional<double>(*r.threshold_speed * kKmh) : none);
  });
  write_line_member(out, "threshold_branch", [&](JsonWriter& j) {
    r.threshold_speed ? j.value(r.threshold_branch) : j.value(nullptr);
  });
  write_line_member(out, "below_threshold_at_lowest_speed", [&](JsonWriter& j) {
    j.begin_array();
    for (const std::string& name : r.below_threshold_at_lowest_speed) {
      std::optional<double> zeta;
      for (const HuntingBranch& b : r.branches)
        if (b.name == name && !b.damping_ratio.empty()) zeta = b.damping_ratio.front();
      j.begin_object().member("branch", name).member("damping_ratio", zeta).end_object();
    }
    j.end_array();
  });
  write_line_member(out, "conicity_curve", [&](JsonWriter& j) {
    j.begin_array();
    for (const ConicityPoint& c : r.conicity_curve) {
      j.begin_object().member("conicity", c.conicity).key("critical");
      write_critical(j, c.critical);
      j.member("verdict", to_string(c.verdict)).end_object();
    }
    j.end_array();
  });
  write_line_member(out, "contacts", [&](JsonWriter& j) {
    j.begin_array();
    for (const ResolvedContact& c : r.contacts) write_contact(j, c);
    j.end_array();
  });
  write_line_member(out, "dofs", [&](JsonWriter& j) { j.value(r.dofs); });
  write_line_member(out, "speeds_m_s", [&](JsonWriter& j) { j.value(r.speeds); });
  write_line_member(out, "speeds_kmh", [&](JsonWriter& j) {
    j.begin_array();
    for (double v : r.speeds) j.value(v * kKmh);
    j.end_array();
  });
  report::write_last_line_array(out, "branches", r.branches, write_branch);
}

}  // namespace

void write_hunting_stability(std::ostream& out, const HuntingResult& result, OutputFormat format) {
  write_hunting_stability(out, result, format, "", Provenance{});
}

void write_hunting_stability(std::ostream& out, const HuntingResult& result, OutputFormat format,
                             const std::string& vehicle, const Provenance& provenance) {
  const Page page{result, vehicle.empty() ? std::string("vehicle") : vehicle, provenance};
  report::write_in_format(
      format, "write_hunting_stability", [&] { write_table(out, page); }, [&] { write_csv(out, result); },
      [&] { write_json(out, page); }, [&] { write_markdown(out, page); }, [&] { write_html(out, page); });
}

}  // namespace railmodal
