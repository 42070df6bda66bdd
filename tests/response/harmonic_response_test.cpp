// Harmonic response: closed forms, direct against modal superposition, undamped resonance.
#include <cmath>

#include "railmodal/matrix_market.hpp"
#include "response/modal_checks.hpp"
#include "response/state_space_modes.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// m = 1000 kg on k = 1 MN/m with a damper c: X = Q/(k − mω² + icω) (SDOF receptance).
TEST(HarmonicResponse, SingleDofReceptance) {
  const std::string file = write_temp("sdof.toml", R"toml(
[vehicle]
name = "sdof"
[[body]]
name = "m"
mass = "1000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
upper = "m"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
vertical_damping = "2 kN*s/m"
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  Eigen::VectorXcd Q(1);
  Q(0) = 1.0;
  for (double f : {0.5, 5.0, 5.0329, 20.0}) {
    const double w = 2 * kPi * f;
    const std::complex<double> expected = 1.0 / std::complex<double>(1e6 - 1000 * w * w, 2000 * w);
    const auto r = harmonic_response(sys, modes, Q, f);
    EXPECT_FALSE(r.unbounded);
    EXPECT_NEAR(std::abs(r.displacement(0) - expected), 0.0, 1e-12 * std::abs(expected)) << f;
  }
}

// Base excitation of a damped SDOF through spring and damper: |X/U| = |k + icω|/|k − mω² + icω|
// peaks at r² = (√(1 + 8ζ²) − 1)/(4ζ²), r = ω/ωn. Under whole-rail joint dips (one harmonic,
// f = V/L) the peak speed is V = r·ωn·L/2π. Golden section to 1e-10 puts it within 1e-8.
TEST(PeakSearch, DampedBaseExcitationPeak) {
  const std::string file = write_temp("sdof_base.toml", R"toml(
[vehicle]
name = "sdof on the track"
[[body]]
name = "m"
mass = "1000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
upper = "m"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
vertical_damping = "12 kN*s/m"
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.01;
  const auto source = make_source(j);
  const double wn = std::sqrt(1e6 / 1000.0), zeta = 12e3 / (2 * std::sqrt(1e6 * 1000.0));
  const double r = std::sqrt((std::sqrt(1 + 8 * zeta * zeta) - 1) / (4 * zeta * zeta));
  const double expected = r * wn * 10.0 / (2 * kPi);
  const Peak p = refine_peak(sys, modes, *source, {0, ResponseQuantity::displacement}, 0.5 * expected,
                             1.5 * expected, 1e-10);
  EXPECT_FALSE(p.unbounded);
  EXPECT_NEAR(p.speed / expected, 1.0, 1e-8);
  const double w = r * wn;
  const double transmissibility = std::abs(std::complex<double>(1e6, 12e3 * w) / std::complex<double>(1e6 - 1000 * w * w, 12e3 * w));
  EXPECT_NEAR(p.amplitude / (0.005 * transmissibility), 1.0, 1e-12);
  EXPECT_LT(p.evaluations, 60);
}

// The phase of the curve is the FRF's: for base excitation of the damped SDOF through spring
// and damper, arg((k + icω)/(k − mω² + icω)); acceleration adds 180°. To 1e-9 degrees.
TEST(AmplitudeCurves, PhaseIsTheTransmissibilityPhase) {
  const std::string file = write_temp("sdof_phase.toml", R"toml(
[vehicle]
name = "sdof on the track"
[[body]]
name = "m"
mass = "1000 kg"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
upper = "m"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
vertical_damping = "12 kN*s/m"
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.01;
  const auto source = make_source(j);
  const std::vector<double> speeds = {20.0, 50.0, 80.0};
  const auto curves = amplitude_curves(sys, modes, *source, 0,
                                       {{0, ResponseQuantity::displacement}, {0, ResponseQuantity::acceleration}}, speeds);
  for (size_t v = 0; v < speeds.size(); ++v) {
    const double w = 2 * kPi * speeds[v] / 10.0;
    const double expected =
        std::arg(std::complex<double>(1e6, 12e3 * w) / std::complex<double>(1e6 - 1000 * w * w, 12e3 * w)) * 180 / kPi;
    EXPECT_NEAR(curves[0].phases_deg[v], expected, 1e-9);
    double acc = expected + 180.0;
    if (acc > 180.0) acc -= 360.0;
    EXPECT_NEAR(curves[1].phases_deg[v], acc, 1e-9);
  }
  // Without its phase an output keeps the same amplitudes, bit for bit, and no phases.
  OutputRequest amplitude_only{0, ResponseQuantity::acceleration};
  amplitude_only.phase = false;
  const auto without = amplitude_curves(sys, modes, *source, 0, {amplitude_only}, speeds);
  EXPECT_TRUE(without[0].phases_deg.empty());
  EXPECT_EQ(without[0].amplitudes, curves[1].amplitudes);
}

// With C = 0 or proportional damping the modes decouple exactly: superposition over all modes
// equals the direct solve to round-off (1e-10 relative covers the conditioning of K − ω²M near
// the frequencies used). Every bundled wagon, all DOFs, joint input at three speeds.
TEST(HarmonicResponse, ModalSuperpositionEqualsDirectSolve) {
  for (const char* name : {"two_axle_freight_wagon.toml", "resort_car.toml", "fette_car.toml",
                           "manchester_benchmark_coach.toml"}) {
    LinearSystem sys = assemble(load_vehicle(data_file(name)), DofSet::all);
    sys.damping = 0.002 * sys.stiffness + 0.1 * sys.mass;  // Rayleigh: proportional
    const ModalResult modes = solve_modes(sys);
    RailJoints j;
    j.rail_length = 12.5;
    j.dip_depth = 0.005;
    j.staggered = true;
    const auto source = make_source(j);
    for (double V : {10.0, 25.0, 40.0}) {
      const HarmonicLoad load = source->load(sys, V, 1);
      const Eigen::VectorXcd Q = generalized_load(sys, load);
      const auto direct = harmonic_response(sys, modes, Q, load.frequency_hz);
      const auto modal = modal_harmonic_response(sys, modes, Q, load.frequency_hz);
      EXPECT_LT((direct.displacement - modal.displacement).norm(), 1e-10 * direct.displacement.norm())
          << name << " at " << V << " m/s";
    }
  }
}

// A body whose roll has no inertia (condensed statically) loaded in roll by staggered joints:
// modal superposition with the static response of the massless DOF equals the direct solve
// (C = 0: exact, to 1e-10 for the conditioning near the modes), and so does the fast sweep.
TEST(HarmonicResponse, MasslessDofLoadedDirectly) {
  const std::string file = write_temp("massless_roll.toml", R"toml(
[vehicle]
name = "body with a massless roll"
[[body]]
name = "b"
mass = "20 t"
inertia = { roll = "0 kg*m^2", pitch = "1e5 kg*m^2", yaw = "1e5 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "yaw"]
[[element]]
name = "front left"
upper = "b"
point = ["2 m", "0.8 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
[[element]]
name = "front right"
upper = "b"
point = ["2 m", "-0.8 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
[[element]]
name = "rear left"
upper = "b"
point = ["-2 m", "0.8 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
[[element]]
name = "rear right"
upper = "b"
point = ["-2 m", "-0.8 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  ASSERT_EQ(modes.condensed.size(), 1u);  // b.roll
  RailJoints j;
  j.rail_length = 12.5;
  j.dip_depth = 0.005;
  j.staggered = true;
  j.harmonics = 3;
  const auto source = make_source(j);
  std::vector<OutputRequest> outputs;
  for (int d = 0; d < sys.size(); ++d) outputs.push_back({d, ResponseQuantity::displacement});
  const std::vector<double> speeds = {3.0, 7.0, 11.0, 23.0};
  const auto curves = amplitude_curves(sys, modes, *source, 0, outputs, speeds);
  const int roll = sys.index_of("b.roll");
  ASSERT_GE(roll, 0);
  for (size_t v = 0; v < speeds.size(); ++v) {
    std::vector<double> direct_sum(sys.size(), 0.0);
    for (int k = 1; k <= 3; ++k) {
      const HarmonicLoad load = source->load(sys, speeds[v], k);
      const Eigen::VectorXcd Q = generalized_load(sys, load);
      const auto direct = harmonic_response(sys, modes, Q, load.frequency_hz);
      const auto modal = modal_harmonic_response(sys, modes, Q, load.frequency_hz);
      EXPECT_LT((direct.displacement - modal.displacement).norm(), 1e-10 * direct.displacement.norm());
      for (int d = 0; d < sys.size(); ++d) direct_sum[d] += std::abs(direct.displacement(d));
    }
    for (int d = 0; d < sys.size(); ++d)
      EXPECT_NEAR(curves[d].amplitudes[v], direct_sum[d], 1e-10 * (direct_sum[roll] + direct_sum[d])) << sys.dofs[d].label;
  }
}

// 12.5 m rails, staggered joints with 5 mm dips 1 m long, 4 harmonics: the sweep tests' joints.
RailJoints staggered_joints() {
  RailJoints j;
  j.rail_length = 12.5;
  j.dip_depth = 0.005;
  j.staggered = true;
  j.dip_length = 1.0;
  j.harmonics = 4;
  return j;
}

// What a sweep must give at one speed: each DOF's amplitudes summed over the source's
// harmonics, each harmonic by a direct solve.
std::vector<double> direct_amplitudes(const LinearSystem& sys, const ModalResult& modes, const ExcitationSource& source,
                                      double speed, ResponseQuantity quantity) {
  std::vector<double> direct(sys.size(), 0.0);
  for (int k = 1; k <= source.harmonic_count(); ++k) {
    const HarmonicLoad load = source.load(sys, speed, k);
    const auto r = harmonic_response(sys, modes, generalized_load(sys, load), load.frequency_hz);
    for (int d = 0; d < sys.size(); ++d) direct[d] += response_amplitude(r, d, quantity);
  }
  return direct;
}

// The fast sweep (modal projection once, exact for C = 0) against direct solves at every
// speed and harmonic on the resort car, all DOFs, three kinds of source; 1e-10 relative.
TEST(AmplitudeCurves, FastSweepEqualsDirectSolves) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  const RailJoints j = staggered_joints();
  WheelEccentricity e;
  e.wheel_diameter = 1.05;
  e.eccentricity = 0.0015;
  e.phases = {0.0, 1.0, 2.0, 3.0};
  WheelFlat f;
  f.wheel_diameter = 1.05;
  f.depth = 0.001;
  f.length = 0.1;
  f.harmonics = 5;
  std::vector<OutputRequest> outputs;
  for (int d = 0; d < sys.size(); ++d) outputs.push_back({d, ResponseQuantity::acceleration});
  const std::vector<double> speeds = {2.0, 9.5, 17.0, 33.0, 48.0};
  for (const auto& source : {make_source(j), make_source(e), make_source(f)}) {
    const auto curves = amplitude_curves(sys, modes, *source, 0, outputs, speeds);
    for (size_t v = 0; v < speeds.size(); ++v) {
      const std::vector<double> direct = direct_amplitudes(sys, modes, *source, speeds[v], ResponseQuantity::acceleration);
      const double scale = *std::max_element(direct.begin(), direct.end());
      for (int d = 0; d < sys.size(); ++d)
        EXPECT_NEAR(curves[d].amplitudes[v], direct[d], 1e-10 * scale) << source->kind() << " " << sys.dofs[d].label;
    }
  }
}

// Staggered joints load the bogies' two sides in antiphase at odd harmonics: harmonic 1 does
// not reach the body's bounce at all (the direct solve gives 1e-55 m). Its modal loads on the
// bounce modes are eigensolver noise, and summed they made a response of up to 9.3e-19 m
// with an arbitrary, steady phase (123.8°). The curve must say 0 for both.
TEST(AmplitudeCurves, NoPhaseWhereTheLoadDoesNotReachTheOutput) {
  const LinearSystem sys = assemble(load_vehicle(data_file("resort_car.toml")), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 12.5;
  j.staggered = true;
  j.dip_depth = 0.005;
  j.dip_length = 1.0;
  const auto source = make_source(j);
  const int bounce = sys.index_of("body.bounce");
  const std::vector<double> speeds = {5.0, 12.0, 20.0, 33.0, 47.0, 60.0};
  const auto curves = amplitude_curves(sys, modes, *source, 0, {{bounce, ResponseQuantity::displacement}}, speeds);
  for (size_t v = 0; v < speeds.size(); ++v) {
    const HarmonicLoad load = source->load(sys, speeds[v], 1);
    const HarmonicResponse direct = harmonic_response(sys, modes, generalized_load(sys, load), load.frequency_hz);
    // The direct solve's round-off: 1e-15 of the largest DOF's response.
    ASSERT_LE(std::abs(direct.displacement(bounce)), 1e-15 * direct.displacement.cwiseAbs().maxCoeff());
    EXPECT_EQ(curves[0].amplitudes[v], 0.0) << speeds[v];
    EXPECT_EQ(curves[0].phases_deg[v], 0.0) << speeds[v];
  }
}

// The sweep skips what a mode shape has at the eigensolver's round-off at an output (below
// 1e-12 of its largest component, speed_sweep.cpp) and must keep every real coupling, however
// weak. A rear spring 1e-7 stiffer than the front couples bounce and pitch weakly; 1e-8 off the
// pitch resonance in ω the body's bounce is mostly the pitch mode's share, so a sweep that
// dropped it would be wrong by orders of magnitude. Tolerance 1e-7: at 1e-8 off resonance the
// direct solve's matrix has a condition number ~1/(2·1e-8), so each side carries ~1e-8 of
// round-off (measured 2.3e-8).
TEST(AmplitudeCurves, WeakCouplingsKeptNearResonance) {
  const std::string file = write_temp("weak_coupling.toml", R"toml(
[vehicle]
name = "bounce and pitch weakly coupled"
[[body]]
name = "b"
mass = "20 t"
inertia = { roll = "1e5 kg*m^2", pitch = "2e5 kg*m^2", yaw = "1e5 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "yaw"]
[[element]]
name = "front"
upper = "b"
point = ["3 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
[[element]]
name = "rear"
upper = "b"
point = ["-3 m", "0 m", "0 m"]
vertical = { stiffness = "1.0000001 MN/m" }
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  const int bounce = sys.index_of("b.bounce");
  const Mode& pitch = modes.modes.front();  // 9.5 rad/s, below the bounce's 10 rad/s
  ASSERT_EQ(pitch.name, "b pitch");
  const double share = std::abs(pitch.shape(bounce)) / pitch.shape.cwiseAbs().maxCoeff();
  ASSERT_GT(share, 1e-9);  // real, far above round-off
  ASSERT_LT(share, 1e-5);  // and weak
  RailJoints j;
  j.rail_length = 12.5;
  j.dip_depth = 0.005;
  j.harmonics = 1;
  const auto source = make_source(j);
  const double speed = source->speed_for(std::sqrt(pitch.eigenvalue) * (1.0 + 1e-8) / (2.0 * M_PI), 1);
  const auto curves = amplitude_curves(sys, modes, *source, 0, {{bounce, ResponseQuantity::displacement}}, {speed});
  const std::vector<double> direct = direct_amplitudes(sys, modes, *source, speed, ResponseQuantity::displacement);
  ASSERT_FALSE(curves[0].unbounded[0]);
  EXPECT_NEAR(curves[0].amplitudes[0], direct[bounce], 1e-7 * direct[bounce]);
  // Without the pitch term the bounce would be its static-like share alone: orders smaller.
  const HarmonicLoad load = source->load(sys, speed, 1);
  const auto far = harmonic_response(sys, modes, generalized_load(sys, load), load.frequency_hz * 0.5);
  EXPECT_GT(direct[bounce], 100.0 * std::abs(far.displacement(bounce)));
}

// Discrete dampers (non-proportional C): the sweep takes the complex modes of the first-order
// form. The Manchester coach (15 DOFs, dampers everywhere), all DOFs as outputs, against a
// direct solve at every speed and harmonic: 1e-10 of the largest, as the proportional path.
// A DOF that a source does not move stays exactly 0 (the lateral hunting wave on the bounce:
// the direct solve's structural zero, not the eigenvectors' round-off).
TEST(AmplitudeCurves, DiscreteDampersSweepEqualsDirectSolves) {
  const LinearSystem sys = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::all);
  const ModalResult modes = solve_modes(sys);
  ASSERT_TRUE(response::state_space_modes(sys));  // the path under test is taken
  const RailJoints j = staggered_joints();
  Hunting h;
  h.conicity = 0.05;
  h.rolling_circle_spacing = 1.5;
  h.rolling_radius = 0.46;
  h.amplitude = 0.005;
  std::vector<OutputRequest> outputs;
  for (int d = 0; d < sys.size(); ++d) outputs.push_back({d, ResponseQuantity::displacement});
  std::vector<double> speeds;
  for (double v = 2.0; v <= 60.0; v += 0.7) speeds.push_back(v);
  for (const auto& source : {make_source(j), make_source(h)}) {
    const auto curves = amplitude_curves(sys, modes, *source, 0, outputs, speeds);
    for (size_t v = 0; v < speeds.size(); ++v) {
      const std::vector<double> direct = direct_amplitudes(sys, modes, *source, speeds[v], ResponseQuantity::displacement);
      const double scale = *std::max_element(direct.begin(), direct.end());
      for (int d = 0; d < sys.size(); ++d) {
        EXPECT_FALSE(curves[d].unbounded[v]);
        if (direct[d] == 0.0) {
          EXPECT_EQ(curves[d].amplitudes[v], 0.0) << source->kind() << " " << sys.dofs[d].label;
        } else {
          EXPECT_NEAR(curves[d].amplitudes[v], direct[d], 1e-10 * scale) << source->kind() << " " << sys.dofs[d].label;
        }
      }
    }
  }
}

// The complex modes are refused where they cannot be trusted, and the sweep then solves each
// speed directly: an undamped mode (its resonance is unbounded), critical damping (a defective
// double root: no basis of eigenvectors), a massless DOF (no M⁻¹).
TEST(AmplitudeCurves, ComplexModesRefusedWhereUntrustworthy) {
  auto one_dof = [](double m, double k, double c) {
    MatrixModel model;
    model.labels = {"x"};
    model.mass = Eigen::MatrixXd::Constant(1, 1, m).sparseView();
    model.stiffness = Eigen::MatrixXd::Constant(1, 1, k).sparseView();
    model.damping = Eigen::MatrixXd::Constant(1, 1, c).sparseView();
    return to_linear_system(model);
  };
  EXPECT_TRUE(response::state_space_modes(one_dof(1.0, 1.0, 0.2)));     // ζ = 0.1
  EXPECT_FALSE(response::state_space_modes(one_dof(1.0, 1.0, 0.0)));    // undamped
  const auto pair = response::state_space_modes(one_dof(1.0, 1.0, 0.0), true);  // unless allowed
  ASSERT_TRUE(pair);
  EXPECT_TRUE(pair->undamped[0] && pair->undamped[1]);
  EXPECT_FALSE(response::state_space_modes(one_dof(1.0, 0.0, 1.0), true));  // rigid body, even so
  EXPECT_FALSE(response::state_space_modes(one_dof(1.0, 1.0, 2.0)));    // ζ = 1: defective
  EXPECT_FALSE(response::state_space_modes(one_dof(0.0, 1.0, 1.0)));    // massless
  EXPECT_FALSE(response::state_space_modes(one_dof(1.0, 0.0, 1.0)));    // rigid body: λ = 0
}

// A damped vehicle with an undamped mode (issue 19, item 4): the steam-locomotive frame, whose
// dampers leave one mode with Cφ = 0. The sweep takes the complex modes for the damped roots
// and the undamped mode's modal term in place of its pair on the imaginary axis, not a direct
// solve per speed. Against the direct solve at every speed and harmonic, all DOFs: 1e-10 of
// the largest (both are exact; round-off is ~1e-14 here), with speeds placed exactly at the
// undamped mode's resonance for each harmonic, where both must flag the same outputs
// unbounded (or, where the load does not drive the mode, give the same finite response).
TEST(AmplitudeCurves, DampedVehicleWithAnUndampedModeSweepsLikeTheDirectSolve) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/steam_locomotive_unbalance.toml");
  const LinearSystem sys = assemble(load_vehicle(scene.vehicle_file), scene.dofs);
  const ModalResult modes = solve_modes(sys);
  const Mode* undamped = nullptr;
  for (const Mode& m : modes.modes)
    if (m.kind == ModeKind::oscillatory && response::undamped(sys, m)) undamped = &m;
  ASSERT_NE(undamped, nullptr);                            // the case under test
  ASSERT_FALSE(response::state_space_modes(sys));          // the old rule refused it
  ASSERT_TRUE(response::state_space_modes(sys, true));     // the new one takes it
  const ExcitationSource& source = *scene.sources.front();
  std::vector<double> speeds;
  for (double v = 2.0; v <= 30.0; v += 0.37) speeds.push_back(v);
  const double f0 = std::sqrt(undamped->eigenvalue) / (2.0 * 3.14159265358979323846);
  for (int k = 1; k <= source.harmonic_count(); ++k) speeds.push_back(source.speed_for(f0, k));
  std::sort(speeds.begin(), speeds.end());
  std::vector<OutputRequest> outputs;
  for (int d = 0; d < sys.size(); ++d) outputs.push_back({d, ResponseQuantity::displacement});
  AnalysisSummary summary;
  const auto curves = amplitude_curves(sys, modes, source, 0, outputs, speeds, 0.0, &summary);
  EXPECT_NE(summary.method.find("undamped modes"), std::string::npos) << summary.method;
  int flagged = 0;
  for (size_t v = 0; v < speeds.size(); ++v) {
    std::vector<double> direct(sys.size(), 0.0);
    std::vector<bool> unbounded(sys.size(), false);
    for (int k = 1; k <= source.harmonic_count(); ++k) {
      const HarmonicLoad load = source.load(sys, speeds[v], k);
      const auto r = harmonic_response(sys, modes, generalized_load(sys, load), load.frequency_hz);
      for (int d = 0; d < sys.size(); ++d) {
        unbounded[d] = unbounded[d] || unbounded_at(r, modes, d);
        direct[d] += response_amplitude(r, d, ResponseQuantity::displacement);
      }
    }
    const double scale = *std::max_element(direct.begin(), direct.end());
    for (int d = 0; d < sys.size(); ++d) {
      EXPECT_EQ(curves[d].unbounded[v], unbounded[d]) << sys.dofs[d].label << " at " << speeds[v] << " m/s";
      flagged += unbounded[d];
      if (!unbounded[d]) {
        EXPECT_NEAR(curves[d].amplitudes[v], direct[d], 1e-10 * scale) << sys.dofs[d].label;
      }
    }
  }
  EXPECT_GT(flagged, 0);  // the unbalance drives the undamped mode: its resonances are in the grid
}

// Exactly at an undamped natural frequency the response is reported unbounded, never inf/NaN.
TEST(HarmonicResponse, UndampedResonanceIsUnboundedNotNaN) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  const Mode& bounce = mode_named(modes, "body bounce");
  Eigen::VectorXcd Q = Eigen::VectorXcd::Zero(sys.size());
  Q(sys.index_of("body.bounce")) = 1000.0;
  const auto r = harmonic_response(sys, modes, Q, bounce.frequency_hz);
  EXPECT_TRUE(r.unbounded);
  EXPECT_EQ(r.resonant_mode, bounce.index);
  EXPECT_TRUE(r.displacement.allFinite());
  // A pitch moment at the bounce frequency of this symmetric wagon does not drive bounce.
  Eigen::VectorXcd M = Eigen::VectorXcd::Zero(sys.size());
  M(sys.index_of("body.pitch")) = 1000.0;
  const auto p = harmonic_response(sys, modes, M, bounce.frequency_hz);
  EXPECT_FALSE(p.unbounded);
  EXPECT_TRUE(p.displacement.allFinite());
}

// Issue 17 item 5's one rule in the modal path too: a harmonic load that is round-off of its
// source's total load (here 1e-12 of it, below kLoadRoundOff = 1e-9) drives no undamped mode
// at resonance, in modal superposition as in the direct solve; measured against the load's own
// norm (the default) it does.
TEST(HarmonicResponse, ModalPathMeasuresRoundOffAgainstTheSourceLoad) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  const Mode& bounce = mode_named(modes, "body bounce");
  Eigen::VectorXcd Q = Eigen::VectorXcd::Zero(sys.size());
  Q(sys.index_of("body.bounce")) = 1e-9;  // N; the source's total load: 1000 N
  const double source_load = 1000.0;
  EXPECT_TRUE(modal_harmonic_response(sys, modes, Q, bounce.frequency_hz).unbounded);
  EXPECT_FALSE(harmonic_response(sys, modes, Q, bounce.frequency_hz, source_load).unbounded);
  EXPECT_FALSE(modal_harmonic_response(sys, modes, Q, bounce.frequency_hz, 0, source_load).unbounded);
}

// At an undamped resonance an output the resonant mode does not move keeps its finite
// amplitude, even when other modes are damped: the symmetric two-axle wagon with a damper on
// pitch alone, driven by joints at its bounce frequency. The pitch amplitude there equals the
// limit of the direct solve from either side (1e-7 away in speed; agreement to 1e-6).
TEST(AmplitudeCurves, OutputsTheResonantModeDoesNotMoveStayFinite) {
  LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const int pitch = sys.index_of("body.pitch"), bounce = sys.index_of("body.bounce");
  sys.damping(pitch, pitch) = 2e4;  // a pitch damper: bounce stays undamped
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 12.5;
  j.dip_depth = 0.005;
  const auto source = make_source(j);
  const double V = source->speed_for(mode_named(modes, "body bounce").frequency_hz, 1);
  const auto curves = amplitude_curves(sys, modes, *source, 0,
                                       {{bounce, ResponseQuantity::displacement}, {pitch, ResponseQuantity::displacement}},
                                       {V * (1 - 1e-7), V, V * (1 + 1e-7)});
  EXPECT_TRUE(curves[0].unbounded[1]);
  ASSERT_FALSE(curves[1].unbounded[1]);
  const double limit = 0.5 * (curves[1].amplitudes[0] + curves[1].amplitudes[2]);
  EXPECT_NEAR(curves[1].amplitudes[1] / limit, 1.0, 1e-6);
}

// Leaf friction against the bounce of the symmetric two-axle wagon: four springs, each with
// R = φ·load, stretched by the mode's bounce entry: Σ R|δ| = 4 φ P |φ_z|.
TEST(FrictionCriterion, FourEqualSpringsInBounce) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  const Mode& bounce = mode_named(modes, "body bounce");
  const double phi_z = std::abs(bounce.shape(sys.index_of("body.bounce")));
  const double P = sys.element_loads[0];
  EXPECT_NEAR(modal_friction_work(sys, bounce.shape), 4 * 0.075 * P * phi_z, 1e-12 * P * phi_z);
}

// Equivalent viscous damping of leaf friction: a damper that dissipates per cycle what
// friction does, πcωX² = 4RX, c = 4R/(πωX) per spring (single-stage springs: s = 1).
// Four springs act in bounce; the track input gets the same damper's velocity term.
TEST(FrictionCriterion, EquivalentViscousDampingDissipatesLikeFriction) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const double omega = 13.09, X = 0.005;
  const double R = 0.075 * sys.element_loads[0];
  const LinearSystem damped = with_equivalent_friction_damping(sys, omega, X);
  const int b = sys.index_of("body.bounce");
  EXPECT_NEAR(damped.damping(b, b), 4 * 4 * R / (kPi * omega * X), 1e-9 * damped.damping(b, b));
  EXPECT_NEAR(damped.track_inputs[0].load_per_velocity(b, 2), 4 * R / (kPi * omega * X), 1e-6);
  EXPECT_TRUE(has_leaf_friction(sys));
  EXPECT_EQ(sys.damping.norm(), 0.0);  // the original is untouched
}

// OutputRequest::phase on the direct path (friction as equivalent viscous damping: one solve
// per speed) and on the modal path with two outputs of one DOF, one with its phase and one
// without: each curve has phases exactly when it asked, and the same amplitudes either way
// (bit for bit: the phase does not enter the amplitude's arithmetic).
TEST(AmplitudeCurves, PhasesOnlyWhereAsked) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.005;
  const auto source = make_source(j);
  const int bounce = sys.index_of("body.bounce");
  OutputRequest displacement{bounce, ResponseQuantity::displacement};
  OutputRequest acceleration{bounce, ResponseQuantity::acceleration};
  acceleration.phase = false;
  const std::vector<double> speeds = {8.0, 15.0, 21.0, 30.0};
  for (double friction_reference : {0.0, 0.005}) {  // modal path, then the direct path
    const auto both = amplitude_curves(sys, modes, *source, 0, {displacement, acceleration}, speeds, friction_reference);
    EXPECT_EQ(both[0].phases_deg.size(), speeds.size()) << friction_reference;
    EXPECT_TRUE(both[1].phases_deg.empty()) << friction_reference;
    acceleration.phase = true;
    const auto with = amplitude_curves(sys, modes, *source, 0, {displacement, acceleration}, speeds, friction_reference);
    acceleration.phase = false;
    EXPECT_EQ(with[1].phases_deg.size(), speeds.size()) << friction_reference;
    EXPECT_EQ(both[0].amplitudes, with[0].amplitudes) << friction_reference;
    EXPECT_EQ(both[1].amplitudes, with[1].amplitudes) << friction_reference;
    EXPECT_EQ(both[0].phases_deg, with[0].phases_deg) << friction_reference;
  }
}

}  // namespace
}  // namespace railmodal::test
