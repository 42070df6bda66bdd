// Assembly: mass and stiffness matrices from bodies and elements.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

Vehicle one_body_on_four_springs(double cg_height) {
  Vehicle v;
  v.name = "box";
  Body b;
  b.name = "body";
  b.mass = 1000.0;
  b.inertia = {200.0, 800.0, 900.0};
  b.centre_of_gravity = {0.1, 0.0, cg_height};
  b.reference_point = {0.1, 0.0, 0.0};
  v.bodies.push_back(b);
  for (double x : {-1.0, 1.0})
    for (double y : {-0.5, 0.5}) {
      Element e;
      e.name = "spring";
      e.upper = "body";
      e.point = {x, y, 0.0};
      e.vertical_stages = {{"coil", 1.0e5, 1}};
      e.lateral_stages = {{"coil", 2.0e4, 1}};
      v.elements.push_back(e);
    }
  return v;
}

TEST(Assembly, MatricesAreSymmetricAndMassIsPositiveDefinite) {
  const auto s = assemble(one_body_on_four_springs(0.8), DofSet::all);
  EXPECT_EQ(s.size(), 5);
  EXPECT_EQ((s.mass - s.mass.transpose()).norm(), 0.0);
  EXPECT_LT((s.stiffness - s.stiffness.transpose()).norm(), 1e-12 * s.stiffness.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(s.mass);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

// The CG a height l above the reference point: roll and pitch inertias gain m·l², lateral
// couples with roll through m·l (the m3·d0 of eq. (254)), and gravity subtracts W·l from roll
// and pitch stiffness (eq. (156a), (160b)).
TEST(Assembly, CentreOfGravityAboveReferenceGivesParallelAxisAndGravityTerms) {
  const double l = 0.8;
  const auto s = assemble(one_body_on_four_springs(l), DofSet::all);
  const int lat = s.index_of("body.lateral"), roll = s.index_of("body.roll"), pitch = s.index_of("body.pitch");
  EXPECT_NEAR(s.mass(roll, roll), 200.0 + 1000.0 * l * l, 1e-9);
  EXPECT_NEAR(s.mass(pitch, pitch), 800.0 + 1000.0 * l * l, 1e-9);
  EXPECT_NEAR(std::abs(s.mass(lat, roll)), 1000.0 * l, 1e-9);
  const double W = 1000.0 * 9.81;
  EXPECT_NEAR(s.gravity_stiffness(roll, roll), -W * l, 1e-9);
  EXPECT_NEAR(s.gravity_stiffness(pitch, pitch), -W * l, 1e-9);
  EXPECT_NEAR(s.stiffness(roll, roll) - s.gravity_stiffness(roll, roll), 4 * 1.0e5 * 0.25, 1e-6);
}

// Static loads come from equilibrium: the lever rule for a CG off the spring centre.
TEST(Assembly, StaticLoadsFollowTheLeverRule) {
  const auto s = assemble(one_body_on_four_springs(0.5), DofSet::vertical);
  const double W = 1000.0 * 9.81;
  double total = 0.0;
  for (size_t k = 0; k < s.element_loads.size(); ++k) {
    total += s.element_loads[k];
    const double x = s.vehicle.elements[k].point.x();
    EXPECT_NEAR(s.element_loads[k], W * (1.0 + x * 0.1) / 4.0, 1e-9 * W) << k;  // (a ± x_cg)/(2a)
  }
  EXPECT_NEAR(total, W, 1e-9 * W);
}

// A swing hanger's lateral stiffness is its static load / (λ cos α).
TEST(Assembly, SwingHangerStiffnessFromItsLoad) {
  Vehicle v = one_body_on_four_springs(0.0);
  for (auto& e : v.elements) {
    e.lateral_stages.clear();
    e.hanger = SwingHanger{0.5, 0.2};
  }
  const auto s = assemble(v, DofSet::lateral);
  const int lat = s.index_of("body.lateral");
  EXPECT_NEAR(s.stiffness(lat, lat), 1000.0 * 9.81 / (0.5 * std::cos(0.2)), 1e-9);
}

// An anti-roll bar is a roll stiffness on the relative rotation of body and bogie: +k on
// both diagonals, −k between them (Manchester coach, 940 kN·m/rad per bogie).
TEST(Assembly, AntiRollBarActsOnRelativeRoll) {
  Vehicle with_bar = load_vehicle(data_file("manchester_benchmark_coach.toml"));
  Vehicle without = with_bar;
  without.elements.erase(std::remove_if(without.elements.begin(), without.elements.end(),
                                        [](const Element& e) { return e.rotational_stiffness.norm() > 0.0; }),
                         without.elements.end());
  ASSERT_EQ(with_bar.elements.size(), without.elements.size() + 2);
  const auto a = assemble(with_bar, DofSet::lateral), b = assemble(without, DofSet::lateral);
  const Eigen::MatrixXd d = (a.stiffness - a.gravity_stiffness) - (b.stiffness - b.gravity_stiffness);
  const int body = a.index_of("body.roll"), bogie = a.index_of("bogie1.roll");
  EXPECT_NEAR(d(body, body), 2 * 940e3, 1e-6);
  EXPECT_NEAR(d(bogie, bogie), 940e3, 1e-6);
  EXPECT_NEAR(d(body, bogie), -940e3, 1e-6);
  // Nothing else changes: (2k)² + 2k² on the diagonals, 4k² off them.
  EXPECT_NEAR(d.norm(), std::sqrt(10.0) * 940e3, 1e-3);
}

TEST(Assembly, HeldMotionsAreNotDegreesOfFreedom) {
  Vehicle v = one_body_on_four_springs(0.5);
  v.bodies[0].held = {Motion::lateral, Motion::yaw};
  const auto s = assemble(v, DofSet::lateral);
  ASSERT_EQ(s.size(), 1);
  EXPECT_EQ(s.dofs[0].label, "body.roll");
}

TEST(Assembly, InconsistentVehiclesAreRejected) {
  Vehicle v = one_body_on_four_springs(0.5);
  v.elements[0].upper = "nobody";
  EXPECT_THROW(assemble(v, DofSet::all), std::invalid_argument);
  v = one_body_on_four_springs(0.5);
  v.bodies[0].mass = 0.0;
  EXPECT_THROW(assemble(v, DofSet::all), std::invalid_argument);
  v = one_body_on_four_springs(0.5);
  v.elements.clear();  // nothing holds it up
  EXPECT_THROW(assemble(v, DofSet::all), NumericalError);
}

}  // namespace
}  // namespace railmodal::test
