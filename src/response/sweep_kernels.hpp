// The arithmetic of a speed sweep over one block of speeds: every loop branch-free over the
// block, so that the compiler vectorises it, and built twice on x86-64 with glibc (SSE2 and
// AVX2, chosen at run time by the CPU). The two builds give identical results: no fused
// multiply-add, and every operation is elementwise and correctly rounded at any vector width.
#pragma once

#include <cstddef>

namespace railmodal::response {

/// Speeds per block: small enough for a block's work arrays to stay in L1 cache.
constexpr int kSweepBlock = 256;

/// A block of speeds: ω, ω² and the load scale s(ω), and the response (re, im) that terms
/// add to. All arrays hold `count` ≤ kSweepBlock values and do not overlap.
struct SweepBlock {
  const double* w;
  const double* w2;
  const double* scale;
  double* re;
  double* im;
  int count;
};

/// One mode's share of an output DOF: φ(o)·s(ω)(a + iωb)/(λ − ω² + iωc), with a = φᵀQ_K and
/// b = φᵀQ_C. An undamped term (c = 0) adds exactly 0 where |λ − ω²| ≤ `tolerance`: it has no
/// steady state there, and the caller flags those speeds.
struct ModalTerm {
  double ar, ai, br, bi, lambda, c, tolerance;
  bool undamped;
};
void add_modal_terms(const ModalTerm* terms, std::size_t count, const SweepBlock& b);

/// One complex root r = −decay + i·lambda_im of the first-order form:
/// s(ω)(a + iωb)/(iω − r), every root strictly damped (decay > 0).
struct RootTerm {
  double ar, ai, br, bi, decay, lambda_im;
};
void add_root_terms(const RootTerm* terms, std::size_t count, const SweepBlock& b);

/// A massless DOF's own quasi-static part: s(ω)(k + iωc), complex k = kr + i·ki, c likewise.
void add_static_term(double kr, double ki, double cr, double ci, const SweepBlock& b);

/// sum0 += |x|, sum1 += |x|·ω, sum2 += |x|·ω² (displacement, velocity, acceleration) with
/// x = re + i·im, over the block.
void add_magnitudes(const SweepBlock& b, double* sum0, double* sum1, double* sum2);

/// Whether every speed is positive and finite, and whether they rise (each ≥ the one before):
/// one branch-free pass over the grid.
struct SpeedScan {
  bool valid, ascending;
};
SpeedScan scan_speeds(const double* speeds, int count);

/// arg of the input s(ω)·input that phases refer to, per speed: `reference_arg`, plus π where
/// s < 0 (s real: its sign turns the input by π), NaN where s = 0 (no input, so no phase).
void input_arguments(const double* scale, double reference_arg, int count, double* out);

/// arg x = atan2(im, re) per speed (rad), NaN where x = 0; see fast_atan2.
void arguments(const double* re, const double* im, int count, double* out);

/// atan2(y, x) to within 2 ulp of π (8.9e-16 rad) of libm in all four quadrants: Cephes's
/// rational approximation of atan on [0, 0.66] after the reduction to [0, 1] by |y|/|x| or
/// |x|/|y| and to ±0.21 by (t − 1)/(t + 1). NaN for x = y = 0, where the phase is undefined;
/// −0 counts as +0. For |x|, |y| between 1e-300 and 1e300 (a response in metres or radians):
/// beyond, |x| + |y| may overflow or 0.66·|y| round, and the result loses accuracy.
/// Branch-free, so that a loop of it vectorises (libm's atan2 does not).
double fast_atan2(double y, double x);

/// Phase in degrees, in (−180, 180]: (arg x − arg input) + `offset_deg` (90° per time
/// derivative), 0 where either argument is NaN. For arg x ∈ [−π, π], arg input ∈ [−π, 2π] (π
/// added for a negative load scale) and an offset in [0°, 180°], the sum lies in
/// [−540°, 540°]: at most two turns are taken off.
double phase_deg(double arg_x, double arg_input, double offset_deg);

/// phase_deg over a block, and 0 where the speed is flagged unbounded (≠ 0).
void phases_deg(const double* arg_x, const double* arg_input, const double* unbounded, double offset_deg, int count,
                double* out);

/// The first i' ≥ i from which a local maximum of a[0, n) (a[j] ≥ a[j − 1] and a[j] > a[j + 1],
/// 0 < j < n − 1) may be found: no j in [i, i') is one. Tests blocks of points without a
/// branch, so the caller's own walk from i' (next_local_maximum) is short. 1 ≤ i.
std::size_t skip_to_local_maximum(const double* a, std::size_t i, std::size_t n);

/// The largest a[j] above `floor`, j in [0, n), and its first place: what one pass keeping a
/// running largest (from `floor`, taking a[j] only when a[j] > it) ends with, at = the place it
/// took last; {floor, n} when no a[j] > floor. Vectorised: running largests of every 32nd point.
struct LargestPoint {
  double value;
  std::size_t at;
};
LargestPoint largest_above(const double* a, std::size_t n, double floor);

}  // namespace railmodal::response
