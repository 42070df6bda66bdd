// Assembly: mass and stiffness matrices from bodies and elements.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "model/assembly.hpp"
#include "model/spring_stages.hpp"
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

// ---- model::VariantAssembly: a study worker's variants assembled on one kept base ----

bool same_bits_matrix(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0);
}

// Whether a and b have the same shape and differ nowhere by more than `relative` times b's
// largest entry.
bool near_matrix(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double relative) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || (a - b).cwiseAbs().maxCoeff() <= relative * b.cwiseAbs().maxCoeff());
}

// What depends on the static loads (the element loads, the dead-load stiffness, and through
// the hangers' lateral stiffness K and the track inputs): a study's workers find the loads by
// a Cholesky factorisation of the sprung block where assemble takes a complete orthogonal
// decomposition (static_loads_on_sprung), two backward-stable solves that differ by the unit
// round-off times the block's condition number. Measured below 1e-15 on the bundled vehicles;
// 1e-13 is the bound a study's round-off change is allowed (docs/performance.md,
// study-base2), about 450 units of round-off. Elsewhere, and where the route does not apply
// (no direction without springs), the workers' system is assemble's bit for bit.
constexpr double kStaticLoadRoundOff = 1e-13;

// Every member assemble fills, bit for bit but for what depends on the static loads (to
// kStaticLoadRoundOff; the vehicles by their shape and stiffnesses: the one moved in is the
// one given).
void expect_same_system(const LinearSystem& got, const LinearSystem& want, const std::string& what) {
  ASSERT_EQ(got.dofs.size(), want.dofs.size()) << what;
  for (size_t i = 0; i < got.dofs.size(); ++i) {
    EXPECT_EQ(got.dofs[i].label, want.dofs[i].label) << what;
    EXPECT_EQ(got.dofs[i].body, want.dofs[i].body) << what;
    EXPECT_EQ(got.dofs[i].motion, want.dofs[i].motion) << what;
  }
  EXPECT_TRUE(same_bits_matrix(got.mass, want.mass)) << what << ": mass";
  EXPECT_TRUE(same_bits_matrix(got.damping, want.damping)) << what << ": damping";
  EXPECT_TRUE(near_matrix(got.stiffness, want.stiffness, kStaticLoadRoundOff)) << what << ": stiffness";
  EXPECT_TRUE(near_matrix(got.gravity_stiffness, want.gravity_stiffness, kStaticLoadRoundOff))
      << what << ": gravity stiffness";
  EXPECT_TRUE(same_bits_matrix(got.element_vertical_map, want.element_vertical_map)) << what << ": element map";
  ASSERT_EQ(got.element_loads.size(), want.element_loads.size()) << what;
  const Eigen::Map<const Eigen::VectorXd> got_loads(got.element_loads.data(),
                                                    static_cast<Eigen::Index>(got.element_loads.size()));
  const Eigen::Map<const Eigen::VectorXd> want_loads(want.element_loads.data(),
                                                     static_cast<Eigen::Index>(want.element_loads.size()));
  EXPECT_TRUE(near_matrix(got_loads, want_loads, kStaticLoadRoundOff)) << what << ": element loads";
  ASSERT_EQ(got.track_inputs.size(), want.track_inputs.size()) << what;
  for (size_t k = 0; k < got.track_inputs.size(); ++k) {
    EXPECT_EQ(got.track_inputs[k].element, want.track_inputs[k].element) << what;
    EXPECT_TRUE(same_bits_matrix(got.track_inputs[k].point, want.track_inputs[k].point)) << what;
    EXPECT_TRUE(near_matrix(got.track_inputs[k].load_per_displacement, want.track_inputs[k].load_per_displacement,
                            kStaticLoadRoundOff))
        << what << ": track input " << k;
    EXPECT_TRUE(same_bits_matrix(got.track_inputs[k].load_per_velocity, want.track_inputs[k].load_per_velocity))
        << what << ": track input " << k;
  }
  ASSERT_EQ(got.series_dampers.size(), want.series_dampers.size()) << what;
  for (size_t k = 0; k < got.series_dampers.size(); ++k) {
    EXPECT_EQ(got.series_dampers[k].element, want.series_dampers[k].element) << what;
    EXPECT_TRUE(same_bits_matrix(got.series_dampers[k].stretch, want.series_dampers[k].stretch)) << what;
    EXPECT_EQ(std::memcmp(&got.series_dampers[k].damping, &want.series_dampers[k].damping, sizeof(double)), 0) << what;
  }
  ASSERT_EQ(got.vehicle.elements.size(), want.vehicle.elements.size()) << what;
  for (size_t k = 0; k < got.vehicle.elements.size(); ++k)
    EXPECT_EQ(series_stiffness(got.vehicle.elements[k].vertical_stages),
              series_stiffness(want.vehicle.elements[k].vertical_stages)) << what;
}

// The coefficients a study varies, scaled: every spring stage's stiffness, the rotational
// stiffnesses and the viscous dampings (a zero stays zero).
Vehicle with_coefficients_scaled(Vehicle v, double by) {
  for (Element& e : v.elements) {
    for (auto* stages : {&e.vertical_stages, &e.lateral_stages, &e.longitudinal_stages})
      for (SpringStage& s : *stages) s.stiffness *= by;
    e.rotational_stiffness *= by;
    e.vertical_damping *= 1.0 / by;
    e.lateral_damping *= by;
    e.longitudinal_damping *= by;
  }
  return v;
}

// A study worker assembles every variant of a bundled vehicle as assemble_with_stiffness does
// (expect_same_system: to the last bit but for the static loads' round-off), whether it reuses its base (only coefficients changed) or builds a new one
// (a mass changed), and reuses exactly when it may.
TEST(VariantAssembly, EveryBundledVehicleAssemblesAsTheGeneralPath) {
  int vehicles = 0;
  for (const auto& file : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/vehicles")) {
    if (file.path().extension() != ".toml") continue;
    const Vehicle base = load_vehicle(file.path().string());
    Vehicle heavier = with_coefficients_scaled(base, 1.07);
    heavier.bodies.front().mass *= 1.05;
    // base; two coefficient variants (reused); a new mass (a new base); a coefficient variant
    // of it (reused again).
    const std::vector<std::pair<Vehicle, bool>> sequence = {
        {base, false},
        {with_coefficients_scaled(base, 1.3), true},
        {with_coefficients_scaled(base, 0.71), true},
        {heavier, false},
        {with_coefficients_scaled(heavier, 1.2), true}};
    for (DofSet set : {DofSet::vertical, DofSet::all}) {
      model::VariantAssembly worker;
      LinearSystem system, stiffness;
      for (size_t i = 0; i < sequence.size(); ++i) {
        const std::string what = file.path().filename().string() + " " + to_string(set) + " #" + std::to_string(i);
        model::SystemAndStiffness want;
        try {
          want = model::assemble_with_stiffness(sequence[i].first, set, DofSet::lateral);
        } catch (const std::exception&) {
          Vehicle given = sequence[i].first;
          EXPECT_THROW(worker.assemble(std::move(given), set, DofSet::lateral, &system, &stiffness), std::exception)
              << what;
          continue;
        }
        Vehicle given = sequence[i].first;
        worker.assemble(std::move(given), set, DofSet::lateral, &system, &stiffness);
        EXPECT_EQ(worker.reused(), sequence[i].second) << what;
        expect_same_system(system, want.system, what);
        EXPECT_EQ(stiffness.dofs.size(), want.stiffness.dofs.size()) << what;
        EXPECT_TRUE(near_matrix(stiffness.stiffness, want.stiffness.stiffness, kStaticLoadRoundOff))
            << what << ": lateral stiffness";
        EXPECT_TRUE(near_matrix(stiffness.gravity_stiffness, want.stiffness.gravity_stiffness, kStaticLoadRoundOff))
            << what;
      }
    }
    ++vehicles;
  }
  EXPECT_GE(vehicles, 10);
}

