// A scene's simulation with only its named effects, and the FFT check of its result.
#include "railmodal/scene_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "model/scene_fit.hpp"
#include "model/spring_stages.hpp"
#include "railmodal/damped_modal.hpp"
#include "railmodal/response.hpp"
#include "simulate/free_response.hpp"
#include "simulate/history_summary.hpp"
#include "simulate/record_memory.hpp"
#include "simulate/record_spectrum.hpp"
#include "simulate/sample_count.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

const char* to_string(FftCheck::Outcome outcome) {
  using Outcome = FftCheck::Outcome;
  switch (outcome) {
    case Outcome::passed: return "passed";
    case Outcome::failed: return "failed";
    case Outcome::not_excited: return "not excited";
    case Outcome::not_resolved: return "not resolved";
    case Outcome::no_line: return "no line";
    case Outcome::not_applicable: return "not applicable";
    case Outcome::decayed: return "decayed";
  }
  return "?";
}

std::optional<FftCheck::Outcome> fft_check_outcome_from_string(const std::string& word) {
  using Outcome = FftCheck::Outcome;
  for (Outcome o : {Outcome::passed, Outcome::failed, Outcome::not_excited, Outcome::not_resolved, Outcome::no_line,
                    Outcome::not_applicable, Outcome::decayed})
    if (word == to_string(o)) return o;
  return std::nullopt;
}

