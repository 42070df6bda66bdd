// Hertz's contact ellipse of a wheel on its rail: which semi-axis is which, how it scales, and
// the errors for inputs that have no point contact. (Against textbook values:
// tests/validation/creep_coefficients_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {
namespace {

HertzContactInput wheel_on_rail(double load = 70e3, double rail_head_radius = 0.3) {
  HertzContactInput in;
  in.wheel_load = load;
  in.rail_head_radius = rail_head_radius;
  return in;
}

// Swapping the two principal curvatures swaps the semi-axes and nothing else: a is always the
// semi-axis along the track, whichever way the ellipse's long axis points.
TEST(HertzContact, SemiAxisAIsAlongTheTrackEitherWay) {
  // A = 1/(2·0.5) = 1 along, B = 1/(2·0.25) = 2 across: the long axis runs along the track.
  const HertzContact along = hertz_contact(wheel_on_rail(50e3, 0.25), 0.5);
  // A = 2, B = 1: the long axis runs across the rail.
  const HertzContact across = hertz_contact(wheel_on_rail(50e3, 0.5), 0.25);
  EXPECT_GT(along.a, along.b);
  EXPECT_LT(across.a, across.b);
  EXPECT_NEAR(along.a / across.b, 1.0, 1e-13);
  EXPECT_NEAR(along.b / across.a, 1.0, 1e-13);
  EXPECT_NEAR(along.max_pressure / across.max_pressure, 1.0, 1e-13);
  EXPECT_NEAR(along.approach / across.approach, 1.0, 1e-13);
}

// A hollow (worn) tread flattens the curvature across the rail: the ellipse grows across and
// its long axis turns across the rail once the sum of curvatures across falls below 1/r0.
TEST(HertzContact, HollowTreadTurnsTheEllipseAcross) {
  HertzContactInput in = wheel_on_rail();
  const HertzContact conical = hertz_contact(in, 0.46);
  in.wheel_transverse_radius = -0.5;  // across: 1/0.3 − 1/0.5 = 1.33 < 1/0.46 = 2.17
  const HertzContact hollow = hertz_contact(in, 0.46);
  EXPECT_GT(conical.a, conical.b);
  EXPECT_LT(hollow.a, hollow.b);
  EXPECT_GT(hollow.b, conical.b);
  EXPECT_LT(hollow.max_pressure, conical.max_pressure);
  in.wheel_transverse_radius = 0.5;  // a crowned tread: more curvature across, narrower still
  EXPECT_LT(hertz_contact(in, 0.46).b, conical.b);
}

// Hertz's power laws: semi-axes and p0 grow as N^(1/3), the approach as N^(2/3); the ellipse's
// shape does not depend on the load. Hertz's pressure integrates to the load by construction
// (p0 = 3N/(2πab)); with ν and E the semi-axes scale as ∛((1 − ν²)/E).
TEST(HertzContact, ScalesAsHertzSays) {
  const HertzContact one = hertz_contact(wheel_on_rail(10e3), 0.46);
  const HertzContact eight = hertz_contact(wheel_on_rail(80e3), 0.46);
  EXPECT_NEAR(eight.a / one.a, 2.0, 1e-12);
  EXPECT_NEAR(eight.b / one.b, 2.0, 1e-12);
  EXPECT_NEAR(eight.max_pressure / one.max_pressure, 2.0, 1e-12);
  EXPECT_NEAR(eight.approach / one.approach, 4.0, 1e-12);
  EXPECT_NEAR(one.max_pressure * 2.0 * M_PI * one.a * one.b / 3.0, 10e3, 1e-7);
  HertzContactInput soft = wheel_on_rail(10e3);
  soft.youngs_modulus = 2.1e11 / 8.0;
  soft.poisson_ratio = 0.28;
  EXPECT_NEAR(hertz_contact(soft, 0.46).a / one.a, 2.0, 1e-12);
}

void expect_invalid(const HertzContactInput& in, double rolling_radius, const std::string& words) {
  try {
    hertz_contact(in, rolling_radius);
    FAIL() << "no error; expected one about " << words;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(HertzContact, BadInputsAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  HertzContactInput in = wheel_on_rail();
  in.wheel_load.reset();
  expect_invalid(in, 0.46, "wheel load is not set");
  for (double load : {0.0, -1.0, nan, inf}) expect_invalid(wheel_on_rail(load), 0.46, "wheel load");
  for (double r : {0.0, -0.3, nan, inf}) expect_invalid(wheel_on_rail(70e3, r), 0.46, "rail head radius");
  for (double r0 : {0.0, -0.46, nan, inf}) expect_invalid(wheel_on_rail(), r0, "rolling radius");
  for (double E : {0.0, -2.1e11, nan, inf}) {
    in = wheel_on_rail();
    in.youngs_modulus = E;
    expect_invalid(in, 0.46, "Young's modulus");
  }
  for (double nu : {-0.01, 0.51, nan}) {
    in = wheel_on_rail();
    in.poisson_ratio = nu;
    expect_invalid(in, 0.46, "Poisson's ratio");
  }
  for (double r : {0.0, nan, inf}) {
    in = wheel_on_rail();
    in.wheel_transverse_radius = r;
    expect_invalid(in, 0.46, "transverse radius");
  }
  // A hollow tread as tight as the rail head conforms to it, a tighter one wraps it: neither
  // touches at a point.
  for (double r : {-0.3, -0.25, -0.1}) {
    in = wheel_on_rail();
    in.wheel_transverse_radius = r;
    expect_invalid(in, 0.46, "no point contact");
  }
}

// Numbers in the messages as the caller gave them ("-2500", "0.51"), not std::to_string's
// "-2500.000000" (docs/input.md, "Names and units in outputs"); a computed one (a/b) to six
// significant digits.
TEST(HertzContact, MessagesGiveTheNumbersAsGiven) {
  expect_invalid(wheel_on_rail(-2500.0), 0.46, "the wheel load must be positive and finite, not -2500");
  HertzContactInput in = wheel_on_rail();
  in.poisson_ratio = 0.51;
  expect_invalid(in, 0.46, "Poisson's ratio must lie in [0, 0.5], not 0.51");
  in = wheel_on_rail(70e3, 0.3);
  in.wheel_transverse_radius = -0.25;
  expect_invalid(in, 0.46, "a hollow tread of transverse radius -0.25 m conforms to or wraps the rail head of radius 0.3 m");
  HertzContact slender;
  slender.a = 50e-3;
  slender.b = 3e-3;  // a/b = 16.666…: six digits
  try {
    creep_coefficients(slender, 2.1e11, 0.28);
    FAIL() << "a/b = 16.7 was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a/b = 16.6667 is outside"), std::string::npos) << e.what();
  }
}

// creep_coefficients refuses a degenerate ellipse and a modulus out of range, and leaves a/b
// and ν to Kalker's table (which names them).
TEST(CreepCoefficients, BadInputsAreNamed) {
  HertzContact e;
  e.a = 6e-3;
  e.b = 4e-3;
  EXPECT_NO_THROW(creep_coefficients(e, 2.1e11, 0.28));
  HertzContact flat = e;
  flat.b = 0.0;
  EXPECT_THROW(creep_coefficients(flat, 2.1e11, 0.28), std::invalid_argument);
  flat.b = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(creep_coefficients(flat, 2.1e11, 0.28), std::invalid_argument);
  EXPECT_THROW(creep_coefficients(e, 0.0, 0.28), std::invalid_argument);
  EXPECT_THROW(creep_coefficients(e, 2.1e11, 0.6), std::invalid_argument);
  HertzContact slender = e;
  slender.a = 50e-3;  // a/b = 12.5: beyond Kalker's table
  EXPECT_THROW(creep_coefficients(slender, 2.1e11, 0.28), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal
