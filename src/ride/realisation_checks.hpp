// The FFT checks of a realisation (issue 21, item 4) as separate steps, so each can be
// tested alone: (a) the exact bin check of a periodic run, (b) the Welch PSD of the realised
// track against its target spectrum. check_ride_realisation (ride_simulation.hpp) adds (c),
// the RMS against solve_ride.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/ride_simulation.hpp"

namespace railmodal::ride {

/// (a) For a periodic geometry run over exactly one period (simulate_ride does so): the
/// largest over outputs of max_k |Y_k − Ŷ_k| / max_k |Ŷ_k|, Y the DFT of the simulated
/// history and Ŷ the frequency-domain prediction for the linearly interpolated track,
///   Ŷ_q / N_e = Σ_j H(k_j f₀) (X_q/N) sinc²(k_j/N) e^{2πi k_j ξ₀/L},  k_j = q + j·N_e,
/// over the track's bins q (X its DFT, N its samples, N_e = N·m the run's, ξ₀ the leading
/// wheel's position at the first sample, f₀ = V/L); H from the same state space, diagonalised:
/// its state part's images summed symmetrically over |j| ≤ 16, its direct part's (the
/// outputs' terms in w and ẇ) exactly, as the DFT of those terms at the samples (Poisson).
double exact_bin_error(const LinearSystem& system, const TrackGeometry& geometry,
                       const RideSimulationResult& simulated, const RideSimulationOptions& options);

/// (b) Welch's estimate of one realised component (periodic Hann segments of `segment`
/// samples, half overlapping) against the expected value of that estimate, the target
/// spectrum seen through the window (so the leakage of a steep spectrum is in the reference,
/// not counted as a miss): the fraction of the in-band bins outside the 95 % band of a
/// chi-square with ν = 2K/(1 + 2(1 − 1/K)ρ) degrees of freedom, K segments and
/// ρ = [Σ w_n w_{n+S}]²/[Σ w_n²]² the correlation of neighbouring segments' estimates for a
/// shift S (Welch, "The use of fast Fourier transform for the estimation of power spectra",
/// IEEE Trans. Audio Electroacoust. 15, 1967, eqs. for the variance of the average; 1/9 for
/// Hann at half overlap), and the largest leakage bias |E Ŝ/S − 1| over those bins.
struct WelchCheck {
  double fraction_outside = 0.0;
  double leakage_bias = 0.0;
  int bins = 0;
  double degrees_of_freedom = 0.0;
};
WelchCheck welch_band_check(const Eigen::VectorXd& profile, double step, const TrackSpectrum& target,
                            Eigen::Index segment);

}  // namespace railmodal::ride
