// Critical speeds: where a harmonic of a source meets a natural frequency, and how much
// the resonance is worth there.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "excitation/generalized_load.hpp"
#include "model/analysis_limits.hpp"
#include "railmodal/response.hpp"
#include "require_valid.hpp"
#include "response/critical_speed_study.hpp"
#include "response/friction_damping.hpp"
#include "response/modal_checks.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;

int dominant_dof(const Mode& mode) {
  int best = 0;
  for (int d = 1; d < mode.kinetic_energy_share.size(); ++d)
    if (mode.kinetic_energy_share(d) > mode.kinetic_energy_share(best)) best = d;
  return best;
}

// The response to one harmonic load; with a friction reference amplitude, leaf friction acts
// as its equivalent viscous damping at this frequency (which also changes the input's
// velocity term, so the load is built on the damped system).
struct Evaluation {
  std::optional<LinearSystem> damped;  ///< the system with equivalent friction damping, if used
  Eigen::VectorXcd damped_load;        ///< the load on `damped`, if used (else the caller's Q)
  HarmonicResponse response;
};

// `Q` is generalized_load(system, load), the undamped system's load, reused where no friction
// damping changes the system.
Evaluation respond(const LinearSystem& system, const ModalResult& modes, const HarmonicLoad& load,
                   const Eigen::VectorXcd& Q, double source_load, double friction_reference_amplitude) {
  Evaluation e;
  if (friction_reference_amplitude > 0.0 && load.frequency_hz > 0.0 && has_leaf_friction(system))
    e.damped = with_equivalent_friction_damping(system, 2.0 * kPi * load.frequency_hz, friction_reference_amplitude);
  if (e.damped) {
    e.damped_load = generalized_load(*e.damped, load);
    e.response = harmonic_response(*e.damped, modes, e.damped_load, load.frequency_hz, source_load);
  } else {
    e.response = harmonic_response(system, modes, Q, load.frequency_hz, source_load);  // Q itself, not a copy
  }
  return e;
}

}  // namespace

bool CriticalSpeedOptions::is_valid(std::string* why) const {
  if (!(min_speed > 0.0) || !(max_speed >= min_speed) || !std::isfinite(max_speed))
    return invalid(why, "need 0 < min_speed ≤ max_speed");
  if (!(friction_reference_amplitude >= 0.0) || !std::isfinite(friction_reference_amplitude))
    return invalid(why,
                   "friction_reference_amplitude must be 0 (friction only in the criterion) or a positive stretch");
  for (const OutputRequest& o : outputs)
    if (o.dof < 0) return invalid(why, "outputs must name DOFs by their index, ≥ 0");
  return true;
}

