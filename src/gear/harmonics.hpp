// Fourier coefficients of a quantity sampled at equal steps over one revolution.
#pragma once

#include <vector>

#include "railmodal/driving_gear.hpp"

namespace railmodal::gear {

/// Harmonics 0 … highest of samples q_i = q(2π·i/n): a_k = (2/n) Σ q_i cos kφ_i, b_k likewise
/// with sin (a_0 the mean). A direct sum: highest is a few and n a few hundred, so it costs
/// less than planning an FFT, and for an analytic periodic q it is exact to aliasing.
std::vector<GearHarmonic> harmonics_of(const std::vector<double>& samples, int highest);

/// Σ_k a_k cos kφ + b_k sin kφ.
double synthesise(const std::vector<GearHarmonic>& harmonics, double angle);

}  // namespace railmodal::gear