namespace {

bool names(const Scene& scene, const char* effect) {
  return scene.simulation &&
         std::find(scene.simulation->effects.begin(), scene.simulation->effects.end(), effect) != scene.simulation->effects.end();
}

// The DOF holding the largest share of the mode's kinetic energy: where the mode itself lives.
int most_energetic_dof(const Mode& mode) {
  int most_energetic = 0;
  mode.kinetic_energy_share.maxCoeff(&most_energetic);
  return most_energetic;
}

// The DOF on which a mode shows in the response: the largest product of the mode's kinetic
// energy share and the DOF's own motion. Usually the mode's most energetic DOF; not when
// repeated modes cancel there (two bogies pitching alike: a basis of the pair may put
// "antiphase" mostly on the bogie that the release leaves at rest, whose record is round-off).
int showing_dof(const Mode& mode, const Eigen::VectorXd& dof_energy) {
  int best = 0;
  for (int d = 1; d < mode.kinetic_energy_share.size(); ++d)
    if (mode.kinetic_energy_share(d) * dof_energy(d) > mode.kinetic_energy_share(best) * dof_energy(best)) best = d;
  return mode.kinetic_energy_share(best) * dof_energy(best) > 0.0 ? best : most_energetic_dof(mode);
}

// The DOF where a mode dominates the record (FftCheck::dof): the largest √M_dd·|φ_d| times
// min(1, |φ_d|·max|η|/max|x_d|), the share of the DOF's motion that the mode's coordinate can
// make, among the DOFs that move (√M_dd·max|x_d| at least FftCheck::kExcitedRatio of the most
// moving one's: a DOF the release leaves at rest holds round-off, where a repeated pair's basis
// may put a mode). Without the share, a DOF the forcing drives through another mode would win
// on the mode's shape alone and show that mode's lines, not this one's. √M_dd puts m and rad on
// one scale (the kinetic-energy scale of the mass-normalised shape). The most energetic DOF when
// nothing moves, or when the mode is not excited: its coordinate then holds round-off, and the
// score would pick whichever moving DOF its shape touches (the resort car's body pitch, left at
// rest by a bounce release, on bogie2.bounce); showing_dof, weighted by the record's motion,
// would too.
int dominant_dof(const Mode& mode, bool excited, double modal_amplitude, const Eigen::VectorXd& mass_diagonal,
                 const Eigen::VectorXd& motion) {
  if (!excited) return most_energetic_dof(mode);
  const Eigen::VectorXd scaled = mass_diagonal.cwiseMax(0.0).cwiseSqrt().cwiseProduct(motion);
  const double floor = FftCheck::kExcitedRatio * scaled.maxCoeff();
  int best = -1;
  double best_score = 0.0;
  for (int d = 0; d < motion.size(); ++d) {
    if (!(scaled(d) > floor)) continue;
    const double share = std::min(1.0, std::abs(mode.shape(d)) * modal_amplitude / motion(d));
    const double score = std::sqrt(mass_diagonal(d)) * std::abs(mode.shape(d)) * share;
    if (score > best_score) best = d, best_score = score;
  }
  return best >= 0 ? best : most_energetic_dof(mode);
}

// The analysis, the method and the counts of the checks (their stages are timed already).
void summarise_checks(FftCheckResult* out) {
  AnalysisSummary& s = out->summary;
  s.analysis = "spectral check of the modal frequencies";
  s.method = "simulated release or run, Hann-windowed spectra zero-padded ×4, nearest interpolated peak within 3 "
             "resolutions of each mode";
  const auto count = [out](bool (*keep)(const FftCheck&)) {
    return static_cast<double>(std::count_if(out->checks.begin(), out->checks.end(), keep));
  };
  const double checked = static_cast<double>(out->checks.size());
  const double excited = count([](const FftCheck& c) { return c.excited; });
  s.checks.push_back({"modes checked", checked, std::numeric_limits<double>::infinity(), true});
  s.checks.push_back({"modes excited, of those checked", excited, checked, true});
  s.checks.push_back({"excited modes with a spectral peak", count([](const FftCheck& c) { return c.peak_hz.has_value(); }),
                      excited, true});
  s.checks.push_back({"excited modes with the peak within its resolution",
                      count([](const FftCheck& c) { return c.within_resolution; }), excited, true});
  s.checks.push_back({"checks made (nonlinear: where the record resolves the tolerance)",
                      static_cast<double>(out->checked), std::numeric_limits<double>::infinity(), true});
  s.checks.push_back(
      {"checks failed (peak outside its tolerance)", static_cast<double>(out->failed), 0.0, out->failed == 0});
}

// Refuses, before the run, a record fft-check could not hold: the history of every DOF
// (displacement and velocity, 16 bytes a sample each), up to one spectrum each (2N + 1 bins:
// 16), and the transform's 72 and the modal products' 8 (with room to spare: 294 bytes a sample
// measured for 6 DOFs against 340 estimated).
void require_check_fits(const SimulationSpec& spec, int dofs, double memory_limit) {
  const double samples = static_cast<double>(simulate::sample_count(spec.duration, spec.time_step));
  simulate::require_record_fits("fft-check (the whole record of every DOF, for its transforms)", samples, dofs,
                                40.0 * dofs + 100.0, memory_limit);
}

// How much each oscillatory mode moves over the record: the largest |η| of its modal
// coordinate, and the mode that moves most.
struct ModalAmplitudes {
  std::vector<double> amplitude;  // per mode of the result; 0 for the non-oscillatory ones
  double most = 0.0;
  int most_mode = -1;
};

ModalAmplitudes modal_amplitudes(const LinearSystem& system, const ModalResult& modes, const TimeHistory& history) {
  ModalAmplitudes e;
  e.amplitude.assign(modes.modes.size(), 0.0);
  for (size_t r = 0; r < modes.modes.size(); ++r) {
    const Mode& mode = modes.modes[r];
    if (mode.kind != ModeKind::oscillatory) continue;
    const Eigen::VectorXd Mphi = system.mass * mode.shape;
    e.amplitude[r] = (history.displacement * Mphi).cwiseAbs().maxCoeff();
    if (e.amplitude[r] > e.most) e.most = e.amplitude[r], e.most_mode = static_cast<int>(r);
  }
  return e;
}

// Sets an excited mode's check's resolution from `spectrum`, and its peak: the peak nearest the
// modal frequency, when within 3 resolutions of it. Returns that peak's amplitude (the DOF's
// unit, m or rad; 0 without a peak).
double match_peak(const Spectrum& spectrum, FftCheck* check) {
  check->resolution_hz = spectrum.resolution;
  const double f = check->damped_hz;
  const SpectralPeak* nearest = nullptr;
  const auto peaks = find_peaks(spectrum);
  for (const auto& p : peaks)
    if (!nearest || std::abs(p.frequency - f) < std::abs(nearest->frequency - f)) nearest = &p;
  if (nearest && std::abs(nearest->frequency - f) <= 3.0 * std::max(nearest->resolution, spectrum.resolution)) {
    check->peak_hz = nearest->frequency;
    check->resolution_hz = std::max(nearest->resolution, spectrum.resolution);
    check->rel_error = (nearest->frequency - f) / f;
    check->within_resolution = std::abs(nearest->frequency - f) <= check->resolution_hz;
    return nearest->amplitude;
  }
  return 0.0;
}

// Holds the check to its tolerance: a linear scene's line within its own width (no line is a
// failure); a nonlinear scene's within FftCheck::kNonlinearTolerance of the mode, checked only
// where the record (of `record_s` seconds) resolves that finely and shows a line at all. The
// mode's frequency is the damped one, where its free response oscillates.
void judge(bool nonlinear, double record_s, FftCheck* check) {
  using Outcome = FftCheck::Outcome;
  const double f = check->damped_hz;
  check->tolerance = nonlinear ? FftCheck::kNonlinearTolerance : check->resolution_hz / f;
  if (!check->excited) {
    check->outcome = Outcome::not_excited;
  } else if (!nonlinear) {
    check->outcome = check->within_resolution ? Outcome::passed : Outcome::failed;
  } else if (!check->peak_hz) {
    check->outcome = Outcome::no_line;
  } else if (check->resolution_hz > check->tolerance * f) {
    check->outcome = Outcome::not_resolved;
    check->needed_duration_s = record_s * check->resolution_hz / (check->tolerance * f);
  } else {
    check->outcome = std::abs(check->rel_error) <= check->tolerance ? Outcome::passed : Outcome::failed;
  }
}

std::string hz_text(double hz) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f Hz", hz);
  return text;
}

