// Every analysis result carries an AnalysisSummary: what was computed, by which method, the
// checks made, and the wall time of its stages, which never add up to more than the call.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// Runs `call` and returns what it returns; *wall receives its wall time, s.
template <class Call>
auto timed(const Call& call, double* wall) {
  const auto start = std::chrono::steady_clock::now();
  auto result = call();
  *wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void expect_filled(const AnalysisSummary& s, double wall) {
  EXPECT_FALSE(s.analysis.empty());
  EXPECT_FALSE(s.method.empty());
  EXPECT_FALSE(s.checks.empty());
  for (const Check& c : s.checks) {
    EXPECT_FALSE(c.name.empty());
    EXPECT_TRUE(std::isfinite(c.value)) << c.name;
  }
  EXPECT_TRUE(s.passed()) << s.brief();
  ASSERT_FALSE(s.stages.empty());
  for (const StageTiming& t : s.stages) {
    EXPECT_FALSE(t.stage.empty());
    EXPECT_GE(t.seconds, 0.0) << t.stage;
  }
  EXPECT_LE(s.total_seconds(), wall);
  const std::string brief = s.brief();
  EXPECT_NE(brief.find(s.analysis), std::string::npos) << brief;
  EXPECT_NE(brief.find(s.method), std::string::npos) << brief;
  EXPECT_NE(brief.find(s.stages.front().stage), std::string::npos) << brief;
}

bool has_check(const AnalysisSummary& s, const std::string& name) {
  for (const Check& c : s.checks)
    if (c.name.find(name) != std::string::npos) return true;
  return false;
}

TEST(AnalysisSummary, BriefCountsChecksAndTotalsStages) {
  AnalysisSummary s;
  s.analysis = "test";
  s.method = "by hand";
  s.checks = {{"a", 1.0, 2.0, true}, {"b", 3.0, 2.0, false}};
  s.stages = {{"first", 0.25}, {"second", 0.5}};
  EXPECT_DOUBLE_EQ(s.total_seconds(), 0.75);
  EXPECT_FALSE(s.passed());
  EXPECT_EQ(s.brief(), "test by by hand: 1 of 2 checks passed; 0.75 s (first 0.25 s, second 0.5 s)");
}

TEST(AnalysisSummary, DenseModes) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::all);
  double wall = 0.0;
  const ModalResult r = timed([&] { return solve_modes(sys); }, &wall);
  expect_filled(r.solver, wall);
  EXPECT_NE(r.solver.method.find("dense"), std::string::npos);
  EXPECT_TRUE(has_check(r.solver, "residual"));
  EXPECT_TRUE(has_check(r.solver, "orthonormality"));
  ASSERT_EQ(r.solver.stages.size(), 2u);
  EXPECT_EQ(r.solver.stages[0].stage, "eigensolve");
}

TEST(AnalysisSummary, ArpackModesOfASparseTrain) {
  const SparseSystem train = wagon_train(200);
  ModalOptions o;
  o.solver = ModalSolver::arpack;
  o.mode_count = 6;
  double wall = 0.0;
  const ModalResult r = timed([&] { return solve_modes(train, o); }, &wall);
  expect_filled(r.solver, wall);
  EXPECT_NE(r.solver.method.find("ARPACK"), std::string::npos);
  EXPECT_EQ(has_check(r.solver, "inertia"), r.solver.count_checked);
}

TEST(AnalysisSummary, SparseModelOnTheDenseSolverTimesItsCopy) {
  const SparseSystem train = wagon_train(3);
  ModalOptions o;
  o.solver = ModalSolver::dense;
  double wall = 0.0;
  const ModalResult r = timed([&] { return solve_modes(train, o); }, &wall);
  expect_filled(r.solver, wall);
  ASSERT_EQ(r.solver.stages.size(), 3u);
  EXPECT_EQ(r.solver.stages[0].stage, "densify");
}

