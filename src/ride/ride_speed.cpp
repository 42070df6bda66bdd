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
                           const Eigen::VectorXd& grid, double speed, const std::vector<BandWeights>& bands) {
  const int m = r.inputs, C = r.components, O = r.outputs, J = r.modes;
  const Eigen::Index K = grid.size();
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
  // The delays: one phasor per distinct x (the two wheels of an axle share theirs).
  std::vector<double> delays;
  std::vector<int> delay_of(m);
  for (int i = 0; i < m; ++i) {
    const double tau = (front - system.track_inputs[i].point.x()) / speed;
    size_t d = 0;
    while (d < delays.size() && std::abs(delays[d] - tau) > 1e-12 * (1.0 + tau)) ++d;
    if (d == delays.size()) delays.push_back(tau);
    delay_of[i] = static_cast<int>(d);
  }
  // Σ_i h_i·e^{−iωτ_i} in real arithmetic: std::complex's operator* checks for NaN and infinity
  // (C99 Annex G) and costs a call where this inner loop is the whole of a speed's work.
  std::vector<double> cos_d(delays.size()), sin_d(delays.size()), pr(m), pi(m);
  auto combine = [&](const std::complex<double>* h, double* re, double* im) {
    double a = 0.0, b = 0.0;
    for (int i = 0; i < m; ++i) {
      a += h[i].real() * pr[i] - h[i].imag() * pi[i];
      b += h[i].real() * pi[i] + h[i].imag() * pr[i];
    }
    *re = a;
    *im = b;
  };
  std::vector<double> qr(static_cast<size_t>(J) * C), qi(static_cast<size_t>(J) * C);
  for (Eigen::Index k = 0; k < K; ++k) {
    const double omega = kTwoPi * grid(k);
    for (size_t d = 0; d < delays.size(); ++d) {
      cos_d[d] = std::cos(omega * delays[d]);
      sin_d[d] = -std::sin(omega * delays[d]);
    }
    for (int i = 0; i < m; ++i) {
      pr[i] = cos_d[delay_of[i]];
      pi[i] = sin_d[delay_of[i]];
    }
    const std::complex<double>* column = r.response.col(k).data();
    for (int o = 0; o < O; ++o)
      for (int c = 0; c < C; ++c) {
        double re, im;
        combine(column + (static_cast<size_t>(o) * C + c) * m, &re, &im);
        const double h2 = re * re + im * im;
        s.outputs[o].power[c](k) = h2 * inside_density(c, k);
        s.psd[o](k) += h2 * s.input_psd[c](k);
      }
    if (J == 0) continue;
    // H_{c,j} = (a·φ_j)(φ_jᵀM Y_c): mode j's term of each output.
    const std::complex<double>* modal = r.modal.col(k).data();
    for (int j = 0; j < J; ++j)
      for (int c = 0; c < C; ++c) combine(modal + (static_cast<size_t>(j) * C + c) * m, &qr[j * C + c], &qi[j * C + c]);
    const std::complex<double>* seen = r.modal_rows.col(k).data();
    for (int o = 0; o < O; ++o)
      for (int j = 0; j < J; ++j) {
        const double seen2 = std::norm(seen[o * J + j]);
        for (int c = 0; c < C; ++c)
          s.modal_variance[o][j] += bands[c].weights(k) * seen2 * (qr[j * C + c] * qr[j * C + c] + qi[j * C + c] * qi[j * C + c]) *
                                    inside_density(c, k);
      }
  }
  return s;
}

}  // namespace railmodal::ride
