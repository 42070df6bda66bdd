// Amplitude against speed: a source swept over many speeds, fast and exact.
//
// Every source's load is Q(ω) = s(ω)(Q_K + iωQ_C) with speed-independent parts (see
// SeparableLoad). Where modal superposition is exact — C = 0 or proportional, and no damper
// on a massless DOF — the parts are projected on the modes once, and each speed costs a few
// complex operations per mode and output. Otherwise each speed is one direct solve, still
// without rebuilding the load.
#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "railmodal/response.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kAtResonance = 1e-9;  // as in the direct solve: ω² within 1e-9 of λ

struct ModalBasis {
  bool exact = false;
  std::vector<const Mode*> modes;  // all modes (oscillatory, rigid-body, unstable)
  std::vector<double> damping;     // φᵀCφ
  std::vector<int> massless;       // DOFs with no mass (condensed)
  Eigen::MatrixXd massless_flexibility;  // K_mm⁻¹
};

ModalBasis modal_basis(const LinearSystem& system, const ModalResult& modes) {
  ModalBasis b;
  const int n = system.size();
  for (const Mode& m : modes.modes) {
    b.modes.push_back(&m);
    b.damping.push_back(m.shape.dot(system.damping * m.shape));
  }
  for (int i = 0; i < n; ++i)
    if (system.mass.row(i).cwiseAbs().maxCoeff() == 0.0) b.massless.push_back(i);
  bool damped_massless = false;
  for (int i : b.massless) damped_massless = damped_massless || system.damping.row(i).cwiseAbs().maxCoeff() > 0.0;
  // Proportional damping: ΦᵀCΦ diagonal to round-off of its largest entry.
  double largest = 0.0, off = 0.0;
  for (size_t i = 0; i < b.modes.size(); ++i) {
    largest = std::max(largest, std::abs(b.damping[i]));
    for (size_t j = 0; j < i; ++j) off = std::max(off, std::abs(b.modes[i]->shape.dot(system.damping * b.modes[j]->shape)));
  }
  b.exact = !damped_massless && off <= 1e-12 * largest && static_cast<int>(b.modes.size()) + static_cast<int>(b.massless.size()) == n;
  if (!b.massless.empty()) {
    Eigen::MatrixXd Kmm(b.massless.size(), b.massless.size());
    for (size_t a = 0; a < b.massless.size(); ++a)
      for (size_t c = 0; c < b.massless.size(); ++c) Kmm(a, c) = system.stiffness(b.massless[a], b.massless[c]);
    b.massless_flexibility = Kmm.inverse();
  }
  return b;
}

