// railmodal — amplitude spectra of uniformly sampled real signals, and their peaks.
//
//   #include <railmodal/spectrum.hpp>
//
//   #include <cmath>
//   #include <iostream>
//
//   int main() {
//     const double fs = 200.0, pi = 3.14159265358979323846;  // Hz
//     Eigen::VectorXd x(4000);                                // 20 s of 3 mm at 1.37 Hz
//     for (Eigen::Index n = 0; n < x.size(); ++n) x(n) = 0.003 * std::sin(2 * pi * 1.37 * n / fs);
//     railmodal::SpectrumOptions options;  // Hann, weighted mean removed
//     options.padding = railmodal::Padding::next_power_of_two;
//     railmodal::SpectrumAnalyzer analyzer(x.size(), options);  // plans once for 4000 samples
//     const railmodal::Spectrum s = analyzer.compute(x, fs);    // reuse for every such signal
//     for (const railmodal::SpectralPeak& p : railmodal::find_peaks(s))
//       std::cout << p.frequency << " Hz  " << p.amplitude << " m  ± " << p.resolution << " Hz\n";
//   }  // prints: 1.37021 Hz  0.00300097 m  ± 0.05038 Hz
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "railmodal/summary.hpp"

namespace railmodal {

/// Data windows, all in the periodic (DFT-even) form w[n], n = 0 … N−1, so that a tone
/// centred on a bin leaks into no other bin but the window's own lobe.
enum class Window {
  rectangular,  ///< w = 1: narrowest line, worst leakage (sidelobes −13 dB), scalloping 36 %
  hann,         ///< w = ½ − ½cos(2πn/N): the choice for frequencies; scalloping 15 %
  /// Five-term flat-top of Matlab's flattopwin and SciPy's signal.windows.flattop:
  /// w = a0 − a1 cos(2πn/N) + a2 cos(4πn/N) − a3 cos(6πn/N) + a4 cos(8πn/N),
  /// a = 0.21557895, 0.41663158, 0.277263158, 0.083578947, 0.006947368. The choice for the
  /// amplitudes of steady tones (scalloping 0.11 %). Not for decaying lines: weighted by the
  /// decay, its flat lobe splits into two humps either side of the line (±1.5 bins at
  /// ζ = 0.05 over 40 s), both reported as peaks.
  flat_top
};
const char* to_string(Window window);
/// Inverse of to_string ("rectangular", "hann", "flat-top"); std::nullopt for an unknown word.
std::optional<Window> window_from_string(const std::string& word);

/// What a window does to a spectrum. Bandwidths are in bins of fs/N (N the number of
/// windowed samples, before any zero padding), for N ≫ 1.
struct WindowProperties {
  /// Σw/N: the amplitude a tone keeps after windowing (a0: 1, 0.5, 0.21557895). Amplitude
  /// spectra divide by it.
  double coherent_gain = 0.0;
  /// N·Σw²/(Σw)²: the width of the ideal filter passing the same noise power
  /// (1, 1.5, 3.7702 bins).
  double equivalent_noise_bandwidth = 0.0;
  /// Width of the main lobe at half amplitude (−6 dB): 1.21, 2.00, 4.58 bins. Two equal
  /// tones closer than this merge into one peak (Harris 1978).
  double half_amplitude_bandwidth = 0.0;
  /// Amplitude of a tone half a bin off centre relative to a centred one: 0.637, 0.849, 0.9989.
  double worst_case_scalloping = 0.0;
};
WindowProperties window_properties(Window window);

/// w[n] for n = 0 … length−1 (periodic form). Throws std::invalid_argument if length < 1.
Eigen::VectorXd window_coefficients(Window window, Eigen::Index length);

/// Zero padding: the transform length M, from the signal length N.
enum class Padding {
  none,               ///< M = N
  to_length,          ///< M = SpectrumOptions::padded_length (≥ N)
  next_power_of_two,  ///< M = the smallest power of two ≥ N
};
const char* to_string(Padding padding);  ///< "none", "to-length", "next-power-of-two"
/// Inverse of to_string; std::nullopt for an unknown word.
std::optional<Padding> padding_from_string(const std::string& word);

struct SpectrumOptions {
  Window window = Window::hann;
  /// Subtract the window-weighted mean Σw·x/Σw before windowing, so that a static offset (a
  /// wagon's static deflection) neither shows at bin 0 nor leaks into the lowest bins. (The
  /// plain mean would leave a spurious line near 0 Hz when the record holds a non-integer
  /// number of cycles; for the rectangular window the two are the same.)
  bool remove_mean = true;
  Padding padding = Padding::none;
  Eigen::Index padded_length = 0;  ///< for Padding::to_length
  /// Returns false and explains in *why when an option is out of range.
  bool is_valid(std::string* why) const;
};

/// A one-sided amplitude spectrum.
///
/// Scaling: with x[n] the N samples (less their weighted mean if remove_mean), w[n] the
/// window and X[k] = Σ_{n<N} w[n] x[n] e^{−2πik n/M} the DFT of the record zero-padded to M,
///
///   amplitude[0] = |X[0]| / Σw,   amplitude[k] = 2|X[k]| / Σw  (0 < k < M/2),
///   amplitude[M/2] = |X[M/2]| / Σw  (M even),
///
/// Σw = N × coherent gain. So a tone A·sin(2πft + φ) with f = j·fs/N, farther from 0 Hz and
/// from Nyquist than the window's main lobe, shows exactly A at its bin (j·M/N) under every
/// window, padded or not: padding adds zeros, not weight. A constant c kept in (remove_mean
/// false) shows c at bin 0. Between bins a tone shows less (scalloping, see
/// WindowProperties); find_peaks corrects for it.
struct Spectrum {
  Eigen::VectorXd amplitude;  ///< bins k = 0 … M/2, in the signal's unit (peak, not RMS)
  double sampling_rate = 0.0;         ///< fs, Hz
  Eigen::Index signal_length = 0;     ///< N, samples in the record
  Eigen::Index transform_length = 0;  ///< M ≥ N, after zero padding
  /// fs/N, Hz: what the record can resolve, whatever the padding.
  double resolution = 0.0;
  /// fs/M, Hz: the spacing of the amplitude bins (finer than resolution when padded).
  double bin_spacing = 0.0;
  Window window = Window::hann;
  double coherent_gain = 0.0;  ///< Σw/N of the window as applied
  /// The method (window, padding), the check that every amplitude is finite and the stage
  /// times ("window", "transform", "scale"). Refilled without allocating when reused.
  AnalysisSummary summary;

