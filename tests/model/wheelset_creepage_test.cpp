// The wheelset's creepage kinematics (src/model/wheelset_creepage.hpp), called on states as a
// nonlinear analysis will call it: rolling without creep gives none, and the linear creep law
// and the loads keep the signs of docs/stability.md.
#include "model/wheelset_creepage.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

// The loads are the transpose of the creepages (issue 20 review: the lateral load had ΣFy where
// the creepage has κẏ/V): for any rates, at y = ψ = 0, the power of the generalised forces
// Q_y·ẏ + Q_ψ·ψ̇ equals V·Σ(Fx·ξx + Fy·ξy + Mz·ξsp), the power the creep forces take at the two
// contacts. So the creep damping dissipates 2f22κ²ẏ²/V, not 2f22κẏ²/V.
TEST(WheelsetCreepage, LoadsAreTheTransposeOfTheCreepages) {
  const CreepCoefficients f{1e7, 0.9e7, 1e4, 100.0};
  for (const WheelsetGeometry& g : {kGeometry, WheelsetGeometry{0.46, 0.75, 0.4, 0.6, 0.3}}) {
    const double v = 25.0, y_rate = 0.03, yaw_rate = -0.02;
    const auto c = wheelset_creepages(g, {0.0, 0.0, y_rate, yaw_rate, v});
    const auto left = linear_creep_forces(f, c.left), right = linear_creep_forces(f, c.right);
    const auto load = wheelset_load(g, left, right);
    auto power = [](const WheelContactForces& F, const WheelCreepage& x) {
      return F.longitudinal * x.longitudinal + F.lateral * x.lateral + F.spin_moment * x.spin;
    };
    const double contact_power = v * (power(left, c.left) + power(right, c.right));
    // 1e-12 relative: a dozen products of O(1) terms.
    EXPECT_NEAR(load.lateral * y_rate + load.yaw * yaw_rate, contact_power, 1e-12 * std::abs(contact_power));
    // And the lateral load alone: κ·ΣFy with κ = 1 + σ·r0/l0.
    const double kappa = 1.0 + g.roll_parameter * g.rolling_radius / g.contact_half_spacing;
    EXPECT_DOUBLE_EQ(load.lateral, kappa * (left.lateral + right.lateral));
  }
}

// σ = 0: the standard model, whose lateral load is the plain sum of the two wheels' forces.
TEST(WheelsetCreepage, WithoutRollTheLateralLoadIsThePlainSum) {
  const WheelsetGeometry g{0.46, 0.75, 0.15, 0.15, 0.0};
  const WheelContactForces left{100.0, 200.0, 3.0}, right{-100.0, 300.0, 4.0};
  EXPECT_EQ(wheelset_load(g, left, right).lateral, 500.0);
}

}  // namespace
}  // namespace railmodal::model
