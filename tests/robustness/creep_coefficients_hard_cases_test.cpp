// Hard cases of the contact ellipse and Kalker's table: a nearly conformal hollow tread, very
// flat ellipses near the table's end, the extreme Poisson's ratios, curvatures a hair apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {
namespace {

// A hollow tread closing on the rail head: across curvature 1/0.3 − 1/|R| → 0. The ellipse
// stretches across the rail without bound, stays finite and positive, carries the load
// (p0·2πab/3 = N), and the ratio a/b falls monotonically; it leaves Kalker's table (a/b < 0.1)
// with an error that says so, never a NaN.
TEST(CreepHardCases, HollowTreadCloseToConformal) {
  HertzContactInput in;
  in.wheel_load = 70e3;
  in.rail_head_radius = 0.3;
  double last_ratio = 1e9;
  bool left_the_table = false;
  for (double gap : {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-9}) {
    in.wheel_transverse_radius = -0.3 * (1.0 + gap);
    const HertzContact h = hertz_contact(in, 0.46);
    ASSERT_TRUE(std::isfinite(h.a) && std::isfinite(h.b) && std::isfinite(h.max_pressure) && std::isfinite(h.approach));
    EXPECT_GT(h.a, 0.0);
    EXPECT_LT(h.a / h.b, last_ratio);
    last_ratio = h.a / h.b;
    // The load balance holds whatever the shape: 1e-12 is the rounding of a few products.
    EXPECT_NEAR(h.max_pressure * 2.0 * M_PI * h.a * h.b / 3.0 / 70e3, 1.0, 1e-12);
    if (h.a / h.b < 0.1) {
      left_the_table = true;
      EXPECT_THROW(creep_coefficients(h, in.youngs_modulus, in.poisson_ratio), std::invalid_argument);
    } else {
      EXPECT_NO_THROW(creep_coefficients(h, in.youngs_modulus, in.poisson_ratio));
    }
  }
  EXPECT_TRUE(left_the_table);
  EXPECT_LT(last_ratio, 1e-3);
}

// Curvature ratios just above 1 (an almost circular ellipse) join the circle smoothly: the
// semi-axes differ by the first-order amount Hertz's series gives, a/b − 1 ≈ (2/3)(B/A − 1)
// (from B/A ≈ 1 + (3/4)e² and a/b ≈ 1 + e²/2), with no jump where the solver changes from the
// series to the elliptic integrals.
TEST(CreepHardCases, NearlyCircular) {
  for (double excess : {1e-10, 1e-8, 1e-7, 1e-6, 1e-5, 5e-5, 7e-5, 8e-5, 1e-4, 1e-3}) {
    HertzContactInput in;
    in.wheel_load = 50e3;
    in.rail_head_radius = 0.46 / (1.0 + excess);  // across curvature (1 + excess) times along
    const HertzContact h = hertz_contact(in, 0.46);
    // Against the first-order estimate: its own truncation, measured −excess/6, plus the
    // rounding of the input ratio (1e-16 of 1 + excess, relative to excess). A jump of 1e-9 at
    // the switch (excess ≈ 7.5e-5, e² = 1e-4) would show.
    EXPECT_NEAR((h.a / h.b - 1.0) / (2.0 / 3.0 * excess), 1.0, 0.2 * excess + 1e-15 / excess + 1e-9)
        << "excess " << excess;
  }
}

// The table's ends and the extreme ν: every coefficient finite and positive, f's positive.
TEST(CreepHardCases, TableEndsAndExtremePoisson) {
  for (double ratio : {0.1, 0.1000001, 9.99999, 10.0})
    for (double nu : {0.0, 1e-12, 0.5 - 1e-12, 0.5}) {
      const KalkerCoefficients c = kalker_coefficients(ratio, nu);
      for (double v : {c.c11, c.c22, c.c23, c.c33}) {
        EXPECT_TRUE(std::isfinite(v));
        EXPECT_GT(v, 0.0);
      }
      HertzContact e;
      e.b = 4e-3;
      e.a = ratio * e.b;
      const CreepCoefficients f = creep_coefficients(e, 2.1e11, nu);
      EXPECT_GT(f.f11, 0.0);
      EXPECT_GT(f.f33, 0.0);
    }
  // ν = 0.5 (incompressible) and ν = 0 through Hertz: E* = E/(2(1 − ν²)) stays finite at both.
  for (double nu : {0.0, 0.5}) {
    HertzContactInput in;
    in.wheel_load = 70e3;
    in.rail_head_radius = 0.3;
    in.poisson_ratio = nu;
    const HertzContact h = hertz_contact(in, 0.46);
    const CreepCoefficients f = creep_coefficients(h, in.youngs_modulus, nu);
    EXPECT_TRUE(std::isfinite(f.f11) && f.f11 > 0.0);
  }
}

// A very slender ellipse across the rail: the solver switches from std::comp_ellint_1/2 to the
// complementary-modulus expansions at minor/major = 1e-3 (here near a hollow-tread gap of
// 4.8e-6). Along a fine sweep through the switch, ln b changes by a smoothly varying step: its
// second difference (about −8e-7, drifting 3e-9 per step) shows no jump larger than 1e-8.
TEST(CreepHardCases, SlenderEllipseSolverBranchesMeet) {
  HertzContactInput in;
  in.wheel_load = 70e3;
  in.rail_head_radius = 0.3;
  std::vector<double> log_b;
  double smallest = 1.0, largest = 0.0;
  for (double gap = 8e-6; gap > 4e-6; gap *= 0.98) {
    in.wheel_transverse_radius = -0.3 * (1.0 + gap);
    const HertzContact h = hertz_contact(in, 0.46);
    smallest = std::min(smallest, h.a / h.b);
    largest = std::max(largest, h.a / h.b);
    log_b.push_back(std::log(h.b));
  }
  ASSERT_LT(smallest, 1e-3);  // the sweep does straddle the switch
  ASSERT_GT(largest, 1e-3);
  for (std::size_t i = 3; i < log_b.size(); ++i) {
    const double dd = log_b[i] - 2 * log_b[i - 1] + log_b[i - 2];
    const double dd_before = log_b[i - 1] - 2 * log_b[i - 2] + log_b[i - 3];
    EXPECT_NEAR(dd, dd_before, 1e-8) << "step " << i;
  }
}

}  // namespace
}  // namespace railmodal
