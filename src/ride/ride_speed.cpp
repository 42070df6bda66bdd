// One speed of the ride: delays and densities applied to the receptances (no solve here: the
// receptances do not depend on speed, docs/ride.md).
#include "ride/ride_speed.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace railmodal::ride {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
using Complex = std::complex<double>;

}  // namespace

std::vector<BandWeights> speed_bands(const std::vector<Component>& components, const Eigen::VectorXd& grid,
                                     double speed) {
  std::vector<BandWeights> bands;
  for (const Component& c : components) {
    const WavenumberBand b = c.spectrum.band();
    bands.push_back(band_weights(grid, speed * b.low / kTwoPi, speed * b.high / kTwoPi));
  }
  return bands;
}

SpeedSpectra speed_spectra(const LinearSystem& system, const Receptances& r, const std::vector<Component>& components,
                           const Eigen::VectorXd& grid, double speed, const std::vector<BandWeights>& bands,
                           const ModalBasis* modal) {
  const int m = static_cast<int>(system.track_inputs.size());
  const int C = static_cast<int>(components.size());
  const Eigen::Index K = grid.size();
  const int O = K > 0 ? static_cast<int>(r.A[0].rows()) : 0;
  const int J = modal ? static_cast<int>(modal->shapes.cols()) : 0;
  double front = system.track_inputs.front().point.x();
  for (const TrackInput& t : system.track_inputs) front = std::max(front, t.point.x());

  SpeedSpectra s;
  s.outputs.assign(O, ComponentPower{std::vector<Eigen::VectorXd>(C, Eigen::VectorXd::Zero(K))});
  s.psd.assign(O, Eigen::VectorXd::Zero(K));
  s.modal_variance.assign(O, std::vector<double>(J, 0.0));
  s.input_psd.assign(C, Eigen::VectorXd::Zero(K));
  // G_c inside the band: the density at the wavenumber clamped to the band, so that an edge
  // point carries the edge value whatever the round-off of 2πf/V there.
  Eigen::MatrixXd inside_density(C, K);
  for (int c = 0; c < C; ++c) {
    const WavenumberBand b = components[c].spectrum.band();
    for (Eigen::Index k = 0; k < K; ++k) {
      const double wavenumber = kTwoPi * grid(k) / speed;
      s.input_psd[c](k) = kTwoPi / speed * components[c].spectrum.density(wavenumber);
      inside_density(c, k) = kTwoPi / speed * components[c].spectrum.density(std::clamp(wavenumber, b.low, b.high));
    }
  }
  Eigen::VectorXcd phasor(m);
  Eigen::MatrixXcd Y(r.X.empty() ? 0 : r.X[0].rows(), C);
  Eigen::MatrixXcd H(O, C);
  for (Eigen::Index k = 0; k < K; ++k) {
    const double omega = kTwoPi * grid(k);
    for (int i = 0; i < m; ++i)
      phasor(i) = std::exp(Complex(0.0, -omega * (front - system.track_inputs[i].point.x()) / speed));
    for (int c = 0; c < C; ++c) {
      Y.col(c) = r.X[k].middleCols(c * m, m) * phasor;
      H.col(c) = r.T[k].middleCols(c * m, m) * phasor;
    }
    H += r.A[k] * Y;
    for (int o = 0; o < O; ++o)
      for (int c = 0; c < C; ++c) {
        const double h2 = std::norm(H(o, c));
        s.outputs[o].power[c](k) = h2 * inside_density(c, k);
        s.psd[o](k) += h2 * s.input_psd[c](k);
      }
    if (!modal) continue;
    // H_{c,j} = (a·φ_j)(φ_jᵀM Y_c): mode j's term of each output.
    const Eigen::MatrixXcd q = modal->left.cast<Complex>() * Y;       // J × C
    const Eigen::MatrixXcd a_phi = r.A[k] * modal->shapes.cast<Complex>();  // O × J
    for (int o = 0; o < O; ++o)
      for (int j = 0; j < J; ++j)
        for (int c = 0; c < C; ++c)
          s.modal_variance[o][j] += bands[c].weights(k) * std::norm(a_phi(o, j) * q(j, c)) * inside_density(c, k);
  }
  return s;
}

}  // namespace railmodal::ride