namespace {

using Eigenspace = std::vector<const Mode*>;

// What a load does to a set of modes, each counted with a weight w (1: the eigenspace itself):
// the combination it drives, ψ = Σ w φ conj(φᵀQ) / N with N = ‖(w φᵀQ)‖ (mass-normalised where
// every w = 1; complex where the modal forces are out of phase); F₀ = ψᵀQ = Σ w|φᵀQ|²/N (the
// unconjugated product, real by construction), the modal force on ψ that the energy criterion
// weighs; and N, with which N·ψ = Σ w (φᵀQ)* φ is the weighted sum of the modes' own forced
// motions, whose magnitude is what each DOF grows by. With every w = 1 this is the eigenspace's
// φ* = Φ_E Φ_EᵀQ / ‖Φ_EᵀQ‖ with F₀ = N = ‖Φ_EᵀQ‖.
struct WeightedMode {
  const Mode* mode;
  double weight;
};

struct DrivenMode {
  Eigen::VectorXcd shape;  // ψ
  double F0 = 0.0;
  double N = 0.0;
};

// The first `count` of `modes` into `out`, whose shape's storage is reused; the shape ψ only
// `with_shape` (F₀ and N do not depend on it; without, out's shape is left as it was).
void driven_mode(const std::vector<WeightedMode>& modes, size_t count, const Eigen::VectorXcd& Q, bool with_shape,
                 DrivenMode* out) {
  DrivenMode& d = *out;
  d.F0 = 0.0;
  d.N = 0.0;
  if (with_shape) d.shape.setZero(Q.size());
  double norm_squared = 0.0, projection = 0.0;
  for (size_t j = 0; j < count; ++j) {
    const WeightedMode& m = modes[j];
    const std::complex<double> f = m.mode->shape.cast<std::complex<double>>().dot(Q);
    // The real shape times the complex weight: the complex product of the shape cast to
    // complex would add 0·Im and 0·Re terms (and a libgcc call per entry), which change only
    // the sign of a zero entry; ψ is read only through magnitudes (|ψ(i)|, |row·ψ|).
    if (with_shape) d.shape += m.mode->shape * (m.weight * std::conj(f));
    norm_squared += m.weight * m.weight * std::norm(f);
    projection += m.weight * std::norm(f);
  }
  if (!(norm_squared > 0.0)) return;
  if (with_shape) d.shape /= std::sqrt(norm_squared);
  d.N = std::sqrt(norm_squared);
  d.F0 = projection / d.N;
}

// Modes whose frequencies lie within this fraction of the resonance's are judged with it by the
// friction criterion. Two modes 1 % apart beat once in 100 periods — at the bounce critical
// speeds of the bundled wagons (2 Hz) 50 s and a kilometre of track, longer than a resonance is
// held — so while a resonance builds they grow together, as an exactly repeated pair does (the
// book's design point r² + d0² = l3², bogie-wagons-natural digest (221), where body pitch and
// bounce coincide). A neighbour at relative gap g counts with weight 1 − g/1 %: fully at
// coincidence, not at all from 1 % on, continuously between — so the criterion does not jump
// when a design passes through the coincidence (issue 17 item 6).
constexpr double kClusterGap = 0.01;

// The eigenspace, each weighted 1, into `cluster`: the first entries of its cluster.
void eigenspace_weights(const Eigenspace& group, std::vector<WeightedMode>* cluster) {
  cluster->clear();
  for (const Mode* m : group) cluster->push_back({m, 1.0});
}

// The eigenspace's neighbours within kClusterGap, weighted as above, appended to its entries.
void add_neighbours(const ModalResult& modes, const Eigenspace& group, std::vector<WeightedMode>* cluster) {
  const double f = group.front()->frequency_hz;
  for (const Mode& m : modes.modes) {
    if (m.kind != ModeKind::oscillatory || std::find(group.begin(), group.end(), &m) != group.end()) continue;
    const double gap = std::abs(m.frequency_hz - f) / std::max(m.frequency_hz, f);  // alike seen from either
    if (gap < kClusterGap) cluster->push_back({&m, 1.0 - gap / kClusterGap});
  }
}

// The DOF a critical speed reports: the mode's most energetic one, or for a repeated frequency
// the one that moves most, weighted by its mass, in the driven combination `shape` (read, and
// computed by the caller, only then: null for a single mode).
int reported_dof(const LinearSystem& system, const Eigenspace& group, const Eigen::VectorXcd* shape) {
  if (group.size() == 1) return dominant_dof(*group.front());
  const Eigen::VectorXd magnitude = shape->cwiseAbs();
  int out = 0;
  for (int d = 1; d < magnitude.size(); ++d)
    if (magnitude(d) * std::sqrt(std::abs(system.mass(d, d))) > magnitude(out) * std::sqrt(std::abs(system.mass(out, out))))
      out = d;
  return out;
}

// Undamped growth per half period at a DOF whose entry in ψ is `at_output`: each mode j grows
// as q = fⱼ t sin(ωt)/(2ω), π fⱼ/(2λ) per half period π/ω, so the weighted cluster moves the DOF
// by π/(2λ)|Σ wⱼ fⱼ φⱼ(i)| = π N |ψ(i)|/(2λ) — exact for a DOF only one mode moves, whatever
// its neighbours' weights (issue 17 review: π F₀|ψ(i)|/(2λ) overstated it by Σw|f|²/Σw²|f|²,
// up to 2× inside the 1 % window).
double growth_at(double eigenvalue, const DrivenMode& cluster, double at_output) {
  return kPi * cluster.N / (2.0 * eigenvalue) * at_output;
}

// Growth per half period without damping, and what leaf friction takes of it (Den Hartog), of
// the combination the load drives in the cluster; `at_output` is its entry at the output.
void add_growth_and_friction(const response::FrictionStages& stages, double eigenvalue, const DrivenMode& cluster,
                             double at_output, CriticalSpeed* row) {
  row->growth_per_half_period = growth_at(eigenvalue, cluster, at_output);
  // Each friction stage slides over the amplitude of its own stretch, in phase with the
  // others or not: Σ R|δ(ψ)| per unit modal amplitude. The energy balance on ψ's amplitude a
  // gains π F₀/(2λ) and loses 2R/λ per half period; the growth above maps a to the output by
  // (N/F₀)|ψ(i)| (π F₀/(2λ)·(N/F₀)|ψ(i)| = π N|ψ(i)|/(2λ)), so the decrement is mapped alike:
  // growth ≤ decrement at the output exactly when π F₀ ≤ 4R, the criterion `friction_stops`.
  const double friction = response::modal_friction_work(stages, cluster.shape);
  row->friction_decrement_per_half_period = 2.0 * friction / eigenvalue * (cluster.N / cluster.F0) * at_output;
  if (friction > 0.0) {
    row->friction_stops = kPi * cluster.F0 <= 4.0 * friction;
    row->friction_threshold_scale = 4.0 * friction / (kPi * cluster.F0);
  }
}

// The resonance at each requested output: its steady amplitude (the finite rest where the
// resonant modes do not move the DOF) or its growth per half period, `modal_growth` (π N/(2λ),
// growth_at) times the driven mode's entry there, ×ω^p for velocity and acceleration (x = X e^{iωt}).
std::vector<ResonanceAtOutput> at_outputs(const LinearSystem& system, const ModalResult& modes,
                                          const std::vector<OutputRequest>& outputs, const HarmonicResponse& response,
                                          double modal_growth, const Eigen::VectorXd& magnitude) {
  std::vector<ResonanceAtOutput> at;
  at.reserve(outputs.size());
  const double omega = 2.0 * kPi * response.frequency_hz;
  for (const OutputRequest& o : outputs) {
    ResonanceAtOutput r;
    r.output = system.dofs[o.dof].label;
    r.quantity = o.quantity;
    r.unbounded = unbounded_at(response, modes, o.dof);
    r.amplitude = r.unbounded ? 0.0 : response_amplitude(response, o.dof, o.quantity);
    const double power = o.quantity == ResponseQuantity::displacement ? 1.0
                         : o.quantity == ResponseQuantity::velocity   ? omega
                                                                      : omega * omega;
    // An entry below 1e-9 of the combination's largest is round-off, as unbounded_at decides.
    const double entry = magnitude(o.dof) > 1e-9 * magnitude.maxCoeff() ? magnitude(o.dof) : 0.0;
    r.growth_per_half_period = modal_growth * entry * power;
    at.push_back(r);
  }
  return at;
}

// Every harmonic's load of a source at one speed, on the DOFs, and their total norm: harmonic k
// drives the resonance and all of them give the norm its round-off rule is relative to. Built
// once for both (the loads, their order and sums are response::source_load_norm's).
struct SourceLoads {
  std::vector<HarmonicLoad> harmonics;        // [k − 1]
  std::vector<Eigen::VectorXcd> generalized;  // [k − 1], generalized_load of each
  double norm = 0.0;                          // √(Σ_k ‖Q_k‖²)
};

// The source's loads at `speed` into `loads`, whose storage serves every resonance.
void source_loads(const LinearSystem& system, const ExcitationSource& source, double speed, SourceLoads* loads) {
  const size_t count = static_cast<size_t>(source.harmonic_count());
  loads->harmonics.resize(count);
  loads->generalized.resize(count);
  double squared = 0.0;
  for (int k = 1; k <= source.harmonic_count(); ++k) {
    loads->harmonics[k - 1] = source.load(system, speed, k);
    excitation::generalized_load_into(system, loads->harmonics[k - 1], &loads->generalized[k - 1]);
    squared += loads->generalized[k - 1].squaredNorm();
  }
  loads->norm = std::sqrt(squared);
}

// What one call of the critical speeds reuses from resonance to resonance: the loads, the
// cluster's list and the driven combinations (their storage; each resonance writes its own).
struct ResonanceScratch {
  SourceLoads loads;
  std::vector<WeightedMode> cluster;
  DrivenMode eigenspace;    // what the load drives in the eigenspace
  DrivenMode cluster_mode;  // and in its cluster
};

// The critical speed where harmonic k of source s meets the eigenspace, if the load drives it;
// with `detail` without_response, without its steady response (response::ResonanceDetail).
std::optional<CriticalSpeed> resonance(const LinearSystem& system, const ModalResult& modes,
                                       const ExcitationSource& source, int s, int k, double speed,
                                       const Eigenspace& group, const CriticalSpeedOptions& options,
                                       const response::FrictionStages& stages,
                                       response::ResonanceDetail detail, ResonanceScratch* scratch) {
  const Mode& first = *group.front();
  source_loads(system, source, speed, &scratch->loads);
  const SourceLoads& loads = scratch->loads;
  const HarmonicLoad& load = loads.harmonics[k - 1];
  const Eigen::VectorXcd& Q = loads.generalized[k - 1];
  // The eigenspace's own combination: its shape is read only to report a repeated frequency's DOF.
  std::vector<WeightedMode>& cluster_modes = scratch->cluster;
  eigenspace_weights(group, &cluster_modes);
  const DrivenMode& d = scratch->eigenspace;
  driven_mode(cluster_modes, group.size(), Q, group.size() > 1, &scratch->eigenspace);
  // Driven unless the modal force is round-off of the source's total load (one rule for
  // every part of the response: response::kLoadRoundOff): symmetry zeros (roll under square
  // joints), and harmonics that are round-off themselves (the 3rd of a full-length cosine dip).
  const double source_load = loads.norm;
  if (!(d.F0 > response::kLoadRoundOff * first.shape.norm() * source_load)) return std::nullopt;
  // The friction criterion and the growth: on the load's projection onto the cluster, the
  // eigenspace and its neighbours (found only for a resonance the load drives).
  add_neighbours(modes, group, &cluster_modes);
  const DrivenMode& cluster = scratch->cluster_mode;
  driven_mode(cluster_modes, cluster_modes.size(), Q, true, &scratch->cluster_mode);

  CriticalSpeed row;
  row.speed = speed;
  row.source = s;
  row.source_kind = source.kind();
  row.harmonic = k;
  row.mode = first.index;
  response::name_eigenspace(group, &row.mode_name);
  row.frequency_hz = first.frequency_hz;
  // A complex modal-force vector (inputs out of phase) gives a rotating combination;
  // its magnitude per DOF is what the output sees.
  const int out = reported_dof(system, group, group.size() > 1 ? &d.shape : nullptr);
  row.output = system.dofs[out].label;
  add_growth_and_friction(stages, first.eigenvalue, cluster, std::abs(cluster.shape(out)), &row);
  if (detail == response::ResonanceDetail::without_response) return row;
  const Eigen::VectorXd cluster_magnitude = cluster.shape.cwiseAbs();
  const HarmonicResponse response =
      respond(system, modes, load, Q, source_load, options.friction_reference_amplitude).response;
  row.unbounded = unbounded_at(response, modes, out);
  row.amplitude = row.unbounded ? 0.0 : std::abs(response.displacement(out));
  row.outputs = at_outputs(system, modes, options.outputs, response, growth_at(first.eigenvalue, cluster, 1.0),
                           cluster_magnitude);
  return row;
}

}  // namespace

