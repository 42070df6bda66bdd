// The whole critical-speed study of a scene: modes, resonances, amplitude curves.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>

#include "railmodal/critical_speed.hpp"
#include "railmodal/errors.hpp"
#include "model/scene_fit.hpp"
#include "response/critical_speed_study.hpp"
#include "response/curve_peaks.hpp"
#include "shortest_text.hpp"
#include "solve/modal_solver.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

// The scene's own grid, ascending and without repeats. Kept per thread for the range it was
// made for: a study's variants share their scene's range, and each made the same 341 points.
const std::vector<double>& scene_grid(const Scene& scene) {
  struct Kept {
    double min = std::nan(""), max = std::nan(""), step = std::nan("");  // NaN: nothing kept yet
    std::vector<double> values;
  };
  thread_local Kept kept;
  if (kept.min == scene.min_speed && kept.max == scene.max_speed && kept.step == scene.speed_step) return kept.values;
  std::vector<double>& grid = kept.values;
  grid.clear();
  const int steps = static_cast<int>(std::ceil((scene.max_speed - scene.min_speed) / scene.speed_step - 1e-9));
  grid.reserve(static_cast<size_t>(steps) + 1);  // one allocation, not a doubling per few points
  for (int i = 0; i <= steps; ++i) grid.push_back(std::min(scene.min_speed + i * scene.speed_step, scene.max_speed));
  if (!std::is_sorted(grid.begin(), grid.end())) std::sort(grid.begin(), grid.end());  // a scene made in code
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  kept.min = scene.min_speed, kept.max = scene.max_speed, kept.step = scene.speed_step;
  return grid;
}

constexpr double kPeakTolerance = 1e-6;  // relative, in speed: far below any grid a user would plot

// The largest bounded amplitude of a curve (0 if none): a function of its own, so that the
// running maximum stays in a register rather than in the caller's frame.
double largest_bounded(const AmplitudeCurve& curve) {
  const auto& a = curve.amplitudes;
  double largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    if (!curve.unbounded[i]) largest = std::max(largest, a[i]);
  return largest;
}

// Local maxima of a curve, refined between their grid neighbours; a maximum beside an
// unbounded (undamped) point has no finite peak to refine and is left out, but the other
// peaks of the same curve are not.
std::vector<Peak> refine_peaks(const CriticalSpeedStudy& study, const ExcitationSource& source,
                               const OutputRequest& output, const AmplitudeCurve& curve) {
  std::vector<Peak> peaks;
  const auto& a = curve.amplitudes;
  if (a.size() < 3) return peaks;
  double largest = -1.0;  // largest_bounded (≥ 0) once a bounded maximum needs it: many curves have none
  // The amplitudes first (next_local_maximum): the flags are bits, slow to read.
  for (size_t i = response::next_local_maximum(a.data(), 1, a.size()); i + 1 < a.size();
       i = response::next_local_maximum(a.data(), i + 1, a.size())) {
    if (curve.unbounded[i - 1] || curve.unbounded[i] || curve.unbounded[i + 1]) continue;
    if (largest < 0.0) largest = largest_bounded(curve);
    if (a[i] >= 0.01 * largest) {
      const Peak p = refine_peak(study.system, study.modes, source, output, curve.speeds[i - 1], curve.speeds[i + 1],
                                 kPeakTolerance, study.scene.friction_reference_amplitude);
      if (!p.unbounded) peaks.push_back(p);
    }
  }
  return peaks;
}

// Solves the assembled vehicle; a vehicle with an unstable mode has no steady response.
// With `naming` deferred only an unstable mode is named, for its error.
void solve_stable_modes(const Scene& scene, solve::ModeNaming naming, CriticalSpeedStudy* study) {
  if (study->system.size() == 0) throw std::invalid_argument("no free degrees of freedom in the chosen set");
  check_scene_fits(scene, study->system);
  model::refuse_scene_series_dampers(scene, study->system, "critical speeds");
  // Into the modes the study holds: a study's worker hands it the previous variant's, whose
  // storage serves again (evaluate_variant.cpp); a fresh study's are empty.
  solve::solve_modes_into(study->system, ModalOptions{}, &study->modes, naming);
  for (Mode& m : study->modes.modes)
    if (m.kind == ModeKind::unstable) {
      if (naming == solve::ModeNaming::deferred) solve::name_mode(solve::ModeNamer(study->system), &m);
      throw NumericalError("mode " + std::to_string(m.index) + " (" + m.name + ") is unstable (divergence rate " +
                           shortest_text(m.divergence_rate, 4) +
                           " 1/s): the vehicle has no steady response to harmonic input; see railmodal modes");
    }
}

// The scene's outputs, or (if it names none) the DOF reported for each critical speed.
std::vector<OutputRequest> curve_outputs(const Scene& scene, const CriticalSpeedStudy& study) {
  std::vector<OutputRequest> outputs;
  for (const auto& o : scene.outputs)
    outputs.push_back({study.system.index_of(o.dof), o.quantity});  // check_scene_fits checked
  if (outputs.empty()) {
    std::set<std::string> seen;
    for (const auto& r : study.critical_speeds)
      if (seen.insert(r.output).second) outputs.push_back({study.system.index_of(r.output), ResponseQuantity::displacement});
    if (outputs.empty()) outputs.push_back({0, ResponseQuantity::displacement});
  }
  return outputs;
}

