// One speed of the ride: the speed-independent receptances combined with the delays x_i/V of
// the track inputs and the track's temporal densities G_c(f) = (2π/V)S_c(2πf/V).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "ride/ride_grid.hpp"
#include "ride/ride_indices.hpp"
#include "ride/ride_transfer.hpp"

namespace railmodal::ride {

/// A component's band in Hz at `speed` and its weights on the grid.
std::vector<BandWeights> speed_bands(const std::vector<Component>& components, const Eigen::VectorXd& grid,
                                     double speed);

struct SpeedSpectra {
  std::vector<ComponentPower> outputs;  ///< per output: |H_c|²·G_c inside each band
  std::vector<Eigen::VectorXd> psd;     ///< per output: Σ_c |H_c|²G_c (G zero outside its band), unit²/Hz
  std::vector<std::vector<double>> modal_variance;  ///< [output][mode]: ∫|H_j|²G df (with a basis)
  std::vector<Eigen::VectorXd> input_psd;           ///< per component: G_c on the grid, m²/Hz
};

/// speed_spectra's working arrays for one speed (not part of its result), kept by the caller
/// from one speed to the next with its spectra (ride_workspace.hpp's SpeedWorkspace).
struct SpeedScratch {
  Eigen::MatrixXd inside_density;  ///< [component][grid point]: the density clamped to the band
  std::vector<char> needed;        ///< [grid point]: whether the speed's bands need it
};

/// H_c(f) = Σ_g h_{c,g}(f)·e^{−iωτ_g} over the input groups, τ_g = (x_front − x_g)/V with x_g
/// from Receptances::x (x forward; `system` is not read), and what the indices need of it (the
/// modal variances when `r` holds modal terms), at the grid points the speed's bands need: the
/// power and PSD elsewhere are left zero, where every index weighs them by zero. Without
/// `with_psd` SpeedSpectra::psd holds empty vectors (no index reads it: only the kept spectra).
/// Written into `s`, with its working arrays in `scratch`, whose arrays are reused where their
/// sizes already fit (a caller's kept from one speed to the next: ride_workspace.hpp); every
/// value is rewritten.
void speed_spectra(const LinearSystem& system, const Receptances& r, const std::vector<Component>& components,
                   const Eigen::VectorXd& grid, double speed, const std::vector<BandWeights>& bands, bool with_psd,
                   SpeedSpectra* s, SpeedScratch* scratch);

}  // namespace railmodal::ride