// A peak found within its resolution of a forcing line is that line's when the scene's linear
// forced response there is at least 1/kForcedLineShare of the peak's amplitude; below, the
// line could have made only a small part of the peak, which is the mode's. The linear model
// understates a forced line near a nonlinear system's own frequency: Khanin's spring (springs
// Example 10) driven by 5 mm joints at its kinked line, 2.015 Hz, reads 81 mm where the linear
// response is 16.6 mm (4.9×). Ten is twice that, and a weak harmonic lies orders below (0.01 mm
// dips: 0.033 mm against the 18.5 mm release, 1.8e-3). The two-axle wagon's pitch at 75 km/h
// reads 1.02 mrad on the joints' line where the linear response is 1.06 (1.04×): the forcing's.
// A linear scene's forced line is exactly its H(ω)Q: the same share there holds a margin for
// the transient's leakage into the line and errs to "the forcing's" (not checked), never to a
// pass on the forcing's line. FftCheck::kForcedLineShare.
constexpr double kForcedLineShare = FftCheck::kForcedLineShare;

// The peak a check found, with what tells the forcing's line from the mode's: its amplitude on
// the check's DOF and the scene's linear system there.
struct FoundPeak {
  const LinearSystem& system;
  const ModalResult& modes;
  int dof = 0;
  double amplitude = 0.0;  // m or rad: the spectrum's peak amplitude (a steady tone's own)
};

// The amplitude on `peak.dof` of the scene's linear forced response to harmonic n of `source`
// at `speed`: |X_dof| of (K − ω²M + iωC)X = Q_n (harmonic_response: the named dampers, the
// springs at their linear rates), m or rad; infinite where an undamped mode the harmonic drives
// sits on its line and moves that DOF. "Drives" is judged against the source's whole load, as
// the critical speeds judge it (docs/scenes.md, "Which harmonics count").
double forced_line_amplitude(const FoundPeak& peak, const ExcitationSource& source, double speed, int n) {
  double source_norm2 = 0.0;
  for (int k = 1; k <= source.harmonic_count(); ++k)
    source_norm2 += generalized_load(peak.system, source.load(peak.system, speed, k)).squaredNorm();
  const HarmonicLoad load = source.load(peak.system, speed, n);
  const HarmonicResponse x = harmonic_response(peak.system, peak.modes, generalized_load(peak.system, load),
                                               load.frequency_hz, std::sqrt(source_norm2));
  if (unbounded_at(x, peak.modes, peak.dof)) return std::numeric_limits<double>::infinity();
  return std::abs(x.displacement(peak.dof));
}

// "the forcing's own line (rail_joints, 2·V/λ = 4.168 Hz)".
std::string forcing_line_name(const ExcitationSource& source, int n, double line) {
  return "the forcing's own line (" + source.kind() + ", " + (n == 1 ? "" : std::to_string(n) + "·") +
         "V/λ = " + hz_text(line) + ")";
}