TEST(AnalysisSummary, DampedModes) {
  const LinearSystem sys = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::all);
  double wall = 0.0;
  const DampedModalResult r = timed([&] { return solve_damped_modes(sys); }, &wall);
  expect_filled(r.summary, wall);
  EXPECT_TRUE(has_check(r.summary, "residual"));
  EXPECT_LE(r.undamped.solver.total_seconds(), r.summary.stages.front().seconds);
}

struct SceneFixture {
  Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/two_axle_freight_wagon_10m_rails.toml");
  Vehicle vehicle = load_vehicle(scene.vehicle_file);
  LinearSystem system = assemble(vehicle, scene.dofs);
  ModalResult modes = solve_modes(system);
  std::vector<const ExcitationSource*> sources() const {
    std::vector<const ExcitationSource*> out;
    for (const auto& s : scene.sources) out.push_back(s.get());
    return out;
  }
};

TEST(AnalysisSummary, CriticalSpeeds) {
  const SceneFixture f;
  CriticalSpeedOptions o;
  o.min_speed = f.scene.min_speed;
  o.max_speed = f.scene.max_speed;
  AnalysisSummary s;
  double wall = 0.0;
  const auto found = timed([&] { return find_critical_speeds(f.system, f.modes, f.sources(), o, &s); }, &wall);
  expect_filled(s, wall);
  ASSERT_FALSE(s.checks.empty());
  EXPECT_EQ(s.checks[0].value, static_cast<double>(found.size()));
}

TEST(AnalysisSummary, CriticalSpeedStudy) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/resort_car_wheel_defects.toml");
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  double wall = 0.0;
  const CriticalSpeedStudy study = timed([&] { return study_critical_speeds(scene, vehicle); }, &wall);
  expect_filled(study.summary, wall);
  EXPECT_TRUE(has_check(study.summary, "residual"));
  ASSERT_EQ(study.summary.stages.size(), 4u);  // assembly and modes, critical speeds, curves, peaks
  EXPECT_EQ(study.summary.stages[2].stage, "amplitude curves");
  EXPECT_EQ(study.summary.stages[3].stage, "peak refinement");
}

TEST(AnalysisSummary, AmplitudeAndDeflectionCurvesAndPeaks) {
  const SceneFixture f;
  const ExcitationSource& source = *f.scene.sources.front();
  std::vector<double> speeds;
  for (double v = f.scene.min_speed; v <= f.scene.max_speed; v += 1.0) speeds.push_back(v);
  const std::vector<OutputRequest> outputs = {{0, ResponseQuantity::displacement, true}};
  AnalysisSummary s;
  double wall = 0.0;
  timed([&] { return amplitude_curves(f.system, f.modes, source, 0, outputs, speeds, 0.0, &s); }, &wall);
  expect_filled(s, wall);
  EXPECT_TRUE(has_check(s, "unbounded"));

  timed([&] { return element_deflection_curves(f.system, f.modes, source, 0, {0}, speeds, {}, &s); }, &wall);
  expect_filled(s, wall);

  timed([&] { return refine_peak(f.system, f.modes, source, outputs[0], speeds[1], speeds[3], 1e-4, 0.0, &s); },
        &wall);
  expect_filled(s, wall);
  EXPECT_TRUE(has_check(s, "evaluations"));
}

TEST(AnalysisSummary, LinearSimulationAndFftCheck) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/resort_car_free_response.toml");
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  double wall = 0.0;
  const TimeHistory h = timed([&] { return simulate_scene(scene, vehicle); }, &wall);
  expect_filled(h.summary, wall);
  EXPECT_NE(h.summary.analysis.find("linear"), std::string::npos);
  EXPECT_TRUE(has_check(h.summary, "not finite"));

  const FftCheckResult r = timed([&] { return fft_check(scene, vehicle); }, &wall);
  expect_filled(r.summary, wall);
  EXPECT_TRUE(has_check(r.summary, "within its resolution"));
  EXPECT_LE(r.history.summary.total_seconds(), r.summary.stages.front().seconds);
  ASSERT_FALSE(r.spectra.empty());
  expect_filled(r.spectra.front().summary, wall);
}

