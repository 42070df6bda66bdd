// Ride indices from a spectrum: the integrals of an output's PSD, weighted or not, and the
// 95th-percentile estimate of a stationary Gaussian process's short-time RMS
// (docs/ride.md, "Ride indices from a spectrum").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "ride/ride_grid.hpp"

namespace railmodal::ride {

/// The χ² distribution's quantile: x with P(χ²_ν ≤ x) = p, for ν > 0 (not necessarily whole)
/// and 0 < p < 1. Solved on the regularised lower incomplete gamma function P(ν/2, x/2).
double chi_square_quantile(double p, double nu);

/// The regularised lower incomplete gamma function P(a, x) = γ(a, x)/Γ(a), a > 0, x ≥ 0.
double regularized_gamma_p(double a, double x);

/// The p-quantile of the RMS over a window of T seconds of a stationary Gaussian process with
/// one-sided PSD S: the window's mean square is taken as σ²·χ²_ν/ν (equal mean and variance,
/// Satterthwaite's approximation) with ν = 2T(∫S df)²/∫S² df (Bendat & Piersol's statistical
/// bandwidth B_s = (∫S)²/∫S² and ν = 2B_sT). `variance` = ∫S df, `integral_of_square` = ∫S² df.
double rms_quantile(double variance, double integral_of_square, double window, double p);

/// One output's spectrum at one speed, per component c: P_c(f_k) = |H_c(f_k)|²·G_c(f_k) with G
/// taken inside its band (the edge value at an edge point), so that bands[c].weights
/// integrate it exactly over the band.
struct ComponentPower {
  std::vector<Eigen::VectorXd> power;  ///< per component, on the grid
};

/// ∫ Σ_c |W(f)|² P_c df over each component's band (W = 1: `weight` empty).
double integral(const ComponentPower& p, const std::vector<BandWeights>& bands, const Eigen::VectorXd& weight,
                bool coarse = false);

/// ∫ (Σ_c |W|² P_c)² df by the trapezoid of the square (the P95 estimate's ∫S²): each interval
/// takes the components inside their band there.
double integral_of_square(const ComponentPower& p, const std::vector<BandWeights>& bands,
                          const Eigen::VectorXd& grid, const Eigen::VectorXd& weight);

}  // namespace railmodal::ride
