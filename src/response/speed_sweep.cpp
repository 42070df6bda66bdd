// Amplitude against speed: a source swept over many speeds, fast and exact.
//
// Every source's load is Q(ω) = s(ω)(Q_K + iωQ_C) with speed-independent parts (see
// SeparableLoad). Where modal superposition is exact — C = 0 or proportional, and no damper
// on a massless DOF — the parts are projected on the modes once, and each speed costs a few
// complex operations per mode and output. With discrete dampers (non-proportional C) the
// complex modes of the first-order form do the same, where they are well conditioned and agree
// with the direct solve at sample speeds. Otherwise each speed is one direct solve, still
// without rebuilding the load.
#include <Eigen/Dense>
#include <cmath>
#include <algorithm>
#include <array>
#include <complex>
#include <functional>
#include <limits>
#include <stdexcept>

#include "railmodal/response.hpp"
#include "response/state_space_modes.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kAtResonance = 1e-9;  // as in the direct solve: ω² within 1e-9 of λ
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

// The source's input of harmonic 1 at its leading wheel (smallest delay), or its first force,
// at the reference frequency of its separable load: the phase reference of the curves.
std::complex<double> reference_input(const LinearSystem& system, const ExcitationSource& source) {
  const HarmonicLoad load = source.load(system, 1e-3 * source.wavelength(), 1);
  const WheelInput* lead = nullptr;
  for (const WheelInput& w : load.wheels)
    if (w.amplitude.cwiseAbs().maxCoeff() > 0.0 && (!lead || w.delay_s < lead->delay_s)) lead = &w;
  const Eigen::Vector3cd* u = lead ? &lead->amplitude : nullptr;
  for (const PointForce& f : load.forces)
    if (!u && f.amplitude.cwiseAbs().maxCoeff() > 0.0) u = &f.amplitude;
  if (!u) return 0.0;
  int largest = 0;
  for (int d = 1; d < 3; ++d)
    if (std::abs((*u)(d)) > std::abs((*u)(largest))) largest = d;
  return (*u)(largest);
}

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

// Phase of the FRF in degrees from arg x − arg input (rad), +90° per time derivative, in
// (−180, 180].
double wrapped_phase_deg(double difference, ResponseQuantity q) {
  double phase = difference * kDegrees +
                 (q == ResponseQuantity::velocity ? 90.0 : q == ResponseQuantity::acceleration ? 180.0 : 0.0);
  while (phase > 180.0) phase -= 360.0;
  while (phase <= -180.0) phase += 360.0;
  return phase;
}

// Phase of the FRF in degrees: x against an input of argument `input_arg` (rad). arg x − arg
// input rather than arg(x/input): one atan2 per speed, no complex division.
double phase_deg(std::complex<double> x, double input_arg, ResponseQuantity q) {
  if (x == 0.0) return 0.0;
  return wrapped_phase_deg(std::arg(x) - input_arg, q);
}

// The same against the input `scale`·`input` (scale real: its sign turns the input by π).
double phase_deg(std::complex<double> x, double scale, std::complex<double> input, ResponseQuantity q) {
  if (input == 0.0 || scale == 0.0) return 0.0;
  return phase_deg(x, std::arg(input) + (scale < 0.0 ? kPi : 0.0), q);
}

