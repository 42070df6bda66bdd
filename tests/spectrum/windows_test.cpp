// Windows: the published properties, the periodic form, and the line shape that peak
// interpolation relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "railmodal/spectrum.hpp"
#include "spectrum/windows.hpp"

namespace railmodal::test {
namespace {

constexpr Window kWindows[] = {Window::rectangular, Window::hann, Window::flat_top};

// Harris (1978), Table 1, for rectangular and Hann; the flat-top's coherent gain is its a0
// and its ENBW 3.7702 bins (the figure Matlab and SciPy's coefficients give).
TEST(Windows, PublishedProperties) {
  const WindowProperties r = window_properties(Window::rectangular);
  EXPECT_DOUBLE_EQ(r.coherent_gain, 1.0);
  EXPECT_DOUBLE_EQ(r.equivalent_noise_bandwidth, 1.0);
  EXPECT_NEAR(r.half_amplitude_bandwidth, 1.21, 0.005);
  EXPECT_NEAR(r.worst_case_scalloping, 2.0 / 3.14159265358979323846, 1e-15);  // −3.92 dB
  const WindowProperties h = window_properties(Window::hann);
  EXPECT_DOUBLE_EQ(h.coherent_gain, 0.5);
  EXPECT_DOUBLE_EQ(h.equivalent_noise_bandwidth, 1.5);
  EXPECT_NEAR(h.half_amplitude_bandwidth, 2.00, 0.005);
  EXPECT_NEAR(20.0 * std::log10(h.worst_case_scalloping), -1.42, 0.005);
  const WindowProperties f = window_properties(Window::flat_top);
  EXPECT_DOUBLE_EQ(f.coherent_gain, 0.21557895);
  EXPECT_NEAR(f.equivalent_noise_bandwidth, 3.7702, 5e-5);
  EXPECT_NEAR(f.worst_case_scalloping, 1.0, 0.002);  // flat: the reason for the window
}

// The closed forms of window_properties are the sums over the actual coefficients, for even
// and odd N; the periodic form is symmetric about N/2, w[n] = w[N − n].
TEST(Windows, CoefficientsMatchTheirProperties) {
  for (Window window : kWindows)
    for (Eigen::Index n : {1000, 1001}) {
      const Eigen::VectorXd w = window_coefficients(window, n);
      const WindowProperties p = window_properties(window);
      const double N = static_cast<double>(n);
      EXPECT_NEAR(w.sum() / N, p.coherent_gain, 1e-14) << to_string(window) << " N=" << n;
      EXPECT_NEAR(N * w.squaredNorm() / (w.sum() * w.sum()), p.equivalent_noise_bandwidth, 1e-12) << to_string(window);
      for (Eigen::Index i = 1; i < n; ++i) EXPECT_EQ(w(i), w(n - i)) << to_string(window) << " n=" << i;
    }
}

// The line shape used to correct scalloping is the window's DTFT: a tone ν bins off centre
// keeps |Σ w[n] e^{2πiνn/N}| / Σw of its amplitude. N = 4096 makes the finite-N difference
// O(1/N²) ≈ 1e-7.
TEST(Windows, ResponseIsTheTransformOfTheCoefficients) {
  const Eigen::Index n = 4096;
  for (Window window : kWindows) {
    const Eigen::VectorXd w = window_coefficients(window, n);
    for (double offset : {0.0, 0.1, 0.25, 0.5, 0.75, 1.3, 2.6, 4.5}) {
      std::complex<double> sum = 0.0;
      for (Eigen::Index i = 0; i < n; ++i)
        sum += w(i) * std::polar(1.0, 2.0 * 3.14159265358979323846 * offset * static_cast<double>(i) / n);
      EXPECT_NEAR(spectrum::window_response(window, offset), std::abs(sum) / w.sum(), 1e-6)
          << to_string(window) << " offset " << offset;
    }
  }
}

TEST(Windows, NamesRoundTrip) {
  for (Window window : kWindows) EXPECT_EQ(window_from_string(to_string(window)), window);
  EXPECT_FALSE(window_from_string("hamming"));
  EXPECT_THROW(window_coefficients(Window::hann, 0), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::test
