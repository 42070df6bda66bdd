// Critical speeds: where a harmonic of a source meets a natural frequency, and how much
// the resonance is worth there.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "railmodal/response.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;

int dominant_dof(const Mode& mode) {
  int best = 0;
  for (int d = 1; d < mode.kinetic_energy_share.size(); ++d)
    if (mode.kinetic_energy_share(d) > mode.kinetic_energy_share(best)) best = d;
  return best;
}

// The mode has a non-zero entry at this DOF (beyond round-off of its largest entry).
bool moves(const Mode& mode, int dof) {
  return std::abs(mode.shape(dof)) > 1e-9 * mode.shape.cwiseAbs().maxCoeff();
}

HarmonicResponse response_without_mode(const LinearSystem& system, const ModalResult& modes,
                                       const Eigen::VectorXcd& load, double frequency_hz, int mode_index) {
  ModalResult rest = modes;
  rest.modes.erase(rest.modes.begin() + (mode_index - 1));
  return modal_harmonic_response(system, rest, load, frequency_hz);
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

Evaluation respond(const LinearSystem& system, const ModalResult& modes, const HarmonicLoad& load,
                   double friction_reference_amplitude) {
  Evaluation e;
  if (friction_reference_amplitude > 0.0 && load.frequency_hz > 0.0 && has_leaf_friction(system))
    e.damped = with_equivalent_friction_damping(system, 2.0 * kPi * load.frequency_hz, friction_reference_amplitude);
  e.load = generalized_load(e.system(system), load);
  e.response = harmonic_response(e.system(system), modes, e.load, load.frequency_hz);
  return e;
}

}  // namespace

std::vector<CriticalSpeed> find_critical_speeds(const LinearSystem& system, const ModalResult& modes,
                                                const std::vector<const ExcitationSource*>& sources,
                                                const CriticalSpeedOptions& options) {
  if (!(options.min_speed > 0.0) || !(options.max_speed >= options.min_speed) || !std::isfinite(options.max_speed))
    throw std::invalid_argument("critical speeds: need 0 < min_speed ≤ max_speed");
  std::vector<CriticalSpeed> found;
  for (size_t s = 0; s < sources.size(); ++s) {
    const ExcitationSource& source = *sources[s];
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      std::vector<CriticalSpeed> rows;
      std::vector<double> modal_forces;
      for (const Mode& mode : modes.modes) {
        if (mode.kind != ModeKind::oscillatory) continue;
        const double speed = source.speed_for(mode.frequency_hz, k);
        if (speed < options.min_speed || speed > options.max_speed) continue;
        const HarmonicLoad load = source.load(system, speed, k);
        const Eigen::VectorXcd Q = generalized_load(system, load);
        const double F0 = std::abs(mode.shape.cast<std::complex<double>>().dot(Q));

        CriticalSpeed row;
        row.speed = speed;
        row.source = static_cast<int>(s);
        row.source_kind = source.kind();
        row.harmonic = k;
        row.mode = mode.index;
        row.mode_name = mode.name;
        row.frequency_hz = mode.frequency_hz;
        const int out = dominant_dof(mode);
        row.output = system.dofs[out].label;
        const double at_output = std::abs(mode.shape(out));
        // Undamped growth at resonance: q = F₀ t sin(ωt)/(2ω), π F₀/(2λ) per half period π/ω.
        row.growth_per_half_period = kPi * F0 / (2.0 * mode.eigenvalue) * at_output;
        const double friction = modal_friction_work(system, mode.shape);
        row.friction_decrement_per_half_period = 2.0 * friction / mode.eigenvalue * at_output;
        if (friction > 0.0) {
          row.friction_stops = kPi * F0 <= 4.0 * friction;
          row.friction_threshold_scale = F0 > 0.0 ? 4.0 * friction / (kPi * F0) : INFINITY;
        }
        const HarmonicResponse response = respond(system, modes, load, options.friction_reference_amplitude).response;
        row.unbounded = response.unbounded;
        row.amplitude = response.unbounded ? 0.0 : std::abs(response.displacement(out));
        rows.push_back(row);
        modal_forces.push_back(F0);
      }
      const double largest = modal_forces.empty() ? 0.0 : *std::max_element(modal_forces.begin(), modal_forces.end());
      for (size_t r = 0; r < rows.size(); ++r)
        if (largest > 0.0 && modal_forces[r] > options.participation_floor * largest) found.push_back(rows[r]);
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
  return found;
}

std::vector<AmplitudeCurve> amplitude_curves(const LinearSystem& system, const ModalResult& modes,
                                             const ExcitationSource& source, int source_index,
                                             const std::vector<OutputRequest>& outputs,
                                             const std::vector<double>& speeds,
                                             double friction_reference_amplitude) {
  std::vector<AmplitudeCurve> curves;
  for (const OutputRequest& o : outputs) {
    if (o.dof < 0 || o.dof >= system.size()) throw std::invalid_argument("amplitude curve: no such output DOF");
    AmplitudeCurve c;
    c.source = source_index;
    c.output = system.dofs[o.dof].label;
    c.quantity = o.quantity;
    curves.push_back(c);
  }
  for (double speed : speeds) {
    std::vector<double> sum(outputs.size(), 0.0);
    std::vector<bool> unbounded(outputs.size(), false);
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const HarmonicLoad load = source.load(system, speed, k);
      const Evaluation e = respond(system, modes, load, friction_reference_amplitude);
      const HarmonicResponse& r = e.response;
      const LinearSystem& used = e.system(system);
      std::optional<HarmonicResponse> without;  // the response less the resonant mode
      for (size_t o = 0; o < outputs.size(); ++o) {
        if (!r.unbounded) {
          sum[o] += response_amplitude(r, outputs[o].dof, outputs[o].quantity);
        } else if (moves(modes.modes[r.resonant_mode - 1], outputs[o].dof) || used.damping.any()) {
          unbounded[o] = true;
        } else {
          // Undamped, and the resonant mode does not move this output: its contribution is
          // zero at every frequency, so the other modes give the exact response here.
          if (!without) without = response_without_mode(used, modes, e.load, load.frequency_hz, r.resonant_mode);
          sum[o] += response_amplitude(*without, outputs[o].dof, outputs[o].quantity);
        }
      }
    }
    for (size_t o = 0; o < outputs.size(); ++o) {
      curves[o].speeds.push_back(speed);
      curves[o].amplitudes.push_back(unbounded[o] ? 0.0 : sum[o]);
      curves[o].unbounded.push_back(unbounded[o]);
    }
  }
  return curves;
}

}  // namespace railmodal