// Whether an expansion of the response (`at_speed(k, dof, ω, s)`) matches the direct solve at
// nine speeds spread over the sweep, every harmonic and output: to 1e-8 of the response's
// largest entry. The expansion is exact in exact arithmetic; its round-off grows with the
// conditioning of the eigenvectors, and this is where a bad case shows before it is used.
template <typename AtSpeed>
bool agrees_with_direct(const LinearSystem& system, const ModalResult& modes, const ExcitationSource& source,
                        const std::vector<SeparableLoad>& parts, const std::vector<OutputRequest>& outputs,
                        const std::vector<double>& speeds, const AtSpeed& at_speed) {
  if (speeds.empty()) return true;
  for (int sample = 0; sample <= 8; ++sample) {
    const double speed = speeds[(speeds.size() - 1) * sample / 8];
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const SeparableLoad& p = parts[k - 1];
      const double omega = kTwoPi * source.frequency_hz(speed, k);
      const double scale = source.load_scale(omega, p.reference_omega);
      const HarmonicResponse direct = harmonic_response(
          system, modes, scale * (p.stiffness_part + std::complex<double>(0.0, omega) * p.damping_part), omega / kTwoPi);
      if (direct.unbounded) return false;
      const double size = direct.displacement.cwiseAbs().maxCoeff();
      for (const OutputRequest& o : outputs)
        if (!(std::abs(at_speed(k, o.dof, omega, scale) - direct.displacement(o.dof)) <= 1e-8 * size)) return false;
    }
  }
  return true;
}

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
  const std::complex<double> input = reference_input(system, source);
  const ModalBasis basis = modal_basis(system, modes);
  std::vector<SeparableLoad> parts;
  for (int k = 1; k <= source.harmonic_count(); ++k) parts.push_back(source.separable_load(system, k));

  auto power = [](ResponseQuantity q, double omega) {
    return q == ResponseQuantity::displacement ? 1.0 : q == ResponseQuantity::velocity ? omega : omega * omega;
  };
  auto finish = [&](double speed, const std::vector<double>& sum, const std::vector<bool>& unbounded,
                    const std::vector<double>& phase) {
    for (size_t o = 0; o < outputs.size(); ++o) {
      curves[o].speeds.push_back(speed);
      curves[o].amplitudes.push_back(unbounded[o] ? 0.0 : sum[o]);
      curves[o].unbounded.push_back(unbounded[o]);
      curves[o].phases_deg.push_back(unbounded[o] ? 0.0 : phase[o]);
    }
  };

  // Speeds as arrays (vectorised by Eigen), one pass per harmonic and output DOF: `respond`
  // adds the complex response of one DOF to a harmonic's load at every speed (re, im) and
  // flags the speeds where it is unbounded; the sums over harmonics and the phases are common.
  using Flags = Eigen::Array<bool, Eigen::Dynamic, 1>;
  using Respond = std::function<void(int k, int dof, const Eigen::ArrayXd& w, const Eigen::ArrayXd& w2,
                                     const Eigen::ArrayXd& scale, Eigen::ArrayXd& re, Eigen::ArrayXd& im, Flags& resonant)>;
  bool ascending = false;  // the speeds in increasing order (set by `vectorised`)
  auto vectorised = [&](const Respond& respond) {
    const int count = static_cast<int>(speeds.size());
    const Eigen::ArrayXd V = Eigen::Map<const Eigen::ArrayXd>(speeds.data(), count);
    ascending = std::is_sorted(speeds.begin(), speeds.end());
    if (!(V > 0.0).all() || !V.isFinite().all()) throw std::invalid_argument("amplitude curve: speeds must be positive");
    // Each output DOF once: displacement, velocity and acceleration of one DOF share its
    // response, its unbounded speeds and its phase (one atan2 per speed and DOF).
    std::vector<int> dofs;
    for (const OutputRequest& o : outputs)
      if (std::find(dofs.begin(), dofs.end(), o.dof) == dofs.end()) dofs.push_back(o.dof);
    auto slot = [&](int dof) { return static_cast<size_t>(std::find(dofs.begin(), dofs.end(), dof) - dofs.begin()); };
    bool wants[3] = {false, false, false};
    for (const OutputRequest& o : outputs) wants[static_cast<int>(o.quantity)] = true;
    // Σ_k |x_k|·ω_k^p for p = 0, 1, 2 (displacement, velocity, acceleration), per DOF.
    std::vector<std::array<Eigen::ArrayXd, 3>> sum(dofs.size());
    for (auto& per_dof : sum)
      for (int q = 0; q < 3; ++q)
        if (wants[q]) per_dof[q] = Eigen::ArrayXd::Zero(count);
    std::vector<Eigen::ArrayXd> first_arg(dofs.size(), Eigen::ArrayXd::Zero(count));  // arg x of harmonic 1, rad
    std::vector<Flags> unbounded(dofs.size(), Flags::Constant(count, false));
    Eigen::ArrayXd input_arg = Eigen::ArrayXd::Zero(count);  // arg of s(ω)·input, rad; NaN: no input
    // Work arrays, allocated once: fresh 80 kB arrays per mode cost more in page faults
    // than the arithmetic.
    Eigen::ArrayXd w(count), w2(count), scale(count), re(count), im(count), magnitude(count);
    Flags resonant(count);
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const SeparableLoad& p = parts[k - 1];
      w = V * (kTwoPi * k / source.wavelength());
      w2 = w.square();
      for (int v = 0; v < count; ++v) scale(v) = source.load_scale(w(v), p.reference_omega);
      if (k == 1) {
        const double arg = input == 0.0 ? kNaN : std::arg(input);
        for (int v = 0; v < count; ++v) input_arg(v) = scale(v) == 0.0 ? kNaN : arg + (scale(v) < 0.0 ? kPi : 0.0);
      }
      for (size_t d = 0; d < dofs.size(); ++d) {
        re.setZero();
        im.setZero();
        resonant.setConstant(false);
        respond(k, dofs[d], w, w2, scale, re, im, resonant);
        magnitude = (re.square() + im.square()).sqrt();
        if (wants[0]) sum[d][0] += magnitude;
        if (wants[1]) sum[d][1] += magnitude * w;
        if (wants[2]) sum[d][2] += magnitude * w2;
        unbounded[d] = unbounded[d] || resonant;
        if (k == 1)
          for (int v = 0; v < count; ++v) first_arg[d](v) = re(v) == 0.0 && im(v) == 0.0 ? kNaN : std::atan2(im(v), re(v));
      }
    }
    for (size_t o = 0; o < outputs.size(); ++o) {
      const size_t d = slot(outputs[o].dof);
      const int q = static_cast<int>(outputs[o].quantity);
      curves[o].speeds = speeds;
      curves[o].amplitudes.resize(count);
      curves[o].unbounded.resize(count);
      curves[o].phases_deg.resize(count);
      for (int v = 0; v < count; ++v) {
        curves[o].unbounded[v] = unbounded[d](v);
        curves[o].amplitudes[v] = unbounded[d](v) ? 0.0 : sum[d][q](v);
        const double arg = first_arg[d](v) - input_arg(v);
        curves[o].phases_deg[v] = unbounded[d](v) || std::isnan(arg) ? 0.0 : wrapped_phase_deg(arg, outputs[o].quantity);
      }
    }
    return curves;
  };

  if (basis.exact && !equivalent_friction) {
    // x_o(ω) = Σ_j φ_j(o)·s(ω)(a_j + iωb_j)/(λ_j − ω² + iωc_j) + s(ω)·static_o(ω).
    const int m = static_cast<int>(basis.modes.size());
    return vectorised([&](int k, int dof, const Eigen::ArrayXd& w, const Eigen::ArrayXd& w2, const Eigen::ArrayXd& scale,
                          Eigen::ArrayXd& re, Eigen::ArrayXd& im, Flags& resonant) {
      const SeparableLoad& p = parts[k - 1];
      const int count = static_cast<int>(w.size());
      const double q_norm_k = p.stiffness_part.norm(), q_norm_c = p.damping_part.norm();
      for (int j = 0; j < m; ++j) {
        const Mode& mode = *basis.modes[j];
        const double at = mode.shape(dof);
        if (at == 0.0) continue;
        const std::complex<double> a = mode.shape.cast<std::complex<double>>().dot(p.stiffness_part) * at;
        const std::complex<double> b = mode.shape.cast<std::complex<double>>().dot(p.damping_part) * at;
        if (a == 0.0 && b == 0.0) continue;  // the load does not reach this mode at all
        const double c = basis.damping[j], lambda = mode.eigenvalue;
        const bool moves = std::abs(at) > 1e-9 * mode.shape.cwiseAbs().maxCoeff();
        const bool undamped = mode.kind == ModeKind::oscillatory && c == 0.0;
        const double tolerance = undamped ? kAtResonance * lambda : -1.0;
        const double drive_floor = 1e-12 * std::abs(at) * mode.shape.norm();
        // One branch-free loop per mode, so that the compiler vectorises it. An undamped mode at
        // its own frequency adds nothing finite: the gap there becomes ∞ and the term exactly 0
        // (a select, where a branch or a masked division would stop the vectorising); those
        // speeds are flagged below.
        const double* wv = w.data();
        const double* w2v = w2.data();
        const double* sv = scale.data();
        double* rv = re.data();
        double* iv = im.data();
        const double ar = a.real(), ai = a.imag(), br = b.real(), bi = b.imag();
        if (undamped) {
          for (int v = 0; v < count; ++v) {
            const double gap = lambda - w2v[v];
            const double f = sv[v] / (std::abs(gap) <= tolerance ? kInfinity : gap);
            rv[v] += (ar - wv[v] * bi) * f;
            iv[v] += (ai + wv[v] * br) * f;
          }
        } else {
          for (int v = 0; v < count; ++v) {
            const double gap = lambda - w2v[v], di = wv[v] * c;
            const double nr = ar - wv[v] * bi, ni = ai + wv[v] * br;
            const double f = sv[v] / (gap * gap + di * di);
            rv[v] += (nr * gap + ni * di) * f;
            iv[v] += (ni * gap - nr * di) * f;
          }
        }
        // Unbounded where the undamped mode sits at ω, moves this DOF and the load drives it (as
        // the direct solve decides). ω² rises with the speed, so on a sorted grid those speeds
        // are one run found by bisection.
        if (undamped && moves) {
          const int first = ascending ? static_cast<int>(std::lower_bound(w2v, w2v + count, lambda - tolerance) - w2v) : 0;
          for (int v = first; v < count && (!ascending || w2v[v] <= lambda + tolerance); ++v)
            if (std::abs(lambda - w2v[v]) <= tolerance &&
                std::abs(a + std::complex<double>(0.0, wv[v]) * b) > drive_floor * (q_norm_k + wv[v] * q_norm_c))
              resonant(v) = true;
        }
      }
      // Massless DOFs also follow their own loads: K_mm⁻¹ Q_m(ω).
      for (size_t i = 0; i < basis.massless.size(); ++i) {
        if (basis.massless[i] != dof) continue;
        std::complex<double> sk = 0.0, sc = 0.0;
        for (size_t c = 0; c < basis.massless.size(); ++c) {
          sk += basis.massless_flexibility(i, c) * p.stiffness_part(basis.massless[c]);
          sc += basis.massless_flexibility(i, c) * p.damping_part(basis.massless[c]);
        }
        re += scale * (sk.real() - w * sc.imag());
        im += scale * (sk.imag() + w * sc.real());
      }
    });
  }

  // Discrete dampers (damping not proportional): the complex modes of the first-order form,
  // where they are trustworthy and agree with the direct solve at sample speeds; otherwise
  // (and for friction as equivalent viscous damping) one direct solve per speed below.
  if (!equivalent_friction) {
    if (const auto complex_modes = response::state_space_modes(system)) {
      const response::StateSpaceModes& cm = *complex_modes;
      std::vector<Eigen::VectorXcd> on_roots_k, on_roots_c;  // participations of Q_K and Q_C per harmonic
      for (const SeparableLoad& p : parts) {
        on_roots_k.push_back(cm.projection * p.stiffness_part);
        on_roots_c.push_back(cm.projection * p.damping_part);
      }
      auto at_speed = [&](int k, int dof, double omega, double scale) {
        std::complex<double> x = 0.0;
        const std::complex<double> iw(0.0, omega);
        for (Eigen::Index r = 0; r < cm.roots.size(); ++r)
          x += cm.shapes(dof, r) * (on_roots_k[k - 1](r) + iw * on_roots_c[k - 1](r)) / (iw - cm.roots(r));
        return scale * x;
      };
      if (agrees_with_direct(system, modes, source, parts, outputs, speeds, at_speed))
        return vectorised([&](int k, int dof, const Eigen::ArrayXd& w, const Eigen::ArrayXd&, const Eigen::ArrayXd& scale,
                              Eigen::ArrayXd& re, Eigen::ArrayXd& im, Flags&) {
          const int count = static_cast<int>(w.size());
          for (Eigen::Index r = 0; r < cm.roots.size(); ++r) {
            const std::complex<double> a = cm.shapes(dof, r) * on_roots_k[k - 1](r);
            const std::complex<double> b = cm.shapes(dof, r) * on_roots_c[k - 1](r);
            const double dr = -cm.roots(r).real(), lambda_im = cm.roots(r).imag();
            for (int v = 0; v < count; ++v) {
              // (a + iωb)/(iω − λ_r): every root strictly damped, so dr > 0 and no division by 0.
              const double nr = a.real() - w(v) * b.imag(), ni = a.imag() + w(v) * b.real();
              const double di = w(v) - lambda_im;
              const double f = scale(v) / (dr * dr + di * di);
              re(v) += (nr * dr + ni * di) * f;
              im(v) += (ni * dr - nr * di) * f;
            }
          }
        });
    }
  }

  // The direct path: non-proportional damping, or friction as equivalent viscous damping.
  std::vector<double> sum(outputs.size()), phase(outputs.size());
  std::vector<bool> unbounded(outputs.size());
  for (double speed : speeds) {
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(phase.begin(), phase.end(), 0.0);
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
        if (unbounded_at(r, modes, outputs[o].dof)) {
          unbounded[o] = true;
          continue;
        }
        sum[o] += std::abs(r.displacement(outputs[o].dof)) * power(outputs[o].quantity, omega);
        if (k == 1) phase[o] = phase_deg(r.displacement(outputs[o].dof), scale, input, outputs[o].quantity);
      }
    }
    finish(speed, sum, unbounded, phase);
  }
  return curves;
}

}  // namespace railmodal
