// Amplitude spectrum: the stated scaling for every window, padded or not, Parseval, mean
// removal, reuse of the plan, and bad arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "railmodal/spectrum.hpp"
#include "spectrum/signals.hpp"

namespace railmodal::test {
namespace {

// The FFT's rounding error grows like ε·log₂N relative to the largest amplitude (≈1e-14 for
// N ~ 1000): 1e-12 leaves two orders of headroom and still fails at any scaling slip.
constexpr double kRoundOff = 1e-12;

class EveryWindow : public ::testing::TestWithParam<Window> {};

SpectrumOptions with(Window window, Padding padding = Padding::none, Eigen::Index padded_length = 0) {
  SpectrumOptions o;
  o.window = window;
  o.padding = padding;
  o.padded_length = padded_length;
  return o;
}

// A·sin(2πft + φ) with f = k·fs/N shows A at bin k, whatever the phase, and nothing outside
// the window's main lobe (|j − k| < number of cosine terms).
TEST_P(EveryWindow, BinCentredToneHasItsAmplitude) {
  const Eigen::Index n = 1000, k = 137;
  const double fs = 50.0, f = k * fs / n, amplitude = 0.0037;
  SpectrumAnalyzer analyzer(n, with(GetParam()));
  for (double phase : {0.0, 0.4, 1.7, 3.0}) {
    const Spectrum s = analyzer.compute(tone(n, fs, f, amplitude, phase), fs);
    EXPECT_NEAR(s.amplitude(k), amplitude, kRoundOff * amplitude) << "phase " << phase;
    const Eigen::Index lobe = GetParam() == Window::rectangular ? 0 : GetParam() == Window::hann ? 1 : 4;
    for (Eigen::Index j = 0; j < s.amplitude.size(); ++j)
      if (std::abs(j - k) > lobe) {
        EXPECT_LT(s.amplitude(j), kRoundOff * amplitude) << "bin " << j;
      }
  }
}

// Padding adds zeros, not weight: padded ×4 the same tone sits on bin 4k with the same
// amplitude; a constant c shows c at bin 0 padded or not.
TEST_P(EveryWindow, ZeroPaddingKeepsTheScaling) {
  const Eigen::Index n = 1000, k = 137;
  const double fs = 50.0, amplitude = 2.5;
  const Eigen::VectorXd x = tone(n, fs, k * fs / n, amplitude, 0.3);
  const Spectrum plain = amplitude_spectrum(x, fs, with(GetParam()));
  const Spectrum padded = amplitude_spectrum(x, fs, with(GetParam(), Padding::to_length, 4 * n));
  EXPECT_EQ(padded.transform_length, 4 * n);
  EXPECT_EQ(padded.amplitude.size(), 2 * n + 1);
  EXPECT_DOUBLE_EQ(padded.bin_spacing, plain.bin_spacing / 4.0);
  EXPECT_DOUBLE_EQ(padded.resolution, plain.resolution);
  EXPECT_DOUBLE_EQ(padded.frequency(4 * k), plain.frequency(k));
  EXPECT_NEAR(padded.amplitude(4 * k), amplitude, kRoundOff * amplitude);

  SpectrumOptions keep_mean = with(GetParam(), Padding::next_power_of_two);
  keep_mean.remove_mean = false;
  const Spectrum constant = amplitude_spectrum(Eigen::VectorXd::Constant(n, -0.8), fs, keep_mean);
  EXPECT_EQ(constant.transform_length, 1024);
  EXPECT_NEAR(constant.amplitude(0), 0.8, kRoundOff);
}

// Removing the window-weighted mean zeroes bin 0 exactly and leaves a bin-centred tone's
// amplitude alone.
TEST_P(EveryWindow, MeanRemovalTakesOutTheOffset) {
  const Eigen::Index n = 1000, k = 137;
  const double fs = 50.0;
  const Eigen::VectorXd x = (tone(n, fs, k * fs / n, 1.0).array() + 0.25).matrix();
  const Spectrum s = amplitude_spectrum(x, fs, with(GetParam()));
  EXPECT_LT(s.amplitude(0), kRoundOff);
  EXPECT_NEAR(s.amplitude(k), 1.0, kRoundOff);
}

INSTANTIATE_TEST_SUITE_P(Spectrum, EveryWindow, ::testing::Values(Window::rectangular, Window::hann, Window::flat_top),
                         [](const auto& info) { return std::string(info.param == Window::flat_top ? "flat_top" : to_string(info.param)); });

// Parseval under the rectangular window: the mean square of the record is the sum of the
// bins' mean squares, A0² + ½ΣA_k² + A_{M/2}², scaled by N/M when padded to M. Random
// samples put energy in every bin; odd N has no Nyquist bin.
TEST(AmplitudeSpectrum, ParsevalRectangular) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1.0, 2.0);
  for (Eigen::Index n : {1024, 999}) {
    Eigen::VectorXd x(n);
    for (auto& v : x) v = uniform(random);
    const double mean_square = x.squaredNorm() / n;
    for (Eigen::Index m : {n, 3 * n / 2}) {
      SpectrumOptions o = with(Window::rectangular, Padding::to_length, m);
      o.remove_mean = false;
      const Spectrum s = amplitude_spectrum(x, 10.0, o);
      double sum = s.amplitude(0) * s.amplitude(0);
      const Eigen::Index last = s.amplitude.size() - 1;
      for (Eigen::Index k = 1; k <= last; ++k)
        sum += (m % 2 == 0 && k == last ? 1.0 : 0.5) * s.amplitude(k) * s.amplitude(k);
      EXPECT_NEAR(sum * static_cast<double>(n) / static_cast<double>(m), mean_square, kRoundOff * mean_square)
          << "N=" << n << " M=" << m;
    }
  }
}

