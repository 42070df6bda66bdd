// Creep coefficients from Hertz and Kalker (issue 20, item 6): Kalker's table against its
// published transcriptions, the Hertz ellipse against the textbook table of Hertz's
// coefficients m, n and the closed-form circle, and the whole chain for a typical wheel.
// docs/stability.md, "Creep coefficients: Hertz and Kalker", cites every source.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Half a unit in the last printed digit of `printed`, as printed with `significant` digits
// (trailing zeros dropped by the source count: 3.4 printed as "3.4" with 3 digits means 3.40).
double half_last_digit(double printed, int significant) {
  const int magnitude = static_cast<int>(std::floor(std::log10(std::abs(printed))));
  return 0.5 * std::pow(10.0, magnitude - significant + 1) * (1 + 1e-9);
}

// a/b of the 20 rows of Kalker's Table E3 as CONTACT lists them: a/b = 0.1 … 1.0, then
// b/a = 0.1 … 1.0.
double contact_row_ratio(int row) { return row < 10 ? 0.1 * (row + 1) : 1.0 / (0.1 * (row - 9)); }

// E.A.H. Vollebregt, CONTACT (Vtech CMCC, open-source release 2023), module m_hertz.f90,
// subroutine linrol: "Table E.3 of Kalker coefficients Cij of the linear theory of rolling
// contact for elliptical contact areas", three digits; per row C11, C22, C23 at ν = 0, 0.25, 0.5.
constexpr std::array<std::array<double, 9>, 20> kContactLinrol = {{
    {2.51, 3.31, 4.85, 2.51, 2.52, 2.53, .334, .473, .731}, {2.59, 3.37, 4.81, 2.59, 2.63, 2.66, .483, .603, .809},
    {2.68, 3.44, 4.80, 2.68, 2.75, 2.81, .607, .715, .889}, {2.78, 3.53, 4.82, 2.78, 2.88, 2.98, .720, .823, .977},
    {2.88, 3.62, 4.83, 2.88, 3.01, 3.14, .827, .929, 1.07}, {2.98, 3.72, 4.91, 2.98, 3.14, 3.31, .930, 1.03, 1.18},
    {3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29}, {3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.40},
    {3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51}, {3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63},
    {10.7, 11.7, 12.9, 10.7, 12.8, 16.0, 12.2, 14.6, 18.0}, {6.96, 7.78, 8.82, 6.96, 8.14, 9.79, 5.72, 6.63, 7.89},
    {5.57, 6.34, 7.34, 5.57, 6.40, 7.51, 3.79, 4.32, 5.01}, {4.84, 5.57, 6.57, 4.84, 5.48, 6.31, 2.88, 3.24, 3.70},
    {4.37, 5.10, 6.11, 4.37, 4.90, 5.56, 2.35, 2.62, 2.96}, {4.06, 4.78, 5.80, 4.06, 4.50, 5.04, 2.01, 2.23, 2.50},
    {3.82, 4.54, 5.58, 3.82, 4.21, 4.67, 1.76, 1.95, 2.18}, {3.65, 4.36, 5.42, 3.65, 3.99, 4.39, 1.58, 1.75, 1.94},
    {3.51, 4.22, 5.30, 3.51, 3.81, 4.16, 1.44, 1.59, 1.77}, {3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63},
}};

// Every C11, C22, C23 of the table, at its three printed digits: our table is CONTACT's value
// for value (the interpolation returns table points exactly, so the match is exact).
TEST(KalkerTableSources, ContactLinrolEveryPoint) {
  const std::array<double, 3> poisson = {0.0, 0.25, 0.5};
  for (int row = 0; row < 20; ++row)
    for (int j = 0; j < 3; ++j) {
      const KalkerCoefficients c = kalker_coefficients(contact_row_ratio(row), poisson[j]);
      const auto& printed = kContactLinrol[row];
      EXPECT_DOUBLE_EQ(c.c11, printed[j]) << "C11, row " << row << ", nu = " << poisson[j];
      EXPECT_DOUBLE_EQ(c.c22, printed[3 + j]) << "C22, row " << row << ", nu = " << poisson[j];
      EXPECT_DOUBLE_EQ(c.c23, printed[6 + j]) << "C23, row " << row << ", nu = " << poisson[j];
    }
}

