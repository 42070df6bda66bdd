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
constexpr double kRoundOffShare = 1e-12;  // a mode shape's component indistinguishable from 0
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

// Phase of the FRF in degrees: x against the input `scale`·`input` (scale real: its sign turns
// the input by π). arg x − arg input rather than arg(x/input): no complex division.
double phase_deg(std::complex<double> x, double scale, std::complex<double> input, ResponseQuantity q) {
  if (input == 0.0 || scale == 0.0 || x == 0.0) return 0.0;
  return wrapped_phase_deg(std::arg(x) - (std::arg(input) + (scale < 0.0 ? kPi : 0.0)), q);
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

// A block of speeds for the vectorised kernels: ω, ω², the load scale s(ω), and the response
// (re, im) and unbounded flags they add to.
constexpr int kBlock = 256;
struct Block {
  const double* w;
  const double* w2;
  const double* scale;
  double* re;
  double* im;
  unsigned char* resonant;  // 0 or 1 (bytes: the flag loops vectorise)
  int count;
  bool ascending;  // ω rises through the block
};
using Kernel = std::function<void(const Block&)>;
using Prepare = std::function<Kernel(int harmonic, int dof)>;

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

  // Speeds in blocks small enough to stay in L1 cache, one pass per block, harmonic and output
  // DOF: `prepare(k, dof)` projects harmonic k's load on the modes once and returns the kernel
  // that adds the complex response of that DOF at a block of speeds (re, im) and flags the
  // speeds where it is unbounded; the sums over harmonics and the phases are common. No array
  // spans all speeds but the curves themselves: fresh 80 kB work arrays per harmonic cost more
  // in page faults and cache misses than the arithmetic.
  auto vectorised = [&](const Prepare& prepare) {
    const int count = static_cast<int>(speeds.size());
    const bool ascending = std::is_sorted(speeds.begin(), speeds.end());
    for (double v : speeds)
      if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument("amplitude curve: speeds must be positive");
    // Each output DOF once: displacement, velocity and acceleration of one DOF share its
    // response, its unbounded speeds and its phase (one atan2 per speed and DOF).
    std::vector<int> dofs;
    for (const OutputRequest& o : outputs)
      if (std::find(dofs.begin(), dofs.end(), o.dof) == dofs.end()) dofs.push_back(o.dof);
    auto slot = [&](int dof) { return static_cast<size_t>(std::find(dofs.begin(), dofs.end(), dof) - dofs.begin()); };
    std::vector<std::vector<Kernel>> kernels(source.harmonic_count());
    for (int k = 1; k <= source.harmonic_count(); ++k)
      for (int dof : dofs) kernels[k - 1].push_back(prepare(k, dof));
    for (AmplitudeCurve& c : curves) {
      c.speeds = speeds;
      c.amplitudes.resize(count);
      c.unbounded.resize(count);
      c.phases_deg.resize(count);
    }
    // Per block: Σ_k |x_k|·ω_k^p for p = 0, 1, 2 (displacement, velocity, acceleration), arg x
    // of harmonic 1 (rad) and the unbounded flags, per DOF; arg of s(ω)·input (NaN: no input).
    struct PerDof {
      std::array<std::array<double, kBlock>, 3> sum;
      std::array<double, kBlock> first_arg;
      std::array<unsigned char, kBlock> unbounded;
    };
    std::vector<PerDof> per_dof(dofs.size());
    alignas(64) std::array<double, kBlock> w, w2, scale, re, im, input_arg;
    std::array<unsigned char, kBlock> resonant;
    const double reference_arg = input == 0.0 ? kNaN : std::arg(input);
    for (int begin = 0; begin < count; begin += kBlock) {
      const int n = std::min(kBlock, count - begin);
      for (PerDof& d : per_dof) {
        for (auto& sum : d.sum) std::fill_n(sum.begin(), n, 0.0);
        std::fill_n(d.unbounded.begin(), n, 0);
      }
      for (int k = 1; k <= source.harmonic_count(); ++k) {
        const SeparableLoad& p = parts[k - 1];
        const double to_omega = kTwoPi * k / source.wavelength();
        for (int v = 0; v < n; ++v) {
          w[v] = speeds[begin + v] * to_omega;
          w2[v] = w[v] * w[v];
        }
        for (int v = 0; v < n; ++v) scale[v] = source.load_scale(w[v], p.reference_omega);
        if (k == 1)
          for (int v = 0; v < n; ++v) input_arg[v] = scale[v] == 0.0 ? kNaN : reference_arg + (scale[v] < 0.0 ? kPi : 0.0);
        for (size_t d = 0; d < dofs.size(); ++d) {
          std::fill_n(re.begin(), n, 0.0);
          std::fill_n(im.begin(), n, 0.0);
          std::fill_n(resonant.begin(), n, 0);
          kernels[k - 1][d](Block{w.data(), w2.data(), scale.data(), re.data(), im.data(), resonant.data(), n, ascending});
          PerDof& out = per_dof[d];
          // Separate arrays, so that each loop vectorises.
          const double* __restrict rv = re.data();
          const double* __restrict iv = im.data();
          double* __restrict s0 = out.sum[0].data();
          double* __restrict s1 = out.sum[1].data();
          double* __restrict s2 = out.sum[2].data();
          for (int v = 0; v < n; ++v) {
            const double magnitude = std::sqrt(rv[v] * rv[v] + iv[v] * iv[v]);
            s0[v] += magnitude;
            s1[v] += magnitude * w[v];
            s2[v] += magnitude * w2[v];
          }
          for (int v = 0; v < n; ++v) out.unbounded[v] |= resonant[v];
          if (k == 1)
            for (int v = 0; v < n; ++v) out.first_arg[v] = re[v] == 0.0 && im[v] == 0.0 ? kNaN : std::atan2(im[v], re[v]);
        }
      }
      for (size_t o = 0; o < outputs.size(); ++o) {
        const PerDof& d = per_dof[slot(outputs[o].dof)];
        const int q = static_cast<int>(outputs[o].quantity);
        AmplitudeCurve& c = curves[o];
        for (int v = 0; v < n; ++v) {
          c.unbounded[begin + v] = d.unbounded[v];
          c.amplitudes[begin + v] = d.unbounded[v] ? 0.0 : d.sum[q][v];
          const double arg = d.first_arg[v] - input_arg[v];
          c.phases_deg[begin + v] = d.unbounded[v] || std::isnan(arg) ? 0.0 : wrapped_phase_deg(arg, outputs[o].quantity);
        }
      }
    }
    return curves;
  };

  if (basis.exact && !equivalent_friction) {
    // x_o(ω) = Σ_j φ_j(o)·s(ω)(a_j + iωb_j)/(λ_j − ω² + iωc_j) + s(ω)·static_o(ω).
    const int m = static_cast<int>(basis.modes.size());
    struct Term {
      double ar, ai, br, bi, lambda, c, tolerance;
      bool undamped, moves;
      std::complex<double> a, b;
      double drive_floor;
    };
    return vectorised([&](int k, int dof) -> Kernel {
      const SeparableLoad& p = parts[k - 1];
      const double q_norm_k = p.stiffness_part.norm(), q_norm_c = p.damping_part.norm();
      std::vector<Term> terms;
      for (int j = 0; j < m; ++j) {
        const Mode& mode = *basis.modes[j];
        // A mode whose share of this DOF is at the eigensolver's round-off (below 1e-12 of its
        // largest component: a pitch mode at the body's bounce in a symmetric car) adds noise,
        // not response; skipping it changes the output by at most 1e-12 of that mode's own
        // response at its largest DOF, and most outputs of a symmetric vehicle skip most modes.
        const double at = mode.shape(dof);
        if (std::abs(at) <= kRoundOffShare * mode.shape.cwiseAbs().maxCoeff()) continue;
        const std::complex<double> a = mode.shape.cast<std::complex<double>>().dot(p.stiffness_part) * at;
        const std::complex<double> b = mode.shape.cast<std::complex<double>>().dot(p.damping_part) * at;
        if (a == 0.0 && b == 0.0) continue;  // the load does not reach this mode at all
        const double c = basis.damping[j], lambda = mode.eigenvalue;
        const bool undamped = mode.kind == ModeKind::oscillatory && c == 0.0;
        terms.push_back({a.real(), a.imag(), b.real(), b.imag(), lambda, c, undamped ? kAtResonance * lambda : -1.0,
                         undamped, std::abs(at) > 1e-9 * mode.shape.cwiseAbs().maxCoeff(), a, b,
                         1e-12 * std::abs(at) * mode.shape.norm()});
      }
      // Massless DOFs also follow their own loads: K_mm⁻¹ Q_m(ω).
      std::complex<double> sk = 0.0, sc = 0.0;
      for (size_t i = 0; i < basis.massless.size(); ++i) {
        if (basis.massless[i] != dof) continue;
        for (size_t c = 0; c < basis.massless.size(); ++c) {
          sk += basis.massless_flexibility(i, c) * p.stiffness_part(basis.massless[c]);
          sc += basis.massless_flexibility(i, c) * p.damping_part(basis.massless[c]);
        }
      }
      return [terms = std::move(terms), sk, sc, q_norm_k, q_norm_c](const Block& b) {
        const int n = b.count;
        const double* __restrict wv = b.w;
        const double* __restrict w2v = b.w2;
        const double* __restrict sv = b.scale;
        double* __restrict rv = b.re;
        double* __restrict iv = b.im;
        for (const Term& t : terms) {
          // One branch-free loop per mode, so that the compiler vectorises it. An undamped mode
          // at its own frequency adds nothing finite: the gap there becomes ∞ and the term
          // exactly 0 (a select, where a branch or a masked division would stop the
          // vectorising); those speeds are flagged below.
          if (t.undamped) {
            for (int v = 0; v < n; ++v) {
              const double gap = t.lambda - w2v[v];
              const double f = sv[v] / (std::abs(gap) <= t.tolerance ? kInfinity : gap);
              rv[v] += (t.ar - wv[v] * t.bi) * f;
              iv[v] += (t.ai + wv[v] * t.br) * f;
            }
          } else {
            for (int v = 0; v < n; ++v) {
              const double gap = t.lambda - w2v[v], di = wv[v] * t.c;
              const double nr = t.ar - wv[v] * t.bi, ni = t.ai + wv[v] * t.br;
              const double f = sv[v] / (gap * gap + di * di);
              rv[v] += (nr * gap + ni * di) * f;
              iv[v] += (ni * gap - nr * di) * f;
            }
          }
          // Unbounded where the undamped mode sits at ω, moves this DOF and the load drives it
          // (as the direct solve decides). ω² rises with the speed, so on a sorted grid those
          // speeds are one run found by bisection.
          if (t.undamped && t.moves) {
            const int first = b.ascending ? static_cast<int>(std::lower_bound(w2v, w2v + n, t.lambda - t.tolerance) - w2v) : 0;
            for (int v = first; v < n && (!b.ascending || w2v[v] <= t.lambda + t.tolerance); ++v)
              if (std::abs(t.lambda - w2v[v]) <= t.tolerance &&
                  std::abs(t.a + std::complex<double>(0.0, wv[v]) * t.b) > t.drive_floor * (q_norm_k + wv[v] * q_norm_c))
                b.resonant[v] = 1;
          }
        }
        if (sk != 0.0 || sc != 0.0)
          for (int v = 0; v < n; ++v) {
            rv[v] += sv[v] * (sk.real() - wv[v] * sc.imag());
            iv[v] += sv[v] * (sk.imag() + wv[v] * sc.real());
          }
      };
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
        return vectorised([&](int k, int dof) -> Kernel {
          // (a_r + iωb_r)/(iω − λ_r) per root: every root strictly damped, so no division by 0.
          struct Root {
            double ar, ai, br, bi, decay, lambda_im;
          };
          std::vector<Root> terms;
          for (Eigen::Index r = 0; r < cm.roots.size(); ++r) {
            const std::complex<double> a = cm.shapes(dof, r) * on_roots_k[k - 1](r);
            const std::complex<double> b = cm.shapes(dof, r) * on_roots_c[k - 1](r);
            terms.push_back({a.real(), a.imag(), b.real(), b.imag(), -cm.roots(r).real(), cm.roots(r).imag()});
          }
          return [terms = std::move(terms)](const Block& b) {
            for (const Root& t : terms)
              for (int v = 0; v < b.count; ++v) {
                const double nr = t.ar - b.w[v] * t.bi, ni = t.ai + b.w[v] * t.br;
                const double di = b.w[v] - t.lambda_im;
                const double f = b.scale[v] / (t.decay * t.decay + di * di);
                b.re[v] += (nr * t.decay + ni * di) * f;
                b.im[v] += (ni * t.decay - nr * di) * f;
              }
          };
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
