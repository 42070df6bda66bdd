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
#include <memory>
#include <optional>
#include <stdexcept>

#include "model/analysis_limits.hpp"
#include "railmodal/response.hpp"
#include "response/modal_checks.hpp"
#include "response/state_space_modes.hpp"
#include "response/sweep_kernels.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kAtResonance = 1e-9;  // as in the direct solve: ω² within 1e-9 of λ
constexpr double kRoundOffShare = 1e-12;  // a mode shape's component indistinguishable from 0
// The complex modes cost a 2n×2n eigensolve and direct solves at nine speeds to check them,
// about 90 µs for the Manchester coach's lateral motions against 3–4 µs a speed for direct
// solves: up to this many speeds the direct solves are cheaper (peak refinement asks for one).
constexpr size_t kDirectUpTo = 16;
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
  // Cφ of each mode, into this thread's vectors kept between calls (every variant of a study
  // asks): the same products the expressions below made as temporaries, once each.
  thread_local std::vector<Eigen::VectorXd> damping_shape;
  if (damping_shape.size() < modes.modes.size()) damping_shape.resize(modes.modes.size());
  b.modes.reserve(modes.modes.size());
  b.damping.reserve(modes.modes.size());
  for (const Mode& m : modes.modes) {
    Eigen::VectorXd& c_phi = damping_shape[b.modes.size()];
    c_phi.noalias() = system.damping * m.shape;
    b.modes.push_back(&m);
    b.damping.push_back(m.shape.dot(c_phi));  // φᵀ(Cφ)
  }
  for (int i = 0; i < n; ++i)
    if (system.mass.row(i).cwiseAbs().maxCoeff() == 0.0) b.massless.push_back(i);
  bool damped_massless = false;
  for (int i : b.massless) damped_massless = damped_massless || system.damping.row(i).cwiseAbs().maxCoeff() > 0.0;
  // Proportional damping: ΦᵀCΦ diagonal to round-off of its largest entry.
  double largest = 0.0, off = 0.0;
  for (size_t i = 0; i < b.modes.size(); ++i) {
    largest = std::max(largest, std::abs(b.damping[i]));
    for (size_t j = 0; j < i; ++j) off = std::max(off, std::abs(b.modes[i]->shape.dot(damping_shape[j])));  // φᵢᵀ(Cφⱼ)
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

// The FRF's phase turns by +90° per time derivative of x.
double phase_offset_deg(ResponseQuantity q) {
  return q == ResponseQuantity::velocity ? 90.0 : q == ResponseQuantity::acceleration ? 180.0 : 0.0;
}

// What every way of sweeping shares: the problem, and the source's separable load per harmonic.
struct Sweep {
  const LinearSystem& system;
  const ModalResult& modes;
  const ExcitationSource& source;
  const std::vector<OutputRequest>& outputs;
  const SpeedGrid& speeds;
  std::vector<SeparableLoad> parts;  // harmonic k at k − 1
  double reference_arg;              // arg of the input that phases refer to; NaN without input
};

// The source's total load at a speed, √(Σ_k ‖Q_k‖²) over its harmonics, from the separable
// parts (without linearised friction): what response::kLoadRoundOff is relative to.
double source_load_at(const Sweep& s, double speed) {
  double squared = 0.0;
  for (int k = 1; k <= s.source.harmonic_count(); ++k) {
    const SeparableLoad& p = s.parts[k - 1];
    const double omega = kTwoPi * s.source.frequency_hz(speed, k);
    const double scale = s.source.load_scale(omega, p.reference_omega);
    squared += (scale * (p.stiffness_part + std::complex<double>(0.0, omega) * p.damping_part)).squaredNorm();
  }
  return std::sqrt(squared);
}

// Whether an expansion of the response (`at_speed(k, dof, ω, s)`) matches the direct solve at
// nine speeds spread over the sweep, every harmonic and output: to 1e-8 of the response's
// largest entry. The expansion is exact in exact arithmetic; its round-off grows with the
// conditioning of the eigenvectors, and this is where a bad case shows before it is used.
template <typename AtSpeed>
bool agrees_with_direct(const Sweep& s, const AtSpeed& at_speed) {
  const std::vector<double>& speeds = s.speeds.values();
  if (speeds.empty()) return true;
  for (int sample = 0; sample <= 8; ++sample) {
    const double speed = speeds[(speeds.size() - 1) * sample / 8];
    const double source_load = source_load_at(s, speed);
    for (int k = 1; k <= s.source.harmonic_count(); ++k) {
      const SeparableLoad& p = s.parts[k - 1];
      const double omega = kTwoPi * s.source.frequency_hz(speed, k);
      const double scale = s.source.load_scale(omega, p.reference_omega);
      const HarmonicResponse direct = harmonic_response(
          s.system, s.modes, scale * (p.stiffness_part + std::complex<double>(0.0, omega) * p.damping_part),
          omega / kTwoPi, source_load);
      if (direct.unbounded) return false;
      const double size = direct.displacement.cwiseAbs().maxCoeff();
      for (const OutputRequest& o : s.outputs)
        if (!(std::abs(at_speed(k, o.dof, omega, scale) - direct.displacement(o.dof)) <= 1e-8 * size)) return false;
    }
  }
  return true;
}

// What a kernel adds for one harmonic and output DOF at a block of speeds: the complex response
// into b.re and b.im, and 1 in `resonant` at the speeds where the response is unbounded (on a
// grid where ω rises, `ascending`, those are found by bisection); true if it flagged any.
using Kernel = std::function<bool(const response::SweepBlock& b, double* resonant, bool ascending)>;
using Prepare = std::function<Kernel(int harmonic, int dof)>;
using response::kSweepBlock;

// Each output DOF once: displacement, velocity and acceleration of one DOF share its
// response, its unbounded speeds and its phase (one arg x per speed and DOF).
struct OutputDofs {
  std::vector<int> dofs;
  std::vector<bool> phase;        // some output of this DOF wants its phase
  std::vector<size_t> of_output;  // where each output's DOF is in `dofs`
  bool any_phase = false;
};

OutputDofs output_dofs(const std::vector<OutputRequest>& outputs) {
  OutputDofs d;
  for (const OutputRequest& o : outputs)
    if (std::find(d.dofs.begin(), d.dofs.end(), o.dof) == d.dofs.end()) d.dofs.push_back(o.dof);
  for (const OutputRequest& o : outputs)
    d.of_output.push_back(static_cast<size_t>(std::find(d.dofs.begin(), d.dofs.end(), o.dof) - d.dofs.begin()));
  d.phase.assign(d.dofs.size(), false);
  for (size_t o = 0; o < outputs.size(); ++o) d.phase[d.of_output[o]] = d.phase[d.of_output[o]] || outputs[o].phase;
  d.any_phase = std::find(d.phase.begin(), d.phase.end(), true) != d.phase.end();
  return d;
}

// Per block and DOF: Σ_k |x_k|·ω_k^p for p = 0, 1, 2 (displacement, velocity,
// acceleration), arg x of harmonic 1 (rad), and the unbounded flags (0 or 1, as doubles so
// that the loops mixing them with values vectorise). Each array starts on a cache line: a
// std::vector aligns only to 16 bytes, and AVX2's 32-byte loads and stores across lines made a
// one-harmonic sweep with phases half as slow again (fette car, 10⁴ speeds: 0.12 against 0.08 ms).
struct DofSums {
  alignas(64) std::array<std::array<double, kSweepBlock>, 3> sum;
  alignas(64) std::array<double, kSweepBlock> first_arg;
  alignas(64) std::array<double, kSweepBlock> unbounded;
  bool any_unbounded;  // in this block: most blocks have none, and skip the flag loops
};

// The arrays of one block of speeds, reused from block to block: ω, ω², s(ω), the response of
// one harmonic and DOF, the arg of s(ω)·input (NaN: no input), and the kernels' flags.
struct BlockWork {
  alignas(64) std::array<double, kSweepBlock> w, w2, scale, re, im;
  alignas(64) std::array<double, kSweepBlock> input_arg;
  alignas(64) std::array<double, kSweepBlock> resonant{};  // all 0 between kernels
  std::vector<DofSums> per_dof;
};

// What the block loop runs: the output DOFs, and per harmonic (k at k − 1) the kernel of each.
struct BlockPlan {
  OutputDofs dofs;
  std::vector<std::vector<Kernel>> kernels;
  bool ascending;
};

// The sums of the sweep's first `dofs` output DOFs (the thread's list may hold more).
void clear_sums(std::vector<DofSums>& per_dof, size_t dofs, int n) {
  for (size_t i = 0; i < dofs; ++i) {
    DofSums& d = per_dof[i];
    for (auto& sum : d.sum) std::fill_n(sum.begin(), n, 0.0);
    std::fill_n(d.unbounded.begin(), n, 0.0);
    d.any_unbounded = false;
  }
}

// Adds harmonic k at the block of n speeds from `begin` to every DOF's sums; harmonic 1 also
// gives the arguments that the phases refer to.
void add_harmonic(const Sweep& s, const BlockPlan& plan, int k, int begin, int n, BlockWork& work) {
  const SeparableLoad& p = s.parts[k - 1];
  const double to_omega = kTwoPi * k / s.source.wavelength();
  const double* at = s.speeds.values().data() + begin;
  for (int v = 0; v < n; ++v) work.w[v] = at[v] * to_omega;
  for (int v = 0; v < n; ++v) work.w2[v] = work.w[v] * work.w[v];
  s.source.load_scales(work.w.data(), n, p.reference_omega, work.scale.data());
  if (k == 1 && plan.dofs.any_phase)
    response::input_arguments(work.scale.data(), s.reference_arg, n, work.input_arg.data());
  const response::SweepBlock block{work.w.data(), work.w2.data(), work.scale.data(), work.re.data(), work.im.data(), n};
  for (size_t d = 0; d < plan.dofs.dofs.size(); ++d) {
    std::fill_n(work.re.begin(), n, 0.0);
    std::fill_n(work.im.begin(), n, 0.0);
    DofSums& out = work.per_dof[d];
    if (plan.kernels[k - 1][d](block, work.resonant.data(), plan.ascending)) {
      for (int v = 0; v < n; ++v) out.unbounded[v] = std::max(out.unbounded[v], work.resonant[v]);
      std::fill_n(work.resonant.begin(), n, 0.0);
      out.any_unbounded = true;
    }
    response::add_magnitudes(block, out.sum[0].data(), out.sum[1].data(), out.sum[2].data());
    if (k == 1 && plan.dofs.phase[d]) response::arguments(work.re.data(), work.im.data(), n, out.first_arg.data());
  }
}

// The block's sums, unbounded speeds and phases into each output's curve.
void write_block(const std::vector<OutputRequest>& outputs, const BlockPlan& plan, const BlockWork& work, int begin,
                 int n, std::vector<AmplitudeCurve>& curves) {
  for (size_t o = 0; o < outputs.size(); ++o) {
    const DofSums& d = work.per_dof[plan.dofs.of_output[o]];
    const double* sum = d.sum[static_cast<int>(outputs[o].quantity)].data();
    AmplitudeCurve& c = curves[o];
    c.amplitudes.insert(c.amplitudes.end(), sum, sum + n);  // the blocks come in order: begin is its size
    double* amplitudes = c.amplitudes.data() + begin;
    if (d.any_unbounded)
      for (int v = 0; v < n; ++v)
        if (d.unbounded[v] != 0.0) c.unbounded[begin + v] = true, amplitudes[v] = 0.0;
    if (outputs[o].phase)
      response::phases_deg(d.first_arg.data(), work.input_arg.data(), d.unbounded.data(),
                           phase_offset_deg(outputs[o].quantity), n, c.phases_deg.data() + begin);
  }
}

// Speeds in blocks small enough to stay in L1 cache, one pass per block, harmonic and output
// DOF: `prepare(k, dof)` projects harmonic k's load on the modes once and returns the kernel
// that adds the complex response of that DOF at a block of speeds; the sums over harmonics and
// the phases are common. No array spans all speeds but the curves themselves: fresh 80 kB
// work arrays per harmonic cost more in page faults and cache misses than the arithmetic.
std::vector<AmplitudeCurve> sweep_in_blocks(const Sweep& s, std::vector<AmplitudeCurve> curves,
                                            const Prepare& prepare) {
  const int count = static_cast<int>(s.speeds.size());
  BlockPlan plan;
  const response::SpeedScan scan = response::scan_speeds(s.speeds.values().data(), count);
  if (!scan.valid) throw std::invalid_argument("amplitude curve: speeds must be positive");
  plan.ascending = scan.ascending;
  plan.dofs = output_dofs(s.outputs);
  plan.kernels.resize(s.source.harmonic_count());
  for (int k = 1; k <= s.source.harmonic_count(); ++k)
    for (int dof : plan.dofs.dofs) plan.kernels[k - 1].push_back(prepare(k, dof));
  for (size_t o = 0; o < s.outputs.size(); ++o) {
    curves[o].amplitudes.reserve(count);  // appended block by block: no zeros written first
    curves[o].unbounded.assign(count, false);  // set below where flagged: rare, and bits are slow to write
    if (s.outputs[o].phase) curves[o].phases_deg.resize(count);
  }
  // This thread's work arrays, kept from sweep to sweep (every variant of a study sweeps): no
  // allocation, and no 10 kB of sums zeroed, per sweep. Each block clears what it sums into;
  // `resonant` is all 0 between kernels (add_harmonic restores it), and what only the phases
  // read is set to NaN only when there are phases to read.
  thread_local std::unique_ptr<BlockWork> kept;
  if (!kept) kept = std::make_unique<BlockWork>();
  BlockWork& work = *kept;
  if (work.per_dof.size() < plan.dofs.dofs.size()) work.per_dof.resize(plan.dofs.dofs.size());
  if (plan.dofs.any_phase) {
    for (DofSums& d : work.per_dof) d.first_arg.fill(kNaN);
    work.input_arg.fill(kNaN);  // no phase unless harmonic 1 sets it (a source could have none)
  }
  for (int begin = 0; begin < count; begin += kSweepBlock) {
    const int n = std::min(kSweepBlock, count - begin);
    clear_sums(work.per_dof, plan.dofs.dofs.size(), n);
    for (int k = 1; k <= s.source.harmonic_count(); ++k) add_harmonic(s, plan, k, begin, n, work);
    write_block(s.outputs, plan, work, begin, n, curves);
  }
  return curves;
}

// An undamped mode that moves the DOF: unbounded where ω² is within `tolerance` of λ and the
// load drives it, |a + iωb| above `drive_floor`·(|Q_K| + ω|Q_C|) of the source's whole load, as
// the direct solve decides.
struct Resonance {
  double lambda, tolerance;
  std::complex<double> a, b;
  double drive_floor;
};

// The modes' terms of one harmonic's response at one DOF, x_o(ω) = Σ_j φ_j(o)·s(ω)(a_j + iωb_j)/
// (λ_j − ω² + iωc_j), and the resonances among them.
struct ModalTerms {
  std::vector<response::ModalTerm> terms;
  std::vector<Resonance> resonances;
};

// The norms of the source's separable parts over all its harmonics, √(Σ_k ‖Q_K,k‖²) and
// √(Σ_k ‖Q_C,k‖²): the source's total load of each kind, for response::kLoadRoundOff.
struct PartNorms {
  double stiffness = 0.0, damping = 0.0;
};

PartNorms part_norms(const std::vector<SeparableLoad>& parts) {
  PartNorms n;
  for (const SeparableLoad& p : parts) {
    n.stiffness += p.stiffness_part.squaredNorm();
    n.damping += p.damping_part.squaredNorm();
  }
  return {std::sqrt(n.stiffness), std::sqrt(n.damping)};
}

ModalTerms modal_terms(const ModalBasis& basis, const SeparableLoad& p, const PartNorms& source, int dof) {
  ModalTerms out;
  for (size_t j = 0; j < basis.modes.size(); ++j) {
    const Mode& mode = *basis.modes[j];
    // A mode whose share of this DOF is at the eigensolver's round-off (below 1e-12 of its
    // largest component: a pitch mode at the body's bounce in a symmetric car) adds noise,
    // not response; skipping it changes the output by at most 1e-12 of that mode's own
    // response at its largest DOF, and most outputs of a symmetric vehicle skip most modes.
    const double at = mode.shape(dof), largest = mode.shape.cwiseAbs().maxCoeff();
    if (std::abs(at) <= kRoundOffShare * largest) continue;
    // Likewise a modal load at round-off of the source's total load (response::modal_force,
    // the direct solve's test of whether a load drives a mode): a load on the bogies' pitch
    // meets a bounce mode only through eigensolver noise, and that noise, summed, would be the
    // response — with an arbitrary phase — where the exact response is 0.
    const double shape_norm = mode.shape.norm();
    const std::complex<double> a = response::modal_force(mode, p.stiffness_part, source.stiffness) * at;
    const std::complex<double> b = response::modal_force(mode, p.damping_part, source.damping) * at;
    if (a == 0.0 && b == 0.0) continue;  // the load does not reach this mode
    const double c = basis.damping[j], lambda = mode.eigenvalue;
    const bool undamped = mode.kind == ModeKind::oscillatory && c == 0.0;
    const double tolerance = undamped ? kAtResonance * lambda : -1.0;
    out.terms.push_back({a.real(), a.imag(), b.real(), b.imag(), lambda, c, tolerance, undamped});
    if (undamped && std::abs(at) > 1e-9 * largest)
      out.resonances.push_back({lambda, tolerance, a, b, response::kLoadRoundOff * std::abs(at) * shape_norm});
  }
  return out;
}

// A massless DOF also follows its own load part: row `dof` of K_mm⁻¹ Q_m; 0 for a DOF with mass.
std::complex<double> massless_follower(const ModalBasis& basis, const Eigen::VectorXcd& load_part, int dof) {
  std::complex<double> x = 0.0;
  for (size_t i = 0; i < basis.massless.size(); ++i) {
    if (basis.massless[i] != dof) continue;
    for (size_t c = 0; c < basis.massless.size(); ++c)
      x += basis.massless_flexibility(i, c) * load_part(basis.massless[c]);
  }
  return x;
}

// 1 in `resonant` at the block's speeds where a resonance has no steady state; true if any.
bool flag_resonances(const std::vector<Resonance>& resonances, double q_norm_k, double q_norm_c,
                     const response::SweepBlock& b, double* resonant, bool ascending) {
  bool flagged = false;
  for (const Resonance& t : resonances) {
    const double* w2 = b.w2;
    const int first = ascending ? static_cast<int>(std::lower_bound(w2, w2 + b.count, t.lambda - t.tolerance) - w2) : 0;
    for (int v = first; v < b.count && (!ascending || w2[v] <= t.lambda + t.tolerance); ++v)
      if (std::abs(t.lambda - w2[v]) <= t.tolerance &&
          std::abs(t.a + std::complex<double>(0.0, b.w[v]) * t.b) > t.drive_floor * (q_norm_k + b.w[v] * q_norm_c))
        resonant[v] = 1.0, flagged = true;
  }
  return flagged;
}

// Modal superposition where it is exact: x_o(ω) = Σ_j φ_j(o)·s(ω)(a_j + iωb_j)/(λ_j − ω² + iωc_j)
// + s(ω)·static_o(ω).
Kernel modal_kernel(const ModalBasis& basis, const std::vector<SeparableLoad>& parts, int k, int dof) {
  const PartNorms source = part_norms(parts);
  const double q_norm_k = source.stiffness, q_norm_c = source.damping;
  const SeparableLoad& p = parts[k - 1];
  ModalTerms modal = modal_terms(basis, p, source, dof);
  const std::complex<double> sk = massless_follower(basis, p.stiffness_part, dof);
  const std::complex<double> sc = massless_follower(basis, p.damping_part, dof);
  return [terms = std::move(modal.terms), resonances = std::move(modal.resonances), sk, sc, q_norm_k, q_norm_c](
             const response::SweepBlock& b, double* resonant, bool ascending) {
    response::add_modal_terms(terms.data(), terms.size(), b);
    const bool flagged = flag_resonances(resonances, q_norm_k, q_norm_c, b, resonant, ascending);
    if (sk != 0.0 || sc != 0.0) response::add_static_term(sk.real(), sk.imag(), sc.real(), sc.imag(), b);
    return flagged;
  };
}

// The participations of Q_K and Q_C in each complex root, per harmonic (k at k − 1).
struct RootLoads {
  std::vector<Eigen::VectorXcd> stiffness, damping;
};

RootLoads root_loads(const response::StateSpaceModes& cm, const std::vector<SeparableLoad>& parts) {
  RootLoads loads;
  for (const SeparableLoad& p : parts) {
    loads.stiffness.push_back(cm.projection * p.stiffness_part);
    loads.damping.push_back(cm.projection * p.damping_part);
  }
  return loads;
}

// The undamped modes (Cφ = 0) of a damped system, as a modal basis whose terms stand in for the
// complex modes' roots on the imaginary axis: each such pair ±iω_j contributes exactly
// φ_jφ_jᵀQ/(λ_j − ω²), and as a modal term it gets the modal path's rules — a load at
// round-off drives nothing, and a driven resonance is flagged unbounded as the direct solve
// flags it. Nothing when the roots on the axis are not exactly the pairs of these modes (a
// root so lightly damped that it passes for undamped without Cφ = 0): the caller then solves
// directly.
std::optional<ModalBasis> undamped_basis(const LinearSystem& system, const ModalResult& modes,
                                         const response::StateSpaceModes& cm) {
  ModalBasis b;
  for (const Mode& m : modes.modes)
    if (m.kind == ModeKind::oscillatory && response::undamped(system, m)) b.modes.push_back(&m);
  b.damping.assign(b.modes.size(), 0.0);
  std::vector<bool> matched(cm.roots.size(), false);
  for (const Mode* m : b.modes)
    for (int side = 0; side < 2; ++side) {  // the pair ±i√λ
      Eigen::Index best = -1;
      for (Eigen::Index r = 0; r < cm.roots.size(); ++r)
        if (cm.undamped[r] && !matched[r] && (cm.roots(r).imag() > 0.0) == (side == 0) &&
            std::abs(std::norm(cm.roots(r)) - m->eigenvalue) <= 1e-6 * m->eigenvalue)
          best = r;
      if (best < 0) return std::nullopt;
      matched[best] = true;
    }
  for (Eigen::Index r = 0; r < cm.roots.size(); ++r)
    if (cm.undamped[r] != matched[r]) return std::nullopt;
  return b;
}

// The complex modes' expansion of harmonic k's response at one DOF and ω, for the check: the
// strictly damped roots, and the undamped modes' terms in place of their roots.
std::complex<double> expanded_response(const response::StateSpaceModes& cm, const RootLoads& loads,
                                       const ModalBasis& undamped, const std::vector<SeparableLoad>& parts, int k,
                                       int dof, double omega, double scale) {
  std::complex<double> x = 0.0;
  const std::complex<double> iw(0.0, omega);
  for (Eigen::Index r = 0; r < cm.roots.size(); ++r)
    if (!cm.undamped[r])
      x += cm.shapes(dof, r) * (loads.stiffness[k - 1](r) + iw * loads.damping[k - 1](r)) / (iw - cm.roots(r));
  for (const response::ModalTerm& t : modal_terms(undamped, parts[k - 1], part_norms(parts), dof).terms)
    x += std::complex<double>(t.ar - omega * t.bi, t.ai + omega * t.br) / (t.lambda - omega * omega);
  return scale * x;
}

// The same expansion as a kernel: (a_r + iωb_r)/(iω − λ_r) per strictly damped root (no
// division by 0), and the undamped modes' terms with their resonance flags.
Kernel root_kernel(const response::StateSpaceModes& cm, const RootLoads& loads, const ModalBasis& undamped,
                   const std::vector<SeparableLoad>& parts, int k, int dof) {
  std::vector<response::RootTerm> terms;
  for (Eigen::Index r = 0; r < cm.roots.size(); ++r) {
    if (cm.undamped[r]) continue;
    const std::complex<double> a = cm.shapes(dof, r) * loads.stiffness[k - 1](r);
    const std::complex<double> b = cm.shapes(dof, r) * loads.damping[k - 1](r);
    terms.push_back({a.real(), a.imag(), b.real(), b.imag(), -cm.roots(r).real(), cm.roots(r).imag()});
  }
  const PartNorms source = part_norms(parts);
  ModalTerms modal = modal_terms(undamped, parts[k - 1], source, dof);
  return [terms = std::move(terms), modal = std::move(modal), q_norm_k = source.stiffness,
          q_norm_c = source.damping](const response::SweepBlock& b, double* resonant, bool ascending) {
    response::add_root_terms(terms.data(), terms.size(), b);
    if (modal.terms.empty()) return false;  // every root damped: bounded everywhere
    response::add_modal_terms(modal.terms.data(), modal.terms.size(), b);
    return flag_resonances(modal.resonances, q_norm_k, q_norm_c, b, resonant, ascending);
  };
}

double power(ResponseQuantity q, double omega) {
  return q == ResponseQuantity::displacement ? 1.0 : q == ResponseQuantity::velocity ? omega : omega * omega;
}

// Harmonic k's response at one speed by a direct solve. Friction as equivalent viscous damping
// also changes the input's velocity term: the load is rebuilt on the damped system.
HarmonicResponse direct_response(const Sweep& s, int k, double speed, double omega, double scale, double source_load,
                                 bool equivalent_friction, double friction_reference_amplitude) {
  if (equivalent_friction) {
    const LinearSystem damped = with_equivalent_friction_damping(s.system, omega, friction_reference_amplitude);
    const HarmonicLoad load = s.source.load(damped, speed, k);
    return harmonic_response(damped, s.modes, generalized_load(damped, load), load.frequency_hz, source_load);
  }
  const SeparableLoad& p = s.parts[k - 1];
  const std::complex<double> iw(0.0, omega);
  return harmonic_response(s.system, s.modes, scale * (p.stiffness_part + iw * p.damping_part), omega / kTwoPi,
                           source_load);
}

// The direct path: non-proportional damping, or friction as equivalent viscous damping.
std::vector<AmplitudeCurve> direct_curves(const Sweep& s, std::vector<AmplitudeCurve> curves,
                                          bool equivalent_friction, double friction_reference_amplitude) {
  const std::vector<OutputRequest>& outputs = s.outputs;
  std::vector<double> sum(outputs.size()), phase(outputs.size());
  std::vector<bool> unbounded(outputs.size());
  for (double speed : s.speeds) {
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(phase.begin(), phase.end(), 0.0);
    std::fill(unbounded.begin(), unbounded.end(), false);
    const double source_load = source_load_at(s, speed);
    for (int k = 1; k <= s.source.harmonic_count(); ++k) {
      const double omega = kTwoPi * s.source.frequency_hz(speed, k);
      const double scale = s.source.load_scale(omega, s.parts[k - 1].reference_omega);
      const HarmonicResponse r =
          direct_response(s, k, speed, omega, scale, source_load, equivalent_friction, friction_reference_amplitude);
      for (size_t o = 0; o < outputs.size(); ++o) {
        if (unbounded_at(r, s.modes, outputs[o].dof)) {
          unbounded[o] = true;
          continue;
        }
        const std::complex<double> x = r.displacement(outputs[o].dof);
        sum[o] += std::abs(x) * power(outputs[o].quantity, omega);
        if (k == 1 && outputs[o].phase) {
          double input_arg = 0.0;
          response::input_arguments(&scale, s.reference_arg, 1, &input_arg);
          phase[o] = response::phase_deg(response::fast_atan2(x.imag(), x.real()), input_arg,
                                         phase_offset_deg(outputs[o].quantity));
        }
      }
    }
    for (size_t o = 0; o < outputs.size(); ++o) {
      curves[o].amplitudes.push_back(unbounded[o] ? 0.0 : sum[o]);
      curves[o].unbounded.push_back(unbounded[o]);
      if (outputs[o].phase) curves[o].phases_deg.push_back(unbounded[o] ? 0.0 : phase[o]);
    }
  }
  return curves;
}

std::vector<SeparableLoad> separable_loads(const LinearSystem& system, const ExcitationSource& source) {
  std::vector<SeparableLoad> parts;
  for (int k = 1; k <= source.harmonic_count(); ++k) parts.push_back(source.separable_load(system, k));
  return parts;
}

}  // namespace

