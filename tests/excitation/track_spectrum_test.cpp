// Track irregularity spectra: the published constants, every convention (rad/m against
// cycles/m, one-sided, temporal density, cross-level as angle or height difference, the band),
// and the exact band variances against numerical quadrature.
#include "railmodal/track_spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr TrackIrregularity kAll[] = {TrackIrregularity::vertical_level, TrackIrregularity::alignment,
                                      TrackIrregularity::cross_level};
const WavenumberBand k3To70m{2 * kPi / 70, 2 * kPi / 3};

// Composite Simpson in u = ln Ω (dΩ = Ω du), 20000 intervals: the integrands are smooth in ln Ω
// and vary over at most a few decades per unit of u, so the error is below 1e-12 relative.
double quadrature(const std::function<double(double)>& f, double a, double b) {
  const int n = 20000;
  const double ua = std::log(a), ub = std::log(b), h = (ub - ua) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double omega = std::min(std::max(std::exp(ua + i * h), a), b);  // exp(ln b) may round above b
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * f(omega) * omega;
  }
  return sum * h / 3.0;
}

// ORE B176 formulas with the constants typed from the first public source (T1, docs/ride.md):
// Ω_c 0.8246, Ω_r 0.0206, Ω_s 0.438, b 0.75 m, A_v 4.032e-7 / 1.08e-6, A_a 2.119e-7 / 6.125e-7.
TEST(TrackSpectrum, OreB176PublishedValues) {
  const double c = 0.8246, r = 0.0206, s = 0.438, b = 0.75;
  const WavenumberBand all{1e-4, 100.0};
  for (double omega : {0.01, 0.1, 0.5, 2.0, 10.0}) {
    const double o2 = omega * omega;
    const double shape = c * c / ((o2 + r * r) * (o2 + c * c));
    EXPECT_NEAR(TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, all).density(omega) /
                    (4.032e-7 * shape),
                1.0, 1e-14);
    EXPECT_NEAR(TrackSpectrum::ore_b176(OreLevel::high, TrackIrregularity::vertical_level, all).density(omega) /
                    (1.08e-6 * shape),
                1.0, 1e-14);
    EXPECT_NEAR(
        TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::alignment, all).density(omega) / (2.119e-7 * shape),
        1.0, 1e-14);
    EXPECT_NEAR(
        TrackSpectrum::ore_b176(OreLevel::high, TrackIrregularity::alignment, all).density(omega) / (6.125e-7 * shape),
        1.0, 1e-14);
    // The published cross-level is an angle: (A_v/b²) Ω_c² Ω² / (…); ours is Δz = 2b θ.
    const double angle = 4.032e-7 / (b * b) * c * c * o2 / ((o2 + r * r) * (o2 + c * c) * (o2 + s * s));
    const TrackSpectrum cross = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::cross_level, all);
    EXPECT_NEAR(cross.cross_level_angle_density(omega, 2 * b) / angle, 1.0, 1e-14);
    EXPECT_NEAR(cross.density(omega) / (angle * 4 * b * b), 1.0, 1e-14);
  }
}

// The reading of the cross-level angle as θ = Δz/(2b) is the one that makes B176 consistent:
// at short wavelengths the rails' irregularities are independent and alike, so the half
// difference Δz/2 and the level (z_l + z_r)/2 have the same density. S_Δz/4 → S_v as Ω → ∞.
TEST(TrackSpectrum, OreCrossLevelMatchesLevelAtShortWavelength) {
  const WavenumberBand all{1e-4, 1e4};
  for (OreLevel level : {OreLevel::low, OreLevel::high}) {
    const double omega = 1000.0;  // the next term is O((Ω_s/Ω)²) = 2e-7
    const double ratio = TrackSpectrum::ore_b176(level, TrackIrregularity::cross_level, all).density(omega) / 4.0 /
                         TrackSpectrum::ore_b176(level, TrackIrregularity::vertical_level, all).density(omega);
    EXPECT_NEAR(ratio, 1.0, 1e-6);
  }
}

