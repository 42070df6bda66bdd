#include "response/sweep_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

// The block loops below (add_*, magnitudes, arguments, phases_deg, the scans) are built for
// SSE2 (every x86-64) and for AVX2, and the loader picks one by the CPU (a GNU ifunc: glibc
// only, and not under a sanitiser, whose runtime the resolver would run before). AVX2 halves
// the cost of the divisions and square roots that dominate the arithmetic. Without FMA in the
// AVX2 build, and with contraction off for this file (CMakeLists.txt), both give the same bits.
#if !defined(RAILMODAL_VECTOR_CLONES) && defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define RAILMODAL_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#ifndef RAILMODAL_VECTOR_CLONES
#define RAILMODAL_VECTOR_CLONES
#endif
// Each clone must inline its loop to build it for its own target; GCC at -O2 does not.
#define RAILMODAL_INLINE_LOOP [[gnu::always_inline]] inline

namespace railmodal::response {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kLargest = std::numeric_limits<double>::max();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;
// π/4 and π/2 rounded to double, and what rounding took off π/2 (Cephes's MOREBITS).
constexpr double kQuarterPi = 0.78539816339744830962;
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kHalfPiRest = 6.123233995736765886130e-17;

// Every select below picks between values already computed, so that it stays a select (a
// branch would stop the vectorising; CMakeLists.txt builds this file without trapping maths).
RAILMODAL_INLINE_LOOP double atan2_kernel(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const bool steep = ay > ax;
  const double lo = steep ? ax : ay, hi = steep ? ay : ax;  // atan of t = lo/hi ∈ [0, 1]
  // atan t = π/4 + atan((t − 1)/(t + 1)) above 0.66, so that the rational sees |r| ≤ 0.21;
  // (lo − hi)/(lo + hi) is that in one division, and lo − hi is exact there (Sterbenz).
  const bool big = lo > 0.66 * hi;
  const double below = lo - hi, above = lo + hi;
  const double r = (big ? below : lo) / (big ? above : hi);  // NaN for 0/0
  const double z = r * r;
  // Cephes atan.c: atan r = r + r·z·P(z)/Q(z) on |r| ≤ 0.66, relative error ~1e-16.
  const double p = (((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z -
                     7.500855792314704667340e1) * z - 1.228866684490136173410e2) * z - 6.485021904942025371773e1;
  const double q = ((((z + 2.485846490142306297962e1) * z + 1.650270098316988542046e2) * z +
                     4.328810604912902668951e2) * z + 4.853903996359136964868e2) * z + 1.945506571482613964425e2;
  const double a0 = r + r * (z * p / q);
  const double shifted = kQuarterPi + (a0 + 0.5 * kHalfPiRest);
  const double a1 = big ? shifted : a0;
  const double complement = (kHalfPi - a1) + kHalfPiRest;
  const double a2 = steep ? complement : a1;
  const double supplement = (2.0 * kHalfPi - a2) + 2.0 * kHalfPiRest;
  const double a3 = x < 0.0 ? supplement : a2;
  const double negated = -a3;
  return y < 0.0 ? negated : a3;
}

// The loops, with every array a restrict parameter: GCC takes restrict from parameters (also
// once inlined), and without it the run-time overlap checks of seven arrays exceed its limit
// and the loop stays scalar.
RAILMODAL_INLINE_LOOP void modal_terms(const ModalTerm* terms, std::size_t count, int n,
                                       const double* __restrict w, const double* __restrict w2,
                                       const double* __restrict scale, double* __restrict re,
                                       double* __restrict im) {
  for (std::size_t j = 0; j < count; ++j) {
    const ModalTerm t = terms[j];
    if (t.undamped) {
      // At its own frequency the gap becomes ∞ and the term exactly 0: a select, where a branch
      // or a masked division would stop the vectorising.
      for (int v = 0; v < n; ++v) {
        const double gap = t.lambda - w2[v];
        const double f = scale[v] / (std::abs(gap) <= t.tolerance ? kInfinity : gap);
        re[v] += (t.ar - w[v] * t.bi) * f;
        im[v] += (t.ai + w[v] * t.br) * f;
      }
    } else {
      for (int v = 0; v < n; ++v) {
        const double gap = t.lambda - w2[v], di = w[v] * t.c;
        const double nr = t.ar - w[v] * t.bi, ni = t.ai + w[v] * t.br;
        const double f = scale[v] / (gap * gap + di * di);
        re[v] += (nr * gap + ni * di) * f;
        im[v] += (ni * gap - nr * di) * f;
      }
    }
  }
}

RAILMODAL_INLINE_LOOP void root_terms(const RootTerm* terms, std::size_t count, int n,
                                      const double* __restrict w, const double* __restrict scale,
                                      double* __restrict re, double* __restrict im) {
  for (std::size_t j = 0; j < count; ++j) {
    const RootTerm t = terms[j];
    for (int v = 0; v < n; ++v) {
      const double nr = t.ar - w[v] * t.bi, ni = t.ai + w[v] * t.br;
      const double di = w[v] - t.lambda_im;
      const double f = scale[v] / (t.decay * t.decay + di * di);
      re[v] += (nr * t.decay + ni * di) * f;
      im[v] += (ni * t.decay - nr * di) * f;
    }
  }
}

// Two flags over the grid in integers, so that the loop vectorises (a branch per speed would
// not, and the early exit of std::is_sorted neither).
RAILMODAL_INLINE_LOOP SpeedScan scan(const double* __restrict v, int n) {
  long invalid = 0, falls = 0;
  for (int i = 0; i < n; ++i) invalid |= !(v[i] > 0.0 && v[i] <= kLargest);
  for (int i = 1; i < n; ++i) falls |= v[i] < v[i - 1];
  return {invalid == 0, falls == 0};
}

RAILMODAL_INLINE_LOOP void input_args(const double* __restrict scale, double reference_arg, int n,
                                      double* __restrict out) {
  // reference + 0 as the scalar form adds it (−0 becomes +0), so that the bits stay the same.
  const double plain = reference_arg + 0.0, turned = reference_arg + kPi;
  for (int v = 0; v < n; ++v) {
    const double arg = scale[v] < 0.0 ? turned : plain;
    out[v] = scale[v] == 0.0 ? kNaN : arg;
  }
}

RAILMODAL_INLINE_LOOP void magnitudes(int n, const double* __restrict re, const double* __restrict im,
                                      const double* __restrict w, const double* __restrict w2,
                                      double* __restrict s0, double* __restrict s1, double* __restrict s2) {
  for (int v = 0; v < n; ++v) {
    const double magnitude = std::sqrt(re[v] * re[v] + im[v] * im[v]);
    s0[v] += magnitude;
    s1[v] += magnitude * w[v];
    s2[v] += magnitude * w2[v];
  }
}

RAILMODAL_INLINE_LOOP void atan2s(int n, const double* __restrict re, const double* __restrict im,
                                  double* __restrict out) {
  for (int v = 0; v < n; ++v) out[v] = atan2_kernel(im[v], re[v]);
}

RAILMODAL_INLINE_LOOP double phase_kernel(double arg_x, double arg_input, double offset_deg) {
  const double difference = arg_x - arg_input;
  const double phase = difference * kDegrees + offset_deg;  // in [−540, 540]
  const double down = phase - 360.0, up = phase + 360.0;
  const double once = phase > 180.0 ? down : phase <= -180.0 ? up : phase;
  const double again = once + 360.0;  // −540 needs two turns
  const double wrapped = once <= -180.0 ? again : once;
  return difference != difference ? 0.0 : wrapped;
}

RAILMODAL_INLINE_LOOP void phases(int n, const double* __restrict arg_x, const double* __restrict arg_input,
                                  const double* __restrict unbounded, double offset_deg, double* __restrict out) {
  for (int v = 0; v < n; ++v) {
    const double phase = phase_kernel(arg_x[v], arg_input[v], offset_deg);
    out[v] = unbounded[v] != 0.0 ? 0.0 : phase;
  }
}

// Points a test of the scans below: few enough that a block holding the point sought is not
// long to walk again one point at a time. A whole block's loop has a constant count, so it is
// vectorised without a remainder.
constexpr std::size_t kScanBlock = 32;

// Whether a point of [i, i + count) may be a local maximum (a[j] ≥ a[j − 1] and a[j] > a[j + 1]):
// the tests of every point or'd, no branch.
RAILMODAL_INLINE_LOOP bool any_peak_test(const double* __restrict a, std::size_t i, std::size_t count) {
  long any = 0;
  for (std::size_t j = i; j < i + count; ++j) any |= static_cast<long>((a[j] >= a[j - 1]) & (a[j] > a[j + 1]));
  return any != 0;
}

// Lane j's running maximum over a block, a[j] taken only when greater than it (never a NaN,
// as a single running maximum): elementwise over the lanes, so it is vectorised.
RAILMODAL_INLINE_LOOP void running_maxima(const double* __restrict a, double* __restrict lane) {
  for (std::size_t j = 0; j < kScanBlock; ++j) lane[j] = a[j] > lane[j] ? a[j] : lane[j];
}

// Whether a block holds `value`: the tests or'd, no branch.
RAILMODAL_INLINE_LOOP bool block_holds(const double* __restrict a, double value) {
  long any = 0;
  for (std::size_t j = 0; j < kScanBlock; ++j) any |= static_cast<long>(a[j] == value);
  return any != 0;
}

}  // namespace

double fast_atan2(double y, double x) { return atan2_kernel(y, x); }

double phase_deg(double arg_x, double arg_input, double offset_deg) {
  return phase_kernel(arg_x, arg_input, offset_deg);
}

RAILMODAL_VECTOR_CLONES
void add_modal_terms(const ModalTerm* terms, std::size_t count, const SweepBlock& b) {
  modal_terms(terms, count, b.count, b.w, b.w2, b.scale, b.re, b.im);
}

RAILMODAL_VECTOR_CLONES
void add_root_terms(const RootTerm* terms, std::size_t count, const SweepBlock& b) {
  root_terms(terms, count, b.count, b.w, b.scale, b.re, b.im);
}

RAILMODAL_VECTOR_CLONES
SpeedScan scan_speeds(const double* speeds, int count) { return scan(speeds, count); }

RAILMODAL_VECTOR_CLONES
void input_arguments(const double* scale, double reference_arg, int count, double* out) {
  input_args(scale, reference_arg, count, out);
}

void add_static_term(double kr, double ki, double cr, double ci, const SweepBlock& b) {
  for (int v = 0; v < b.count; ++v) {
    b.re[v] += b.scale[v] * (kr - b.w[v] * ci);
    b.im[v] += b.scale[v] * (ki + b.w[v] * cr);
  }
}

RAILMODAL_VECTOR_CLONES
void add_magnitudes(const SweepBlock& b, double* sum0, double* sum1, double* sum2) {
  magnitudes(b.count, b.re, b.im, b.w, b.w2, sum0, sum1, sum2);
}

RAILMODAL_VECTOR_CLONES
void arguments(const double* re, const double* im, int count, double* out) { atan2s(count, re, im, out); }

RAILMODAL_VECTOR_CLONES
void phases_deg(const double* arg_x, const double* arg_input, const double* unbounded, double offset_deg, int count,
                double* out) {
  phases(count, arg_x, arg_input, unbounded, offset_deg, out);
}

RAILMODAL_VECTOR_CLONES
std::size_t skip_to_local_maximum(const double* a, std::size_t i, std::size_t n) {
  for (; i + kScanBlock < n; i += kScanBlock)  // whole blocks: [i, i + kScanBlock) all below n − 1
    if (any_peak_test(a, i, kScanBlock)) return i;
  return i;  // the rest, fewer than a block: the caller walks it
}

RAILMODAL_VECTOR_CLONES
LargestPoint largest_above(const double* a, std::size_t n, double floor) {
  // kScanBlock running maxima, lane j over a[j], a[j + kScanBlock], …, then the largest of the
  // lanes and the rest: the largest value a single pass keeps, whatever order the values are
  // met in (a value enters only when greater, so no NaN does, and of equal values the first).
  double lane[kScanBlock];
  for (double& l : lane) l = floor;
  std::size_t i = 0;
  for (; i + kScanBlock <= n; i += kScanBlock) running_maxima(a + i, lane);
  double largest = floor;
  for (; i < n; ++i) largest = a[i] > largest ? a[i] : largest;
  for (const double l : lane) largest = l > largest ? l : largest;
  if (!(largest > floor)) return {floor, n};
  // A single pass's strict `>` keeps the first place of the largest: every value before it is
  // smaller. Its value is read there (of +0 and −0 the pass keeps the one it met).
  // The blocks before its block are passed by a vectorised test.
  std::size_t at = 0;
  while (at + kScanBlock <= n && !block_holds(a + at, largest)) at += kScanBlock;
  while (!(a[at] == largest)) ++at;
  return {a[at], at};
}

}  // namespace railmodal::response