// A constant-speed forcing's line (a harmonic n·V/λ of a source) within the check's tolerance of
// the mode, in words; empty when there is none. A peak there is the forcing's whatever the mode
// (the bundled scenes at a critical speed choose V so that it is), and the check would pass by
// construction; nor can a decayed transient be told from it there.
std::string forcing_line_at_mode(const Scene& scene, const FftCheck& check) {
  const SimulationSpec& spec = *scene.simulation;
  if (!(spec.speed > 0.0) || spec.final_speed > 0.0) return "";
  for (const auto& source : scene.sources)
    for (int n = 1; n <= source->harmonic_count(); ++n) {
      const double line = n * spec.speed / source->wavelength();
      if (std::abs(line - check.damped_hz) <= check.tolerance * check.damped_hz)
        return forcing_line_name(*source, n, line) +
               " lies within the tolerance of the mode: a peak there is the forcing's whatever the mode";
    }
  return "";
}

// Why no run of a scene, however long, could check `check`'s mode by its line (empty
// when a long enough one could). Asked of a check that found a peak (passed, failed, not
// resolved) and, for a speed ramp, of every excited mode:
//  - a speed ramp sweeps the forcing: the response is not stationary, and its spectrum is that
//    of the sweep (a band), not a line of the mode;
//  - a constant speed whose forcing has a line (a harmonic n·V/λ of a source) within the
//    tolerance of the mode: the peak is the forcing's whatever the mode (the bundled scenes at a
//    critical speed choose V so that it is), and the check would pass by construction;
//  - a constant speed whose forcing has a line within the peak's resolution of the peak found,
//    and whose linear forced response explains the peak's amplitude (at least
//    1/kForcedLineShare of it): the peak is that line, not the mode's. A line that could make
//    only a small part of the peak (a weak harmonic near the mode's own peak) does not take it
//    from the mode: the check is made;
//  - a release that comes to rest (a spring stuck in its dead band): its line is as wide as the
//    motion before, and a longer run adds only rest.
std::string why_no_run_could_check(const Scene& scene, const FftCheck& check, const std::optional<Swings>& swings,
                                   const FoundPeak& peak) {
  const SimulationSpec& spec = *scene.simulation;
  if (spec.final_speed > 0.0 && !scene.sources.empty()) {
    double low = std::numeric_limits<double>::infinity(), high = 0.0;
    for (const auto& source : scene.sources) {
      low = std::min(low, std::min(spec.speed, spec.final_speed) / source->wavelength());
      high = std::max(high, std::max(spec.speed, spec.final_speed) / source->wavelength());
    }
    return "a speed ramp: the forcing's V/λ sweeps " + hz_text(low) + " to " + hz_text(high) +
           ", so the response is not stationary and its spectrum is the sweep's, not the mode's line";
  }
  if (const std::string at = forcing_line_at_mode(scene, check); !at.empty()) return at;
  if (spec.speed > 0.0)
    for (const auto& source : scene.sources)
      for (int n = 1; n <= source->harmonic_count(); ++n) {
        const double line = n * spec.speed / source->wavelength();
        const std::string named = forcing_line_name(*source, n, line);
        // The peak found is the forcing's (within its resolution, and the linear forced response
        // there makes at least a share of its amplitude that nonlinearity cannot have made from
        // nothing), and the mode's is not there: a longer run narrows the forcing's line, it does
        // not make the mode's.
        if (check.peak_hz && std::abs(line - *check.peak_hz) <= check.resolution_hz &&
            kForcedLineShare * forced_line_amplitude(peak, *source, spec.speed, n) >= peak.amplitude)
          return "the peak found is " + named + ", not the mode's; a longer run only narrows it";
      }
  if (swings && swings->comes_to_rest && !swings->turning_times.empty() && check.outcome == FftCheck::Outcome::not_resolved) {
    char text[160];
    std::snprintf(text, sizeof text, "the motion comes to rest at %.2f s (a spring stuck in its dead band): its line is "
                  "as wide as the motion before, and a longer run adds only rest", swings->turning_times.back());
    return text;
  }
  return "";
}