// Over a non-integer number of cycles the plain mean is not the offset: subtracting it
// leaves −(mean − offset)·w, a line of that height at bins 0 and 1 (Hann) or 0 to 4
// (flat-top). Subtracting the window-weighted mean takes out the offset and leaves the
// spectrum of the signal without it, but for bin 0 and the tone's own tiny leakage there.
TEST(AmplitudeSpectrum, WeightedMeanRemovalTakesOutTheOffsetOnly) {
  const Eigen::Index n = 1000;
  const double fs = 50.0;
  const Eigen::VectorXd pure = tone(n, fs, 20.3 * fs / n, 1.0, 0.5);  // plain mean −0.015
  const Eigen::VectorXd offset = (pure.array() + 0.25).matrix();
  const Eigen::VectorXd plain = (offset.array() - offset.mean()).matrix();
  for (Window window : {Window::hann, Window::flat_top}) {
    SpectrumOptions keep = with(window);
    keep.remove_mean = false;
    const Eigen::VectorXd reference = amplitude_spectrum(pure, fs, keep).amplitude;
    const Eigen::VectorXd weighted = amplitude_spectrum(offset, fs, with(window)).amplitude;
    const Eigen::VectorXd unweighted = amplitude_spectrum(plain, fs, keep).amplitude;
    EXPECT_LT(weighted(0), kRoundOff);
    EXPECT_LT((weighted - reference).tail(n / 2).cwiseAbs().maxCoeff(), 1e-4) << to_string(window);
    EXPECT_GT(std::abs(unweighted(1) - reference(1)), 0.01) << to_string(window);
  }
}

TEST(AmplitudeSpectrum, ReportsResolutionAndBinSpacing) {
  SpectrumOptions o;
  o.padding = Padding::next_power_of_two;
  SpectrumAnalyzer analyzer(3000, o);
  EXPECT_EQ(analyzer.signal_length(), 3000);
  EXPECT_EQ(analyzer.transform_length(), 4096);
  const Spectrum s = analyzer.compute(tone(3000, 100.0, 7.0, 1.0), 100.0);
  EXPECT_DOUBLE_EQ(s.resolution, 100.0 / 3000);
  EXPECT_DOUBLE_EQ(s.bin_spacing, 100.0 / 4096);
  EXPECT_EQ(s.amplitude.size(), 2049);
  EXPECT_DOUBLE_EQ(s.frequencies()(2048), 50.0);
  EXPECT_DOUBLE_EQ(s.coherent_gain, 0.5);
  EXPECT_EQ(s.window, Window::hann);
}

// One plan, many signals: the same input gives the same bits, from a reused analyzer, into
// a reused Spectrum, and from a fresh one (FFTW_ESTIMATE plans alike every time).
TEST(AmplitudeSpectrum, ReusedPlanIsDeterministic) {
  const Eigen::VectorXd a = tone(4096, 100.0, 7.3, 1.0), b = tone(4096, 100.0, 21.1, 0.2);
  SpectrumAnalyzer analyzer(4096);
  const Spectrum first = analyzer.compute(a, 100.0);
  Spectrum reused;
  analyzer.compute(b, 100.0, &reused);
  analyzer.compute(a, 100.0, &reused);
  EXPECT_EQ(reused.amplitude, first.amplitude);
  SpectrumAnalyzer moved = std::move(analyzer);
  EXPECT_EQ(moved.compute(a, 100.0).amplitude, first.amplitude);
  EXPECT_EQ(amplitude_spectrum(a, 100.0).amplitude, first.amplitude);
}

template <typename F>
void expect_invalid(F f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning '" << fragment << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(AmplitudeSpectrum, BadArgumentsAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  expect_invalid([] { amplitude_spectrum(Eigen::VectorXd(), 10.0); }, "at least 2 samples, got 0");
  expect_invalid([] { amplitude_spectrum(Eigen::VectorXd::Ones(1), 10.0); }, "at least 2 samples, got 1");
  for (double fs : {0.0, -5.0, nan, inf})
    expect_invalid([fs] { amplitude_spectrum(Eigen::VectorXd::Ones(8), fs); }, "sampling_rate must be positive");
  Eigen::VectorXd x = Eigen::VectorXd::Ones(8);
  x(5) = nan;
  expect_invalid([&] { amplitude_spectrum(x, 10.0); }, "signal[5] is nan");
  x(5) = -inf;
  expect_invalid([&] { amplitude_spectrum(x, 10.0); }, "signal[5] is -inf");
  SpectrumAnalyzer analyzer(8);
  expect_invalid([&] { analyzer.compute(Eigen::VectorXd::Ones(9), 10.0); }, "8 samples, got 9");
  expect_invalid([] { SpectrumAnalyzer(100, with(Window::hann, Padding::to_length, 50)); },
                 "padded_length must be at least the signal length 100, got 50");
  std::string why;
  EXPECT_FALSE(with(Window::hann, Padding::to_length, 0).is_valid(&why));
  EXPECT_NE(why.find("padded_length"), std::string::npos);
}

}  // namespace
}  // namespace railmodal::test