// FRA classes (T7 for A_v, A_a, Ω_s; T8 for A_v, k and Ω_c; T10's class-6 cross-level and
// class-5 vertical lines), in cm² converted to m² by 1e-4.
TEST(TrackSpectrum, FraPublishedValues) {
  const double av[] = {1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339};
  const double aa[] = {3.3634, 1.2107, 0.4128, 0.3027, 0.0762, 0.0339};
  const double os[] = {0.6046, 0.9308, 0.852, 1.1312, 0.8209, 0.438};
  const double k = 0.25, c = 0.8245;
  for (int cls = 1; cls <= 6; ++cls)
    for (double omega : {0.05, 0.3, 1.0, 3.0}) {
      const double o2 = omega * omega;
      const double level = k * av[cls - 1] * c * c / (o2 * (o2 + c * c)) * 1e-4;
      const double alignment = k * aa[cls - 1] * c * c / (o2 * (o2 + c * c)) * 1e-4;
      const double cross = 4 * k * av[cls - 1] * c * c / ((o2 + c * c) * (o2 + os[cls - 1] * os[cls - 1])) * 1e-4;
      EXPECT_NEAR(TrackSpectrum::fra_class(cls, TrackIrregularity::vertical_level).density(omega) / level, 1.0, 1e-14);
      EXPECT_NEAR(TrackSpectrum::fra_class(cls, TrackIrregularity::alignment).density(omega) / alignment, 1.0, 1e-14);
      EXPECT_NEAR(TrackSpectrum::fra_class(cls, TrackIrregularity::cross_level).density(omega) / cross, 1.0, 1e-14);
    }
  // T10, literally: 4*0.25*0.0339*0.8245^2/((O^2+0.438^2)(O^2+0.8245^2)) cm^2/(rad/m), class 6.
  const double o = 0.4;
  EXPECT_NEAR(TrackSpectrum::fra_class(6, TrackIrregularity::cross_level).density(o),
              4 * 0.25 * 0.0339 * 0.8245 * 0.8245 / ((o * o + 0.438 * 0.438) * (o * o + 0.8245 * 0.8245)) * 1e-4,
              1e-18);
  // The default band is the FRA range of wavelengths, 1.524 … 304.8 m (5 … 1000 ft).
  const WavenumberBand band = TrackSpectrum::fra_class(4, TrackIrregularity::alignment).band();
  EXPECT_NEAR(2 * kPi / band.low, 304.8, 1e-12);
  EXPECT_NEAR(2 * kPi / band.high, 1.524, 1e-12);
  // Class 6 is the best track: the smallest variance of every component.
  for (TrackIrregularity i : kAll)
    for (int cls = 1; cls < 6; ++cls)
      EXPECT_LT(TrackSpectrum::fra_class(cls + 1, i).variance(), TrackSpectrum::fra_class(cls, i).variance() * 1.0001)
          << cls << " " << to_string(i);
}

// The closed-form band variance (partial fractions) against quadrature, for every standard
// spectrum and three bands; relative 1e-9 is far above the quadrature's error (1e-12) and far
// below any constant's effect.
TEST(TrackSpectrum, VarianceIsTheIntegralOfTheDensity) {
  std::vector<TrackSpectrum> spectra;
  for (TrackIrregularity i : kAll) {
    for (OreLevel l : {OreLevel::low, OreLevel::high}) spectra.push_back(TrackSpectrum::ore_b176(l, i, {1e-3, 60.0}));
    for (int cls = 1; cls <= 6; ++cls) spectra.push_back(TrackSpectrum::fra_class(cls, i));
  }
  for (const TrackSpectrum& s : spectra)
    for (const WavenumberBand& band : {k3To70m, WavenumberBand{0.01, 0.5}, s.band()}) {
      const double a = std::max(band.low, s.band().low), b = std::min(band.high, s.band().high);
      const double numeric = quadrature([&s](double o) { return s.density(o); }, a, b);
      EXPECT_NEAR(s.variance(band) / numeric, 1.0, 1e-9) << s.name() << " [" << band.low << ", " << band.high << "]";
    }
}

