// Kalker's coefficient table: how it is interpolated between its points, its two branches and
// its edges. (The values at its points are checked against their sources in
// tests/validation/creep_coefficients_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {
namespace {

constexpr std::array<double, 3> kTabulatedPoisson = {0.0, 0.25, 0.5};

std::array<double, 4> as_array(const KalkerCoefficients& c) { return {c.c11, c.c22, c.c23, c.c33}; }

// The table's a/b values: a/b = g on the first branch, 1/g on the second, g = 0.1 … 1.
std::array<double, 19> tabulated_ratios() {
  std::array<double, 19> r{};
  for (int i = 0; i < 10; ++i) r[i] = 0.1 * (i + 1);
  for (int i = 0; i < 9; ++i) r[10 + i] = 1.0 / (0.1 * (9 - i));
  return r;
}

// Between two rows of a branch the coefficients run linearly in that branch's g: halfway in g
// is the mean of the two rows, here on both branches (values from Kalker's Table E3, ν = 0).
TEST(KalkerTable, LinearInEachBranchsRatio) {
  const KalkerCoefficients short_mid = kalker_coefficients(0.15, 0.0);  // a/b between 0.1 and 0.2
  EXPECT_NEAR(short_mid.c11, (2.51 + 2.59) / 2, 1e-12);
  EXPECT_NEAR(short_mid.c33, (6.42 + 3.46) / 2, 1e-12);
  // b/a = 0.15 lies between the b/a rows 0.1 and 0.2: linear in b/a, not in a/b.
  const KalkerCoefficients long_mid = kalker_coefficients(1.0 / 0.15, 0.0);
  EXPECT_NEAR(long_mid.c11, (10.7 + 6.96) / 2, 1e-12);
  EXPECT_NEAR(long_mid.c23, (12.2 + 5.72) / 2, 1e-12);
}

// Between two columns of ν, 1/C runs linearly (Kalker's slender-ellipse limit C11 ∝ 1/(1 − ν)).
TEST(KalkerTable, HarmonicInPoissonsRatio) {
  const KalkerCoefficients c = kalker_coefficients(1.0, 0.125);  // the circle, halfway to 0.25
  EXPECT_NEAR(c.c11, 2.0 / (1 / 3.40 + 1 / 4.12), 1e-12);
  EXPECT_NEAR(c.c33, 2.0 / (1 / 1.21 + 1 / 1.19), 1e-12);
  const KalkerCoefficients d = kalker_coefficients(1.0, 0.3);  // a fifth of the way to 0.5
  EXPECT_NEAR(d.c22, 1.0 / (0.8 / 3.67 + 0.2 / 3.98), 1e-12);
}

// Every point of the table comes back from the interpolation exactly, however the ratio was
// computed (1/(b/a) is not always the tabulated a/b to the last bit).
TEST(KalkerTable, ExactAtEveryTablePoint) {
  for (double ratio : tabulated_ratios())
    for (double nu : kTabulatedPoisson) {
      const auto at = as_array(kalker_coefficients(ratio, nu));
      const auto nudged = as_array(kalker_coefficients(ratio * (1 + 1e-15), nu));
      for (int k = 0; k < 4; ++k) EXPECT_EQ(at[k], nudged[k]) << "a/b = " << ratio << ", nu = " << nu;
    }
  EXPECT_EQ(kalker_coefficients(0.3, 0.25).c11, 3.44);
  EXPECT_EQ(kalker_coefficients(1.0 / 0.3, 0.25).c11, 6.34);
  EXPECT_EQ(kalker_coefficients(10.0, 0.5).c22, 16.0);
}

// An interpolated value lies between the values at the four table points around it, for every
// cell of the table (both branches, both halves of ν), at interior points of each cell.
TEST(KalkerTable, BracketedByItsNeighbours) {
  const std::array<double, 19> ratios = tabulated_ratios();
  for (int i = 0; i + 1 < 19; ++i)
    for (int j = 0; j < 2; ++j) {
      std::array<std::array<double, 4>, 4> corners{};
      int n = 0;
      for (int di = 0; di < 2; ++di)
        for (int dj = 0; dj < 2; ++dj)
          corners[n++] = as_array(kalker_coefficients(ratios[i + di], kTabulatedPoisson[j + dj]));
      for (double s : {0.13, 0.5, 0.91})
        for (double t : {0.07, 0.5, 0.77}) {
          const double ratio = ratios[i] + s * (ratios[i + 1] - ratios[i]);
          const double nu = kTabulatedPoisson[j] + t * 0.25;
          const auto c = as_array(kalker_coefficients(ratio, nu));
          for (int k = 0; k < 4; ++k) {
            double lo = corners[0][k], hi = corners[0][k];
            for (const auto& corner : corners) lo = std::min(lo, corner[k]), hi = std::max(hi, corner[k]);
            EXPECT_GE(c[k], lo) << "coefficient " << k << " at a/b = " << ratio << ", nu = " << nu;
            EXPECT_LE(c[k], hi) << "coefficient " << k << " at a/b = " << ratio << ", nu = " << nu;
          }
        }
    }
}

// The two branches meet at the circle: approaching a/b = 1 from either side gives the circle's
// row, and the coefficients are continuous there.
TEST(KalkerTable, BranchesMeetAtTheCircle) {
  for (double nu : {0.0, 0.25, 0.28, 0.5}) {
    const auto circle = as_array(kalker_coefficients(1.0, nu));
    const auto below = as_array(kalker_coefficients(1.0 - 1e-9, nu));
    const auto above = as_array(kalker_coefficients(1.0 + 1e-9, nu));
    for (int k = 0; k < 4; ++k) {
      // Within 1e-9 of the node the slope (at most ~30 per unit ratio) moves a value < 1e-7.
      EXPECT_NEAR(below[k], circle[k], 1e-7);
      EXPECT_NEAR(above[k], circle[k], 1e-7);
    }
  }
  EXPECT_EQ(kalker_coefficients(1.0, 0.25).c11, 4.12);
}

// The table's edges are inside; beyond them, or outside 0 ≤ ν ≤ 0.5, is an error that names
// the value and the range.
TEST(KalkerTable, OutsideTheTableIsAnError) {
  EXPECT_NO_THROW(kalker_coefficients(0.1, 0.0));
  EXPECT_NO_THROW(kalker_coefficients(10.0, 0.5));
  EXPECT_NO_THROW(kalker_coefficients(1.0 / 0.1, 0.25));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double ratio : {0.0999, 10.01, 0.0, -1.0, nan, inf})
    EXPECT_THROW(kalker_coefficients(ratio, 0.25), std::invalid_argument);
  for (double nu : {-0.01, 0.501, nan}) EXPECT_THROW(kalker_coefficients(1.0, nu), std::invalid_argument);
  try {
    kalker_coefficients(12.0, 0.25);
    FAIL() << "no error for a/b = 12";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a/b = 12"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.1 <= a/b <= 10"), std::string::npos) << e.what();
  }
}