// Why a linear scene's mode has no line of its own in the record (FftCheck::Outcome::decayed),
// or empty. Its free response, `free` (amplitude A at t = 0, decaying as e^{−σt}), would make a
// line of |φ_d|·A·g on the check's DOF in the Hann spectrum of a `record_s` record (g:
// hann_decay_gain, the window being near zero where the transient still is); when that is under
// 1/kForcedLineShare of what the spectrum holds at its frequency (the forced lines' leakage,
// other modes) the spectrum there is another's, and a peak read there would pass or fail the mode
// on someone else's line; under find_peaks' threshold (3 % of the largest line) no peak is sought
// and the mode would fail for want of one. Only where the decay is the cause: were |φ_d|·A itself
// under that floor, the mode is weak on this DOF, not decayed, and is checked as before.
std::string why_decayed(const FftCheck& check, const simulate::FreeMode& free, double shape_at_dof,
                        const Spectrum& spectrum, double record_s) {
  if (!check.excited || !(free.decay_rate > 0.0) || !(free.initial_amplitude > 0.0)) return "";
  const Eigen::Index bin = std::lround(free.damped_hz / spectrum.bin_spacing);
  if (bin >= spectrum.amplitude.size()) return "";
  // What a line must reach to be read as the mode's: a tenth of what the spectrum holds at its
  // frequency, and the share of the largest line above which find_peaks looks at all.
  const double largest = spectrum.amplitude.tail(spectrum.amplitude.size() - 1).maxCoeff();
  const double sought = PeakOptions{}.threshold * largest;
  const double floor = std::max(spectrum.amplitude(bin) / kForcedLineShare, sought);
  const double steady = std::abs(shape_at_dof) * free.initial_amplitude;  // its line, were it not to decay
  const double line = steady * simulate::hann_decay_gain(free.decay_rate, record_s);
  if (line >= floor || steady < floor) return "";
  // Only a free release is advised: a record short enough for the decay (a few 1/σ) has a
  // resolution 1/T too coarse to tell the mode from the forcing's lines (review 2026-11-27).
  char text[520];
  std::snprintf(text, sizeof text,
                "its free response (ζ = %.3f) falls as e^{−%.3g t}, to 1 %% of its start by %.3g s; in the Hann "
                "spectrum of the %.3g s record its line would be %.1e of the largest (%s): a free release (no "
                "[[source]], [[simulation.initial]] displacing the mode) checks it",
                free.damping_ratio, free.decay_rate, std::log(100.0) / free.decay_rate, record_s, line / largest,
                floor == sought ? "peaks are sought above 3 % of it" : "under a tenth of the spectrum at its frequency");
  return text;
}

// A free friction decay's half periods between turning points against the linear half period
// (FftCheckResult::half_period_check): where it applies, else nothing.
// The largest relative friction φ of the vehicle's leaf springs (0 without any).
double largest_leaf_friction(const Vehicle& vehicle) {
  double phi = 0.0;
  model::each_spring_stage(vehicle, [&](const SpringStage& stage) { phi = std::max(phi, stage.relative_friction); });
  return phi;
}

std::optional<FftCheckResult::HalfPeriodCheck> check_half_periods(const Scene& scene, const Vehicle& vehicle,
                                                                  const FftCheckResult& r) {
  const NonlinearEffects effects = scene_effects(scene);
  const int excited = static_cast<int>(
      std::count_if(r.checks.begin(), r.checks.end(), [](const FftCheck& c) { return c.excited; }));
  if (!scene.sources.empty() || !effects.leaf_friction || effects.progressive_springs || excited != 1 || !r.swings)
    return std::nullopt;
  const std::vector<double> halves = r.swings->half_periods_between_turns();
  if (halves.empty()) return std::nullopt;
  FftCheckResult::HalfPeriodCheck c;
  // Leaf friction makes the half periods π/k₁ and π/k₂ with k² = (1 ± φ)k₀² (springs digest
  // (51), (63)): up to 1/√(1 − φ) − 1 longer than the linear one (4.5 % at φ = 0.085, 8.5 % at
  // the book's largest φ = 0.15), so a fixed 5 % would fail a correct run at large φ. The
  // tolerance is that offset plus 1 % for where the turning points fall between the integrator's
  // steps and for the other DOFs' share in a multi-DOF mode, and never below kNonlinearTolerance.
  const double phi = std::min(largest_leaf_friction(vehicle), 0.99);
  c.tolerance = std::max(FftCheck::kNonlinearTolerance, 1.0 / std::sqrt(1.0 - phi) - 1.0 + 0.01);
  c.count = static_cast<int>(halves.size());
  for (double h : halves)
    c.worst_rel_error = std::max(c.worst_rel_error, std::abs(h - r.linear_half_period_s) / r.linear_half_period_s);
  c.passed = c.worst_rel_error <= c.tolerance;
  return c;
}

}  // namespace

