// A realisation of random track from its spectra by inverse FFT, with Gaussian Fourier
// coefficients. Derivation and conventions: docs/ride.md, "Realisations".
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "railmodal/ride_simulation.hpp"
#include "require_valid.hpp"
#include "ride/gaussian_stream.hpp"
#include "spectrum/real_fft.hpp"
#include "xoshiro256.hpp"

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The sample count of a profile: length rounded up to whole steps, even (a real FFT's
// Nyquist bin then exists, and is left empty: see realise).
Eigen::Index sample_count(const TrackSynthesisOptions& options) {
  const auto n = static_cast<Eigen::Index>(std::ceil(options.length / options.step - 1e-9));
  return n + (n % 2);
}

// Each component draws from its own stream, derived from the seed and the component, so a
// component's profile does not depend on which others are synthesised with it.
std::uint64_t component_seed(std::uint64_t seed, TrackIrregularity irregularity) {
  std::uint64_t x = seed ^ (0x5851f42d4c957f2dULL * (static_cast<std::uint64_t>(irregularity) + 1));
  return splitmix64(&x);
}

void require_representable(const TrackSpectrum& spectrum, double lowest, double nyquist) {
  const WavenumberBand band = spectrum.band();
  std::ostringstream why;
  if (band.high > nyquist)
    why << spectrum.name() << ": the band's upper end " << band.high
        << " rad/m is above the Nyquist wavenumber pi/step = " << nyquist << " rad/m; take a shorter step";
  else if (band.low < lowest)
    why << spectrum.name() << ": the band's lower end " << band.low
        << " rad/m is below the lowest wavenumber 2 pi/length = " << lowest
        << " rad/m the profile holds; take a longer length or raise the band's lower end";
  if (why.tellp() > 0) throw IrregularityComponentError(spectrum.irregularity(), "synthesise_track: " + why.str());
}

// z_n = Σ_k Re(c_k e^{iΩ_k x_n}), k = 1 … N/2 − 1, Ω_k = kΔΩ, ΔΩ = 2π/(NΔx): c_k has
// independent normal real and imaginary parts of variance S(Ω_k)ΔΩ, so that E z² = Σ S(Ω_k)ΔΩ.
// The c2r transform computes y_n = Y_0 + 2 Re Σ Y_k e^{2πikn/N} (+ the Nyquist term), so
// Y_k = c_k/2. The DC and Nyquist bins stay empty: a real bin cannot carry a complex Gaussian
// coefficient of the same law, and the band excludes both (Ω_low ≥ ΔΩ, Ω_high ≤ π/Δx).
Eigen::VectorXd realise(const TrackSpectrum& spectrum, Eigen::Index n, double step, std::uint64_t seed) {
  spectrum::InverseRealFft fft(n);
  const double dOmega = 2.0 * kPi / (static_cast<double>(n) * step);
  ride::GaussianStream stream(component_seed(seed, spectrum.irregularity()));
  auto Y = fft.input();
  Y.setZero();
  for (Eigen::Index k = 1; k < n / 2; ++k) {
    // Drawn for every bin, so a bin's draw does not depend on the band; outside the band (the
    // density exactly 0: most bins, the band's top usually far below Nyquist) the pair is only
    // skipped and the bin left at 0. It would be ±0 (0 times the draw's sign), and a signed
    // zero added to the other bins' nonzero terms leaves every sample the same double.
    const double density = spectrum.density(static_cast<double>(k) * dOmega);
    if (density == 0.0) {
      stream.skip_normal_pair();
      continue;
    }
    double re = 0.0, im = 0.0;
    stream.next_normal_pair(&re, &im);
    const double sigma = std::sqrt(density * dOmega);
    Y(k) = std::complex<double>(0.5 * sigma * re, 0.5 * sigma * im);
  }
  Eigen::VectorXd profile;
  fft.execute(&profile);  // straight into the profile: no copy, no second buffer touched
  return profile;
}

}  // namespace

double TrackGeometry::length() const {
  const Eigen::Index n = std::max({vertical_level.size(), alignment.size(), cross_level.size()});
  return static_cast<double>(n) * step;
}

bool TrackSynthesisOptions::is_valid(std::string* why) const {
  if (!(std::isfinite(length) && length > 0.0)) return invalid(why, "length must be positive and finite");
  if (!(std::isfinite(step) && step > 0.0)) return invalid(why, "step must be positive and finite");
  if (length / step < 4.0) return invalid(why, "length must hold at least 4 steps");
  if (length / step > 1e9) return invalid(why, "length / step must be at most 1e9 samples");
  return true;
}

TrackGeometry synthesise_track(const TrackIrregularitySpectra& track, const TrackSynthesisOptions& options) {
  require_valid(options, "TrackSynthesisOptions: ");
  if (!track.vertical_level && !track.alignment && !track.cross_level)
    throw std::invalid_argument("synthesise_track: the track has no irregularity component");
  const Eigen::Index n = sample_count(options);
  const double lowest = 2.0 * kPi / (static_cast<double>(n) * options.step), nyquist = kPi / options.step;
  TrackGeometry geometry;
  geometry.step = options.step;
  geometry.periodic = true;
  std::ostringstream source;
  const auto component = [&](const std::optional<TrackSpectrum>& spectrum, TrackIrregularity slot,
                             Eigen::VectorXd* profile) {
    if (!spectrum) return;
    if (spectrum->irregularity() != slot)
      throw std::invalid_argument(std::string("synthesise_track: a ") + to_string(spectrum->irregularity()) +
                                  " spectrum in the " + to_string(slot) + " slot");
    require_representable(*spectrum, lowest, nyquist);
    *profile = realise(*spectrum, n, options.step, options.seed);
    source << (source.tellp() > 0 ? "; " : "") << spectrum->name();
  };
  component(track.vertical_level, TrackIrregularity::vertical_level, &geometry.vertical_level);
  component(track.alignment, TrackIrregularity::alignment, &geometry.alignment);
  component(track.cross_level, TrackIrregularity::cross_level, &geometry.cross_level);
  source << "; " << static_cast<double>(n) * options.step << " m every " << options.step << " m; seed "
         << options.seed;
  geometry.source = source.str();
  return geometry;
}

}  // namespace railmodal