// R.L. Giossi, SimRail, lib/contact_kalkers_table.py: all four coefficients, per coefficient
// per ν (0, 0.25, 0.5), over a/b = 0.1 … 1.0, 1/0.9 … 1/0.1, printed to two decimals below 10
// and one above. It is the only second source found for C33.
constexpr std::array<double, 19> kSimRailRatios = {0.1,     0.2,     0.3,     0.4,     0.5,     0.6,     0.7,
                                                   0.8,     0.9,     1.0,     1 / 0.9, 1 / 0.8, 1 / 0.7, 1 / 0.6,
                                                   1 / 0.5, 1 / 0.4, 1 / 0.3, 1 / 0.2, 1 / 0.1};
using SimRailTable = std::array<std::array<double, 19>, 3>;
constexpr SimRailTable kSimRailC11 = {{
    {2.51, 2.59, 2.68, 2.78, 2.88, 2.98, 3.09, 3.19, 3.29, 3.4, 3.61, 3.65, 3.82, 4.06, 4.37, 4.84, 5.57, 6.96, 10.7},
    {3.31, 3.37, 3.44, 3.53, 3.62, 3.72, 3.81, 3.91, 4.01, 4.12, 4.22, 4.36, 4.54, 4.78, 5.10, 5.57, 6.34, 7.78, 11.7},
    {4.85, 4.81, 4.8, 4.82, 4.83, 4.91, 4.97, 5.05, 5.12, 5.2, 5.3, 5.42, 5.58, 5.8, 6.11, 6.57, 7.34, 8.82, 12.9},
}};
constexpr SimRailTable kSimRailC22 = {{
    {2.51, 2.59, 2.68, 2.78, 2.88, 2.98, 3.09, 3.19, 3.29, 3.4, 3.51, 3.65, 3.82, 4.06, 4.37, 4.84, 5.57, 6.96, 10.7},
    {2.52, 2.63, 2.75, 2.88, 3.01, 3.14, 3.28, 3.41, 3.54, 3.67, 3.81, 3.99, 4.21, 4.50, 4.90, 5.48, 6.40, 8.14, 12.8},
    {2.53, 2.66, 2.81, 2.98, 3.14, 3.31, 3.48, 3.65, 3.82, 3.98, 4.16, 4.39, 4.67, 5.04, 5.56, 6.31, 7.51, 9.79, 16},
}};
constexpr SimRailTable kSimRailC23 = {{
    {0.33, 0.48, 0.61, 0.72, 0.83, 0.93, 1.03, 1.13, 1.23, 1.33, 1.44, 1.58, 1.76, 2.01, 2.35, 2.88, 3.79, 5.72, 12.2},
    {0.47, 0.60, 0.72, 0.82, 0.93, 1.03, 1.14, 1.25, 1.36, 1.47, 1.59, 1.75, 1.95, 2.23, 2.62, 3.24, 4.32, 6.63, 14.6},
    {0.73, 0.81, 0.89, 0.98, 1.07, 1.18, 1.29, 1.4, 1.51, 1.63, 1.77, 1.94, 2.18, 2.5, 2.96, 3.7, 5.01, 7.89, 18},
}};
constexpr SimRailTable kSimRailC33 = {{
    {6.42, 3.46, 2.49, 2.02, 1.74, 1.56, 1.43, 1.34, 1.27, 1.21, 1.16, 1.1, 1.05, 1.01, 0.96, 0.91, 0.87, 0.83, 0.8},
    {8.28, 4.27, 2.96, 2.32, 1.93, 1.68, 1.5, 1.37, 1.27, 1.19, 1.11, 1.04, 0.97, 0.89, 0.82, 0.75, 0.67, 0.6, 0.53},
    {11.7, 5.66, 3.72, 2.77, 2.22, 1.86, 1.6, 1.42, 1.27, 1.16, 1.06, 0.95, 0.85, 0.75, 0.65, 0.55, 0.45, 0.34, 0.23},
}};

double decimals_tolerance(double printed) { return (printed < 10 ? 0.005 : 0.05) * (1 + 1e-9); }