// A coefficient the assembly refuses is refused with assemble's message, and the kept base
// still serves the next variant.
TEST(VariantAssembly, ABadCoefficientGivesAssemblesMessage) {
  const Vehicle base = load_vehicle(data_file("resort_car.toml"));
  model::VariantAssembly worker;
  LinearSystem system, stiffness;
  Vehicle first = base;
  worker.assemble(std::move(first), DofSet::vertical, DofSet::lateral, &system, &stiffness);
  Vehicle bad = base;
  bad.elements.front().vertical_stages.front().stiffness = -1.0;
  std::string expected;
  try {
    assemble(bad, DofSet::vertical);
  } catch (const std::invalid_argument& e) {
    expected = e.what();
  }
  ASSERT_FALSE(expected.empty());
  try {
    worker.assemble(std::move(bad), DofSet::vertical, DofSet::lateral, &system, &stiffness);
    ADD_FAILURE() << "a negative stiffness was assembled";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
  Vehicle next = with_coefficients_scaled(base, 1.1);
  worker.assemble(std::move(next), DofSet::vertical, DofSet::lateral, &system, &stiffness);
  EXPECT_TRUE(worker.reused());
  expect_same_system(system, assemble(with_coefficients_scaled(base, 1.1), DofSet::vertical), "after the refusal");
}

// The one walk over spring stages (coefficient checks, the largest leaf friction, the scene's
// effect warnings) visits each stage of every direction once: vertical, lateral, longitudinal,
// element by element. A direction added to Element must join it (the size test below says when).
TEST(SpringStages, EachStageOfEveryDirectionOnceInOrder) {
  Element front, rear;
  front.vertical_stages = {{"leaf", 1.0, 1}, {"coil", 2.0, 1}};
  front.lateral_stages = {{"coil", 3.0, 1}};
  front.longitudinal_stages = {{"coil", 4.0, 1}};
  rear.longitudinal_stages = {{"coil", 5.0, 1}};
  Vehicle v;
  v.elements = {front, rear};
  std::vector<double> seen;
  model::each_spring_stage(v, [&](const SpringStage& s) { seen.push_back(s.stiffness); });
  EXPECT_EQ(seen, (std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0}));
  seen.clear();
  model::each_spring_stage(rear, [&](const SpringStage& s) { seen.push_back(s.stiffness); });
  EXPECT_EQ(seen, (std::vector<double>{5.0}));
}

// same_but_coefficients (src/model/assembly.cpp) compares every field of the vehicle's structs
// that the kept base was made from; a field added to them must be compared there (or left out
// with a reason) before these sizes (x86-64, libstdc++) are updated, as VehicleNumbers' are.
TEST(VariantAssembly, ComparesEveryFieldTheAssemblyReads) {
  if (sizeof(void*) != 8 || sizeof(std::string) != 32) GTEST_SKIP() << "sizes measured on x86-64 with libstdc++";
  // 144: Vehicle::warnings (168, 2026-11-27) went back out of the model on 2026-11-28 (the
  // reader hands its warnings beside the vehicle: load_vehicle's out-parameter).
  EXPECT_EQ(sizeof(Vehicle), 144u);
  EXPECT_EQ(sizeof(Body), 248u);  // 232 before Body::floor_height (2026-11-27, night): compared
  EXPECT_EQ(sizeof(BodyBending), 80u);
  EXPECT_EQ(sizeof(SpringStage), 112u);
  EXPECT_EQ(sizeof(SwingHanger), 16u);
  EXPECT_EQ(sizeof(SeriesDamper), 24u);
  EXPECT_EQ(sizeof(Element), 288u);
  EXPECT_EQ(sizeof(Wheelset), 216u);
}

}  // namespace
}  // namespace railmodal::test
