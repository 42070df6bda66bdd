// sin and cos of many phases at once, in a loop the compiler vectorises: the ride's delay
// phasors e^{−iωτ} (ride_speed.cpp), 2·10⁵ of them at the benchmark's 20 speeds × 10⁴ frequencies,
// where glibc's scalar sincos (a call per phase) was 14 % of the solve.
#pragma once

#include <cstddef>

namespace railmodal::ride {

/// Largest |x| the vector path reduces (phase_sincos.cpp): its Cody–Waite reduction by π/2 is
/// exact for quadrant counts up to 2²⁰, and any x beyond this is handed to the C library.
constexpr double kPhaseSincosLimit = 1.0e6;

/// sine[i] = sin x[i], cosine[i] = cos x[i] for i < n, each within 2⁻⁵² of the correctly
/// rounded value (one unit in the last place of 1: what a phasor's error is measured against,
/// since it multiplies a receptance and is summed; tests/ride/phase_sincos_test.cpp checks it
/// against std::sin and std::cos). Arguments beyond kPhaseSincosLimit, infinite or NaN take
/// ::sincos (a NaN in gives a NaN out).
void phase_sincos(const double* x, double* sine, double* cosine, std::size_t n);

}  // namespace railmodal::ride