// One source harmonic projected on the modes, for the requested outputs.
struct ProjectedHarmonic {
  int harmonic = 1;
  double reference_omega = 0.0;
  Eigen::VectorXcd modal_stiffness_part, modal_damping_part;  // φᵀQ_K, φᵀQ_C per mode
  Eigen::VectorXd shape_norm;  // ‖φ‖ per mode, and ‖Q_K‖, ‖Q_C‖: the driven test's scale
  double stiffness_norm = 0.0, damping_norm = 0.0;
  // Static response of each output that is a massless DOF: K_mm⁻¹ Q_m (stiffness, damping parts).
  std::vector<std::complex<double>> static_stiffness, static_damping;
};

}  // namespace

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
    c.speeds.reserve(speeds.size());
    c.amplitudes.reserve(speeds.size());
    c.unbounded.reserve(speeds.size());
    curves.push_back(c);
  }
  const bool equivalent_friction = friction_reference_amplitude > 0.0 && has_leaf_friction(system);
  const ModalBasis basis = modal_basis(system, modes);
  std::vector<SeparableLoad> parts;
  for (int k = 1; k <= source.harmonic_count(); ++k) parts.push_back(source.separable_load(system, k));

  auto power = [](ResponseQuantity q, double omega) {
    return q == ResponseQuantity::displacement ? 1.0 : q == ResponseQuantity::velocity ? omega : omega * omega;
  };
  auto finish = [&](double speed, const std::vector<double>& sum, const std::vector<bool>& unbounded) {
    for (size_t o = 0; o < outputs.size(); ++o) {
      curves[o].speeds.push_back(speed);
      curves[o].amplitudes.push_back(unbounded[o] ? 0.0 : sum[o]);
      curves[o].unbounded.push_back(unbounded[o]);
    }
  };

  if (basis.exact && !equivalent_friction) {
    // Project once.
    std::vector<ProjectedHarmonic> projected;
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const SeparableLoad& p = parts[k - 1];
      ProjectedHarmonic h;
      h.harmonic = k;
      h.reference_omega = p.reference_omega;
      const int m = static_cast<int>(basis.modes.size());
      h.modal_stiffness_part.resize(m);
      h.modal_damping_part.resize(m);
      h.shape_norm.resize(m);
      h.stiffness_norm = p.stiffness_part.norm();
      h.damping_norm = p.damping_part.norm();
      for (int j = 0; j < m; ++j) {
        const Eigen::VectorXcd phi = basis.modes[j]->shape.cast<std::complex<double>>();
        h.modal_stiffness_part(j) = phi.dot(p.stiffness_part);
        h.modal_damping_part(j) = phi.dot(p.damping_part);
        h.shape_norm(j) = basis.modes[j]->shape.norm();
      }
      for (const OutputRequest& o : outputs) {
        std::complex<double> sk = 0.0, sc = 0.0;
        for (size_t a = 0; a < basis.massless.size(); ++a)
          if (basis.massless[a] == o.dof)
            for (size_t c = 0; c < basis.massless.size(); ++c) {
              sk += basis.massless_flexibility(a, c) * p.stiffness_part(basis.massless[c]);
              sc += basis.massless_flexibility(a, c) * p.damping_part(basis.massless[c]);
            }
        h.static_stiffness.push_back(sk);
        h.static_damping.push_back(sc);
      }
      projected.push_back(h);
    }
    // Output entries of each mode, and whether the mode moves the output.
    const int m = static_cast<int>(basis.modes.size());
    Eigen::MatrixXd at(outputs.size(), m);
    std::vector<std::vector<bool>> moves(outputs.size(), std::vector<bool>(m));
    for (int j = 0; j < m; ++j) {
      const double largest = basis.modes[j]->shape.cwiseAbs().maxCoeff();
      for (size_t o = 0; o < outputs.size(); ++o) {
        at(o, j) = basis.modes[j]->shape(outputs[o].dof);
        moves[o][j] = std::abs(at(o, j)) > 1e-9 * largest;
      }
    }
    std::vector<double> sum(outputs.size());
    std::vector<bool> unbounded(outputs.size());
    std::vector<std::complex<double>> x(outputs.size());
    for (double speed : speeds) {
      if (!(speed > 0.0) || !std::isfinite(speed)) throw std::invalid_argument("amplitude curve: speeds must be positive");
      std::fill(sum.begin(), sum.end(), 0.0);
      std::fill(unbounded.begin(), unbounded.end(), false);
      for (const ProjectedHarmonic& h : projected) {
        const double omega = kTwoPi * source.frequency_hz(speed, h.harmonic);
        const std::complex<double> scale = source.load_scale(omega, h.reference_omega);
        const std::complex<double> iw(0.0, omega);
        std::fill(x.begin(), x.end(), std::complex<double>(0.0));
        for (int j = 0; j < m; ++j) {
          const Mode& mode = *basis.modes[j];
          const std::complex<double> force = scale * (h.modal_stiffness_part(j) + iw * h.modal_damping_part(j));
          const double gap = mode.eigenvalue - omega * omega;
          if (mode.kind == ModeKind::oscillatory && basis.damping[j] == 0.0 &&
              std::abs(gap) <= kAtResonance * mode.eigenvalue) {
            // An undamped mode at its own frequency: unbounded where it moves the output, if driven.
            if (std::abs(force) > 1e-12 * std::abs(scale) * h.shape_norm(j) * (h.stiffness_norm + omega * h.damping_norm))
              for (size_t o = 0; o < outputs.size(); ++o) unbounded[o] = unbounded[o] || moves[o][j];
            continue;
          }
          const std::complex<double> q = force / std::complex<double>(gap, omega * basis.damping[j]);
          for (size_t o = 0; o < outputs.size(); ++o) x[o] += at(o, j) * q;
        }
        for (size_t o = 0; o < outputs.size(); ++o) {
          x[o] += scale * (h.static_stiffness[o] + iw * h.static_damping[o]);
          sum[o] += std::abs(x[o]) * power(outputs[o].quantity, omega);
        }
      }
      finish(speed, sum, unbounded);
    }
    return curves;
  }

  // The direct path: non-proportional damping, or friction as equivalent viscous damping.
  std::vector<double> sum(outputs.size());
  std::vector<bool> unbounded(outputs.size());
  for (double speed : speeds) {
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(unbounded.begin(), unbounded.end(), false);
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const SeparableLoad& p = parts[k - 1];
      const double omega = kTwoPi * source.frequency_hz(speed, k);
      const double scale = source.load_scale(omega, p.reference_omega);
      const std::complex<double> iw(0.0, omega);
      HarmonicResponse r;
      if (equivalent_friction) {
        // The damper also changes the input's velocity term: rebuild the load on that system.
        const LinearSystem damped = with_equivalent_friction_damping(system, omega, friction_reference_amplitude);
        const HarmonicLoad load = source.load(damped, speed, k);
        r = harmonic_response(damped, modes, generalized_load(damped, load), load.frequency_hz);
      } else {
        r = harmonic_response(system, modes, scale * (p.stiffness_part + iw * p.damping_part), omega / kTwoPi);
      }
      for (size_t o = 0; o < outputs.size(); ++o) {
        if (unbounded_at(r, modes, outputs[o].dof)) unbounded[o] = true;
        else sum[o] += std::abs(r.displacement(outputs[o].dof)) * power(outputs[o].quantity, omega);
      }
    }
    finish(speed, sum, unbounded);
  }
  return curves;
}

}  // namespace railmodal
