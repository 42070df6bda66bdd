// Spring formulas in isolation (book cases are in validation/springs_test.cpp).
#include "model/spring_formulas.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace railmodal::model {
namespace {

TEST(SpringFormulas, CoilStiffnessScalesWithWireToTheFourth) {
  const double c = coil_spring_stiffness(0.03, 0.06, 4.5, 8.3e10);
  EXPECT_NEAR(coil_spring_stiffness(0.06, 0.06, 4.5, 8.3e10) / c, 16.0, 1e-12);
  EXPECT_NEAR(coil_spring_stiffness(0.03, 0.06, 9.0, 8.3e10) / c, 0.5, 1e-12);
}

TEST(SpringFormulas, LeafSpringWithVerticalShacklesIsLinear) {
  LeafSpringGeometry leaf{1.15, 0.076, 0.0127, 11, 2, 2.1e11, 0.0, 0.0};
  EXPECT_NEAR(leaf_spring_deflection(leaf, 2e4) / leaf_spring_deflection(leaf, 1e4), 2.0, 1e-12);
  EXPECT_NEAR(leaf_spring_stiffness(leaf, 5e4) / leaf_spring_stiffness(leaf, 1.0), 1.0, 1e-12);
}

// Inclined shackles make the spring softer (springs digest §2.6: by 4–7 % for tg α = 0.5–1.0
// in the digest's illustration; here only the direction is asserted) and load-dependent.
TEST(SpringFormulas, InclinedShacklesSoftenTheSpring) {
  LeafSpringGeometry vertical{2.1, 0.12, 0.016, 8, 2, 2.2e11 / 1.0, 0.25, 0.0};
  LeafSpringGeometry inclined = vertical;
  inclined.shackle_inclination = std::atan(0.5);
  EXPECT_LT(leaf_spring_stiffness(inclined, 4e4), leaf_spring_stiffness(vertical, 4e4));
}

}  // namespace
}  // namespace railmodal::model