// The curves hold sources × outputs × speeds points, and the grid holds every source's
// critical speeds, so a scene's curves grow as the square of its sources (200 rail-joint
// sources: 1000 curves of 1341 speeds, 113 MB of JSON; 2000: 1.45 GB). Refused before the
// sweep above kMaxCurvePoints: about 3 GB while the JSON report is written (some 300 bytes a
// point measured, where the study itself holds 17), and 10 times the points of a bundled
// scene's largest grid (a [speed] range of 10⁶ steps for one source and output).
constexpr double kMaxCurvePoints = 1e7;
constexpr double kReportBytesPerPoint = 300.0;

void check_curve_points(size_t sources, size_t outputs, size_t speeds, size_t critical_speeds) {
  const double points = static_cast<double>(sources) * static_cast<double>(outputs) * static_cast<double>(speeds);
  if (points <= kMaxCurvePoints) return;
  char message[400];
  std::snprintf(message, sizeof message,
                "the amplitude curves would need about %.2g GB for %zu sources x %zu outputs x %zu speeds (the "
                "scene's grid and all %zu critical speeds) = %.3g points; the limit is %.0e points (about %.0f GB): "
                "give fewer sources or outputs, or a coarser [speed] step",
                points * kReportBytesPerPoint / 1e9, sources, outputs, speeds, critical_speeds, points, kMaxCurvePoints,
                kMaxCurvePoints * kReportBytesPerPoint / 1e9);
  throw std::invalid_argument(message);
}

// One source's curves over the whole grid, swept in chunks so that a long sweep reports its
// progress (`done` sweeps are finished before this one, of `total` speeds × sources).
std::vector<AmplitudeCurve> source_curves(const CriticalSpeedStudy& study, const ExcitationSource& source,
                                          int source_index, const std::vector<OutputRequest>& outputs,
                                          const std::vector<double>& speeds, double done, double total,
                                          const std::function<void(double)>& progress) {
  constexpr size_t kChunk = 4096;
  std::vector<AmplitudeCurve> curves;
  for (size_t first = 0; first < speeds.size(); first += kChunk) {
    // A grid of one chunk (every bundled scene's) is swept as it is, not copied per variant.
    const bool whole = first == 0 && speeds.size() <= kChunk;
    const std::vector<double> part_of_grid =
        whole ? std::vector<double>()
              : std::vector<double>(speeds.begin() + first, speeds.begin() + std::min(speeds.size(), first + kChunk));
    const std::vector<double>& chunk = whole ? speeds : part_of_grid;
    auto part = amplitude_curves(study.system, study.modes, source, source_index, outputs, chunk,
                                 study.scene.friction_reference_amplitude);
    if (curves.empty()) {
      curves = std::move(part);
    } else {
      for (size_t o = 0; o < curves.size(); ++o) {
        curves[o].amplitudes.insert(curves[o].amplitudes.end(), part[o].amplitudes.begin(), part[o].amplitudes.end());
        curves[o].unbounded.insert(curves[o].unbounded.end(), part[o].unbounded.begin(), part[o].unbounded.end());
        curves[o].phases_deg.insert(curves[o].phases_deg.end(), part[o].phases_deg.begin(), part[o].phases_deg.end());
      }
    }
    if (progress) progress((done + first + chunk.size()) / total);
  }
  return curves;
}

// What the study did, and the checks it inherits from its parts.
void summarise(CriticalSpeedStudy* study, double sweep_seconds, double peak_seconds) {
  AnalysisSummary& s = study->summary;
  s.stages.push_back({"amplitude curves", sweep_seconds});
  s.stages.push_back({"peak refinement", peak_seconds});
  s.analysis = "critical speeds and amplitude curves";
  s.method = "critical speeds where a source harmonic meets an excited mode; amplitude against speed on the "
             "scene's grid and every critical speed; peaks refined by golden-section search";
  s.checks.push_back({"modes: max relative residual", study->modes.max_residual, ModalOptions{}.max_residual,
                      study->modes.max_residual <= ModalOptions{}.max_residual});
  size_t unbounded = 0;
  for (const AmplitudeCurve& c : study->curves) unbounded += std::count(c.unbounded.begin(), c.unbounded.end(), true);
  s.checks.push_back({"curve points unbounded by an undamped resonance", static_cast<double>(unbounded),
                      std::numeric_limits<double>::infinity(), true});
}

}  // namespace