NonlinearEffects scene_effects(const Scene& scene) {
  NonlinearEffects effects;
  effects.leaf_friction = names(scene, "leaf_friction");
  effects.progressive_springs = names(scene, "progressive_springs");
  effects.constant_friction = scene.simulation && scene.simulation->friction_law == "constant";
  return effects;
}

namespace {

// What a scene simulates of an element: without "viscous_dampers" named, not its vertical and
// lateral viscous damping (the longitudinal dampers, series dampers and a body's bending damping
// stay in C). One rule for scene_system, which builds it, and unsimulated_parts, which counts
// what it leaves out: the warning cannot drift from the model.
Element simulated_part(const Scene& scene, Element e) {
  if (!names(scene, "viscous_dampers")) e.vertical_damping = e.lateral_damping = 0.0;
  return e;
}

}  // namespace

LinearSystem scene_system(const Scene& scene, const Vehicle& vehicle) {
  Vehicle v = vehicle;
  for (Element& e : v.elements) e = simulated_part(scene, std::move(e));
  return assemble(v, scene.dofs);
}

namespace {

// How many of the vehicle's parts in `dofs` `counts` finds: dampers or spring stages, each
// direction of an element on its own (a vertical-only scene has no use for the lateral ones).
int count_parts(const Vehicle& vehicle, DofSet dofs, int (*counts)(const Element&, bool vertical)) {
  int n = 0;
  for (const Element& e : vehicle.elements) {
    if (dofs != DofSet::lateral) n += counts(e, true);
    if (dofs != DofSet::vertical) n += counts(e, false);
  }
  return n;
}

int stages_where(const std::vector<SpringStage>& stages, bool (*has)(const SpringStage&)) {
  return static_cast<int>(std::count_if(stages.begin(), stages.end(), has));
}

// "add effects = [\"x\"]" to a scene that names none; "add \"x\" to effects" to one that names some.
std::string add_effect(const Scene& scene, const std::string& effect) {
  return scene.simulation->effects.empty() ? "add effects = [\"" + effect + "\"]"
                                           : "add \"" + effect + "\" to effects";
}

}  // namespace

std::vector<std::string> unsimulated_parts(const Scene& scene, const Vehicle& vehicle) {
  std::vector<std::string> out;
  // "effects = []" written in the file: the linear, undamped model chosen, not forgotten.
  if (!scene.simulation || (scene.simulation->effects.empty() && scene.name_places.count("simulation.effects")))
    return out;
  // The dampers scene_system leaves out (simulated_part), in the directions the scene moves: a
  // lateral scene's roll feels a vertical damper set off the centre line too.
  int dampers = 0;
  for (const Element& e : vehicle.elements) {
    const Element kept = simulated_part(scene, e);
    const bool vertical = e.vertical_damping > 0.0 && kept.vertical_damping != e.vertical_damping;
    const bool lateral = e.lateral_damping > 0.0 && kept.lateral_damping != e.lateral_damping;
    if (scene.dofs != DofSet::lateral) dampers += vertical;
    if (scene.dofs != DofSet::vertical) dampers += lateral;
    if (scene.dofs == DofSet::lateral) dampers += vertical && e.point.y() != 0.0;
  }
  if (dampers > 0)
    out.push_back(std::to_string(dampers) + (dampers == 1 ? " viscous damper" : " viscous dampers") +
                  " in the vehicle " + (dampers == 1 ? "is" : "are") + " not simulated: " +
                  add_effect(scene, "viscous_dampers"));
  // Leaf friction acts on the vertical stages only (docs/scenes.md, "leaf_friction").
  const int leaves = scene.dofs == DofSet::lateral
                         ? 0
                         : count_parts(vehicle, DofSet::vertical, [](const Element& e, bool) {
                             return stages_where(e.vertical_stages,
                                                 [](const SpringStage& s) { return s.relative_friction > 0.0; });
                           });
  if (leaves > 0 && !names(scene, "leaf_friction"))
    out.push_back(std::to_string(leaves) + (leaves == 1 ? " spring stage" : " spring stages") +
                  " with leaf friction in the vehicle " + (leaves == 1 ? "is" : "are") +
                  " simulated without it: " + add_effect(scene, "leaf_friction"));
  const int curves = count_parts(vehicle, scene.dofs, [](const Element& e, bool vertical) {
    return stages_where(vertical ? e.vertical_stages : e.lateral_stages,
                        [](const SpringStage& s) { return s.curve.has_value(); });
  });
  if (curves > 0 && !names(scene, "progressive_springs"))
    out.push_back(std::to_string(curves) + (curves == 1 ? " progressive spring" : " progressive springs") +
                  " in the vehicle " + (curves == 1 ? "is" : "are") +
                  " simulated as linear (the tangent at the carried load): " +
                  add_effect(scene, "progressive_springs"));
  return out;
}

