// Critical speeds: where a harmonic of a source meets a natural frequency, and how much
// the resonance is worth there.
#include <Eigen/Dense>
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

// Undamped modes at this frequency: φᵀCφ = 0 with C positive semi-definite means Cφ = 0,
// so each is an exact null vector of the dynamic stiffness D = K − ω²M + iωC.
std::vector<const Mode*> undamped_modes_at(const LinearSystem& system, const ModalResult& modes, double omega) {
  std::vector<const Mode*> at;
  for (const Mode& m : modes.modes)
    if (m.kind == ModeKind::oscillatory && std::abs(m.eigenvalue - omega * omega) <= 1e-9 * m.eigenvalue &&
        m.shape.dot(system.damping * m.shape) == 0.0)
      at.push_back(&m);
  return at;
}

// The response less its resonant part: those modes decouple exactly, so the rest solves
// D x = Q − Σ Mφ(φᵀQ) with x M-orthogonal to them (a bordered system, exact with damping).
HarmonicResponse response_without_resonant_modes(const LinearSystem& system, const std::vector<const Mode*>& resonant,
                                                 const Eigen::VectorXcd& load, double frequency_hz) {
  const int n = system.size(), r = static_cast<int>(resonant.size());
  const double omega = 2.0 * kPi * frequency_hz;
  const std::complex<double> i(0.0, 1.0);
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(n + r, n + r);
  A.topLeftCorner(n, n) = (system.stiffness - omega * omega * system.mass).cast<std::complex<double>>() +
                          i * omega * system.damping.cast<std::complex<double>>();
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(n + r);
  rhs.head(n) = load;
  for (int k = 0; k < r; ++k) {
    const Eigen::VectorXd b = system.mass * resonant[k]->shape;
    A.block(0, n + k, n, 1) = b.cast<std::complex<double>>();
    A.block(n + k, 0, 1, n) = b.transpose().cast<std::complex<double>>();
    rhs.head(n) -= b.cast<std::complex<double>>() * resonant[k]->shape.cast<std::complex<double>>().dot(load);
  }
  HarmonicResponse out;
  out.frequency_hz = frequency_hz;
  out.displacement = A.partialPivLu().solve(rhs).head(n);
  return out;
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
      if (!r.unbounded) {
        for (size_t o = 0; o < outputs.size(); ++o)
          sum[o] += response_amplitude(r, outputs[o].dof, outputs[o].quantity);
        continue;
      }
      // An output that no driven resonant mode moves keeps a finite amplitude: the rest.
      const auto resonant = undamped_modes_at(used, modes, 2.0 * kPi * load.frequency_hz);
      std::optional<HarmonicResponse> rest;
      for (size_t o = 0; o < outputs.size(); ++o) {
        bool moved = false;
        for (const Mode* m : resonant)
          moved = moved || (moves(*m, outputs[o].dof) &&
                            std::abs(m->shape.cast<std::complex<double>>().dot(e.load)) > 1e-12 * e.load.norm() * m->shape.norm());
        if (moved) {
          unbounded[o] = true;
          continue;
        }
        if (!rest) rest = response_without_resonant_modes(used, resonant, e.load, load.frequency_hz);
        sum[o] += response_amplitude(*rest, outputs[o].dof, outputs[o].quantity);
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
