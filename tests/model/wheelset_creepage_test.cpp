// The wheelset's creepage kinematics (src/model/wheelset_creepage.hpp), called on states as a
// nonlinear analysis will call it: rolling without creep gives none, and the linear creep law
// and the loads keep the signs of docs/stability.md.
#include "model/wheelset_creepage.hpp"

#include <gtest/gtest.h>

namespace railmodal::model {
namespace {

const WheelsetGeometry kGeometry{0.46, 0.75, 0.15, 0.15, 0.15};

// Rolling without creep (Klingel's kinematics with the roll term): ψ̇ = −Vλy/(r0·l0) and
// κ·ẏ = V·ψ, κ = 1 + σ·r0/l0. Every creepage vanishes there (ε = σ: no spin from y).
TEST(WheelsetCreepage, RollingWithoutCreepHasNone) {
  const double v = 30.0, y = 0.004, psi = 0.002;
  const double kappa = 1.0 + 0.15 * 0.46 / 0.75;
  const WheelsetState s{y, psi, v * psi / kappa, -v * 0.15 * y / (0.46 * 0.75), v};
  const auto c = wheelset_creepages(kGeometry, s);
  // 1e-15: a few roundings of O(1e-3) quantities.
  EXPECT_NEAR(c.left.longitudinal, 0.0, 1e-15);
  EXPECT_NEAR(c.right.longitudinal, 0.0, 1e-15);
  EXPECT_NEAR(c.left.lateral, 0.0, 1e-15);
  // The spin is the yaw rate's alone.
  EXPECT_NEAR(c.left.spin, s.yaw_rate / v, 1e-15);
}

// A left displacement: the left wheel (larger radius) creeps backwards, the right forwards; the
// creep forces push the left wheel forwards and turn the wheelset clockwise.
TEST(WheelsetCreepage, LeftDisplacementSteersBack) {
  const WheelsetState s{0.003, 0.0, 0.0, 0.0, 20.0};
  const auto c = wheelset_creepages(kGeometry, s);
  EXPECT_LT(c.left.longitudinal, 0.0);
  EXPECT_DOUBLE_EQ(c.right.longitudinal, -c.left.longitudinal);
  const CreepCoefficients f{1e7, 0.9e7, 1e4, 100.0};
  const auto left = linear_creep_forces(f, c.left), right = linear_creep_forces(f, c.right);
  EXPECT_GT(left.longitudinal, 0.0);
  const auto load = wheelset_load(kGeometry, left, right);
  EXPECT_LT(load.yaw, 0.0);
  EXPECT_NEAR(load.yaw, -2 * f.f11 * 0.15 * 0.75 * 0.003 / 0.46, 1e-9);
  EXPECT_NEAR(load.lateral, 0.0, 0.0);  // ε = σ and no rates: no lateral creep
}

// Spin from a lateral displacement when the contact angles change faster than the roll
// (ε > σ, worn profiles): −(ε − σ)·y/(r0·l0) on both wheels, giving the lateral force f23·…
TEST(WheelsetCreepage, SpinFromContactAngleChange) {
  const WheelsetGeometry worn{0.46, 0.75, 0.15, 0.6, 0.15};
  const auto c = wheelset_creepages(worn, {0.002, 0.0, 0.0, 0.0, 10.0});
  const double spin = -(0.6 - 0.15) * 0.002 / (0.46 * 0.75);
  EXPECT_DOUBLE_EQ(c.left.spin, spin);
  EXPECT_DOUBLE_EQ(c.right.spin, spin);
  const CreepCoefficients f{1e7, 0.9e7, 1e4, 100.0};
  EXPECT_DOUBLE_EQ(linear_creep_forces(f, c.left).lateral, -f.f23 * spin);
  EXPECT_DOUBLE_EQ(linear_creep_forces(f, c.left).spin_moment, -f.f33 * spin);
}

}  // namespace
}  // namespace railmodal::model