TimeHistory simulate_scene(const Scene& scene, const Vehicle& vehicle) {
  return simulate::recorded([&](HistorySink& sink) { return simulate_scene(scene, vehicle, {&sink}); });
}

TimeHistory simulate_scene(const Scene& scene, const Vehicle& vehicle, const std::vector<HistorySink*>& sinks) {
  if (!scene.simulation) throw std::invalid_argument("the scene has no [simulation] table");
  model::refuse_ride_only_scene(scene, "simulations of [simulation]");
  const SimulationSpec& spec = *scene.simulation;
  const LinearSystem system = scene_system(scene, vehicle);
  check_scene_fits(scene, system);
  model::refuse_scene_series_dampers(scene, system, "simulation");
  std::vector<const ExcitationSource*> sources;
  for (const auto& s : scene.sources) sources.push_back(s.get());
  SimulationOptions options;
  options.speed = spec.speed;
  options.final_speed = spec.final_speed;
  options.duration = spec.duration;
  options.time_step = spec.time_step;
  options.initial = spec.initial;
  options.tolerance = spec.tolerance;
  options.event_tolerance = spec.event_tolerance;
  const NonlinearEffects effects = scene_effects(scene);
  // A ramp changes the load's frequency as it goes: the adaptive path, which takes any forcing.
  simulate::HistoryFanOut sink(sinks);
  return effects.any() || spec.final_speed > 0.0 ? simulate_nonlinear(system, sources, options, effects, sink)
                                                 : simulate_linear(system, sources, options, sink);
}

