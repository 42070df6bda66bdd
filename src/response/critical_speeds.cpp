// Critical speeds: where a harmonic of a source meets a natural frequency, and how much
// the resonance is worth there.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "railmodal/response.hpp"
#include "require_valid.hpp"
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
  Eigen::VectorXcd load;
  HarmonicResponse response;
  const LinearSystem& system(const LinearSystem& base) const { return damped ? *damped : base; }
};

Evaluation respond(const LinearSystem& system, const ModalResult& modes, const HarmonicLoad& load, double source_load,
                   double friction_reference_amplitude) {
  Evaluation e;
  if (friction_reference_amplitude > 0.0 && load.frequency_hz > 0.0 && has_leaf_friction(system))
    e.damped = with_equivalent_friction_damping(system, 2.0 * kPi * load.frequency_hz, friction_reference_amplitude);
  e.load = generalized_load(e.system(system), load);
  e.response = harmonic_response(e.system(system), modes, e.load, load.frequency_hz, source_load);
  return e;
}

}  // namespace

bool CriticalSpeedOptions::is_valid(std::string* why) const {
  if (!(min_speed > 0.0) || !(max_speed >= min_speed) || !std::isfinite(max_speed))
    return invalid(why, "need 0 < min_speed ≤ max_speed");
  if (!(friction_reference_amplitude >= 0.0) || !std::isfinite(friction_reference_amplitude))
    return invalid(why,
                   "friction_reference_amplitude must be 0 (friction only in the criterion) or a positive stretch");
  return true;
}

namespace {

using Eigenspace = std::vector<const Mode*>;

// What a load does to an eigenspace: the mode of it that the load drives, φ* = Φ_E Φ_EᵀQ / ‖Φ_EᵀQ‖
// (mass-normalised, as each φ is), with F₀ = ‖Φ_EᵀQ‖ its modal force.
struct DrivenMode {
  Eigen::VectorXcd unscaled_shape;  // Φ_E conj(Φ_EᵀQ): φ* before the division by F₀
  double F0 = 0.0;
};

DrivenMode driven_mode(const Eigenspace& group, const Eigen::VectorXcd& Q) {
  DrivenMode d;
  d.unscaled_shape = Eigen::VectorXcd::Zero(Q.size());
  double F0_squared = 0.0;
  for (const Mode* m : group) {
    const std::complex<double> f = m->shape.cast<std::complex<double>>().dot(Q);
    d.unscaled_shape += m->shape.cast<std::complex<double>>() * std::conj(f);
    F0_squared += std::norm(f);
  }
  d.F0 = std::sqrt(F0_squared);
  return d;
}

// The DOF a critical speed reports: the mode's most energetic one, or for a repeated frequency
// the one that moves most, weighted by its mass, in the driven combination.
int reported_dof(const LinearSystem& system, const Eigenspace& group, const Eigen::VectorXd& magnitude) {
  if (group.size() == 1) return dominant_dof(*group.front());
  int out = 0;
  for (int d = 1; d < magnitude.size(); ++d)
    if (magnitude(d) * std::sqrt(std::abs(system.mass(d, d))) > magnitude(out) * std::sqrt(std::abs(system.mass(out, out))))
      out = d;
  return out;
}

// Growth per half period without damping, and what leaf friction takes of it (Den Hartog).
void add_growth_and_friction(const LinearSystem& system, const Eigenspace& group, const Eigen::VectorXcd& Q,
                             double F0, double at_output, CriticalSpeed* row) {
  const Mode& first = *group.front();
  // For friction, the real combination (exact when the modal forces share a phase).
  Eigen::VectorXd driven = Eigen::VectorXd::Zero(system.size());
  for (const Mode* m : group)
    driven += m->shape * (std::conj(m->shape.cast<std::complex<double>>().dot(Q)) / F0).real();
  // Undamped growth at resonance: q = F₀ t sin(ωt)/(2ω), π F₀/(2λ) per half period π/ω.
  row->growth_per_half_period = kPi * F0 / (2.0 * first.eigenvalue) * at_output;
  const double friction = modal_friction_work(system, group.size() == 1 ? first.shape : driven);
  row->friction_decrement_per_half_period = 2.0 * friction / first.eigenvalue * at_output;
  if (friction > 0.0) {
    row->friction_stops = kPi * F0 <= 4.0 * friction;
    row->friction_threshold_scale = 4.0 * friction / (kPi * F0);
  }
}

// The critical speed where harmonic k of source s meets the eigenspace, if the load drives it.
std::optional<CriticalSpeed> resonance(const LinearSystem& system, const ModalResult& modes,
                                       const ExcitationSource& source, int s, int k, double speed,
                                       const Eigenspace& group, const CriticalSpeedOptions& options) {
  const Mode& first = *group.front();
  const HarmonicLoad load = source.load(system, speed, k);
  const Eigen::VectorXcd Q = generalized_load(system, load);
  const DrivenMode d = driven_mode(group, Q);
  // Driven unless the modal force is round-off of the source's total load (one rule for
  // every part of the response: response::kLoadRoundOff): symmetry zeros (roll under square
  // joints), and harmonics that are round-off themselves (the 3rd of a full-length cosine dip).
  const double source_load = response::source_load_norm(system, source, speed);
  if (!(d.F0 > response::kLoadRoundOff * first.shape.norm() * source_load)) return std::nullopt;
  // A complex modal-force vector (inputs out of phase) gives a rotating combination;
  // its magnitude per DOF is what the output sees.
  const Eigen::VectorXd magnitude = (d.unscaled_shape / d.F0).cwiseAbs();

  CriticalSpeed row;
  row.speed = speed;
  row.source = s;
  row.source_kind = source.kind();
  row.harmonic = k;
  row.mode = first.index;
  row.mode_name = first.name;
  for (size_t g = 1; g < group.size(); ++g) row.mode_name += " + " + group[g]->name;
  row.frequency_hz = first.frequency_hz;
  const int out = reported_dof(system, group, magnitude);
  row.output = system.dofs[out].label;
  add_growth_and_friction(system, group, Q, d.F0, magnitude(out), &row);
  const HarmonicResponse response =
      respond(system, modes, load, source_load, options.friction_reference_amplitude).response;
  row.unbounded = unbounded_at(response, modes, out);
  row.amplitude = row.unbounded ? 0.0 : std::abs(response.displacement(out));
  return row;
}

}  // namespace

