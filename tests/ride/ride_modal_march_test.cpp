// The modal march (ride_modal_march.hpp) against the dense march (ride_march.hpp): the same
// discretisation in other coordinates, so the same histories to round-off; which systems take
// which path (the eigenvector condition test), repeated roots with independent eigenvectors
// modal, a defective system dense, and simulate_ride's answer the same either way.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "railmodal/railmodal.hpp"
#include "ride/ride_march.hpp"
#include "ride/ride_modal_march.hpp"
#include "ride/ride_state_space.hpp"
#include "ride/ride_test_systems.hpp"
#include "ride/track_under_wheels.hpp"
#include "test_support.hpp"

namespace railmodal::test::modal_march_test {
namespace {

// The dense march's outputs as simulate_ride evaluates them (ride_simulation.cpp): rows on
// (s, w, ẇ), from `start`, or from the periodic orbit when `periodic`.
Eigen::MatrixXd dense_outputs(const ride::RideStateSpace& model, const ride::TrackUnderWheels& track,
                              const std::vector<ride::OutputRow>& rows, double speed, double step, long count,
                              bool periodic) {
  ride::RideMarch march(model, track, speed, step, track.span());
  Eigen::VectorXd s = Eigen::VectorXd::Zero(2 * model.n);
  if (periodic) {
    for (long k = 0; k < count; ++k) march.advance(k, &s);
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(2 * model.n, 2 * model.n);
    s = (I - march.transition_power(count)).fullPivLu().solve(s);
  }
  Eigen::MatrixXd y(count, static_cast<Eigen::Index>(rows.size()));
  Eigen::VectorXd w, dw;
  for (long k = 0; k < count; ++k) {
    track.displacement(march.leading(k), &w);
    track.slope(march.leading(k), &dw);
    for (size_t j = 0; j < rows.size(); ++j)
      y(k, static_cast<Eigen::Index>(j)) = rows[j].Ls.dot(s) + rows[j].Lw.dot(w) + speed * rows[j].Ld.dot(dw);
    if (k + 1 < count) march.advance(k, &s);
  }
  return y;
}

// The modal march's outputs (one vector each) as the columns of a matrix.
Eigen::MatrixXd modal_outputs(ride::ModalRideMarch* modal, const ride::ModalRideMarch::State& start, long count) {
  const std::vector<Eigen::VectorXd> runs = modal->outputs(start, count);
  Eigen::MatrixXd y(count, static_cast<Eigen::Index>(runs.size()));
  for (size_t j = 0; j < runs.size(); ++j) y.col(static_cast<Eigen::Index>(j)) = runs[j];
  return y;
}

// The largest difference of each column over that column's largest value.
double worst_relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0.0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    worst = std::max(worst, (a.col(j) - b.col(j)).cwiseAbs().maxCoeff() / a.col(j).cwiseAbs().maxCoeff());
  return worst;
}

TrackGeometry ore_track(double length, double step, bool all_three) {
  const auto ore = [](TrackIrregularity c) { return TrackSpectrum::ore_b176(OreLevel::high, c, {0.06, 6.0}); };
  TrackIrregularitySpectra spectra;
  spectra.vertical_level = ore(TrackIrregularity::vertical_level);
  if (all_three) {
    spectra.alignment = ore(TrackIrregularity::alignment);
    spectra.cross_level = ore(TrackIrregularity::cross_level);
  }
  TrackSynthesisOptions o;
  o.length = length;
  o.step = step;
  o.seed = 11;
  return synthesise_track(spectra, o);
}

struct Case {
  LinearSystem system;
  std::vector<RideOutput> outputs;
};

// Both marches over one track, periodic (from the orbit) and measured (from rest); the step
// a third of a sample's time, and a speed that puts the axles' kinks at different phases.
void expect_same_histories(const Case& c, const TrackGeometry& geometry, double speed, double tolerance,
                           long steps_a_sample = 3) {
  const ride::RideStateSpace model = ride::ride_state_space(c.system);
  const std::vector<ride::OutputRow> rows = ride::output_rows(c.system, model, c.outputs);
  const ride::TrackUnderWheels track(c.system, geometry, ride::cross_level_directions(c.system, 0.0, 0.0));
  const double step = geometry.step / speed / static_cast<double>(steps_a_sample);
  const long count = steps_a_sample * geometry.vertical_level.size();
  const auto modal = ride::ModalRideMarch::make(model, track, rows, speed, step, track.span());
  ASSERT_TRUE(modal);
  for (bool periodic : {true, false}) {
    ride::ModalRideMarch::State start = modal->rest();
    if (periodic) {
      ASSERT_TRUE(modal->periodic_start(count, &start));
    }
    const Eigen::MatrixXd y = modal_outputs(modal.get(), start, count);
    EXPECT_LT(worst_relative(dense_outputs(model, track, rows, speed, step, count, periodic), y), tolerance)
        << "periodic " << periodic << ", eigenvector condition " << modal->condition();
  }
}

TEST(ModalRideMarch, GivesTheDenseMarchsHistoriesOnTheVerticalCoach) {
  Case c;
  c.system = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
  c.outputs = default_ride_outputs(c.system);
  for (RideOutput o : default_ride_outputs(c.system)) {  // and the other quantities
    o.quantity = ResponseQuantity::displacement;
    c.outputs.push_back(o);
  }
  // 6 DOFs; two axleboxes an axle, summed into one input. Round-off of two different sets of
  // exponentials over 6000 steps, amplified by at most the condition of the eigenvectors
  // (kModalConditionLimit): 1e-10 of the largest value.
  expect_same_histories(c, ore_track(500.0, 0.25, false), 37.0, 1e-10);
}

TEST(ModalRideMarch, OneStepASampleGivesTheDenseMarchsHistories) {
  // One step a sample: the march reads the track along straight runs of samples (the inputs'
  // fractions fixed), falling back to the step-by-step read at the period's wrap and the
  // record's ends. The axles at 17.5 m: at 0.25 m a sample the wheels are on samples; at
  // 0.3 m they are not (the fraction and the slope of a segment). Tolerance as above.
  // The front bogie's acceleration too: its primary dampers feed the track's velocity (the
  // slope read) straight into it.
  Case c;
  c.system = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
  c.outputs = default_ride_outputs(c.system);
  RideOutput bogie;
  bogie.name = "front bogie";
  bogie.body = "bogie1";
  c.outputs.push_back(bogie);
  expect_same_histories(c, ore_track(500.0, 0.25, false), 37.0, 1e-10, 1);
  expect_same_histories(c, ore_track(501.0, 0.3, false), 37.0, 1e-10, 1);
}

TEST(ModalRideMarch, BlocksOfStepsChangeNoBit) {
  // The march goes in blocks of steps; a history cut at another step (so its last block is
  // partial elsewhere) is the same doubles as the first rows of a longer one.
  Case c;
  c.system = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
  c.outputs = default_ride_outputs(c.system);
  const TrackGeometry geometry = ore_track(500.0, 0.25, false);
  const ride::RideStateSpace model = ride::ride_state_space(c.system);
  const std::vector<ride::OutputRow> rows = ride::output_rows(c.system, model, c.outputs);
  const ride::TrackUnderWheels track(c.system, geometry, ride::cross_level_directions(c.system, 0.0, 0.0));
  for (long steps_a_sample : {1L, 3L}) {
    const double step = geometry.step / 37.0 / static_cast<double>(steps_a_sample);
    const auto modal = ride::ModalRideMarch::make(model, track, rows, 37.0, step, track.span());
    ASSERT_TRUE(modal);
    ride::ModalRideMarch::State start = modal->rest();
    ASSERT_TRUE(modal->periodic_start(steps_a_sample * geometry.vertical_level.size(), &start));
    const Eigen::MatrixXd longer = modal_outputs(modal.get(), start, 1000);
    for (long count : {1L, 255L, 257L, 700L})
      EXPECT_EQ(modal_outputs(modal.get(), start, count), longer.topRows(count)) << count << " steps, m = " << steps_a_sample;
  }
}

TEST(ModalRideMarch, GivesTheDenseMarchsHistoriesWithAllThreeProfiles) {
  // The coach with its wheelsets, lateral and vertical: the alignment and the cross-level's
  // roll reach the inputs through direction(i, p), summed over the axle's two wheels.
  Case c;
  c.system = assemble(load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::vertical);
  c.outputs = default_ride_outputs(c.system);
  expect_same_histories(c, ore_track(400.0, 0.25, true), 41.0, 1e-10);
}

TEST(ModalRideMarch, RepeatedRootsWithIndependentEigenvectorsMarchModally) {
  // Two identical masses on their own wheels, uncoupled: every root of A is double, with two
  // eigenvectors, so the eigenvector matrix is well conditioned and the modal path is taken.
  LinearSystem s = bouncing_mass(1e4, 4e5, 8e3, {3.1, -3.1});
  s.mass = Eigen::Matrix2d::Identity() * 1e4;
  s.stiffness = Eigen::Matrix2d::Identity() * 4e5;
  s.damping = Eigen::Matrix2d::Identity() * 8e3;
  s.gravity_stiffness = Eigen::Matrix2d::Zero();
  s.dofs.push_back({"other.bounce", 0, Motion::bounce});
  s.track_inputs[1].load_per_displacement = Eigen::MatrixXd::Zero(2, 3);
  s.track_inputs[1].load_per_velocity = Eigen::MatrixXd::Zero(2, 3);
  s.track_inputs[1].load_per_displacement(1, 2) = 4e5;
  s.track_inputs[1].load_per_velocity(1, 2) = 8e3;
  s.track_inputs[0].load_per_displacement.conservativeResize(2, 3);
  s.track_inputs[0].load_per_velocity.conservativeResize(2, 3);
  s.track_inputs[0].load_per_displacement.row(1).setZero();
  s.track_inputs[0].load_per_velocity.row(1).setZero();
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(ride::ride_state_space(s).A);
  ASSERT_NEAR(std::abs(eigen.eigenvalues()(0) - eigen.eigenvalues()(2)) + std::abs(eigen.eigenvalues()(1) - eigen.eigenvalues()(3)),
              0.0, 1e-12 * std::abs(eigen.eigenvalues()(0)))
      << eigen.eigenvalues().transpose();  // the roots are double (in Eigen's order: pair, pair)
  RideOutput a;
  a.name = "body";
  a.body = "body";
  a.quantity = ResponseQuantity::acceleration;
  Case c{s, {a}};
  expect_same_histories(c, ore_track(300.0, 0.25, false), 29.0, 1e-10);
}

TEST(ModalRideMarch, DefectiveSystemTakesTheDenseMarchWithTheSameAnswer) {
  // A critically damped mass: c² = 4km, A = [[0, 1], [−ω², −2ω]] has the double root −ω with
  // one eigenvector (a Jordan block), so no modal coordinates: make() refuses and
  // simulate_ride marches densely, which still gives the right history.
  constexpr double kMass = 1e4, kStiffness = 4e5;  // per wheel, two wheels
  const double critical = std::sqrt(4.0 * 2.0 * kStiffness * kMass) / 2.0;
  const LinearSystem s = bouncing_mass(kMass, kStiffness, critical, {4.3, -4.3});
  RideOutput a;
  a.name = "body";
  a.body = "body";
  a.quantity = ResponseQuantity::displacement;
  const TrackGeometry geometry = ore_track(300.0, 0.25, false);
  const ride::RideStateSpace model = ride::ride_state_space(s);
  const std::vector<ride::OutputRow> rows = ride::output_rows(s, model, {a});
  const ride::TrackUnderWheels track(s, geometry, ride::cross_level_directions(s, 0.0, 0.0));
  EXPECT_FALSE(ride::ModalRideMarch::make(model, track, rows, 30.0, 0.25 / 30.0, track.span()));

  // A hair under critical damping (1 − 1e-14: roots split by √(2e-14)ω ≈ 1.4e-7ω, the two
  // eigenvectors as close, κ ≈ 1e7): still refused, so no answer rides on that basis.
  const LinearSystem near = bouncing_mass(kMass, kStiffness, critical * (1.0 - 1e-14), {4.3, -4.3});
  const ride::RideStateSpace near_model = ride::ride_state_space(near);
  EXPECT_FALSE(ride::ModalRideMarch::make(near_model, track, ride::output_rows(near, near_model, {a}), 30.0,
                                          0.25 / 30.0, track.span()));
  // 1e-6 under critical (split 1.4e-3ω, κ ≈ 1e3): modal, and the dense march's histories.
  expect_same_histories({bouncing_mass(kMass, kStiffness, critical * (1.0 - 1e-6), {4.3, -4.3}), {a}}, geometry,
                        30.0, 1e-10);

  // simulate_ride on the defective system is the dense march's answer, bit for bit.
  RideSimulationOptions o;
  o.speed = 30.0;
  o.time_step = 0.25 / 30.0;
  const RideSimulationResult r = simulate_ride(s, geometry, {a}, o);
  const Eigen::MatrixXd dense =
      dense_outputs(model, track, rows, o.speed, o.time_step, r.time.size(), /*periodic=*/true);
  EXPECT_EQ(r.histories[0].values, dense.col(0));
}

TEST(ModalRideMarch, WellDampedVehicleTakesTheModalPath) {
  // The coach's eigenvectors are far inside the bound (so simulate_ride marches modally).
  const LinearSystem s = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
  const ride::RideStateSpace model = ride::ride_state_space(s);
  const TrackGeometry geometry = ore_track(150.0, 0.25, false);
  const ride::TrackUnderWheels track(s, geometry, ride::cross_level_directions(s, 0.0, 0.0));
  const auto modal = ride::ModalRideMarch::make(model, track, ride::output_rows(s, model, default_ride_outputs(s)),
                                                30.0, 0.25 / 30.0, track.span());
  ASSERT_TRUE(modal);
  // balanced, its modes are nearly orthogonal: κ measured 3.3 (without the balancing the
  // benchmark's histories differed from the dense march's by 1e-12 of their largest value,
  // with it by 1.3e-13)
  EXPECT_LT(modal->condition(), 10.0);
}

}  // namespace
}  // namespace railmodal::test::modal_march_test
