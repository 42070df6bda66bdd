// One variant of a study: what the designer compares (docs/studies.md, "What is computed").
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/critical_speed.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/hunting.hpp"
#include "railmodal/ride.hpp"
#include "railmodal/scene.hpp"
#include "railmodal/stability.hpp"
#include "railmodal/study.hpp"
#include "model/assembly.hpp"
#include "response/critical_speed_study.hpp"
#include "response/curve_peaks.hpp"
#include "response/golden_section.hpp"
#include "response/modal_checks.hpp"
#include "ride/nmv_scope.hpp"
#include "solve/lateral_stability.hpp"
#include "solve/modal_solver.hpp"
#include "solve/mode_naming.hpp"
#include "study/parallel_evaluation.hpp"
#include "study/permissible_deflection.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {
namespace {

void summarise_modes(const ModalResult& modes, VariantResult* r) {
  r->modes.reserve(r->modes.size() + modes.modes.size());
  for (const Mode& m : modes.modes)
    r->modes.push_back({m.name, to_string(m.kind), m.frequency_hz, m.period_s, m.divergence_rate});
}

// Static deflection of each body's reference point: K_el q = M u g, with u the upward unit
// translation of every body, is the elastic response to the weights turned upward (M u g is
// the generalised weight, moments of off-centre CGs included); gravity stiffness is left
// out because the deflection is measured from the unloaded springs, as the book's f_st.
void static_deflections(const Vehicle& vehicle, const LinearSystem& any, VariantResult* r) {
  // The given system where it is the vertical one (no copy: a system holds its vehicle).
  LinearSystem vertical;
  const bool is_vertical = any.size() > 0 && std::all_of(any.dofs.begin(), any.dofs.end(), [](const Dof& d) {
    return d.motion == Motion::bounce || d.motion == Motion::pitch || d.motion == Motion::longitudinal;
  });
  if (!is_vertical) vertical = assemble(vehicle, DofSet::vertical);
  const LinearSystem& s = is_vertical ? any : vertical;
  if (s.size() == 0) return;
  Eigen::VectorXd up = Eigen::VectorXd::Zero(s.size());
  for (int i = 0; i < s.size(); ++i)
    if (s.dofs[i].motion == Motion::bounce) up(i) = 1.0;
  // This thread's factorisation, its storage kept between calls (every variant of a study):
  // the same factorisation of the same matrix.
  thread_local Eigen::FullPivLU<Eigen::MatrixXd> lu;
  lu.compute(s.stiffness - s.gravity_stiffness);
  if (!lu.isInvertible()) return;  // a free vertical direction: no static position to report
  const Eigen::VectorXd q = lu.solve(s.mass * up * vehicle.gravity);
  r->static_deflections.reserve(r->static_deflections.size() + static_cast<size_t>(up.sum()));  // a body a bounce DOF
  for (int i = 0; i < s.size(); ++i)
    if (s.dofs[i].motion == Motion::bounce) r->static_deflections.push_back({vehicle.bodies[s.dofs[i].body].name, q(i)});
}

// The metacentric height of the body named "body", from the lateral set's stiffness (`lateral`,
// as model::assemble_stiffness gives it) when the caller has it, else assembled here.
void metacentric_height(const Vehicle& vehicle, const LinearSystem* lateral, VariantResult* r) {
  for (const Body& b : vehicle.bodies)
    if (b.name == "body" && std::find(b.held.begin(), b.held.end(), Motion::roll) == b.held.end()) {
      try {
        if (lateral) {
          thread_local LateralStability out;  // this thread's: its strings serve every variant
          solve::condense_roll(vehicle, *lateral, "body", &out);
          r->metacentric_height = out.metacentric_height;
        } else {
          r->metacentric_height = lateral_stability(vehicle, "body").metacentric_height;
        }
      } catch (const std::invalid_argument&) {
        // no free roll in the lateral set: nothing to report
      }
    }
}

void summarise_response(const CriticalSpeedStudy& study, VariantResult* r) {
  r->critical_speeds.reserve(r->critical_speeds.size() + study.critical_speeds.size());
  r->peaks.reserve(r->peaks.size() + study.curves.size());
  for (const CriticalSpeed& c : study.critical_speeds)
    r->critical_speeds.push_back({c.speed, c.source, c.source_kind, c.harmonic, c.mode_name, c.friction_stops});
  for (size_t k = 0; k < study.curves.size(); ++k) {
    const AmplitudeCurve& curve = study.curves[k];
    VariantResult::PeakSummary p;
    p.source = curve.source;
    p.output = curve.output;
    p.quantity = to_string(curve.quantity);
    const response::LargestResponse largest = response::largest_response(study, k);
    p.amplitude = largest.amplitude, p.speed = largest.speed, p.unbounded = largest.unbounded;
    r->peaks.push_back(p);
  }
}

// The response of one element for one source at the largest point near grid point v (a local
// maximum of its stretch): golden-section search between the neighbours, to 1e-6 of the
// speed, as the damped peaks of the amplitude curves are refined. Returns the curve at that
// one speed (unbounded if the search met an undamped speed).
DeflectionCurve refine_deflection(const CriticalSpeedStudy& study, const ExcitationSource& source, int s, int element,
                                  const std::vector<double>& reference, const DeflectionCurve& curve, size_t v) {
  auto at = [&](double speed) {
    return element_deflection_curves(study.system, study.modes, source, s, {element}, {speed}, reference).front();
  };
  auto score = [](const DeflectionCurve& c) { return c.unbounded[0] ? std::nan("") : c.amplitudes[0]; };
  const auto g = response::golden_section(curve.speeds[v - 1], curve.speeds[v + 1], 1e-6, at, score);
  if (std::isnan(score(g.fc))) return g.fc;
  if (std::isnan(score(g.fd))) return g.fd;
  return score(g.fc) >= score(g.fd) ? g.fc : g.fd;
}

// The largest dynamic deflection of every element or stage the rule limits, over every source
// and the scene's speeds, by the rule of docs/studies.md, "Permissible dynamic deflections":
//  1. an undamped resonance in range (no viscous damping in the vehicle's modes) that leaf
//     friction does not stop (the critical speeds' criterion, the book's (169a) read as Den
//     Hartog's) grows without limit: every element its modes stretch is unbounded;
//  2. otherwise leaf friction is linearised at the element stretch X_lim where the element
//     reaches its first limit, and the response is compared with the limit. For one mode
//     driven through its own coordinate, with friction linearised at X the response A(X) has
//     A(X)/X non-increasing in X, so A(X_lim) ≤ X_lim exactly when the harmonic-balance
//     amplitude X* ≤ X_lim. With the track's own motion under the spring (every axle-box
//     spring) the stretch at resonance is |X_lim/s ± |u_r − u_f|/2| (tests/response/
//     element_deflection_test.cpp): a linearised check, not an exact one. The figure reported
//     is A(X_lim): it decides the verdict, it is not the amplitude the spring reaches. Every
//     check of an element is evaluated at the element's first limit; a stage in series with
//     leaf friction deflects by the springs' force (friction included) over its stiffness.
// Friction of an element without a limit is linearised at the largest X_lim of the limited
// elements (the least damping any limited element assumes; too much for such a spring if it
// moves more than that); the vehicle's dampers act as they are. Grid maxima are refined by
// golden-section search.
// The elements with a limit, and the stretch at which each element's friction is linearised:
// its first limit, or the largest of them for an element without one (see above).
struct FrictionReference {
  std::vector<int> elements;
  std::vector<double> stretch;  // per element of the vehicle
};

FrictionReference friction_reference(const std::vector<study::PermissibleDeflection>& limits, size_t element_count) {
  FrictionReference f;
  f.stretch.assign(element_count, 0.0);
  for (const auto& l : limits) {
    if (std::find(f.elements.begin(), f.elements.end(), l.element) == f.elements.end()) f.elements.push_back(l.element);
    const double stretch = l.permissible / l.share + l.hold;
    f.stretch[l.element] = f.stretch[l.element] > 0.0 ? std::min(f.stretch[l.element], stretch) : stretch;
  }
  const double largest = *std::max_element(f.stretch.begin(), f.stretch.end());
  for (size_t k = 0; k < f.stretch.size(); ++k)
    if (std::find(f.elements.begin(), f.elements.end(), static_cast<int>(k)) == f.elements.end())
      f.stretch[k] = largest;
  return f;
}

// Rule 1: resonances that nothing damps and friction does not stop.
void flag_undamped_resonances(const CriticalSpeedStudy& study, const std::vector<study::PermissibleDeflection>& limits,
                              VariantResult* r) {
  const LinearSystem& system = study.system;
  for (const CriticalSpeed& cs : study.critical_speeds) {
    const std::vector<const Mode*> group = response::eigenspace_of(study.modes, cs.mode);
    if (cs.friction_stops ||
        !std::all_of(group.begin(), group.end(), [&](const Mode* m) { return response::undamped(system, *m); }))
      continue;
    for (size_t i = 0; i < limits.size(); ++i) {
      VariantResult::DeflectionCheck& c = r->deflections[i];
      const Eigen::RowVectorXd row = system.element_vertical_map.row(limits[i].element);
      if (!c.unbounded &&
          std::any_of(group.begin(), group.end(), [&](const Mode* m) { return response::moves(row, m->shape); }))
        c.unbounded = true, c.speed = cs.speed, c.source = cs.source;
    }
  }
}

// Every check of the curve's element sees the curve `at` at its point v, speed `speed`, of source s.
void take_deflection(const std::vector<study::PermissibleDeflection>& limits, int element, const DeflectionCurve& at,
                     size_t v, double speed, int s, VariantResult* r) {
  for (size_t i = 0; i < limits.size(); ++i) {
    const auto& l = limits[i];
    VariantResult::DeflectionCheck& c = r->deflections[i];
    if (l.element != element || c.unbounded) continue;
    if (at.unbounded[v]) {
      c.unbounded = true, c.speed = speed, c.source = s;
      continue;
    }
    const double d = l.force_stiffness > 0.0 ? at.spring_forces[v] / l.force_stiffness
                                             : l.share * std::max(at.amplitudes[v] - l.hold, 0.0);
    if (d > c.deflection) c.deflection = d, c.speed = speed, c.source = s;
  }
}

// Rule 2 for one element's curve under source s: on the grid, and at every local maximum of
// the element's stretch above 1 % of its largest, refined.
void check_curve(const CriticalSpeedStudy& study, const std::vector<study::PermissibleDeflection>& limits,
                 const std::vector<double>& reference, int s, const DeflectionCurve& curve, VariantResult* r) {
  const std::vector<double>& speeds = curve.speeds.values();
  const std::vector<double>& a = curve.amplitudes;
  double largest = 0.0;
  for (size_t v = 0; v < speeds.size(); ++v) {
    take_deflection(limits, curve.element, curve, v, speeds[v], s, r);
    if (!curve.unbounded[v]) largest = std::max(largest, a[v]);
  }
  for (size_t v = response::next_local_maximum(a.data(), 1, a.size()); v + 1 < a.size();
       v = response::next_local_maximum(a.data(), v + 1, a.size())) {
    if (curve.unbounded[v - 1] || curve.unbounded[v] || curve.unbounded[v + 1] || !(a[v] >= 0.01 * largest)) continue;
    const DeflectionCurve refined =
        refine_deflection(study, *study.scene.sources[s], s, curve.element, reference, curve, v);
    take_deflection(limits, curve.element, refined, 0, refined.speeds[0], s, r);
  }
}

void check_deflections(const DeflectionRule& rule, const CriticalSpeedStudy& study, VariantResult* r) {
  r->deflections_checked = true;
  if (study.scene.dofs == DofSet::lateral)  // load_study refuses this; a direct call fails the variant
    throw std::invalid_argument("permissible dynamic deflections need the vertical motions: the scene's dofs are lateral");
  const LinearSystem& system = study.system;
  const std::vector<study::PermissibleDeflection> limits = study::permissible_deflections(rule, system);
  if (limits.empty()) return;
  const FrictionReference reference = friction_reference(limits, system.vehicle.elements.size());
  for (const auto& l : limits) {
    VariantResult::DeflectionCheck c;
    const Element& e = system.vehicle.elements[l.element];
    c.element = e.name;
    c.stage = l.stage < 0 ? "" : e.vertical_stages[l.stage].kind;
    c.basis = l.basis;
    c.permissible = l.permissible;
    r->deflections.push_back(c);
  }
  flag_undamped_resonances(study, limits, r);
  // Rule 2: the largest finite deflection of each check per source.
  const SpeedGrid speeds = study.curves.empty() ? SpeedGrid() : study.curves.front().speeds;
  for (size_t s = 0; s < study.scene.sources.size() && !speeds.empty(); ++s)
    for (const DeflectionCurve& curve :
         element_deflection_curves(system, study.modes, *study.scene.sources[s], static_cast<int>(s),
                                   reference.elements, speeds.values(), reference.stretch))
      check_curve(study, limits, reference.stretch, static_cast<int>(s), curve, r);
  for (auto& c : r->deflections)
    if (c.unbounded) c.deflection = 0.0;
}

// The linear hunting critical speed as a metric: +∞ stable over the range, 0 already unstable at
// its lowest speed (maximised, such a design ranks last), else the critical speed. Nothing for a
// vehicle without wheelsets.
void hunting_speed(const Vehicle& vehicle, const HuntingOptions& options, VariantResult* r) {
  if (vehicle.wheelsets.empty()) return;
  const HuntingResult h = solve_hunting_stability(assemble(vehicle, DofSet::lateral), options);
  switch (h.verdict) {
    case HuntingVerdict::stable_throughout:
      r->hunting_speed = std::numeric_limits<double>::infinity();
      break;
    case HuntingVerdict::unstable_at_lowest_speed:
      r->hunting_speed = 0.0;
      break;
    case HuntingVerdict::critical_speed_in_range:
      // Unstable in the range with no refined crossing cannot be: the solver refines every one.
      r->hunting_speed = h.critical ? h.critical->speed : 0.0;
      break;
  }
}

// The ride on the scene's random track, when the scene has one: per output the largest RMS and
// Sperling Wz over the ride's speeds, and the largest N_MV estimate (the spectra are not kept);
// with rms_only (ride_rms_only(study)) the RMS alone. With a worker's `kept` (may be null) the
// solve's large arrays are the ones it kept from its previous variant (ride_workspace.hpp).
void ride_summary(const Vehicle& vehicle, const Scene& scene, bool rms_only, ride::Workspace* kept, VariantResult* r) {
  if (!scene.irregularity || !scene.ride) return;
  const LinearSystem system = assemble(vehicle, scene.dofs);
  check_scene_fits(scene, system);
  RideOptions options = scene.ride->options;
  options.keep_spectra = false;  // the metrics need the indices only
  options.threads = 1;           // the variants are spread over the threads
  options.rms_only = rms_only;
  const std::vector<RideOutput> outputs =
      scene.ride->outputs.empty() ? default_ride_outputs(system) : scene.ride->outputs;
  const RideResult ride = ride::solve_ride(system, *scene.irregularity, outputs, options, kept);
  r->ride_evaluated = true;
  for (size_t i = 0; i < ride.outputs.size(); ++i) {
    VariantResult::RideSummary o;
    o.output = ride.outputs[i].name;
    o.unit = unit_of(ride.outputs[i]);
    for (const RideAtSpeed& at : ride.speeds) {
      const RideOutputAtSpeed& a = at.outputs[i];
      o.unbounded = o.unbounded || a.unbounded;
      if (a.unbounded) continue;
      o.max_rms = std::max(o.max_rms, a.rms);
      if (a.sperling_wz) o.max_wz = std::max(o.max_wz.value_or(*a.sperling_wz), *a.sperling_wz);
    }
    if (o.unbounded) o.max_rms = 0.0, o.max_wz.reset();
    r->ride.push_back(o);
  }
  // The largest N_MV and what it covers: that of the floor point it is taken at (the first of equals).
  for (const RideAtSpeed& at : ride.speeds)
    for (const RideComfortAtPoint& c : at.comfort)
      if (!r->max_nmv || c.nmv_estimate > *r->max_nmv) r->max_nmv = c.nmv_estimate, r->max_nmv_partial = ride::nmv_scope(c);
}

// A divergent mode makes the variant a failure naming it (the critical-speed study refuses such a
// vehicle; a study that asks for no critical speeds must not rank its "period" instead).
bool name_unstable_mode(const ModalResult& modes, VariantResult* r) {
  for (const Mode& m : modes.modes)
    if (m.kind == ModeKind::unstable) {
      char rate[32];
      std::snprintf(rate, sizeof rate, "%.4g", m.divergence_rate);
      r->failure = "unstable: mode " + std::to_string(m.index) + ", " + m.name + ", diverges at " + rate + " 1/s";
      return true;
    }
  return false;
}

// The modes and statics of a variant with no critical-speed study to take them from (its
// ranking reads no critical speed, or a ride scene has no periodic source).
void summarise_without_sources(const StudyVariant& variant, VariantResult* r) {
  const LinearSystem system = assemble(variant.vehicle, variant.scene.dofs);
  const ModalResult modes = solve_modes(system);
  summarise_modes(modes, r);
  name_unstable_mode(modes, r);
  static_deflections(variant.vehicle, system, r);
  metacentric_height(variant.vehicle, nullptr, r);
}

// The analysis, method and checks of an evaluation (its stages are timed already).
void summarise_evaluation(VariantResult* r) {
  AnalysisSummary& s = r->summary;
  s.analysis = "design variant";
  s.method = "critical-speed study of the variant in its scene, then its metrics";
  constexpr double kNoLimit = std::numeric_limits<double>::infinity();
  s.checks.reserve(s.checks.size() + 6);  // the checks below: one allocation
  s.checks.push_back({"evaluated (0: failed)", r->ok() ? 1.0 : 0.0, kNoLimit, r->ok()});
  s.checks.push_back({"modes", static_cast<double>(r->modes.size()), kNoLimit, true});
  s.checks.push_back({"critical speeds", static_cast<double>(r->critical_speeds.size()), kNoLimit, true});
  if (r->hunting_speed) s.checks.push_back({"hunting speed evaluated", 1.0, kNoLimit, true});
  if (r->ride_evaluated) s.checks.push_back({"ride outputs", static_cast<double>(r->ride.size()), kNoLimit, true});
  if (r->deflections_checked) {
    const double kept = static_cast<double>(std::count_if(r->deflections.begin(), r->deflections.end(),
                                                          [](const VariantResult::DeflectionCheck& c) { return c.kept(); }));
    s.checks.push_back({"permissible deflections kept", kept, static_cast<double>(r->deflections.size()), true});
  }
}

// The failure of a vehicle with no steady response: its modes (when they can be computed), and
// the unstable one named.
void describe_failure(const Vehicle& vehicle, DofSet dofs, const std::string& why, VariantResult* r) {
  r->failure = "numerical failure: " + why;
  const LinearSystem system = assemble(vehicle, dofs);
  const ModalResult modes = solve_modes(system);
  summarise_modes(modes, r);
  static_deflections(vehicle, system, r);
  metacentric_height(vehicle, nullptr, r);
  name_unstable_mode(modes, r);
}

// Names, among the modes a critical-speed study left unnamed (solve::ModeNaming::deferred) and
// its critical speeds, what the ranking reads (study::ModeNamesRead): the same names, in the
// same places, as a study that named every mode.
void name_what_is_read(const study::ModeNamesRead& read, CriticalSpeedStudy* study) {
  std::vector<Mode>& modes = study->modes.modes;
  std::optional<solve::ModeNamer> namer;  // made with the first name
  thread_local std::vector<char> named;   // per mode; this thread's, its storage kept
  named.assign(modes.size(), 0);
  const auto name = [&](size_t k) {
    if (named[k]) return;
    if (!namer) namer.emplace(study->system);
    solve::name_mode(*namer, &modes[k]);
    named[k] = 1;
  };
  thread_local std::vector<std::vector<const Mode*>> groups;  // the eigenspaces, as the rows found them
  response::eigenspaces_into(study->modes, &groups);
  const auto name_speed = [&](CriticalSpeed* c) {
    for (const auto& group : groups)
      if (group.front()->index == c->mode) {
        for (const Mode* m : group) name(static_cast<size_t>(m->index - 1));  // Mode::index: 1-based place
        response::name_eigenspace(group, &c->mode_name);
        return;
      }
  };
  if (read.lowest_critical_speed && !study->critical_speeds.empty()) name_speed(&study->critical_speeds.front());
  bool every = false;  // a mode a metric names is missing: every name, for check_mode_names's list
  for (const std::string& x : read.periods) {  // metric_value: the first oscillatory mode named x
    bool found = false;
    for (size_t k = 0; k < modes.size() && !found; ++k) {
      name(k);
      found = modes[k].kind == ModeKind::oscillatory && modes[k].name == x;
    }
    every = every || !found;
  }
  for (const std::string& x : read.critical_speeds) {  // metric_value: the first critical speed named x
    bool found = false;
    for (size_t i = 0; i < study->critical_speeds.size() && !found; ++i) {
      name_speed(&study->critical_speeds[i]);
      found = study->critical_speeds[i].mode_name == x;
    }
    every = every || !found;
  }
  if (!every) return;
  for (size_t k = 0; k < modes.size(); ++k) name(k);
  for (CriticalSpeed& c : study->critical_speeds) name_speed(&c);
}

// Gives the workspace its system, scene and modes back when the evaluation ends (their
// storage serves the next variant), however it ends.
struct HandBack {
  CriticalSpeedStudy* from;
  study::Workspace* to;
  ~HandBack() {
    if (!to) return;
    to->system = std::move(from->system);
    to->scene = std::move(from->scene);
    to->modes = std::move(from->modes);
  }
};

// Gives the workspace a ride variant's vehicle and scene back when its evaluation ends, as
// HandBack does for the others through the critical-speed study: the next variant is read into
// their storage (parallel_evaluation.cpp).
struct GiveBackRead {
  StudyVariant* from;
  study::Workspace* to;
  ~GiveBackRead() {
    if (!from || !to) return;
    to->system.vehicle = std::move(from->vehicle);
    to->scene = std::move(from->scene);
  }
};

// evaluate_variant; `owned`, when given, is `variant` itself, which the caller gives up: its
// scene moves into the critical-speed study and its vehicle into the study's system instead of
// being copied there (a copy of each a variant fewer: their names, lists and the scene's key
// places are allocations), and what follows reads them there. With a `workspace` the worker's
// VariantAssembly assembles it into the workspace's systems: the same matrices, bit for bit,
// from the base it keeps. Throws the InputError of an analysis that refuses the variant's input
// (a scene output or source that does not fit its vehicle, a series damper), an error of the
// input rather than a result of the design, unless settings.input_error_is_failure.
VariantResult evaluate_in_full(const StudyVariant& variant, StudyVariant* owned, int index,
                               const study::VariantSettings& settings, study::Workspace* workspace) {
  const DeflectionRule& rule = settings.rule;
  const std::optional<HuntingOptions>& hunting = settings.hunting;
  const bool ride_rms_only = settings.ride_rms_only;
  const VariantWork& work = settings.work;
  const study::ModeNamesRead& names = settings.names;
  VariantResult r;
  r.index = index;
  r.name = variant.name;
  r.parameters = variant.parameters;
  StageClock clock(&r.summary);
  try {
    if (!work.critical_speeds || (variant.scene.sources.empty() && variant.scene.irregularity)) {
      // No critical speeds: the ranking reads none (nothing is built for them: a vehicle the
      // scene's analyses refuse, one with series dampers say, still has its modes and hunting
      // speed), or a ride scene has no periodic source.
      const GiveBackRead give_back{owned, workspace};
      summarise_without_sources(variant, &r);
      clock.lap("modes");
      if (!r.ok()) {  // a divergent mode: nothing else of it to rank
        summarise_evaluation(&r);
        return r;
      }
      r.critical_speeds_evaluated = work.critical_speeds;  // asked for, and a ride scene has none
      if (work.ride)
        ride_summary(variant.vehicle, variant.scene, ride_rms_only, workspace ? &workspace->ride : nullptr, &r);
      clock.lap("ride");
      if (hunting) hunting_speed(variant.vehicle, *hunting, &r);
      clock.lap("hunting stability");
      summarise_evaluation(&r);
      return r;
    }
    // One assembly and one modal solve serve everything: the study's own, which assembles the
    // lateral stiffness of the metacentric height with its system.
    CriticalSpeedStudy study;
    if (workspace) study.modes = std::move(workspace->modes);  // solved into (solve::solve_modes_into)
    const HandBack hand_back{&study, workspace};
    LinearSystem own_lateral;
    LinearSystem& lateral = workspace ? workspace->lateral : own_lateral;
    bool vehicle_moved = false;  // into study.system (owned only, once assembled)
    const DofSet dofs = variant.scene.dofs;
    try {
      const auto assembled = [&] {
        if (workspace) {  // the variant's own vehicle moved in, or a copy (as assemble copies it)
          workspace->assembly.assemble(owned ? std::move(owned->vehicle) : Vehicle(variant.vehicle), dofs,
                                       DofSet::lateral, &workspace->system, &lateral);
          vehicle_moved = owned != nullptr;
          return std::move(workspace->system);
        }
        model::SystemAndStiffness both =
            owned ? model::assemble_with_stiffness(std::move(owned->vehicle), dofs, DofSet::lateral)
                  : model::assemble_with_stiffness(variant.vehicle, dofs, DofSet::lateral);
        vehicle_moved = owned != nullptr;
        lateral = std::move(both.stiffness);
        return std::move(both.system);
      };
      // Summary rows and no phases: a variant's result reads no resonance's steady response and
      // only the curves' amplitudes (peaks).
      // Its modes named now, or (names.all false) those the ranking reads once it is done.
      const response::StudyDetail kVariant{response::ResonanceDetail::without_response,
                                           response::CurvePhases::left_out,
                                           names.all ? solve::ModeNaming::now : solve::ModeNaming::deferred};
      if (owned)
        response::study_critical_speeds_into(std::move(owned->scene), assembled, &study, {}, kVariant);
      else
        response::study_critical_speeds_into(variant.scene, assembled, &study, {}, kVariant);
    } catch (const NumericalError& e) {
      describe_failure(vehicle_moved ? study.system.vehicle : variant.vehicle, dofs, e.what(), &r);
      clock.lap("failure");
      summarise_evaluation(&r);
      return r;
    }
    // The variant's vehicle and scene, wherever they are now (bit for bit the variant's).
    const Vehicle& vehicle = study.system.vehicle;
    const Scene& scene = study.scene;
    if (!names.all) name_what_is_read(names, &study);
    clock.lap("critical-speed study");
    summarise_modes(study.modes, &r);
    static_deflections(vehicle, study.system, &r);
    metacentric_height(vehicle, &lateral, &r);
    summarise_response(study, &r);
    r.critical_speeds_evaluated = true;
    clock.lap("summaries");
    if (rule.active()) check_deflections(rule, study, &r);
    clock.lap("deflection checks");
    if (hunting) hunting_speed(vehicle, *hunting, &r);
    clock.lap("hunting stability");
    if (work.ride) ride_summary(vehicle, scene, ride_rms_only, workspace ? &workspace->ride : nullptr, &r);
    clock.lap("ride");
  } catch (const NumericalError& e) {
    if (r.failure.empty()) r.failure = std::string("numerical failure: ") + e.what();
  } catch (const InputError& e) {
    // Input an analysis refuses (a scene output or source that does not fit this vehicle, a
    // series damper): the study's error at the variant (study::evaluate_each), or the failure of
    // a variant without a study file, naming the file, line and key the analysis names.
    if (!settings.input_error_is_failure) throw;
    r.failure = e.what();
  } catch (const std::invalid_argument& e) {
    r.failure = e.what();
  }
  if (!r.ok()) r.deflections.clear();  // a check cut short is no verdict
  summarise_evaluation(&r);
  return r;
}

}  // namespace

VariantResult evaluate_variant(const StudyVariant& variant, int index, const DeflectionRule& rule,
                               const std::optional<HuntingOptions>& hunting, bool ride_rms_only,
                               const VariantWork& work) {
  // Every mode named (ModeNamesRead's default), as the public result promises. One variant
  // without its study: input an analysis refuses is its failure.
  return evaluate_in_full(variant, nullptr, index, study::VariantSettings{rule, hunting, ride_rms_only, work, {}, true},
                          nullptr);
}

VariantResult study::evaluate_in_workspace(const StudyVariant& variant, int index, const VariantSettings& settings,
                                           Workspace* workspace) {
  return evaluate_in_full(variant, nullptr, index, settings, workspace);
}

VariantResult study::evaluate_owned_variant(StudyVariant&& variant, int index, const VariantSettings& settings,
                                            Workspace* workspace) {
  return evaluate_in_full(variant, &variant, index, settings, workspace);
}

}  // namespace railmodal
