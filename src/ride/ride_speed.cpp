// One speed of the ride: delays and densities applied to the receptances (no solve here: the
// receptances do not depend on speed, docs/ride.md).
#include "ride/ride_speed.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>

#include "ride/phase_sincos.hpp"

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

void speed_spectra(const LinearSystem& system, const Receptances& r, const std::vector<Component>& components,
                   const Eigen::VectorXd& grid, double speed, const std::vector<BandWeights>& bands, bool with_psd,
                   SpeedSpectra* into, SpeedScratch* scratch) {
  (void)system;  // the inputs' positions are the receptances' own (Receptances::x)
  const int m = r.inputs, C = r.components, O = r.outputs, J = r.modes;
  const Eigen::Index K = grid.size();
  const double front = *std::max_element(r.x.begin(), r.x.end());

  // Every array at its size and zero, in the storage it already has when that fits (resize
  // keeps it at an unchanged size; a vector of vectors shrinks without freeing the rest).
  SpeedSpectra& s = *into;
  const auto zeros = [K](Eigen::VectorXd* v) {
    v->resize(K);
    v->setZero();
  };
  s.outputs.resize(O);
  for (ComponentPower& p : s.outputs) {
    p.power.resize(C);
    for (Eigen::VectorXd& v : p.power) zeros(&v);
  }
  s.psd.resize(O);
  for (Eigen::VectorXd& v : s.psd)
    if (with_psd) zeros(&v);
    else v.resize(0);
  s.modal_variance.resize(O);
  for (std::vector<double>& v : s.modal_variance) v.assign(J, 0.0);
  s.input_psd.resize(C);
  for (Eigen::VectorXd& v : s.input_psd) zeros(&v);
  // G_c inside the band: the density at the wavenumber clamped to the band, so that an edge
  // point carries the edge value whatever the round-off of 2πf/V there. Outside the band the
  // density is zero (TrackSpectrum::density) and the clamped one is the edge's, computed once.
  Eigen::MatrixXd& inside_density = scratch->inside_density;
  inside_density.resize(C, K);  // every value written below
  // A grid point this speed needs: one with an integration weight, on an interval inside a
  // band, or with a density. Elsewhere every index multiplies the power by a zero weight and
  // the PSD is H²·0, so the point's combine is skipped and its power left at zero: the sums
  // come out bit for bit as with it (x + 0 = x), at a third to a half of the work.
  std::vector<char>& needed = scratch->needed;
  needed.assign(K, 0);
  for (int c = 0; c < C; ++c) {
    const WavenumberBand b = components[c].spectrum.band();
    const double below = kTwoPi / speed * components[c].spectrum.density(b.low);
    const double above = kTwoPi / speed * components[c].spectrum.density(b.high);
    for (Eigen::Index k = 0; k < K; ++k) {
      const double wavenumber = kTwoPi * grid(k) / speed;
      // A band edge's grid point (speed·Ω_edge/2π, rounded) takes the edge value: its round-off
      // must not put it outside the band.
      const bool edge = std::abs(wavenumber - b.low) <= 1e-9 * b.low || std::abs(wavenumber - b.high) <= 1e-9 * b.high;
      if (edge || (wavenumber >= b.low && wavenumber <= b.high)) {
        const double g = kTwoPi / speed * components[c].spectrum.density(std::clamp(wavenumber, b.low, b.high));
        s.input_psd[c](k) = g;
        inside_density(c, k) = g;
      } else {
        inside_density(c, k) = wavenumber < b.low ? below : above;
      }
      const bool on_inside_interval = (k + 1 < K && bands[c].inside[k]) || (k > 0 && bands[c].inside[k - 1]);
      if (on_inside_interval || bands[c].weights(k) != 0.0 || bands[c].coarse_weights(k) != 0.0 ||
          s.input_psd[c](k) != 0.0)
        needed[k] = 1;
    }
  }
  // The delays τ_g of the input groups (the front one's is zero: no trigonometry). A delay that
  // is the sum of two earlier ones (the rear axle of a bogie coach: bogie pitch plus axle
  // spacing) takes the product of their phasors, one complex product for a sincos. Its phase
  // differs from the direct ωτ by at most 1e-14·ωτ (the test below; a symmetric layout gives a
  // few ulps): under 4e-11 rad at the largest phase of the benchmark (80 Hz, 19.5 m at
  // 10 km/h, ωτ ≈ 3500 rad), whose direct evaluation already carries 4e-13 rad of round-off.
  std::vector<double> delays(m);
  for (int g = 0; g < m; ++g) delays[g] = (front - r.x[g]) / speed;
  // In increasing delay, so that the two parts (each shorter) are settled as direct ones first.
  std::vector<int> order(m);
  for (int g = 0; g < m; ++g) order[g] = g;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return delays[a] < delays[b]; });
  std::vector<std::pair<int, int>> sum_of(m, {-1, -1});
  for (int g : order)
    for (int a = 0; a < m && sum_of[g].first < 0; ++a)
      for (int b = a; b < m; ++b)
        if (a != g && b != g && delays[a] > 0.0 && delays[b] > 0.0 && sum_of[a].first < 0 && sum_of[b].first < 0 &&
            std::abs(delays[a] + delays[b] - delays[g]) <= 1e-14 * delays[g]) {
          sum_of[g] = {a, b};
          break;
        }
  // Σ_g h_g·e^{−iωτ_g} in real arithmetic: std::complex's operator* checks for NaN and infinity
  // (C99 Annex G) and costs a call where this inner loop is the whole of a speed's work.
  std::vector<double> pr(m), pi(m);
  auto combine = [&](const std::complex<double>* h, double* re, double* im) {
    double a = 0.0, b = 0.0;
    for (int g = 0; g < m; ++g) {
      a += h[g].real() * pr[g] - h[g].imag() * pi[g];
      b += h[g].real() * pi[g] + h[g].imag() * pr[g];
    }
    *re = a;
    *im = b;
  };
  std::vector<double> qr(static_cast<size_t>(J) * C), qi(static_cast<size_t>(J) * C);
  // The direct groups' phases ω_kτ_g for a chunk of needed points at once, their sin and cos
  // by the vector phase_sincos (glibc's scalar sincos, a call per phase, was 12–14 % of the
  // benchmark's CPU); a chunk stays in the first-level cache.
  std::vector<int> direct;
  for (int g = 0; g < m; ++g)
    if (delays[g] != 0.0 && sum_of[g].first < 0) direct.push_back(g);
  const size_t D = direct.size();
  constexpr size_t kChunk = 256;
  std::vector<Eigen::Index> chunk(kChunk);
  std::vector<double> phase(D * kChunk), sine(D * kChunk), cosine(D * kChunk);
  for (int g = 0; g < m; ++g)
    if (delays[g] == 0.0) {
      pr[g] = 1.0;
      pi[g] = 0.0;
    }
  Eigen::Index next = 0;
  while (next < K) {
    size_t n = 0;
    for (; next < K && n < kChunk; ++next)
      if (needed[next]) chunk[n++] = next;
    for (size_t d = 0; d < D; ++d)
      for (size_t i = 0; i < n; ++i) phase[d * n + i] = kTwoPi * grid(chunk[i]) * delays[direct[d]];
    phase_sincos(phase.data(), sine.data(), cosine.data(), D * n);
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Index k = chunk[i];
      for (size_t d = 0; d < D; ++d) {
        pr[direct[d]] = cosine[d * n + i];
        pi[direct[d]] = -sine[d * n + i];
      }
      for (int g = 0; g < m; ++g)
        if (sum_of[g].first >= 0) {
          const int a = sum_of[g].first, b = sum_of[g].second;
          pr[g] = pr[a] * pr[b] - pi[a] * pi[b];
          pi[g] = pr[a] * pi[b] + pi[a] * pr[b];
        }
      const std::complex<double>* column = r.response.col(k).data();
      for (int o = 0; o < O; ++o)
        for (int c = 0; c < C; ++c) {
          double re, im;
          combine(column + (static_cast<size_t>(o) * C + c) * m, &re, &im);
          const double h2 = re * re + im * im;
          s.outputs[o].power[c](k) = h2 * inside_density(c, k);
          if (with_psd) s.psd[o](k) += h2 * s.input_psd[c](k);
        }
      if (J == 0) continue;
      // H_{c,j} = (a·φ_j)(φ_jᵀM Y_c): mode j's term of each output, needed only where a band
      // weighs it.
      bool weighed = false;
      for (int c = 0; c < C; ++c) weighed = weighed || bands[c].weights(k) != 0.0;
      if (!weighed) continue;
      const std::complex<double>* modal = r.modal.col(k).data();
      for (int j = 0; j < J; ++j)
        for (int c = 0; c < C; ++c) combine(modal + (static_cast<size_t>(j) * C + c) * m, &qr[j * C + c], &qi[j * C + c]);
      const double* seen = r.modal_rows.col(k).data();
      for (int o = 0; o < O; ++o)
        for (int j = 0; j < J; ++j) {
          const double seen2 = seen[o * J + j];
          for (int c = 0; c < C; ++c)
            s.modal_variance[o][j] += bands[c].weights(k) * seen2 *
                                      (qr[j * C + c] * qr[j * C + c] + qi[j * C + c] * qi[j * C + c]) *
                                      inside_density(c, k);
        }
    }
  }
}

}  // namespace railmodal::ride
