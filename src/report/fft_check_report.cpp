// The fft-check for people (table, an HTML page with plots) and programs (CSV, JSON).
#include "railmodal/fft_check_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/document_table.hpp"
#include "report/json_writer.hpp"
#include "report/number_text.hpp"
#include "report/svg_chart.hpp"
#include "report/text_format.hpp"
#include "report/unwritten_format.hpp"
#include "shortest_text.hpp"

namespace railmodal {

using report::fixed;
using report::html_escape;

namespace {

// Histories are drawn from at most this many points per line: a 20 s record at 1 ms is
// 20 001 samples, more than a 500 px plot can show, and the page stays small.
constexpr Eigen::Index kMaxPlotPoints = 4000;
// Event lines stop being readable beyond this many.
constexpr size_t kMaxEventLines = 24;

bool is_rotation(const std::string& dof) {
  return dof.find(".pitch") != std::string::npos || dof.find(".roll") != std::string::npos ||
         dof.find(".yaw") != std::string::npos;
}

// The first ten periods of the lowest checked mode (all of a shorter record): long records of
// several DOFs are a solid band at page width; the spectra cover the whole record.
double shown_duration(const FftCheckResult& r) {
  const double end = r.history.time(r.history.time.size() - 1);
  double lowest = 0.0;
  for (const auto& c : r.checks)
    if (c.modal_hz > 0.0 && (lowest == 0.0 || c.modal_hz < lowest)) lowest = c.modal_hz;
  return lowest > 0.0 ? std::min(end, 10.0 / lowest) : end;
}

// The histories of the DOFs whose spectra were taken, translations (mm) or rotations (mrad):
// one unit on each chart's axis. Nothing when no DOF is of that kind.
std::optional<report::Chart> history_chart(const FftCheckResult& r, bool rotations) {
  report::Chart c;
  c.id = rotations ? "history-rotations" : "history-translations";
  c.title = rotations ? "Time histories: rotations" : "Time histories: translations";
  c.x_label = "time (s)";
  c.y_label = rotations ? "rotation (mrad)" : "displacement (mm)";
  const auto& h = r.history;
  const double until = shown_duration(r);
  Eigen::Index samples = 0;
  while (samples < h.time.size() && h.time(samples) <= until) ++samples;
  const Eigen::Index stride = std::max<Eigen::Index>(1, samples / kMaxPlotPoints);
  for (const auto& label : r.spectrum_dofs) {
    const auto at = std::find(h.labels.begin(), h.labels.end(), label);
    if (at == h.labels.end() || is_rotation(label) != rotations) continue;
    const Eigen::Index col = at - h.labels.begin();
    report::ChartSeries s;
    s.label = label;
    for (Eigen::Index i = 0; i < samples; i += stride) {
      s.x.push_back(h.time(i));
      s.y.push_back(1e3 * h.displacement(i, col));
    }
    c.series.push_back(std::move(s));
  }
  if (c.series.empty()) return std::nullopt;
  c.x_min = 0.0;
  c.x_max = until;
  if (!h.events.empty() && h.events.size() <= kMaxEventLines)
    for (const auto& e : h.events) c.lines.push_back({"", e.time, true, ""});
  return c;
}

report::Chart spectrum_chart(const FftCheckResult& r, size_t k) {
  const Spectrum& s = r.spectra[k];
  report::Chart c;
  c.id = "spectrum-" + std::to_string(k);
  c.title = "Amplitude spectrum of " + r.spectrum_dofs[k] + " (" + to_string(s.window) + " window)";
  c.x_label = "frequency (Hz)";
  c.y_label = is_rotation(r.spectrum_dofs[k]) ? "amplitude (mrad)" : "amplitude (mm)";
  double top = 0.0;
  for (const auto& check : r.checks) top = std::max(top, check.modal_hz);
  top = top > 0.0 ? 1.5 * top : s.sampling_rate / 2;
  report::ChartSeries line;
  line.label = r.spectrum_dofs[k];
  for (Eigen::Index b = 0; b < s.amplitude.size() && s.frequency(b) <= top; ++b) {
    line.x.push_back(s.frequency(b));
    line.y.push_back(1e3 * s.amplitude(b));
  }
  c.series.push_back(std::move(line));
  c.x_min = 0.0;
  c.x_max = top;
  for (const auto& check : r.checks) c.lines.push_back({std::to_string(check.mode), check.damped_hz, true, ""});
  return c;
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * fraction);
  return text;
}

std::string not_excited_text(const FftCheck& c) {
  char ratio[32];
  std::snprintf(ratio, sizeof ratio, "%.1e", c.modal_amplitude_ratio);
  return std::string("not excited (modal amplitude ") + ratio + " of the largest)";
}

// The run that would resolve the tolerance, rounded up to a readable number of seconds.
std::string needed_run(double seconds) {
  char text[48];
  std::snprintf(text, sizeof text, "a run of at least %.*f s", seconds < 10.0 ? 1 : 0,
                seconds < 10.0 ? std::ceil(10.0 * seconds) / 10.0 : std::ceil(seconds));
  return text;
}

// One check's verdict in words. A linear scene's line is held to its own width; a nonlinear
// scene's to FftCheck::kNonlinearTolerance of the mode where the record resolves that, and
// otherwise says why it was not checked (neither a pass nor a failure).
std::string verdict_text(const FftCheck& c, bool nonlinear) {
  using Outcome = FftCheck::Outcome;
  switch (c.outcome) {
    case Outcome::not_excited:
      return not_excited_text(c);
    case Outcome::no_line:
      return "not checked: no line within 3 resolutions (friction, a kink or the forcing moved it: see the half "
             "periods)";
    case Outcome::not_resolved:
      return "not checked: the record resolves only " + percent(c.resolution_hz / c.damped_hz) + " of f (needs ≤ " +
             percent(c.tolerance) + ": " + needed_run(c.needed_duration_s) + ")";
    case Outcome::not_applicable:
      return "not applicable: " + c.why_not_applicable;
    case Outcome::decayed:
      return "not checked: decayed: " + c.why_decayed;
    case Outcome::passed:
      return nonlinear ? "passed (within " + percent(c.tolerance) + ")" : "passed";
    case Outcome::failed:
      if (!c.peak_hz) return "FAILED: no line within 3 resolutions";
      return nonlinear ? "FAILED: " + percent(std::abs(c.rel_error)) + " off (tolerance " + percent(c.tolerance) + ")"
                       : "OUTSIDE the resolution";
  }
  return "";
}

// Whether the scene builds damping: its checks compare the damped frequencies.
bool damped(const FftCheckResult& r) {
  return std::any_of(r.checks.begin(), r.checks.end(), [](const FftCheck& c) { return c.damping_ratio > 0.0; });
}

// What a nonlinear scene's checks compare, and the verdict of all of them.
std::string compared_text(const FftCheckResult& r) {
  if (!r.nonlinear) {
    const bool others = std::any_of(r.checks.begin(), r.checks.end(), [](const FftCheck& c) {
      return c.outcome == FftCheck::Outcome::not_applicable || c.outcome == FftCheck::Outcome::decayed;
    });
    return std::string("compared: the spectral peak of each excited mode with its ") +
           (damped(r) ? "damped frequency (where its free response oscillates)" : "modal frequency") +
           ", within the line's width" +
           (others ? "; not where the peak is a forcing's line (its linear forced response, exact here, makes at "
                     "least a tenth of it) or the mode's free response has decayed under a tenth of the spectrum "
                     "there"
                   : "");
  }
  return std::string("compared: the spectral peak of each excited mode with its LINEAR ") +
         (damped(r) ? "damped frequency (the dampers' viscous part)" : "modal frequency") + ", within " +
         percent(FftCheck::kNonlinearTolerance) +
         " (friction moves the lines by √(1 ± φ), ≤ 4.3 % for φ ≤ 0.085), where the record resolves " +
         percent(FftCheck::kNonlinearTolerance) + " of f (line width ≤ " + percent(FftCheck::kNonlinearTolerance) +
         " of f) and shows a line that no forcing could have made; other modes are not checked" +
         (r.half_period_check ? "; and the half periods between turning points of a free friction decay with the "
                                "linear half period, within " + percent(r.half_period_check->tolerance) +
                                " (π/k₁, π/k₂ with k² = (1 ± φ)k₀², springs digest (51), (63))"
                              : "");
}

// The reason of the first check that no run could make (they share it in the bundled scenes:
// the ramp, or a forcing at the mode's frequency); the table says each one's.
std::string first_not_applicable(const FftCheckResult& r) {
  for (const auto& c : r.checks)
    if (c.outcome == FftCheck::Outcome::not_applicable) return c.why_not_applicable;
  return "";
}

// The first decayed mode's name and reason (what would check it holds for the others alike).
std::string first_decayed(const FftCheckResult& r) {
  for (const auto& c : r.checks)
    if (c.outcome == FftCheck::Outcome::decayed) return c.mode_name + ": " + c.why_decayed;
  return "";
}


// The half-period check of a free friction decay, in words.
std::string half_period_text(const FftCheckResult& r) {
  const FftCheckResult::HalfPeriodCheck& h = *r.half_period_check;
  return std::string(h.passed ? "" : "FAILED: ") + "the " + std::to_string(h.count) + " half periods of " +
         r.swings->dof + " between turning points within " + percent(h.worst_rel_error) + " of the linear " +
         fixed(r.linear_half_period_s, 4) + " s (tolerance " + percent(h.tolerance) + ")";
}

// Why the checks not made were not: "2 not resolved: a run of at least 31 s; 1 no line".
std::string not_checked_reasons(const FftCheckResult& r) {
  using Outcome = FftCheck::Outcome;
  int not_excited = 0, not_resolved = 0, no_line = 0, not_applicable = 0, decayed = 0;
  double needed = 0.0;
  for (const auto& c : r.checks) {
    not_excited += c.outcome == Outcome::not_excited;
    no_line += c.outcome == Outcome::no_line;
    not_applicable += c.outcome == Outcome::not_applicable;
    decayed += c.outcome == Outcome::decayed;
    if (c.outcome == Outcome::not_resolved) ++not_resolved, needed = std::max(needed, c.needed_duration_s);
  }
  std::string text;
  const auto add = [&text](const std::string& part) { text += (text.empty() ? "" : "; ") + part; };
  if (not_resolved) add(std::to_string(not_resolved) + " not resolved: " + needed_run(needed));
  if (no_line) add(std::to_string(no_line) + " no line");
  if (not_applicable) add(std::to_string(not_applicable) + " not applicable: " + first_not_applicable(r));
  if (decayed) add(std::to_string(decayed) + " decayed, " + first_decayed(r));
  if (not_excited) add(std::to_string(not_excited) + " not excited");
  return text;
}

// The verdict of all the checks: how many were made and passed, and how many were not, and why.
std::string fft_check_verdict_text(const FftCheckResult& r) {
  const int spectral_checked = r.checked - (r.half_period_check ? 1 : 0);
  const size_t not_checked = r.checks.size() - static_cast<size_t>(spectral_checked);
  const std::string rest =
      not_checked ? "; " + std::to_string(not_checked) + " not checked (" + not_checked_reasons(r) + ")" : "";
  const std::string made = std::to_string(spectral_checked) + " of " + std::to_string(r.checks.size()) + " modes checked";
  const std::string halves = r.half_period_check ? "; " + half_period_text(r) : "";
  const int spectral_failed = r.failed - (r.half_period_check && !r.half_period_check->passed ? 1 : 0);
  if (r.failed > 0)
    return "FAILED: " + made + ", " + std::to_string(spectral_failed) +
           (spectral_failed == 1 ? " outside its tolerance" : " outside their tolerances") + halves + rest;
  if (r.checked == 0) return "NOT CHECKED: no mode's line could be checked (" + not_checked_reasons(r) + ")";
  const std::string within =
      r.nonlinear ? "within " + percent(FftCheck::kNonlinearTolerance) : "each within its line's width";
  if (spectral_checked == 0)  // the half periods alone
    return "passed: " + half_period_text(r) + "; no mode's line could be checked (" + not_checked_reasons(r) + ")";
  return "passed: " + made + ", " + within + halves + rest;
}

std::string overall_verdict(const FftCheckResult& r) { return "verdict: " + fft_check_verdict(r); }

// The verdict for programs: "passed", "FAILED" or "not checked".
std::string verdict_word(const FftCheckResult& r) {
  return r.failed > 0 ? "FAILED" : r.checked == 0 ? "not checked" : "passed";
}

void checks_table(std::ostream& out, const FftCheckResult& r) {
  out << "<table><tr><th>#</th><th>mode</th><th>dof</th><th>" << (damped(r) ? "damped" : "modal")
      << " [Hz]</th><th>peak [Hz]</th><th>rel. error</th>"
         "<th>resolution [Hz]</th><th>check</th></tr>\n";
  for (const auto& c : r.checks) {
    const bool failed = c.outcome == FftCheck::Outcome::failed;
    out << "<tr><td class=n>" << c.mode << "</td><td>" << html_escape(c.mode_name) << "</td><td>" << html_escape(c.dof)
        << "</td><td class=n>" << fixed(c.damped_hz, 4) << "</td>";
    if (c.peak_hz) {
      std::ostringstream rel;
      rel << std::scientific << std::setprecision(2) << c.rel_error;
      out << "<td class=n>" << fixed(*c.peak_hz, 4) << "</td><td class=n>" << rel.str() << "</td><td class=n>"
          << fixed(c.resolution_hz, 4) << "</td><td>" << (failed ? "<b>" : "")
          << html_escape(verdict_text(c, r.nonlinear)) << (failed ? "</b>" : "") << "</td>";
    } else {
      out << "<td class=n>—</td><td></td><td></td><td>" << html_escape(verdict_text(c, r.nonlinear)) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</table>\n";
}

// A swing driven steadily (a wagon at resonance whose leaf friction holds it at one amplitude)
// turns at the same two displacements, the same half periods apart, for the whole record: 68
// rows of 0.2946 s (user audit 2026-11-28b, F9 c). The tables show such a run once; the CSV and
// JSON keep every turn. Row i repeats when its displacement and half period, as the tables print
// them (6 and 4 decimals), are row i − 2's. A run of repeats, rows `first` to `last` (from 0),
// is shown as one line and then its last row, which says where the record ends.
struct RepeatedRows {
  size_t first = 0, last = 0;
};

std::vector<RepeatedRows> repeated_rows(const Swings& w) {
  const std::vector<double> halves = w.half_periods_between_turns();
  const auto printed = [&](size_t i) { return fixed(w.turning_values[i], 6) + " " + fixed(halves[i - 1], 4); };
  std::vector<RepeatedRows> runs;
  for (size_t i = 3; i < w.turning_times.size(); ++i) {  // row 0 has no half period, so row 1 no row to repeat
    if (printed(i) != printed(i - 2)) continue;
    if (!runs.empty() && runs.back().last + 1 == i)
      runs.back().last = i;
    else
      runs.push_back({i, i});
  }
  // A run hides all but its last row; under four hidden rows a line in their place would save
  // little and show less (two rows of a decay that has just settled).
  constexpr size_t kFewestHidden = 4;
  runs.erase(std::remove_if(runs.begin(), runs.end(),
                            [](const RepeatedRows& r) { return r.last - r.first < kFewestHidden; }),
             runs.end());
  return runs;
}

// The run that hides row i (all but a run's last row), or null.
const RepeatedRows* hiding(const std::vector<RepeatedRows>& runs, size_t i) {
  for (const RepeatedRows& r : runs)
    if (i >= r.first && i < r.last) return &r;
  return nullptr;
}

// "rows 5–67: as the two rows above them, repeated (a steady swing)", numbered from 1.
std::string repeated_text(const RepeatedRows& r) {
  return "rows " + std::to_string(r.first + 1) + "–" + std::to_string(r.last) +
         ": as the two rows above them, repeated (a steady swing)";
}

void swings_table(std::ostream& out, const FftCheckResult& r) {
  const Swings& w = *r.swings;
  out << "<h2>Half periods (nonlinear scene)</h2>\n<p>Friction and kinks broaden the spectral lines; the half periods of <code>"
      << html_escape(w.dof) << "</code> are read between its turning points instead (linear: " << fixed(r.linear_half_period_s, 4)
      << " s).</p>\n<table><tr><th>#</th><th>turn at [s]</th><th>displacement</th><th>half period [s]</th></tr>\n";
  const auto halves = w.half_periods_between_turns();
  const std::vector<RepeatedRows> runs = repeated_rows(w);
  for (size_t i = 0; i < w.turning_times.size(); ++i) {
    if (const RepeatedRows* run = hiding(runs, i)) {
      if (i == run->first) out << "<tr><td></td><td colspan=3>" << repeated_text(*run) << "</td></tr>\n";
      continue;
    }
    out << "<tr><td class=n>" << i + 1 << "</td><td class=n>" << fixed(w.turning_times[i], 4) << "</td><td class=n>"
        << fixed(w.turning_values[i], 6) << "</td><td class=n>" << (i > 0 ? fixed(halves[i - 1], 4) : "") << "</td></tr>\n";
  }
  out << "</table>\n";
  if (w.comes_to_rest) out << "<p>Then at rest: a spring has stuck in its dead band.</p>\n";
  const auto crossings = w.half_periods_between_crossings();
  if (!crossings.empty()) {
    out << "<p>Half periods between passes through the static position [s]:";
    for (size_t i = 0; i < crossings.size() && i < 12; ++i) out << " " << fixed(crossings[i], 4);
    if (crossings.size() > 12) out << " … (" << crossings.size() << " in all)";
    out << "</p>\n";
  }
}

// Members in alphabetical order, as the files had them (json_writer.hpp).
void write_json_check(report::JsonWriter& j, const FftCheck& c) {
  const std::optional<double> none;
  j.begin_object();
  // The mode's frequencies under the names `modes --damped` gives them (damped_frequency_hz,
  // undamped_frequency_hz), the spectral line's as a frequency too (peak_frequency_hz).
  j.member("checked", c.checked()).member("damped_frequency_hz", c.damped_hz).member("damping_ratio", c.damping_ratio);
  j.member("dof", c.dof).member("excited", c.excited);
  j.member("modal_amplitude_ratio", c.modal_amplitude_ratio);
  j.member("mode", c.mode).member("mode_name", c.mode_name).member("outcome", to_string(c.outcome));
  j.member("passed", c.outcome == FftCheck::Outcome::passed);
  j.member("peak_frequency_hz", c.peak_hz ? std::optional<double>(*c.peak_hz) : none);
  j.member("rel_error", c.peak_hz ? std::optional<double>(c.rel_error) : none);
  j.member("resolution_hz", c.resolution_hz).member("tolerance", c.tolerance);
  j.member("undamped_frequency_hz", c.modal_hz);
  if (c.outcome == FftCheck::Outcome::decayed) j.member("why_decayed", c.why_decayed);
  if (c.outcome == FftCheck::Outcome::not_applicable) j.member("why_not_applicable", c.why_not_applicable);
  j.member("within_resolution", c.within_resolution);
  j.end_object();
}

void write_json(std::ostream& out, const FftCheckResult& r, const Scene& scene, const Vehicle& vehicle) {
  report::JsonWriter j(out);
  j.begin_object();
  j.member("checked", r.checked > 0);
  j.key("checks").begin_array();
  for (const auto& c : r.checks) write_json_check(j, c);
  j.end_array();
  j.member("checks_failed", r.failed).member("checks_made", r.checked).member("compared", compared_text(r));
  if (r.half_period_check) {
    const FftCheckResult::HalfPeriodCheck& h = *r.half_period_check;
    j.key("half_period_check").begin_object();
    j.member("count", h.count).member("passed", h.passed).member("tolerance", h.tolerance);
    j.member("worst_rel_error", h.worst_rel_error);
    j.end_object();
  }
  if (r.swings) {
    const Swings& w = *r.swings;
    j.key("half_periods").begin_object();
    j.member("between_crossings_s", w.half_periods_between_crossings());
    j.member("between_turning_points_s", w.half_periods_between_turns());
    j.member("comes_to_rest", w.comes_to_rest).member("dof", w.dof);
    j.member("linear_half_period_s", r.linear_half_period_s);
    j.key("turning_points").begin_array();
    for (size_t i = 0; i < w.turning_times.size(); ++i)
      j.begin_object().member("displacement", w.turning_values[i]).member("time_s", w.turning_times[i]).end_object();
    j.end_array();
    j.end_object();
  }
  j.member("nonlinear", r.nonlinear).member("passed", r.passed).member("scene", scene.name);
  j.key("unsimulated_parts").begin_array();
  for (const std::string& part : unsimulated_parts(scene, vehicle)) j.value(part);
  j.end_array();
  j.member("verdict", verdict_word(r)).member("verdict_text", fft_check_verdict(r));
  j.end_object();
}

void write_csv(std::ostream& out, const FftCheckResult& r) {
  using report::csv_heading;
  using report::number_text;
  out << "mode,mode_name,dof," << csv_heading("undamped_frequency", "Hz") << "," << csv_heading("damped_frequency", "Hz")
      << ",damping_ratio," << csv_heading("peak_frequency", "Hz") << ",rel_error,"
      << csv_heading("resolution", "Hz")
      << ",within_resolution,excited,modal_amplitude_ratio,tolerance,outcome,checked,passed,verdict\n";
  for (const auto& c : r.checks)
    out << c.mode << ",\"" << c.mode_name << "\"," << c.dof << "," << number_text(c.modal_hz) << ","
        << number_text(c.damped_hz) << "," << number_text(c.damping_ratio) << ","
        << (c.peak_hz ? number_text(*c.peak_hz) : "") << "," << (c.peak_hz ? number_text(c.rel_error) : "") << ","
        << number_text(c.resolution_hz) << "," << (c.within_resolution ? "true" : "false") << ","
        << (c.excited ? "true" : "false") << "," << number_text(c.modal_amplitude_ratio) << ","
        << number_text(c.tolerance) << "," << to_string(c.outcome) << "," << (c.checked() ? "true" : "false")
        << "," << (c.outcome == FftCheck::Outcome::passed ? "true" : "false") << "," << verdict_word(r) << "\n";
}

// Nonlinear scenes, in the table: the turning points of the swinging DOF and the half periods
// between them.
void swings_text(std::ostream& out, const FftCheckResult& r) {
  const Swings& w = *r.swings;
  out << std::right << "\nnonlinear scene: spectral lines are broadened; the half periods of " << w.dof
      << " (linear: " << std::fixed << std::setprecision(4) << r.linear_half_period_s << " s)\n"
      << std::setw(5) << "#" << std::setw(14) << "turn at [s]" << std::setw(16) << "displacement" << std::setw(18)
      << "half period [s]" << "\n";
  const auto halves = w.half_periods_between_turns();
  const std::vector<RepeatedRows> runs = repeated_rows(w);
  for (size_t i = 0; i < w.turning_times.size(); ++i) {
    if (const RepeatedRows* run = hiding(runs, i)) {
      if (i == run->first) out << "      " << repeated_text(*run) << "\n";
      continue;
    }
    out << std::setw(5) << i + 1 << std::setw(14) << std::setprecision(4) << w.turning_times[i] << std::setw(16)
        << std::setprecision(6) << w.turning_values[i];
    if (i > 0) out << std::setw(18) << std::setprecision(4) << halves[i - 1];
    out << "\n";
  }
  if (w.comes_to_rest) out << "      then at rest (a stuck spring)\n";
  const auto crossings = w.half_periods_between_crossings();
  if (!crossings.empty()) {
    out << "half periods between passes through the static position [s]:";
    for (size_t i = 0; i < crossings.size() && i < 8; ++i) out << " " << std::setprecision(4) << crossings[i];
    if (crossings.size() > 8) out << " … (" << crossings.size() << " in all)";
    out << "\n";
  }
}

void write_table(std::ostream& out, const FftCheckResult& r, const Scene& scene, const Vehicle& vehicle) {
  out << "railmodal fft-check: " << scene.name << "\n"
      << "spectra: Hann window, zero-padded x4, of " << r.history.time.size() << " samples at "
      << 1.0 / scene.simulation->time_step << " Hz\n";
  // In the header, where it is read before the checks it explains (an undamped resonance).
  for (const std::string& part : unsimulated_parts(scene, vehicle)) out << "warning: " << part << "\n";
  out << "\n";
  out << std::left << std::setw(5) << "#" << std::setw(32) << "mode" << std::setw(16) << "dof" << std::right
      << std::setw(11) << (damped(r) ? "damped [Hz]" : "modal [Hz]") << std::setw(11) << "peak [Hz]" << std::setw(12)
      << "rel. error" << std::setw(13) << "resol. [Hz]" << "  check\n";
  for (const auto& c : r.checks) {
    out << std::left << std::setw(5) << c.mode << std::setw(32) << c.mode_name << std::setw(16) << c.dof << std::right
        << std::fixed << std::setprecision(4) << std::setw(11) << c.damped_hz;
    if (c.peak_hz)
      out << std::setw(11) << *c.peak_hz << std::scientific << std::setprecision(2) << std::setw(12) << c.rel_error
          << std::fixed << std::setprecision(4) << std::setw(13) << c.resolution_hz << "  "
          << verdict_text(c, r.nonlinear);
    else
      out << std::setw(11) << "—" << std::setw(12) << "" << std::setw(13) << ""
          << "  " << verdict_text(c, r.nonlinear);
    out << "\n";
  }
  if (r.swings) swings_text(out, r);
  // The verdict last, below everything it judges (README: every report ends with it).
  out << (r.swings ? "\n" : "") << compared_text(r) << "\n" << overall_verdict(r) << "\n";
}

void write_html(std::ostream& out, const FftCheckResult& r, const Scene& scene, const Vehicle& vehicle,
                const Provenance& provenance) {
  report::write_html_head(out, "FFT check: " + scene.name);
  out << "<h1>FFT check: " << html_escape(scene.name) << "</h1>\n<p>Vehicle <b>" << html_escape(vehicle.name)
      << "</b> (<code>" << html_escape(scene.vehicle_file) << "</code>). ";
  const auto& sim = *scene.simulation;
  out << fixed(sim.duration, 3) << " s at a step of " << fixed(1e3 * sim.time_step, 3) << " ms";
  if (sim.speed > 0.0) out << ", " << shortest_text(sim.speed * 3.6, 6) << " km/h";
  out << "; effects: ";
  if (sim.effects.empty()) out << "none (the linear, undamped model)";
  for (size_t i = 0; i < sim.effects.size(); ++i) out << (i ? ", " : "") << html_escape(sim.effects[i]);
  out << ".</p>\n";
  for (const std::string& part : unsimulated_parts(scene, vehicle))
    out << "<p><b>Warning:</b> " << html_escape(part) << ".</p>\n";
  if (!r.spectra.empty()) {
    const Spectrum& s = r.spectra.front();
    out << "<p>Spectra: " << to_string(s.window) << " window, " << s.signal_length << " samples zero-padded to "
        << s.transform_length << " (bin spacing " << fixed(s.bin_spacing, 4) << " Hz, resolution fs/N = "
        << fixed(s.resolution, 4) << " Hz); peak amplitudes of the displacement less its mean.</p>\n";
  }
  out << "<h2>Checks</h2>\n";
  checks_table(out, r);
  if (r.swings) swings_table(out, r);
  out << "<h2>Time histories</h2>\n";
  for (bool rotations : {false, true})
    if (const auto chart = history_chart(r, rotations)) out << report::svg_chart(*chart) << "\n";
  out << "<p>";
  if (shown_duration(r) < r.history.time(r.history.time.size() - 1))
    out << "The first " << fixed(shown_duration(r), 2) << " s (ten periods of the lowest mode) of the record. ";
  if (!r.history.events.empty() && r.history.events.size() <= kMaxEventLines)
    out << "Dotted lines: the " << r.history.events.size() << " stick/slip/kink events. ";
  else if (!r.history.events.empty())
    out << r.history.events.size() << " stick/slip/kink events, too many to mark (<code>railmodal simulate --format json</code> "
        << "lists them). ";
  out << "</p>\n<h2>Spectra</h2>\n<p>Dotted lines: the modal frequencies, numbered as in the checks.</p>\n";
  for (size_t k = 0; k < r.spectra.size(); ++k) out << report::svg_chart(spectrum_chart(r, k)) << "\n";
  // The verdict last, below everything it judges.
  out << "<h2>Verdict</h2>\n<p>" << html_escape(compared_text(r)) << ". <b>" << html_escape(overall_verdict(r))
      << "</b></p>\n";
  report::write_html_footer(out, "fft-check", provenance);
}

}  // namespace

std::string fft_check_verdict(const FftCheckResult& result) { return fft_check_verdict_text(result); }

void write_fft_check(std::ostream& out, const FftCheckResult& result, const Scene& scene, const Vehicle& vehicle,
                     OutputFormat format, const Provenance& provenance) {
  switch (format) {
    case OutputFormat::table: write_table(out, result, scene, vehicle); break;
    case OutputFormat::csv: write_csv(out, result); break;
    case OutputFormat::json: write_json(out, result, scene, vehicle); break;
    case OutputFormat::html: write_html(out, result, scene, vehicle, provenance); break;
    default:
      throw std::invalid_argument(report::unwritten_format("write_fft_check", "table, csv, json or html", format));
  }
}

}  // namespace railmodal