std::complex<double> phase_reference(const LinearSystem& system, const ExcitationSource& source) {
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

namespace {

// amplitude_curves() without its summary; *method names the path taken (a literal: the
// summary-less calls of peak refinement allocate nothing for it).
std::vector<AmplitudeCurve> sweep_curves(const LinearSystem& system, const ModalResult& modes,
                                         const ExcitationSource& source, int source_index,
                                         const std::vector<OutputRequest>& outputs, const SpeedGrid& speeds,
                                         double friction_reference_amplitude, const char** method) {
  std::vector<AmplitudeCurve> curves;
  for (const OutputRequest& o : outputs) {
    if (o.dof < 0 || o.dof >= system.size()) throw std::invalid_argument("amplitude curve: no such output DOF");
    AmplitudeCurve c;
    c.source = source_index;
    c.output = system.dofs[o.dof].label;
    c.quantity = o.quantity;
    c.speeds = speeds;  // shared, not copied
    curves.push_back(c);
  }
  const bool equivalent_friction = friction_reference_amplitude > 0.0 && has_leaf_friction(system);
  // The input the phases refer to, found only when some output has a phase (it builds a load).
  const bool any_phase = std::any_of(outputs.begin(), outputs.end(), [](const OutputRequest& o) { return o.phase; });
  const std::complex<double> input = any_phase ? phase_reference(system, source) : 0.0;
  const double reference_arg = input == 0.0 ? kNaN : std::arg(input);
  const ModalBasis basis = modal_basis(system, modes);
  const Sweep sweep{system, modes, source, outputs, speeds, separable_loads(system, source), reference_arg};

  if (basis.exact && !equivalent_friction) {
    *method = "modal superposition over the undamped modes, blocks of speeds";
    return sweep_in_blocks(sweep, std::move(curves),
                           [&](int k, int dof) { return modal_kernel(basis, sweep.parts, k, dof); });
  }

  // Discrete dampers (damping not proportional): the complex modes of the first-order form,
  // where they are trustworthy and agree with the direct solve at sample speeds; otherwise
  // (and for friction as equivalent viscous damping) one direct solve per speed.
  if (!equivalent_friction && speeds.size() > kDirectUpTo) {
    const auto complex_modes = response::state_space_modes(system, /*allow_undamped=*/true);
    const auto undamped = complex_modes ? undamped_basis(system, modes, *complex_modes) : std::nullopt;
    if (undamped) {
      const response::StateSpaceModes& cm = *complex_modes;
      const RootLoads loads = root_loads(cm, sweep.parts);
      auto at_speed = [&](int k, int dof, double omega, double scale) {
        return expanded_response(cm, loads, *undamped, sweep.parts, k, dof, omega, scale);
      };
      if (agrees_with_direct(sweep, at_speed)) {
        *method = undamped->modes.empty()
                      ? "complex modes of the first-order form, checked against direct solves at 9 speeds"
                      : "complex modes of the first-order form and modal terms of its undamped modes, checked "
                        "against direct solves at 9 speeds";
        return sweep_in_blocks(sweep, std::move(curves), [&](int k, int dof) {
          return root_kernel(cm, loads, *undamped, sweep.parts, k, dof);
        });
      }
    }
  }
  *method = equivalent_friction ? "direct solve per speed and harmonic, leaf friction as equivalent viscous damping"
                                : "direct solve per speed and harmonic";
  return direct_curves(sweep, std::move(curves), equivalent_friction, friction_reference_amplitude);
}

}  // namespace

std::vector<AmplitudeCurve> amplitude_curves(const LinearSystem& system, const ModalResult& modes,
                                             const ExcitationSource& source, int source_index,
                                             const std::vector<OutputRequest>& outputs, const SpeedGrid& speeds,
                                             double friction_reference_amplitude, AnalysisSummary* summary) {
  const char* method = "";
  model::refuse_series_dampers(system, "speed sweep");
  if (!summary)  // peak refinement sweeps one speed at a time: no clock, no strings
    return sweep_curves(system, modes, source, source_index, outputs, speeds, friction_reference_amplitude, &method);
  *summary = AnalysisSummary{};
  StageClock clock(summary);
  std::vector<AmplitudeCurve> curves = sweep_curves(system, modes, source, source_index, outputs, speeds,
                                                    friction_reference_amplitude, &method);
  clock.lap("sweep");
  summary->method = method;
  summary->analysis = "amplitude against speed";
  size_t unbounded = 0;
  for (const AmplitudeCurve& c : curves) unbounded += std::count(c.unbounded.begin(), c.unbounded.end(), true);
  summary->checks.push_back({"points where an undamped resonance makes the response unbounded",
                             static_cast<double>(unbounded), std::numeric_limits<double>::infinity(), true});
  return curves;
}

}  // namespace railmodal