FftCheckResult fft_check(const Scene& scene, const Vehicle& vehicle, double memory_limit) {
  if (!scene.simulation) throw std::invalid_argument("the scene has no [simulation] table");
  FftCheckResult out;
  StageClock clock(&out.summary);
  const LinearSystem system = scene_system(scene, vehicle);
  require_check_fits(*scene.simulation, system.size(), memory_limit);
  out.history = simulate_scene(scene, vehicle);
  clock.lap("simulate");
  // A damped scene's free response oscillates at the damped frequencies and decays: the damped
  // modes (their undamped solve is the scene's modes, matched by index) say where and how fast.
  std::optional<DampedModalResult> damped;
  if (system.damping.size() > 0 && system.damping.cwiseAbs().maxCoeff() > 0.0) {
    damped = solve_damped_modes(system);
    out.modes = damped->undamped;
  } else {
    out.modes = solve_modes(system);
  }
  clock.lap("modes");
  const SimulationSpec& spec = *scene.simulation;
  const bool ramp = spec.final_speed > 0.0;
  std::vector<const ExcitationSource*> sources;
  if (!ramp)  // a ramp has no steady state to take out
    for (const auto& s : scene.sources) sources.push_back(s.get());
  const std::vector<simulate::FreeMode> free =
      simulate::free_modes(system, out.modes, damped ? &*damped : nullptr, sources, spec.speed, spec.initial);
  const double fs = 1.0 / scene.simulation->time_step;
  const Eigen::Index n = out.history.time.size();
  SpectrumAnalyzer analyzer(n, record_spectrum_options(n));
  // Modal coordinates η = ΦᵀM x over the record: mass-normalised, so one scale for every mode
  // whatever its DOFs' units; a mode far below the most excited one holds only round-off.
  Eigen::VectorXd dof_energy(system.size());  // M_dd max|x_d|²: comparable across m and rad
  Eigen::VectorXd motion(system.size());  // max |x_d| over the record
  for (int d = 0; d < system.size(); ++d) {
    motion(d) = out.history.displacement.col(d).cwiseAbs().maxCoeff();
    dof_energy(d) = system.mass(d, d) * motion(d) * motion(d);
  }
  const ModalAmplitudes amplitudes = modal_amplitudes(system, out.modes, out.history);
  out.nonlinear = scene_effects(scene).any();
  // Friction and kinks broaden the lines: the half periods of the most excited mode's DOF
  // are the check (the lowest mode may barely move: the two-axle wagon's pitch over joints).
  if (out.nonlinear && amplitudes.most_mode >= 0) {
    const Mode& mode = out.modes.modes[amplitudes.most_mode];
    out.swings = swings(out.history, showing_dof(mode, dof_energy));
    out.linear_half_period_s = 0.5 / mode.frequency_hz;
  }
  clock.lap("swings");
  const double record_s = static_cast<double>(n) / fs;
  const Eigen::VectorXd mass_diagonal = system.mass.diagonal();
  for (size_t r = 0; r < out.modes.modes.size(); ++r) {
    const Mode& mode = out.modes.modes[r];
    if (mode.kind != ModeKind::oscillatory || mode.frequency_hz > fs / 4.0) continue;
    FftCheck check;
    check.mode = mode.index;
    check.mode_name = mode.name;
    check.modal_hz = mode.frequency_hz;
    check.damped_hz = free[r].damped_hz;
    check.damping_ratio = free[r].damping_ratio;
    check.modal_amplitude_ratio = amplitudes.most > 0.0 ? amplitudes.amplitude[r] / amplitudes.most : 0.0;
    check.excited = check.modal_amplitude_ratio >= FftCheck::kExcitedRatio;
    const int dof = dominant_dof(mode, check.excited, amplitudes.amplitude[r], mass_diagonal, motion);
    check.dof = system.dofs[dof].label;
    // A mode not excited needs no spectrum (no peak is sought): only the record's resolution fs/N,
    // which every spectrum of it has. Its DOF, which may be at rest, adds no chart of round-off.
    check.resolution_hz = fs / static_cast<double>(n);
    double peak_amplitude = 0.0;
    const Spectrum* spectrum = nullptr;
    if (check.excited) {
      auto at = std::find(out.spectrum_dofs.begin(), out.spectrum_dofs.end(), check.dof);
      if (at == out.spectrum_dofs.end()) {
        out.spectrum_dofs.push_back(check.dof);
        out.spectra.push_back(analyzer.compute(out.history.displacement.col(dof), fs));
        at = out.spectrum_dofs.end() - 1;
      }
      spectrum = &out.spectra[at - out.spectrum_dofs.begin()];
      peak_amplitude = match_peak(*spectrum, &check);
    }
    judge(out.nonlinear, record_s, &check);
    // Its free response gone, a linear scene's mode has no line to check; the free part of a
    // nonlinear or ramped scene is not the linear one (no steady state to take out).
    // A forcing line at the mode makes it not applicable first: no run could tell the two apart.
    if (spectrum && !out.nonlinear && !ramp && forcing_line_at_mode(scene, check).empty())
      check.why_decayed = why_decayed(check, free[r], mode.shape(dof), *spectrum, record_s);
    if (!check.why_decayed.empty()) {
      check.outcome = FftCheck::Outcome::decayed;
      check.needed_duration_s = 0.0;
    } else if (check.excited && (ramp || check.peak_hz)) {
      const FoundPeak peak{system, out.modes, dof, peak_amplitude};
      check.why_not_applicable = why_no_run_could_check(scene, check, out.swings, peak);
      if (!check.why_not_applicable.empty()) {
        check.outcome = FftCheck::Outcome::not_applicable;
        check.needed_duration_s = 0.0;
      }
    }
    out.checks.push_back(check);
  }
  for (const FftCheck& c : out.checks) {
    out.checked += c.checked();
    out.failed += c.outcome == FftCheck::Outcome::failed;
  }
  out.half_period_check = check_half_periods(scene, vehicle, out);
  if (out.half_period_check) {
    ++out.checked;
    out.failed += !out.half_period_check->passed;
  }
  out.passed = out.checked > 0 && out.failed == 0;
  clock.lap("spectra and peaks");
  summarise_checks(&out);
  return out;
}

}  // namespace railmodal