TEST(KalkerTableSources, SimRailEveryPoint) {
  const std::array<double, 3> poisson = {0.0, 0.25, 0.5};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 19; ++i) {
      const KalkerCoefficients c = kalker_coefficients(kSimRailRatios[i], poisson[j]);
      const double ratio = kSimRailRatios[i];
      // SimRail's one slip: C11(b/a = 0.9, ν = 0) printed 3.61; CONTACT has 3.51, and at ν = 0
      // Kalker's C11 equals C22, which SimRail itself gives as 3.51 (checked just below).
      if (!(i == 10 && j == 0)) {
        EXPECT_NEAR(c.c11, kSimRailC11[j][i], decimals_tolerance(kSimRailC11[j][i])) << "C11 a/b " << ratio;
      }
      EXPECT_NEAR(c.c22, kSimRailC22[j][i], decimals_tolerance(kSimRailC22[j][i])) << "C22 a/b " << ratio;
      EXPECT_NEAR(c.c23, kSimRailC23[j][i], decimals_tolerance(kSimRailC23[j][i])) << "C23 a/b " << ratio;
      EXPECT_NEAR(c.c33, kSimRailC33[j][i], decimals_tolerance(kSimRailC33[j][i])) << "C33 a/b " << ratio;
    }
  EXPECT_DOUBLE_EQ(kalker_coefficients(1 / 0.9, 0.0).c11, kSimRailC22[0][10]);
  // At ν = 0 the table has C11 = C22 on every row (with ν = 0 the half-space's tangential
  // displacements along and across the track decouple and obey the same equation).
  for (double ratio : kSimRailRatios) {
    const KalkerCoefficients c = kalker_coefficients(ratio, 0.0);
    EXPECT_EQ(c.c11, c.c22) << "a/b = " << ratio;
  }
}

// A third, independent use of the table: a Python port of a MATLAB wheel–rail code in the
// stored public index (read_file id 55279513234, class ContactMechanics, repository not named
// by the index) tabulates C11, C22, C23, C33 at ν = 0.3, each made by linear interpolation in
// ν between the 0.25 and 0.5 columns, to four digits. Rebuilding them from our columns checks
// C33's third digit on the b/a branch, which SimRail rounds away. One disagreement: at
// b/a = 0.6 its C33 = 0.8638 needs C33(ν = 0.25) ≈ 0.893 where we (and SimRail's 0.89) have
// 0.892; the rest agree to its printed digits.
constexpr std::array<std::array<double, 5>, 10> kPortShortInRolling = {{
    {0.1, 3.618, 2.522, 0.5246, 8.964},
    {0.2, 3.658, 2.636, 0.6442, 4.548},
    {0.3, 3.712, 2.762, 0.7498, 3.112},
    {0.4, 3.788, 2.9, 0.8538, 2.41},
    {0.5, 3.862, 3.036, 0.9572, 1.988},
    {0.6, 3.958, 3.174, 1.06, 1.716},
    {0.7, 4.042, 3.32, 1.17, 1.52},
    {0.8, 4.138, 3.458, 1.28, 1.38},
    {0.9, 4.232, 3.596, 1.39, 1.27},
    {1.0, 4.336, 3.732, 1.502, 1.184},
}};
constexpr std::array<std::array<double, 5>, 10> kPortLongInRolling = {{
    {1, 4.336, 3.732, 1.502, 1.184},
    {0.9, 4.436, 3.88, 1.626, 1.1},
    {0.8, 4.572, 4.07, 1.788, 1.0228},
    {0.7, 4.748, 4.302, 1.996, 0.9424},
    {0.6, 4.984, 4.608, 2.284, 0.8638},
    {0.5, 5.302, 5.032, 2.688, 0.7852},
    {0.4, 5.77, 5.646, 3.332, 0.7074},
    {0.3, 6.54, 6.622, 4.458, 0.6284},
    {0.2, 7.988, 8.47, 6.882, 0.549},
    {0.1, 11.94, 13.44, 15.28, 0.4664},
}};