TEST(AnalysisSummary, NonlinearSimulation) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/leaf_spring_drop_test.toml");
  const Vehicle vehicle = load_vehicle(scene.vehicle_file);
  double wall = 0.0;
  const TimeHistory h = timed([&] { return simulate_scene(scene, vehicle); }, &wall);
  expect_filled(h.summary, wall);
  EXPECT_NE(h.summary.analysis.find("nonlinear"), std::string::npos);
  EXPECT_TRUE(has_check(h.summary, "integrator steps"));
}

TEST(AnalysisSummary, SpectrumReusedWithoutGrowing) {
  Eigen::VectorXd x(1000);
  for (Eigen::Index n = 0; n < x.size(); ++n) x(n) = std::sin(0.1 * static_cast<double>(n));
  SpectrumAnalyzer analyzer(x.size());
  Spectrum s;
  double wall = 0.0;
  for (int run = 0; run < 2; ++run) {
    timed([&] { return analyzer.compute(x, 100.0, &s), 0; }, &wall);
    expect_filled(s.summary, wall);
    EXPECT_EQ(s.summary.stages.size(), 3u);
    EXPECT_EQ(s.summary.checks.size(), 1u);
  }
}

TEST(AnalysisSummary, SpectralPeaks) {
  Eigen::VectorXd x(1000);
  for (Eigen::Index n = 0; n < x.size(); ++n) x(n) = std::sin(0.3 * static_cast<double>(n));
  const Spectrum spectrum = amplitude_spectrum(x, 100.0);
  AnalysisSummary s;
  double wall = 0.0;
  const auto peaks = timed([&] { return find_peaks(spectrum, {}, &s); }, &wall);
  expect_filled(s, wall);
  ASSERT_EQ(s.checks.size(), 2u);
  EXPECT_EQ(s.checks[1].value, static_cast<double>(peaks.size()));
}

TEST(AnalysisSummary, LateralStability) {
  double wall = 0.0;
  const LateralStability s =
      timed([&] { return lateral_stability(load_vehicle(data_file("resort_car.toml")), "body"); }, &wall);
  expect_filled(s.summary, wall);
  ASSERT_EQ(s.summary.checks.size(), 1u);
  EXPECT_DOUBLE_EQ(s.summary.checks[0].value, -s.margin);
}

TEST(AnalysisSummary, StudyVariantsAndShard) {
  StudyVariant variant;
  variant.name = "base";
  variant.scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/two_axle_freight_wagon_10m_rails.toml");
  variant.vehicle = load_vehicle(variant.scene.vehicle_file);
  Study study;
  study.variants = {variant, variant};
  EvaluationOptions o;
  o.threads = 2;
  AnalysisSummary s;
  double wall = 0.0;
  const auto results = timed([&] { return evaluate_study(study, o, &s); }, &wall);
  expect_filled(s, wall);
  // The method says what runs: the workers' own workspaces, not evaluate_variant.
  EXPECT_EQ(s.method, "variants evaluated on 2 thread(s), each in its thread's workspace (the base's assembly kept "
                      "between variants), one result slot per variant");
  ASSERT_EQ(results.size(), 2u);
  for (const VariantResult& r : results) {
    EXPECT_TRUE(r.ok()) << r.failure;
    expect_filled(r.summary, wall);
    EXPECT_TRUE(has_check(r.summary, "critical speeds"));
  }
}

TEST(AnalysisSummary, Ranking) {
  const Study study = load_study(std::string(RAILMODAL_DATA_DIR) + "/studies/two_axle_rail_length_and_springs.toml");
  std::vector<VariantResult> results = evaluate_study(study, {});
  double wall = 0.0;
  const Comparison c = timed([&] { return rank_variants(study, std::move(results)); }, &wall);
  expect_filled(c.summary, wall);
  ASSERT_EQ(c.summary.checks.size(), 2u);
  size_t feasible = 0;
  for (const RankedVariant& v : c.variants) feasible += v.result.ok() && v.feasible;
  EXPECT_EQ(c.summary.checks[0].value, static_cast<double>(feasible));  // "variants feasible"
  EXPECT_EQ(c.summary.checks[1].value, 0.0);                            // none failed
}

}  // namespace
}  // namespace railmodal::test