// Convergence and divergence: B176's level has a finite variance over 0 … ∞,
// A Ω_c²/(Ω_c² − Ω_r²) · (π/2)(1/Ω_r − 1/Ω_c); FRA's level grows as 1/Ω_low (Ω⁻²), so it must
// have a lower cut-off and refuses a band from 0.
TEST(TrackSpectrum, TheBandMatters) {
  const double c = 0.8246, r = 0.0206;
  const double total = 4.032e-7 * c * c / (c * c - r * r) * kPi / 2 * (1 / r - 1 / c);
  const TrackSpectrum ore = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, {0.0, 1e9});
  EXPECT_NEAR(ore.variance() / total, 1.0, 1e-12);  // the tail beyond 1e9 rad/m is 1e-28 of it
  EXPECT_THROW(TrackSpectrum::fra_class(4, TrackIrregularity::vertical_level, {0.0, 1.0}), std::invalid_argument);
  const TrackSpectrum fra1 = TrackSpectrum::fra_class(4, TrackIrregularity::vertical_level, {1e-3, 1.0});
  const TrackSpectrum fra2 = TrackSpectrum::fra_class(4, TrackIrregularity::vertical_level, {1e-4, 1.0});
  // ∝ 1/Ω_low − 1/Ω_high − O(1) as Ω_low → 0: 9998/998 = 10.02
  EXPECT_NEAR(fra2.variance() / fra1.variance(), 10.0, 0.03);
  // Zero outside the band, and a band outside the spectrum's holds nothing.
  EXPECT_EQ(fra1.density(2.0), 0.0);
  EXPECT_EQ(fra1.density(1e-4), 0.0);
  EXPECT_GT(fra1.density(0.5), 0.0);
  EXPECT_EQ(fra1.variance({2.0, 3.0}), 0.0);
  EXPECT_NEAR(fra1.variance({0.0, 1e6}), fra1.variance(), 0.0);
  EXPECT_THROW(fra1.variance({1.0, 0.5}), std::invalid_argument);
}