TEST(KalkerTableSources, LinearBlendAtPoisson03FromAThirdCode) {
  const auto check = [](const std::array<double, 5>& row, double ratio, bool long_branch) {
    const KalkerCoefficients lo = kalker_coefficients(ratio, 0.25), hi = kalker_coefficients(ratio, 0.5);
    const std::array<double, 4> blend = {0.8 * lo.c11 + 0.2 * hi.c11, 0.8 * lo.c22 + 0.2 * hi.c22,
                                         0.8 * lo.c23 + 0.2 * hi.c23, 0.8 * lo.c33 + 0.2 * hi.c33};
    for (int k = 0; k < 4; ++k) {
      if (long_branch && row[0] == 0.6 && k == 3) continue;  // the one disagreement, above
      // Four significant digits as printed (fewer where its trailing zeros were dropped).
      EXPECT_NEAR(blend[k], row[k + 1], half_last_digit(row[k + 1], 4)) << "C" << k << " g = " << row[0];
    }
  };
  for (const auto& row : kPortShortInRolling) check(row, row[0], false);
  for (const auto& row : kPortLongInRolling) check(row, 1.0 / row[0], true);
  const double odd = 0.8 * kalker_coefficients(1 / 0.6, 0.25).c33 + 0.2 * kalker_coefficients(1 / 0.6, 0.5).c33;
  EXPECT_NEAR(odd, 0.8632, 1e-12);  // ours; the port prints 0.8638
}

// Hertz's coefficients m, n (a = m·∛(3N/(4E*(A+B))), b = n·∛(…), cos θ = (B − A)/(A + B)) as
// printed by S. Timoshenko and J.N. Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill 1970,
// §140 (the table of m and n against θ), and transcribed the same in the port above
// (_beta_table_m/_n; it prints m(40°) as 2.13 for the book's 2.136). The book's values were
// computed by hand from the elliptic integrals; our exact solution meets them within 0.0025
// (largest: n(70°) = 0.7999 against 0.802). It is a check of the method, not the method.
TEST(HertzContactValidation, HertzCoefficientsTable) {
  struct Row {
    double theta, m, n;
  };
  constexpr std::array<Row, 13> table = {{{30, 2.731, 0.493},
                                          {35, 2.397, 0.530},
                                          {40, 2.136, 0.567},
                                          {45, 1.926, 0.604},
                                          {50, 1.754, 0.641},
                                          {55, 1.611, 0.678},
                                          {60, 1.486, 0.717},
                                          {65, 1.378, 0.759},
                                          {70, 1.284, 0.802},
                                          {75, 1.202, 0.846},
                                          {80, 1.128, 0.893},
                                          {85, 1.061, 0.944},
                                          {90, 1.000, 1.000}}};
  for (const Row& row : table) {
    // Curvatures with A + B = 2 and the given θ; A along the track (the larger semi-axis a).
    const double c = std::cos(row.theta * kPi / 180.0);
    const double along = 1.0 - c, across = 1.0 + c;
    HertzContactInput in;
    in.wheel_load = 1e4;
    in.rail_head_radius = 0.5 / across;  // conical wheel: the rail head alone curves across
    in.poisson_ratio = 0.3;
    const HertzContact h = hertz_contact(in, 0.5 / along);
    const double e_star = in.youngs_modulus / (2.0 * (1.0 - 0.09));
    const double scale = std::cbrt(3.0 * 1e4 / (4.0 * e_star * (along + across)));
    EXPECT_NEAR(h.a / scale, row.m, 0.0025) << "theta = " << row.theta;
    EXPECT_NEAR(h.b / scale, row.n, 0.0025) << "theta = " << row.theta;
  }
}

// Equal curvatures make a circle, Hertz's sphere on a plane: a = b = ∛(3NR/(4E*)), the
// approach a²/R and p0 = 3N/(2πa²) (Johnson, Contact Mechanics, 1985, §4.2). Here a
// wheel of rolling radius R on a conical tread and a rail head of radius R, and again with a
// crowned tread of radius 2R on a rail head of 2R.
TEST(HertzContactValidation, EqualCurvaturesGiveHertzsCircle) {
  const double R = 0.46, N = 70e3, E = 2.1e11, nu = 0.28;
  const double e_star = E / (2.0 * (1.0 - nu * nu));
  const double a = std::cbrt(3.0 * N * R / (4.0 * e_star));
  HertzContactInput conical;
  conical.wheel_load = N;
  conical.rail_head_radius = R;
  conical.youngs_modulus = E;
  conical.poisson_ratio = nu;
  HertzContactInput crowned = conical;
  crowned.rail_head_radius = 2 * R;
  crowned.wheel_transverse_radius = 2 * R;
  for (const HertzContactInput& in : {conical, crowned}) {
    const HertzContact h = hertz_contact(in, R);
    // The near-circle series of the elliptic integrals is exact to 1e-12 (hertz_contact.cpp).
    EXPECT_NEAR(h.a / a, 1.0, 1e-12);
    EXPECT_NEAR(h.b / a, 1.0, 1e-12);
    EXPECT_NEAR(h.approach / (a * a / R), 1.0, 1e-12);
    EXPECT_NEAR(h.max_pressure / (3 * N / (2 * kPi * a * a)), 1.0, 1e-12);
  }
}

