// Hard cases of the wheel–rail contact terms (issue 20 item 7): zero conicity, no yaw
// restraint, a crawling speed and a very high one give finite matrices and finite eigenvalues,
// never a NaN; a wheelset the system cannot carry is a clear error naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "test_support.hpp"
#include "validation/hunting_test_support.hpp"

namespace railmodal::test {
namespace {

bool all_finite(const Eigen::VectorXcd& values) {
  for (const auto& l : values)
    if (!std::isfinite(l.real()) || !std::isfinite(l.imag())) return false;
  return true;
}

bool all_finite(const ContactMatrices& c) {
  return c.stiffness.allFinite() && c.creep_damping.allFinite() && c.gyroscopic.allFinite();
}

// Zero conicity: no kinematic coupling (no yaw moment from a lateral displacement), no roll, no
// gravitational stiffness; Klingel's wavelength is infinite and the eigenvalues are finite.
TEST(HuntingContactHardCases, ZeroConicity) {
  WheelsetData d;
  d.conicity = 0.0;
  const auto m = hunting_model(wheelset_on_springs(d));
  ASSERT_TRUE(all_finite(m.contact));
  EXPECT_EQ(m.contact.stiffness(1, 0), 0.0);
  EXPECT_EQ(m.contact.stiffness(0, 0), 0.0);
  EXPECT_EQ(m.contact.gyroscopic.norm(), 0.0);
  EXPECT_TRUE(std::isinf(m.contact.wheelsets[0].klingel_wavelength));
  for (double v : {1e-3, 1.0, 100.0, 1000.0}) {
    const auto l = eigenvalues(m, v);
    EXPECT_TRUE(all_finite(l)) << "V = " << v;
    // With λ = 0 nothing feeds energy in: the creep is pure damping, so nothing grows.
    EXPECT_LE(l.real().maxCoeff(), 1e-9 * l.cwiseAbs().maxCoeff()) << "V = " << v;
  }
  // The conicity override to zero does the same to a wheelset given a conicity.
  const auto zero = hunting_model(wheelset_on_springs(WheelsetData{}), 0.0);
  EXPECT_EQ(zero.contact.stiffness(1, 0), 0.0);
  EXPECT_TRUE(std::isinf(zero.contact.wheelsets[0].klingel_wavelength));
}

// A free wheelset at zero conicity has no lateral stiffness at all: a zero eigenvalue (it may
// drift sideways), still finite.
TEST(HuntingContactHardCases, FreeWheelsetAtZeroConicityDriftsWithoutNaN) {
  WheelsetData d;
  d.conicity = 0.0;
  const auto m = hunting_model(wheelset_on_springs(d, 0.0, 0.0));
  for (double v : {1e-3, 10.0, 500.0}) EXPECT_TRUE(all_finite(eigenvalues(m, v))) << "V = " << v;
}

// No yaw restraint: only the lateral spring; the creep forces alone hold the yaw.
TEST(HuntingContactHardCases, NoYawRestraint) {
  const auto m = hunting_model(wheelset_on_springs(WheelsetData{}, 1.0e6, 0.0));
  for (double v : {1e-3, 1.0, 50.0, 500.0}) EXPECT_TRUE(all_finite(eigenvalues(m, v))) << "V = " << v;
}

// A crawl, V = 1 mm/s: the creep damping C_c/V is 1e3 times its value at 1 m/s and the roots
// spread over ~1e10 in modulus; still finite, and the kinematic root is still Klingel-like.
TEST(HuntingContactHardCases, CrawlingSpeed) {
  WheelsetData d;
  d.sigma = 0.0;  // so that the limit is Klingel's own wavelength
  d.epsilon = 0.0;
  const auto m = hunting_model(wheelset_on_springs(d, 0.0, 0.0));
  const double v = 1e-3;
  ASSERT_TRUE(all_finite(eigenvalues(m, v)));
  const auto root = slowest_oscillatory_root(m, v);
  const double wavelength = 2 * kPi * v / root.imag();
  // 1e-5: the kinematic root's modulus is ~1e-3 against roots of ~1e10; rounding of the
  // eigen-solve (~1e-16 · 1e10) bounds its accuracy at ~1e-6 of itself.
  EXPECT_NEAR(wavelength, m.contact.wheelsets[0].klingel_wavelength, 1e-5 * wavelength);
}

// A very high speed, 1000 m/s: the gyroscopic terms V·G grow and the creep damping vanishes;
// finite, and the gyroscopic matrix stays skew-symmetric.
TEST(HuntingContactHardCases, VeryHighSpeedGyroscopicTerms) {
  WheelsetData d;
  d.spin_inertia = 300.0;  // large, to make V·G count
  const auto m = hunting_model(wheelset_on_springs(d));
  EXPECT_GT(m.contact.gyroscopic(1, 0), 0.0);
  EXPECT_EQ(m.contact.gyroscopic(1, 0), -m.contact.gyroscopic(0, 1));
  for (double v : {300.0, 1000.0, 1e4}) EXPECT_TRUE(all_finite(eigenvalues(m, v))) << "V = " << v;
}

// Errors name the wheelset and the rule.
void expect_error(const Vehicle& v, DofSet set, const std::string& words) {
  try {
    contact_matrices(assemble(v, set));
    ADD_FAILURE() << "no error; expected one mentioning '" << words << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(HuntingContactHardCases, ErrorsNameTheWheelset) {
  Vehicle none;
  none.name = "no wheelsets";
  Body b;
  b.name = "body";
  b.mass = 1000;
  b.inertia = {100, 100, 100};
  b.held = {Motion::bounce, Motion::roll, Motion::pitch};
  none.bodies.push_back(b);
  none.elements.push_back(spring("s", "body", "", {0, 0, 0}, 1e6, 1e6));
  expect_error(none, DofSet::lateral, "no wheelsets");

  const Vehicle good = wheelset_on_springs(WheelsetData{});
  expect_error(good, DofSet::vertical, "'wheelset': its lateral and yaw motions must be free");

  Vehicle yaw_held = good;
  yaw_held.bodies[0].held.push_back(Motion::yaw);
  expect_error(yaw_held, DofSet::lateral, "'wheelset': its lateral and yaw motions must be free");

  Vehicle roll_free = good;
  roll_free.bodies[0].held = {Motion::bounce, Motion::pitch};
  roll_free.elements.push_back(spring("roll", "wheelset", "", {0, 0.7, 0}, 0, 0, 1e6));
  roll_free.elements.push_back(spring("roll", "wheelset", "", {0, -0.7, 0}, 0, 0, 1e6));
  expect_error(roll_free, DofSet::lateral, "'wheelset': its roll must be held");

  Vehicle unknown = good;
  unknown.wheelsets[0].body = "axle";
  expect_error(unknown, DofSet::lateral, "'axle': no body of that name");

  Vehicle both = good;
  both.wheelsets[0].contact.hertz = HertzContactInput{};
  expect_error(both, DofSet::lateral, "exactly one of the creep coefficients and the Hertz contact");

  Vehicle neither = good;
  neither.wheelsets[0].contact.creep.reset();
  expect_error(neither, DofSet::lateral, "exactly one of the creep coefficients and the Hertz contact");

  Vehicle negative = good;
  negative.wheelsets[0].contact.conicity = -0.1;
  expect_error(negative, DofSet::lateral, "conicity");

  Vehicle no_radius = good;
  no_radius.wheelsets[0].contact.rolling_radius = 0.0;
  expect_error(no_radius, DofSet::lateral, "rolling radius r0");

  Vehicle nan_creep = good;
  nan_creep.wheelsets[0].contact.creep->f22 = std::numeric_limits<double>::quiet_NaN();
  expect_error(nan_creep, DofSet::lateral, "f22");

  Vehicle twice = good;
  twice.wheelsets.push_back(twice.wheelsets[0]);
  expect_error(twice, DofSet::lateral, "listed twice");

  EXPECT_THROW(contact_matrices(assemble(good, DofSet::lateral), -1.0), std::invalid_argument);

  // One conicity rule everywhere (reader, HuntingOptions, here): 0 ≤ λ < 1.
  Vehicle steep = good;
  steep.wheelsets[0].contact.conicity = 1.5;
  expect_error(steep, DofSet::lateral, "conicity = 1.5 must be ≥ 0 and below 1");
  try {
    contact_matrices(assemble(good, DofSet::lateral), 1.0);
    ADD_FAILURE() << "a conicity override of 1 was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("conicity = 1 must be ≥ 0 and below 1"), std::string::npos) << e.what();
  }

  // The contact acts at the centre of gravity, the axle centre: off the track's centre line or the
  // axle plane it is refused (a longitudinal offset is the lever, HuntingValidation.AxleLoadAnd…).
  for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(0, 0, 0.2)}) {
    Vehicle off = good;
    off.bodies[0].centre_of_gravity += offset;
    expect_error(off, DofSet::lateral, "'wheelset': its centre of gravity (the axle centre) and reference point");
  }
}

// The conicity override replaces λ and the ε, σ that default from it, but not ε, σ given.
TEST(HuntingContactHardCases, ConicityOverrideKeepsGivenParameters) {
  WheelsetData d;
  d.epsilon = 0.02;
  const auto m = hunting_model(wheelset_on_springs(d), 0.3);
  const auto& r = m.contact.wheelsets[0];
  EXPECT_EQ(r.conicity, 0.3);
  EXPECT_EQ(r.contact_angle_parameter, 0.02);
  EXPECT_EQ(r.roll_parameter, 0.3);
}

}  // namespace
}  // namespace railmodal::test