std::vector<CriticalSpeed> find_critical_speeds(const LinearSystem& system, const ModalResult& modes,
                                                const std::vector<const ExcitationSource*>& sources,
                                                const CriticalSpeedOptions& options, AnalysisSummary* summary) {
  return response::find_critical_speeds_in(system, modes, sources, options, response::ResonanceDetail::full, summary);
}

std::vector<CriticalSpeed> response::find_critical_speeds_in(const LinearSystem& system, const ModalResult& modes,
                                                             const std::vector<const ExcitationSource*>& sources,
                                                             const CriticalSpeedOptions& options,
                                                             ResonanceDetail detail, AnalysisSummary* summary) {
  require_valid(options, "critical speeds: ");
  model::refuse_series_dampers(system, "critical speeds");
  for (const OutputRequest& o : options.outputs)
    if (o.dof >= system.size())
      throw std::invalid_argument("critical speeds: output DOF " + std::to_string(o.dof) + " is out of range (" +
                                  std::to_string(system.size()) + " DOFs)");
  if (summary) *summary = AnalysisSummary{};
  StageClock clock(summary);  // no clock, no strings without a summary
  // This thread's eigenspaces and scratch: every call's lists and resonances reuse their storage.
  thread_local std::vector<std::vector<const Mode*>> groups;
  response::eigenspaces_into(modes, &groups);
  const response::FrictionStages stages = response::friction_stages(system);  // found once, not per resonance
  int in_range = 0;
  thread_local ResonanceScratch scratch;
  std::vector<CriticalSpeed> found;
  size_t most = 0;  // every harmonic of every source meeting every eigenspace
  for (const ExcitationSource* source : sources) most += static_cast<size_t>(source->harmonic_count()) * groups.size();
  found.reserve(most);
  for (size_t s = 0; s < sources.size(); ++s) {
    const ExcitationSource& source = *sources[s];
    for (int k = 1; k <= source.harmonic_count(); ++k)
      for (const auto& group : groups) {
        const double speed = source.speed_for(group.front()->frequency_hz, k);
        if (speed < options.min_speed || speed > options.max_speed) continue;
        ++in_range;
        if (auto row = resonance(system, modes, source, static_cast<int>(s), k, speed, group, options, stages, detail,
                                  &scratch))
          found.push_back(std::move(*row));
      }
  }
  clock.lap("resonances");
  // By speed, ties in the order found: the order std::stable_sort gives, by insertion (a few
  // rows; stable_sort's buffer was an allocation per call, two calls per variant of a study).
  for (size_t i = 1; i < found.size(); ++i)
    for (size_t j = i; j > 0 && found[j].speed < found[j - 1].speed; --j) std::swap(found[j], found[j - 1]);
  clock.lap("sort");
  if (summary) {
    summary->analysis = "critical speeds";
    summary->method =
        "V = Λ·f/k for each source harmonic and eigenspace, modal force against 1e-9 of the source's "
        "total load, direct harmonic solve at each resonance, friction criterion on the cluster of modes "
        "within 1 %";
    const double driven = static_cast<double>(found.size());
    summary->checks.push_back({"resonances driven, of those in range", driven, static_cast<double>(in_range), true});
    const double stopped = static_cast<double>(
        std::count_if(found.begin(), found.end(), [](const CriticalSpeed& c) { return c.friction_stops; }));
    summary->checks.push_back({"resonances leaf friction stops (Den Hartog)", stopped, driven, true});
  }
  return found;
}

}  // namespace railmodal