// The few critical speeds are sorted and each put in its place, the grid copied in runs between
// them: the same values as merging the two and removing repeats. A grid not ascending is sorted
// first (a Python user's array); the study's comes ascending (min(v₀ + i·Δv, v_max) never
// decreases) and is copied once.
std::vector<double> grid_with_critical_speeds(const std::vector<double>& given, const std::vector<CriticalSpeed>& rows) {
  std::vector<double> sorted;
  if (!std::is_sorted(given.begin(), given.end())) {
    sorted = given;
    std::sort(sorted.begin(), sorted.end());
  }
  const std::vector<double>& grid = sorted.empty() ? given : sorted;
  std::vector<double> critical;
  critical.reserve(rows.size());
  for (const auto& r : rows) critical.push_back(r.speed);
  std::sort(critical.begin(), critical.end());
  std::vector<double> speeds;
  speeds.reserve(grid.size() + critical.size());
  auto next = grid.begin();  // the first grid point not yet copied
  for (const double v : critical) {
    const auto at = std::lower_bound(next, grid.end(), v);
    speeds.insert(speeds.end(), next, at);
    next = at;
    const bool on_grid = at != grid.end() && *at == v;
    if (!on_grid && (speeds.empty() || speeds.back() != v)) speeds.push_back(v);  // else a repeat
  }
  speeds.insert(speeds.end(), next, grid.end());
  return speeds;
}

CriticalSpeedStudy study_critical_speeds(const Scene& scene, const Vehicle& vehicle,
                                         const std::function<void(double)>& progress) {
  return response::study_critical_speeds_of(scene, [&] { return assemble(vehicle, scene.dofs); }, progress);
}

CriticalSpeedStudy response::study_critical_speeds_of(const Scene& scene, const std::function<LinearSystem()>& assembled,
                                                      const std::function<void(double)>& progress) {
  CriticalSpeedStudy study;
  study_critical_speeds_into(scene, assembled, &study, progress);
  return study;
}

void response::study_critical_speeds_into(Scene given, const std::function<LinearSystem()>& assembled,
                                          CriticalSpeedStudy* into, const std::function<void(double)>& progress,
                                          StudyDetail detail) {
  model::refuse_ride_only_scene(given, "critical speeds");
  CriticalSpeedStudy& study = *into;
  const bool full = detail.rows == ResonanceDetail::full;
  StageClock clock(full ? &study.summary : nullptr);  // summary rows' callers keep their own summary
  study.scene = std::move(given);
  const Scene& scene = study.scene;
  study.system = assembled();
  solve_stable_modes(scene, detail.naming, &study);
  clock.lap("assembly and modes");

  std::vector<const ExcitationSource*> sources;
  for (const auto& s : scene.sources) sources.push_back(s.get());
  CriticalSpeedOptions options;
  options.min_speed = scene.min_speed;
  options.max_speed = scene.max_speed;
  options.friction_reference_amplitude = scene.friction_reference_amplitude;
  // Every row reports every output of the curves: the scene's, or (when it names none) the
  // DOFs the rows report, known only once they are found — then the rows are found again. A
  // scene that names its outputs finds them once (half the time of a study's critical speeds),
  // and so do summary rows, which report no outputs. The first finding feeds only the DOFs
  // (CriticalSpeed::output, set before the response): its rows are without their response
  // (a harmonic solve a resonance fewer), and a full study's are then found again in full,
  // which refuses a failing solve at the same resonance as before.
  if (scene.outputs.empty())
    study.critical_speeds =
        find_critical_speeds_in(study.system, study.modes, sources, options, ResonanceDetail::without_response);
  std::vector<OutputRequest> outputs = curve_outputs(scene, study);
  if (full || !scene.outputs.empty()) {
    options.outputs = outputs;
    study.critical_speeds = find_critical_speeds_in(study.system, study.modes, sources, options, detail.rows);
  }
  clock.lap("critical speeds");
  for (OutputRequest& o : outputs) o.phase = detail.phases == CurvePhases::kept;  // the curves' (the rows kept theirs)

  // The chunks' grids joined, shared by every curve: the scene's with every critical speed.
  const SpeedGrid grid(grid_with_critical_speeds(scene_grid(scene), study.critical_speeds));
  const std::vector<double>& speeds = grid.values();
  check_curve_points(sources.size(), outputs.size(), speeds.size(), study.critical_speeds.size());
  const double total = static_cast<double>(sources.size() * speeds.size());
  double sweep_seconds = 0.0, peak_seconds = 0.0;  // interleaved per source: timed apart
  using Clock = std::chrono::steady_clock;
  for (size_t s = 0; s < sources.size(); ++s) {
    const auto started = full ? Clock::now() : Clock::time_point{};
    std::vector<AmplitudeCurve> curves = source_curves(study, *sources[s], static_cast<int>(s), outputs, speeds,
                                                       static_cast<double>(s * speeds.size()), total, progress);
    const auto swept = full ? Clock::now() : Clock::time_point{};
    for (size_t o = 0; o < curves.size(); ++o) {
      curves[o].speeds = grid;
      study.curves.push_back(std::move(curves[o]));
      for (const Peak& p : refine_peaks(study, *sources[s], outputs[o], study.curves.back()))
        study.peaks.push_back({static_cast<int>(study.curves.size()) - 1, p});
    }
    if (!full) continue;
    sweep_seconds += std::chrono::duration<double>(swept - started).count();
    peak_seconds += std::chrono::duration<double>(Clock::now() - swept).count();
  }
  if (full) summarise(&study, sweep_seconds, peak_seconds);
}

}  // namespace railmodal