  double frequency(Eigen::Index bin) const { return static_cast<double>(bin) * bin_spacing; }
  Eigen::VectorXd frequencies() const;  ///< frequency(k) for every bin, Hz
};

/// Computes amplitude spectra of signals of one length with a transform planned once (FFTW
/// r2c, planned by estimate so that the same input gives the same bits on every run). Plan
/// once, compute many times: planning costs more than a transform. One analyzer must not be
/// used by two threads at once; make one per thread.
class SpectrumAnalyzer {
 public:
  /// Throws std::invalid_argument if signal_length < 2 or the options are invalid for it.
  explicit SpectrumAnalyzer(Eigen::Index signal_length, const SpectrumOptions& options = {});
  ~SpectrumAnalyzer();
  SpectrumAnalyzer(SpectrumAnalyzer&&) noexcept;
  SpectrumAnalyzer& operator=(SpectrumAnalyzer&&) noexcept;

  Eigen::Index signal_length() const;     ///< N
  Eigen::Index transform_length() const;  ///< M
  const SpectrumOptions& options() const;

  /// The amplitude spectrum of `signal` sampled at `sampling_rate` Hz. Throws
  /// std::invalid_argument if the signal does not have signal_length() samples, a sample is
  /// NaN or infinite, or the sampling rate is not positive and finite.
  Spectrum compute(const Eigen::Ref<const Eigen::VectorXd>& signal, double sampling_rate);
  /// The same into *out, reusing its storage (no allocation when it already has M/2+1 bins).
  void compute(const Eigen::Ref<const Eigen::VectorXd>& signal, double sampling_rate, Spectrum* out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One-off: plans, computes, discards the plan.
Spectrum amplitude_spectrum(const Eigen::Ref<const Eigen::VectorXd>& signal, double sampling_rate,
                            const SpectrumOptions& options = {});

struct PeakOptions {
  /// Keep peaks at least this fraction of the largest peak's amplitude, in (0, 1]. The
  /// default lies above the Hann window's highest sidelobe (−31.5 dB, 2.7 %), which zero
  /// padding shows as a local maximum beside every strong steady line; under the rectangular
  /// window (sidelobes −13 dB) leakage needs 0.22 to be left out.
  double threshold = 0.03;
  /// A local maximum is a peak only if the spectrum falls by at least this fraction of its
  /// amplitude on both sides before it rises above it (or ends), in [0, 1). This keeps the
  /// ripple on a flat-top's lobe and the notch of two barely separated lines from counting
  /// as peaks; 0 keeps every local maximum.
  double min_dip = 0.1;
  /// Returns false and explains in *why when an option is out of range.
  bool is_valid(std::string* why) const;
};

struct SpectralPeak {
  /// Interpolated, Hz: the vertex of the parabola through the log-amplitudes of the peak bin
  /// and its two neighbours (parabolic interpolation on dB, i.e. Gaussian interpolation).
  /// Chosen because one formula serves every window and it is robust on broad (damped)
  /// lines, where window-specific ratio formulas (Jain, Grandke) are exact only for steady
  /// tones. Error for a steady tone, unpadded, in bins of fs/N: Hann ≤ 0.016, rectangular
  /// ≤ 0.17, flat-top ≤ 0.14; padding ×2 makes Hann ≤ 0.0016 and rectangular ≤ 0.011.
  double frequency = 0.0;
  /// The peak bin's amplitude corrected for scalloping by the window's response at the
  /// interpolated offset: exact for a bin-centred tone; for a steady tone unpadded at most
  /// +0.7 % (Hann) or ±0.07 % (flat-top) off. Rectangular needs padding (×4: 0.1 %).
  double amplitude = 0.0;
  Eigen::Index bin = 0;  ///< the local maximum (0 < bin < M/2)
  /// The resolution limit of this peak, Hz: half its width at half amplitude measured on
  /// the spectrum, and never less than half the window's half_amplitude_bandwidth × fs/N
  /// (the width of a steady tone's line). A second line nearer than twice this would merge
  /// with this one; a frequency within it of the peak cannot be told apart from it. A damped
  /// line is wider than a steady one.
  double resolution = 0.0;
};

/// Spectral peaks in ascending frequency: local maxima of the amplitude away from bin 0 and
/// the last bin, with the dip that options.min_dip asks for, of at least options.threshold
/// times the largest such maximum. Throws std::invalid_argument for invalid options or a
/// spectrum with fewer than 3 bins. `summary`, if given, receives the method, the maxima
/// found and kept, and the stage times.
std::vector<SpectralPeak> find_peaks(const Spectrum& spectrum, const PeakOptions& options = {},
                                     AnalysisSummary* summary = nullptr);

}  // namespace railmodal
