// The ride's vector sincos. How it works (Cody and Waite's argument reduction, the method of
// fdlibm's e_rem_pio2.c and k_sin.c/k_cos.c, written anew for a branch-free loop):
//
// 1. q = nearest integer to x·2/π, found by adding and subtracting 1.5·2⁵² (the addition rounds
//    to an integer in the current, round-to-nearest mode); its two low bits are the quadrant.
// 2. r = x − q·π/2 with π/2 split into three parts p1 + p2 + p3 of 33, 33 and 53 bits
//    (fdlibm's pio2_1, pio2_2, pio2_3): for |q| ≤ 2²⁰ the products q·p1 and q·p2 are exact, and
//    x − q·p1 is exact too (Sterbenz: the two are within a factor 2 whenever q ≠ 0), so r
//    carries the rounding of two subtractions and q·p3 and the neglected tail q·(π/2 − p1 − p2
//    − p3) < 2²⁰·8.5e−32: an absolute error under 2⁻⁵³·|r| + 1e−25.
// 3. On |r| ≤ π/4 the minimax polynomials of fdlibm (k_sin.c S1…S6, k_cos.c C1…C6, published
//    with errors below 2⁻⁵⁸ against sin and cos there): sin r = r + r³(S1 + r²(S2 + …)),
//    cos r = 1 − r²/2 + r⁴(C1 + …), the latter summed as w + ((1 − w) − r²/2 + …) with
//    w = 1 − r²/2, which keeps the rounding of 1 − r²/2 out of the result.
// 4. The quadrant rotates (sin r, cos r) by a multiple of π/2: an exchange and sign flips done
//    on the bits, so the loop has no branch and vectorises.
//
// Beyond kPhaseSincosLimit (|q| could pass 2²⁰) and for infinities and NaN, ::sincos.
#include "ride/phase_sincos.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace railmodal::ride {

namespace {

constexpr double kTwoOverPi = 6.36619772367581382433e-01;
constexpr double kRoundShift = 6755399441055744.0;  // 1.5·2⁵²
constexpr double kHalfPiPart1 = 1.57079632673412561417e+00;
constexpr double kHalfPiPart2 = 6.07710050630396597660e-11;
constexpr double kHalfPiPart3 = 2.02226624871116645580e-21;
constexpr double kSin1 = -1.66666666666666324348e-01, kSin2 = 8.33333333332248946124e-03,
                 kSin3 = -1.98412698298579493134e-04, kSin4 = 2.75573137070700676789e-06,
                 kSin5 = -2.50507602534068634195e-08, kSin6 = 1.58969099521155010221e-10;
constexpr double kCos1 = 4.16666666666666019037e-02, kCos2 = -1.38888888888741095749e-03,
                 kCos3 = 2.48015872894767294178e-05, kCos4 = -2.75573143513906633035e-07,
                 kCos5 = 2.08757232129817482790e-09, kCos6 = -1.13596475577881948265e-11;

std::uint64_t bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

}  // namespace

void phase_sincos(const double* x, double* sine, double* cosine, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const double shifted = x[i] * kTwoOverPi + kRoundShift;
    const double q = shifted - kRoundShift;
    const std::uint64_t quadrant = bits_of(shifted);  // q's low bits, two's complement
    const double r = ((x[i] - q * kHalfPiPart1) - q * kHalfPiPart2) - q * kHalfPiPart3;
    const double z = r * r;
    const double s = r + r * z * (kSin1 + z * (kSin2 + z * (kSin3 + z * (kSin4 + z * (kSin5 + z * kSin6)))));
    const double half = 0.5 * z;
    const double w = 1.0 - half;
    const double c =
        w + (((1.0 - w) - half) + z * z * (kCos1 + z * (kCos2 + z * (kCos3 + z * (kCos4 + z * (kCos5 + z * kCos6))))));
    // Quadrant 1 or 3: (sin, cos) = (c, −s) or (−c, s); quadrant 2 or 3 negates the sine,
    // quadrant 1 or 2 the cosine.
    const std::uint64_t exchange = 0 - (quadrant & 1);  // all ones in quadrants 1 and 3
    const std::uint64_t sine_sign = (quadrant & 2) << 62;
    const std::uint64_t cosine_sign = ((quadrant + 1) & 2) << 62;
    const std::uint64_t sb = bits_of(s), cb = bits_of(c);
    sine[i] = from_bits(((sb & ~exchange) | (cb & exchange)) ^ sine_sign);
    cosine[i] = from_bits(((cb & ~exchange) | (sb & exchange)) ^ cosine_sign);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!(std::abs(x[i]) <= kPhaseSincosLimit)) ::sincos(x[i], &sine[i], &cosine[i]);
}

}  // namespace railmodal::ride
