// Kalker's linear-theory creepage and spin coefficients C11, C22, C23, C33 for an elliptic
// contact area, and their interpolation (docs/stability.md, "Creep coefficients: Hertz and
// Kalker", says where the values come from and how they were checked).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "railmodal/wheel_rail.hpp"
#include "shortest_text.hpp"

namespace railmodal {
namespace {

// One row of the table: the four coefficients at ν = 0, 0.25, 0.5.
struct KalkerRow {
  std::array<double, 3> c11, c22, c23, c33;
};

// J.J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer 1990, Table E3
// (first published in his thesis, On the Rolling Contact of Two Elastic Bodies in the Presence
// of Dry Friction, Delft 1967). Each branch lists g = 0.1, 0.2, …, 1.0; the a ≤ b branch has
// g = a/b (a along the rolling direction), the a ≥ b branch g = b/a. Both end at the circle.
//
// Checked value by value (tests/validation/creep_coefficients_test.cpp) against two
// transcriptions: C11, C22, C23 against E.A.H. Vollebregt's CONTACT (routine linrol of
// m_hertz.f90, Vtech CMCC 2023, Apache-2.0), all three digits; all four against the SimRail
// tables of R.L. Giossi (lib/contact_kalkers_table.py), to their printed digits (C33 on the
// b/a branch to two decimals only: the third digit has no second source here). The two
// transcriptions disagree in two places, both typing slips: CONTACT's usetab_table.f90 copy
// has C23(a/b = 0.8, ν = 0.25) = 1.15 where m_hertz.f90 and SimRail have 1.25 (the column must
// increase with g), and SimRail has C11(b/a = 0.9, ν = 0) = 3.61 where CONTACT has 3.51 (at
// ν = 0 Kalker's C11 equals C22, which SimRail gives as 3.51).
constexpr std::array<KalkerRow, 10> kShortInRollingDirection = {{
    // g = a/b     C11                  C22                  C23                     C33
    {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}},  // 0.1
    {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}},  // 0.2
    {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}},  // 0.3
    {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}},  // 0.4
    {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}},   // 0.5
    {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}},    // 0.6
    {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}},     // 0.7
    {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}},     // 0.8
    {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}},     // 0.9
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},     // 1.0
}};
constexpr std::array<KalkerRow, 10> kLongInRollingDirection = {{
    // g = b/a     C11                  C22                  C23                     C33
    {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.795, 0.526, 0.228}},  // 0.1
    {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.828, 0.601, 0.341}},  // 0.2
    {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.868, 0.674, 0.446}},  // 0.3
    {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.912, 0.747, 0.549}},  // 0.4
    {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.958, 0.819, 0.650}},  // 0.5
    {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.892, 0.748}},   // 0.6
    {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.965, 0.852}},   // 0.7
    {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.954}},    // 0.8
    {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}},     // 0.9
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}},     // 1.0
}};

constexpr double kSmallestRatio = 0.1;  // g at the first row of each branch
constexpr double kRowSpacing = 0.1;
constexpr double kPoissonSpacing = 0.25;  // the columns ν = 0, 0.25, 0.5
// Ratios a hair outside the table (a/b = 1/(b/a) rounded) are read at its edge.
constexpr double kEdgeSlack = 1e-12;

// A position on an evenly spaced axis: the interval and the fraction into it, with positions
// within rounding of a node snapped onto it so that the table's values come back exactly.
struct AxisPosition {
  int index;
  double fraction;
};

AxisPosition locate(double position, int intervals) {
  const double nearest = std::round(position);
  if (std::abs(position - nearest) < 1e-9) position = nearest;
  const int index = std::min(static_cast<int>(std::floor(position)), intervals - 1);
  return {index, position - index};
}

// The coefficient at ν between two columns: linear in 1/C. Kalker's limit for a slender
// ellipse, C11 = π²/(4(1 − ν)) as a/b → 0 (the asymptote CONTACT's linrol uses below the
// table), makes 1/C exactly linear in ν; C11, C22 and C23 stay within 0.6 % of linrol's
// parabola in 1/C through the three columns (docs/stability.md). A harmonic blend of two
// positive values stays between them, so an interpolated value is bracketed by the table's.
double across_poisson(const std::array<double, 3>& column, AxisPosition nu) {
  const double lo = column[nu.index], hi = column[nu.index + 1];
  if (nu.fraction == 0.0) return lo;
  if (nu.fraction == 1.0) return hi;
  return 1.0 / ((1.0 - nu.fraction) / lo + nu.fraction / hi);
}

}  // namespace

KalkerCoefficients kalker_coefficients(double a_over_b, double poisson_ratio) {
  if (!std::isfinite(a_over_b) || a_over_b < kSmallestRatio * (1.0 - kEdgeSlack) ||
      a_over_b > (1.0 + kEdgeSlack) / kSmallestRatio)
    throw std::invalid_argument("kalker_coefficients: a/b = " + shortest_text(a_over_b, 6) +
                                " is outside Kalker's table (0.1 <= a/b <= 10)");
  if (!std::isfinite(poisson_ratio) || poisson_ratio < 0.0 || poisson_ratio > 0.5)
    throw std::invalid_argument("kalker_coefficients: Poisson's ratio " + shortest_text(poisson_ratio) +
                                " is outside Kalker's table (0 <= nu <= 0.5)");

  // Each branch is tabulated against its own g = min(a/b, b/a); interpolate linearly in that g.
  const bool short_in_rolling = a_over_b <= 1.0;
  const auto& rows = short_in_rolling ? kShortInRollingDirection : kLongInRollingDirection;
  const double g = std::clamp(short_in_rolling ? a_over_b : 1.0 / a_over_b, kSmallestRatio, 1.0);
  const AxisPosition row = locate((g - kSmallestRatio) / kRowSpacing, static_cast<int>(rows.size()) - 1);
  const AxisPosition nu = locate(poisson_ratio / kPoissonSpacing, 2);

  // At each of the two bracketing rows, first the value at ν, then linearly between the rows.
  const auto value = [&](std::array<double, 3> KalkerRow::*coefficient) {
    const double lo = across_poisson(rows[row.index].*coefficient, nu);
    if (row.fraction == 0.0) return lo;
    const double hi = across_poisson(rows[row.index + 1].*coefficient, nu);
    return lo + row.fraction * (hi - lo);
  };
  return {value(&KalkerRow::c11), value(&KalkerRow::c22), value(&KalkerRow::c23), value(&KalkerRow::c33)};
}

}  // namespace railmodal