// CONTACT's routine linrol interpolates across ν by a parabola in 1/C through the three
// columns; ours is piecewise linear in 1/C. At the steels' ν = 0.28 and 0.3 the two agree to
// 0.6 % for C11, C22 and C23 at every row of the table (largest: C23 at a/b = 0.1, ν = 0.3,
// 0.54 %),
// which bounds what the choice of ν-interpolation means for f11, f22, f23.
TEST(KalkerTable, PoissonInterpolationAgreesWithContactsThreePointForm) {
  for (double nu : {0.28, 0.3})
    for (double ratio : tabulated_ratios()) {
      const auto c0 = as_array(kalker_coefficients(ratio, 0.0));
      const auto c1 = as_array(kalker_coefficients(ratio, 0.25));
      const auto c2 = as_array(kalker_coefficients(ratio, 0.5));
      const auto c = as_array(kalker_coefficients(ratio, nu));
      for (int k = 0; k < 3; ++k) {
        // Lagrange's parabola through (0, 1/c0), (0.25, 1/c1), (0.5, 1/c2).
        const double inverse = (nu - 0.25) * (nu - 0.5) / 0.125 / c0[k] - nu * (nu - 0.5) / 0.0625 / c1[k] +
                               nu * (nu - 0.25) / 0.125 / c2[k];
        EXPECT_NEAR(c[k] * inverse, 1.0, 0.006) << "coefficient " << k << " at a/b = " << ratio << ", nu = " << nu;
      }
    }
}

}  // namespace
}  // namespace railmodal