// S_n(n) = 2π S(2πn); G(f) = (2π/V) S(2πf/V); and ∫ G df over the band seen at speed V is the
// spatial variance.
TEST(TrackSpectrum, ConventionsBetweenDensities) {
  const TrackSpectrum s = TrackSpectrum::ore_b176(OreLevel::high, TrackIrregularity::alignment, k3To70m);
  EXPECT_NEAR(s.density_per_cycle(0.1), 2 * kPi * s.density(2 * kPi * 0.1), 1e-20);
  const double speed = 200 / 3.6;
  EXPECT_NEAR(s.temporal_density(3.0, speed), 2 * kPi / speed * s.density(2 * kPi * 3.0 / speed), 1e-20);
  const double f_low = speed * k3To70m.low / (2 * kPi), f_high = speed * k3To70m.high / (2 * kPi);
  EXPECT_NEAR(f_low, speed / 70, 1e-12);  // f = V/λ
  const double in_time = quadrature([&](double f) { return s.temporal_density(f, speed); }, f_low, f_high);
  EXPECT_NEAR(in_time / s.variance(), 1.0, 1e-9);
  const double per_cycle =
      quadrature([&](double n) { return s.density_per_cycle(n); }, k3To70m.low / (2 * kPi), k3To70m.high / (2 * kPi));
  EXPECT_NEAR(per_cycle / s.variance(), 1.0, 1e-9);
  EXPECT_THROW(s.temporal_density(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(s.density(-1.0), std::invalid_argument);
  EXPECT_THROW(s.cross_level_angle_density(0.1, 1.5), std::invalid_argument);  // not cross-level
}

// A table sampled from a standard spectrum, given in each abscissa, describes one spectrum; a
// pure power law (including β = −1) integrates exactly; nothing outside the table.
TEST(TrackSpectrum, UserTable) {
  const TrackSpectrum ore = TrackSpectrum::ore_b176(OreLevel::low, TrackIrregularity::vertical_level, k3To70m);
  std::vector<double> omega, density, n, per_cycle, wavelength;
  for (int i = 0; i <= 200; ++i) {
    const double o = k3To70m.low * std::pow(k3To70m.high / k3To70m.low, i / 200.0);
    omega.push_back(o);
    density.push_back(ore.density(o));
    n.push_back(o / (2 * kPi));
    per_cycle.push_back(ore.density_per_cycle(o / (2 * kPi)));
    wavelength.push_back(2 * kPi / o);
  }
  const TrackSpectrum a =
      TrackSpectrum::table(TrackIrregularity::vertical_level, SpectrumAbscissa::wavenumber, omega, density);
  const TrackSpectrum b =
      TrackSpectrum::table(TrackIrregularity::vertical_level, SpectrumAbscissa::spatial_frequency, n, per_cycle);
  const TrackSpectrum c =
      TrackSpectrum::table(TrackIrregularity::vertical_level, SpectrumAbscissa::wavelength, wavelength, per_cycle);
  for (double o : {0.1, 0.5, 1.7}) {
    EXPECT_NEAR(b.density(o) / a.density(o), 1.0, 1e-12);
    EXPECT_NEAR(c.density(o) / a.density(o), 1.0, 1e-12);
    EXPECT_NEAR(a.density(o) / ore.density(o), 1.0, 1e-3);  // log-log between 201 points
  }
  EXPECT_NEAR(a.variance() / ore.variance(), 1.0, 1e-4);
  EXPECT_NEAR(a.band().low, k3To70m.low, 1e-15);
  EXPECT_EQ(a.density(k3To70m.high * 1.01), 0.0);  // refused outside: zero, not extrapolated
  for (double beta : {-3.0, -1.0, 0.5}) {
    const std::vector<double> x = {0.1, 0.4, 2.0};
    std::vector<double> y;
    for (double xi : x) y.push_back(1e-6 * std::pow(xi, beta));
    const TrackSpectrum p = TrackSpectrum::table(TrackIrregularity::alignment, SpectrumAbscissa::wavenumber, x, y);
    const double exact = beta == -1.0 ? 1e-6 * std::log(1.5 / 0.2)
                                      : 1e-6 * (std::pow(1.5, beta + 1) - std::pow(0.2, beta + 1)) / (beta + 1);
    EXPECT_NEAR(p.variance({0.2, 1.5}) / exact, 1.0, 1e-12) << beta;
  }
  EXPECT_THROW(TrackSpectrum::table(TrackIrregularity::alignment, SpectrumAbscissa::wavenumber, {0.1}, {1e-6}),
               std::invalid_argument);
  EXPECT_THROW(
      TrackSpectrum::table(TrackIrregularity::alignment, SpectrumAbscissa::wavenumber, {0.1, 0.2}, {1e-6, 0.0}),
      std::invalid_argument);
  EXPECT_THROW(
      TrackSpectrum::table(TrackIrregularity::alignment, SpectrumAbscissa::wavenumber, {0.1, 0.1}, {1e-6, 1e-7}),
      std::invalid_argument);
  EXPECT_THROW(TrackSpectrum::table(TrackIrregularity::alignment, SpectrumAbscissa::wavelength, {0.1, 0.2}, {1e-6}),
               std::invalid_argument);
}

TEST(TrackSpectrum, NamesRoundTrip) {
  for (TrackIrregularity i : kAll) EXPECT_EQ(track_irregularity_from_string(to_string(i)), i);
  for (OreLevel l : {OreLevel::low, OreLevel::high}) EXPECT_EQ(ore_level_from_string(to_string(l)), l);
  for (SpectrumAbscissa a :
       {SpectrumAbscissa::wavenumber, SpectrumAbscissa::spatial_frequency, SpectrumAbscissa::wavelength})
    EXPECT_EQ(spectrum_abscissa_from_string(to_string(a)), a);
  EXPECT_FALSE(track_irregularity_from_string("gauge"));
  EXPECT_FALSE(ore_level_from_string("medium"));
  EXPECT_FALSE(spectrum_abscissa_from_string("frequency"));
  EXPECT_EQ(TrackSpectrum::fra_class(3, TrackIrregularity::cross_level).name(), "FRA class 3, cross-level");
  EXPECT_THROW(TrackSpectrum::fra_class(7, TrackIrregularity::cross_level), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::test