// The whole chain for a typical wheel: r0 = 0.46 m on a 0.3 m rail head, conical tread,
// 60–80 kN, E = 2.1e11 Pa. The ellipse is longer along the track (a/b ≈ 1.33: the rail head
// curves more than the wheel), p0 near 1 GPa, and f11, f22 of the 10 MN order engineers quote
// for a coach wheel (Knothe and Stichel, Rail Vehicle Dynamics, 2017, §4.3; the bundled
// wheelset_on_springs.toml rounds to 10 MN). Figures at 70 kN, ν = 0.28 (docs/stability.md):
// a = 6.386 mm, b = 4.804 mm, f11 = 11.45 MN, f22 = 10.42 MN.
TEST(CreepCoefficientsValidation, TypicalWheelOnRail) {
  for (double load : {60e3, 70e3, 80e3})
    for (double nu : {0.28, 0.3}) {
      HertzContactInput in;
      in.wheel_load = load;
      in.rail_head_radius = 0.3;
      in.poisson_ratio = nu;
      const HertzContact h = hertz_contact(in, 0.46);
      EXPECT_GT(h.a, h.b);
      EXPECT_NEAR(h.a / h.b, 1.33, 0.01);  // fixed by the curvature ratio 1.53 alone, whatever the load
      EXPECT_GT(h.max_pressure, 0.9e9);
      EXPECT_LT(h.max_pressure, 1.3e9);
      const CreepCoefficients f = creep_coefficients(h, 2.1e11, nu);
      EXPECT_GT(f.f11, 8e6);
      EXPECT_LT(f.f11, 14e6);
      EXPECT_GT(f.f22, 8e6);
      EXPECT_LT(f.f22, 14e6);
      EXPECT_GT(f.f11, f.f22);  // C11 > C22 for ν > 0
      EXPECT_GT(f.f23, 0.0);
      EXPECT_GT(f.f33, 0.0);
    }
  HertzContactInput in;
  in.wheel_load = 70e3;
  in.rail_head_radius = 0.3;
  const HertzContact h = hertz_contact(in, 0.46);
  // Regression figures for docs/stability.md (to the 4 digits quoted there).
  EXPECT_NEAR(h.a * 1e3, 6.386, 5e-4);
  EXPECT_NEAR(h.b * 1e3, 4.804, 5e-4);
  const CreepCoefficients f = creep_coefficients(h, 2.1e11, 0.28);
  EXPECT_NEAR(f.f11 / 1e6, 11.45, 5e-3);
  EXPECT_NEAR(f.f22 / 1e6, 10.42, 5e-3);
}

// f's scale as the formulas say: G·c²·C for f11, f22, G·c³·C23, G·c⁴·C33 with c² = ab; and the
// coefficients come from Kalker's table at the ellipse's own a/b.
TEST(CreepCoefficientsValidation, KalkersScaling) {
  HertzContact ellipse;
  ellipse.a = 6e-3;
  ellipse.b = 4e-3;
  const double E = 2.1e11, nu = 0.25, G = E / 2.5;
  const KalkerCoefficients c = kalker_coefficients(1.5, nu);
  const CreepCoefficients f = creep_coefficients(ellipse, E, nu);
  const double area = 24e-6;
  EXPECT_NEAR(f.f11 / (G * area * c.c11), 1.0, 1e-14);
  EXPECT_NEAR(f.f22 / (G * area * c.c22), 1.0, 1e-14);
  EXPECT_NEAR(f.f23 / (G * std::pow(area, 1.5) * c.c23), 1.0, 1e-14);
  EXPECT_NEAR(f.f33 / (G * area * area * c.c33), 1.0, 1e-14);
  // a/b = 1.5 is b/a = 2/3 on the second branch: between its rows 0.6 and 0.7.
  EXPECT_GT(c.c11, 4.54);
  EXPECT_LT(c.c11, 4.78);
}

