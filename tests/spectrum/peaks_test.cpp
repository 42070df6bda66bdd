// Spectral peaks: interpolated frequency and amplitude of off-bin tones, two close tones
// resolved or not by each window, a damped free response, thresholds and bad arguments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "railmodal/spectrum.hpp"
#include "spectrum/signals.hpp"

namespace railmodal::test {
namespace {

SpectrumOptions with(Window window, Eigen::Index padding_factor, Eigen::Index n) {
  SpectrumOptions o;
  o.window = window;
  o.padding = Padding::to_length;
  o.padded_length = padding_factor * n;
  return o;
}

struct Accuracy {
  double frequency = 0.0;  // max |error|, bins of fs/N
  double amplitude = 0.0;  // max |relative error|
};

// Sweeps a unit tone across one bin (offsets 0, 0.05, … 0.95 from bin 200 of N = 4096) and
// returns the worst errors of the single strongest peak.
Accuracy sweep(Window window, Eigen::Index padding_factor) {
  const Eigen::Index n = 4096;
  const double fs = 1000.0, bin = fs / n;
  SpectrumAnalyzer analyzer(n, with(window, padding_factor, n));
  Accuracy worst;
  for (int i = 0; i < 20; ++i) {
    const double f = (200.0 + 0.05 * i) * bin;
    const auto peaks = find_peaks(analyzer.compute(tone(n, fs, f, 1.0, 0.7), fs));
    const auto strongest = *std::max_element(peaks.begin(), peaks.end(),
                                             [](const auto& a, const auto& b) { return a.amplitude < b.amplitude; });
    worst.frequency = std::max(worst.frequency, std::abs(strongest.frequency - f) / bin);
    worst.amplitude = std::max(worst.amplitude, std::abs(strongest.amplitude - 1.0));
  }
  return worst;
}

// Parabolic interpolation on log-amplitude is exact for a Gaussian line and biased for the
// windows' lines by a fixed function of the offset; its worst case over a bin, from the
// windows' transforms (N → ∞), in bins of fs/N: Hann 0.0160, flat-top 0.141, rectangular
// 0.168 unpadded; padded ×2 Hann 0.0016, ×4 rectangular 0.0015. The amplitude, corrected by
// the window's response at the interpolated offset, inherits that error through the slope of
// the response: Hann 0.70 %, flat-top 0.07 % (its flat top forgives a poor offset),
// rectangular padded ×4 0.06 %. The bounds below are those figures with ~25 % headroom for
// finite N and the tone's negative-frequency image, which adds its leakage at 2×200 bins
// away: 1/(π·400) = 0.08 % under the rectangular window, nothing under the others.
TEST(Peaks, OffBinToneInterpolation) {
  const Accuracy hann = sweep(Window::hann, 1);
  EXPECT_LT(hann.frequency, 0.02);
  EXPECT_LT(hann.amplitude, 0.009);
  const Accuracy hann2 = sweep(Window::hann, 2);
  EXPECT_LT(hann2.frequency, 0.002);
  EXPECT_LT(hann2.amplitude, 0.0005);
  const Accuracy flat = sweep(Window::flat_top, 1);
  EXPECT_LT(flat.frequency, 0.18);
  EXPECT_LT(flat.amplitude, 0.001);
  const Accuracy rect4 = sweep(Window::rectangular, 4);
  EXPECT_LT(rect4.frequency, 0.002);
  EXPECT_LT(rect4.amplitude, 0.0015);
  std::cout << "worst errors [bins of fs/N, relative amplitude]: hann " << hann.frequency << ", " << hann.amplitude
            << "; hann x2 " << hann2.frequency << ", " << hann2.amplitude << "; flat-top " << flat.frequency << ", "
            << flat.amplitude << "; rectangular x4 " << rect4.frequency << ", " << rect4.amplitude << "\n";
}

// Two equal tones `separation` bins of fs/N apart, padded ×8 so that the spectrum shows the
// continuous line shape: the fewest peaks over six relative phases. (Tones in antiphase
// always notch each other apart; in phase they merge when the lines overlap.)
size_t fewest_peaks_of_two_tones(Window window, double separation) {
  const Eigen::Index n = 2048;
  const double fs = 100.0, bin = fs / n, f1 = 300.3 * bin;
  SpectrumAnalyzer analyzer(n, with(window, 8, n));
  PeakOptions options;
  options.threshold = 0.5;  // the rectangular window's sidelobes (−13 dB) are not the tones
  size_t fewest = 99;
  for (double phase : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0}) {
    const Eigen::VectorXd x = tone(n, fs, f1, 1.0) + tone(n, fs, f1 + separation * bin, 1.0, phase);
    fewest = std::min(fewest, find_peaks(analyzer.compute(x, fs), options).size());
  }
  return fewest;
}

// Two equal tones merge when closer than about the window's half-amplitude bandwidth
// (rectangular 1.21, Hann 2.00, flat-top 4.58 bins): 2 bins apart the rectangular window
// always shows two where Hann and flat-top can show one at 1 and 2 bins; 3 bins apart Hann
// always resolves them and the flat-top does not; the flat-top needs 6.
TEST(Peaks, CloseTonesResolvedByWindow) {
  EXPECT_EQ(fewest_peaks_of_two_tones(Window::rectangular, 2.0), 2u);
  EXPECT_EQ(fewest_peaks_of_two_tones(Window::hann, 1.0), 1u);
  EXPECT_EQ(fewest_peaks_of_two_tones(Window::flat_top, 2.0), 1u);
  EXPECT_EQ(fewest_peaks_of_two_tones(Window::hann, 3.0), 2u);
  EXPECT_EQ(fewest_peaks_of_two_tones(Window::flat_top, 3.0), 1u);
  EXPECT_EQ(fewest_peaks_of_two_tones(Window::flat_top, 6.0), 2u);
}

// The free decay e^{−ζωt} cos ω_d t at the resort car's body bounce (1.0586 Hz) over 40 s at
// 200 Hz: the Hann spectrum's one peak lands on f_d = f√(1 − ζ²). A damped line is a hump
// symmetric about f_d, so its shape adds no interpolation bias; a lightly damped one is
// nearly a steady line and keeps the Hann bias (≤ 0.016 bin). Measured: 0.013, 0.0014,
// 0.008 bins unpadded for ζ = 0.005, 0.02, 0.05, under 0.0002 padded ×4; bound 0.05 bin. The
// more damped the line, the wider it is: at ζ = 0.05 the resolution limit is ~1.9 fs/N.
TEST(Peaks, DampedFreeResponseLandsOnTheDampedFrequency) {
  const double fs = 200.0, f = 1.0586;
  const Eigen::Index n = 8000;
  for (double zeta : {0.005, 0.02, 0.05})
    for (Eigen::Index padding : {1, 4}) {
      const double f_d = f * std::sqrt(1.0 - zeta * zeta);
      const Spectrum s =
          amplitude_spectrum(damped_free_response(n, fs, f, zeta), fs, with(Window::hann, padding, n));
      const auto peaks = find_peaks(s);
      ASSERT_EQ(peaks.size(), 1u) << "zeta " << zeta << " padding " << padding;
      EXPECT_LT(std::abs(peaks[0].frequency - f_d), 0.05 * s.resolution) << "zeta " << zeta << " padding " << padding;
      EXPECT_LT(std::abs(peaks[0].frequency - f_d), peaks[0].resolution);
      EXPECT_GE(peaks[0].resolution, s.resolution);
      if (zeta == 0.05) {
        EXPECT_GT(peaks[0].resolution, 1.5 * s.resolution);
      }
    }
}

// Why the flat-top is not for decaying lines: weighted by e^{−ζωt}, its flat main lobe
// turns into two humps either side of f_d (±1.5 bins at ζ = 0.05 over 40 s), each a
// "peak". They straddle f_d symmetrically, but neither is on it.
TEST(Peaks, FlatTopSplitsADampedLine) {
  const double fs = 200.0, f = 1.0586, zeta = 0.05, f_d = f * std::sqrt(1.0 - zeta * zeta);
  const Eigen::Index n = 8000;
  const Spectrum s = amplitude_spectrum(damped_free_response(n, fs, f, zeta), fs, with(Window::flat_top, 4, n));
  const auto peaks = find_peaks(s);
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_GT(f_d - peaks[0].frequency, s.resolution);
  EXPECT_GT(peaks[1].frequency - f_d, s.resolution);
  EXPECT_NEAR(0.5 * (peaks[0].frequency + peaks[1].frequency), f_d, 0.01 * s.resolution);
}

// A steady tone's resolution limit is the window's half-amplitude half-width: 1 bin for Hann.
TEST(Peaks, SteadyToneResolutionIsTheWindows) {
  const Eigen::Index n = 1000;
  const double fs = 50.0;
  const Spectrum s = amplitude_spectrum(tone(n, fs, 137 * fs / n, 1.0), fs);
  const auto peaks = find_peaks(s);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_EQ(peaks[0].bin, 137);
  EXPECT_NEAR(peaks[0].resolution, s.resolution, 1e-3 * s.resolution);
}

// Peaks come in ascending frequency; the threshold is relative to the largest peak.
TEST(Peaks, ThresholdAndOrder) {
  const Eigen::Index n = 4000;
  const double fs = 100.0;
  const Eigen::VectorXd x = tone(n, fs, 12.0, 1.0) + tone(n, fs, 3.0, 0.005) + tone(n, fs, 30.0, 0.2);
  const Spectrum s = amplitude_spectrum(x, fs);
  const auto strong = find_peaks(s);
  ASSERT_EQ(strong.size(), 2u);
  EXPECT_NEAR(strong[0].frequency, 12.0, 1e-9);
  EXPECT_NEAR(strong[1].frequency, 30.0, 1e-9);
  EXPECT_NEAR(strong[1].amplitude, 0.2, 1e-9);
  PeakOptions low;
  low.threshold = 0.001;
  const auto all = find_peaks(s, low);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_NEAR(all[0].frequency, 3.0, 1e-9);
  EXPECT_NEAR(all[0].amplitude, 0.005, 1e-9);
}

// One steady line, finely padded, is one peak: the Hann window's sidelobes (−31.5 dB) stay
// under the default threshold, and the flat-top's lobe, flat to 0.1 % but not exactly,
// ripples into several local maxima that min_dip keeps from counting.
TEST(Peaks, OneLineIsOnePeak) {
  const Eigen::Index n = 1024;
  const double fs = 100.0;
  for (Window window : {Window::hann, Window::flat_top}) {
    const Spectrum s = amplitude_spectrum(tone(n, fs, 200.4 * fs / n, 1.0), fs, with(window, 16, n));
    EXPECT_EQ(find_peaks(s).size(), 1u) << to_string(window);
  }
  const Spectrum s = amplitude_spectrum(tone(n, fs, 200.4 * fs / n, 1.0), fs, with(Window::flat_top, 16, n));
  PeakOptions every;
  every.min_dip = 0.0;
  every.threshold = 0.5;
  EXPECT_GT(find_peaks(s, every).size(), 1u);
}

TEST(Peaks, BadArgumentsAreNamed) {
  const Spectrum s = amplitude_spectrum(tone(64, 10.0, 2.0, 1.0), 10.0);
  for (double threshold : {0.0, -0.1, 1.5}) {
    PeakOptions o;
    o.threshold = threshold;
    EXPECT_THROW(find_peaks(s, o), std::invalid_argument) << threshold;
  }
  PeakOptions o;
  o.min_dip = 1.0;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("min_dip"), std::string::npos);
  Spectrum tiny;
  tiny.amplitude = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(find_peaks(tiny), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::test