std::vector<CriticalSpeed> find_critical_speeds(const LinearSystem& system, const ModalResult& modes,
                                                const std::vector<const ExcitationSource*>& sources,
                                                const CriticalSpeedOptions& options, AnalysisSummary* summary) {
  require_valid(options, "critical speeds: ");
  if (summary) *summary = AnalysisSummary{};
  StageClock clock(summary);  // no clock, no strings without a summary
  const auto groups = response::eigenspaces(modes);
  int in_range = 0;
  std::vector<CriticalSpeed> found;
  for (size_t s = 0; s < sources.size(); ++s) {
    const ExcitationSource& source = *sources[s];
    for (int k = 1; k <= source.harmonic_count(); ++k)
      for (const auto& group : groups) {
        const double speed = source.speed_for(group.front()->frequency_hz, k);
        if (speed < options.min_speed || speed > options.max_speed) continue;
        ++in_range;
        if (auto row = resonance(system, modes, source, static_cast<int>(s), k, speed, group, options))
          found.push_back(std::move(*row));
      }
  }
  clock.lap("resonances");
  std::stable_sort(found.begin(), found.end(),
                   [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
  clock.lap("sort");
  if (summary) {
    summary->analysis = "critical speeds";
    summary->method = "V = Λ·f/k for each source harmonic and eigenspace, modal force against 1e-9 of the source's "
                      "total load, direct harmonic solve at each resonance";
    const double driven = static_cast<double>(found.size());
    summary->checks.push_back({"resonances driven, of those in range", driven, static_cast<double>(in_range), true});
    const double stopped = static_cast<double>(
        std::count_if(found.begin(), found.end(), [](const CriticalSpeed& c) { return c.friction_stops; }));
    summary->checks.push_back({"resonances leaf friction stops (Den Hartog)", stopped, driven, true});
  }
  return found;
}

}  // namespace railmodal