// A printed ellipse from a third party's program: E.A.H. Vollebregt's CONTACT (open-source
// release, Vtech CMCC, Apache-2.0) ships example inputs with the output it prints for them
// (examples/*.inp, *.ref_out). Its Hertz routine (m_hertz.f90, hzcalc3d) solves the elliptic-
// integral equations to 1e-9, and the a/b iteration (elliptic_to_curv) to 1e-8, so every printed
// digit is Hertz's own; CONTACT's A1, B1 are our A, B (the half-sums of the curvatures, its user
// guide, eq. "a1_b1"). The material of both cases: G = 82 000 N/mm², ν = 0.28, i.e. E = 2G(1 + ν).
// No textbook worked example of a wheel–rail ellipse could be read here (docs/stability.md,
// "Published examples"); this is the closest printed case, and independent of our code.
//
// The tolerance is the printed digits, carried through: the inputs we take from the printout are
// rounded to 4 digits, so the semi-axes are computed at the corners of that rounding box, and the
// printed value must lie within their range widened by half a unit of its own last digit.
struct PrintedEllipseCase {
  double along, across;          // A, B (1/m) as fed to hertz_contact
  double along_half, across_half;  // half a unit of the printed digit (0 where the input is exact)
  double load;                   // N
  double a_printed, b_printed;   // m
  int a_digits, b_digits;
};

void expect_printed_ellipse(const PrintedEllipseCase& c) {
  const double G = 82e9, nu = 0.28;
  double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
  for (int corner = 0; corner < 4; ++corner) {
    const double A = c.along + ((corner & 1) ? c.along_half : -c.along_half);
    const double B = c.across + ((corner & 2) ? c.across_half : -c.across_half);
    HertzContactInput in;
    in.wheel_load = c.load;
    in.rail_head_radius = 0.5 / B;  // a conical tread: the rail head alone curves across
    in.youngs_modulus = 2.0 * G * (1.0 + nu);
    in.poisson_ratio = nu;
    const HertzContact h = hertz_contact(in, 0.5 / A);  // the wheel alone curves along
    a_lo = std::min(a_lo, h.a);
    a_hi = std::max(a_hi, h.a);
    b_lo = std::min(b_lo, h.b);
    b_hi = std::max(b_hi, h.b);
  }
  const double ha = half_last_digit(c.a_printed, c.a_digits), hb = half_last_digit(c.b_printed, c.b_digits);
  EXPECT_GE(c.a_printed, a_lo - ha);
  EXPECT_LE(c.a_printed, a_hi + ha);
  EXPECT_GE(c.b_printed, b_lo - hb);
  EXPECT_LE(c.b_printed, b_hi + hb);
}

// examples/fastsim.inp: semi-axes AA = 8 mm, BB = 4 mm prescribed with FN = 82 kN; CONTACT prints
// the curvatures they need, "THE CURVATURES A1,B1 ARE: 0.8464E-03 0.2406E-02" (1/mm,
// fastsim.ref_out). Fed those curvatures, hertz_contact must return the 8 mm by 4 mm ellipse,
// long along the track.
TEST(HertzContactValidation, ContactProgramPrintedEllipseAlongTheTrack) {
  expect_printed_ellipse({0.8464, 2.406, 0.00005, 0.0005, 82e3, 8.000e-3, 4.000e-3, 4, 4});
}

// examples/tractcurv.inp: the Eurosprinter wheel of O. Polach (Wear 258, 2005, "Creep forces
// in simulations of traction vehicles running on adhesion limit"): radius 625 mm, so A1 = 0.0008
// 1/mm exactly, 106.7 kN on the wheel, a/b = 0.5 prescribed. CONTACT prints "THE CURVATURES
// A1,B1 ARE: 0.8000E-03 0.2814E-03" and "BASIC SEMIAXES AA,BB, RATIO 6.304 12.61 0.5000"
// (tractcurv.ref_out): an ellipse turned across the rail (b > a), which checks that `a` stays
// the semi-axis along the track whichever is longer.
TEST(HertzContactValidation, ContactProgramPrintedEllipseAcrossTheRail) {
  expect_printed_ellipse({0.8, 0.2814, 0.0, 0.00005, 106.7e3, 6.304e-3, 12.61e-3, 4, 4});
}

}  // namespace
}  // namespace railmodal
