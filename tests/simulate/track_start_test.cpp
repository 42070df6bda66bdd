// Where the track starts (issue 17 item 4): the phase of each periodic source at t = 0, the
// same in the inputs, the simulation and the harmonic (critical-speed) path.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <utility>
#include <vector>

#include "test_support.hpp"

namespace railmodal {
namespace {

using test::kPi;

// The time in [0, period) where the vertical input under the wheel of track element `index`,
// u(t) = Σ_k Re(A_k e^{iω_k(t − τ)}) over the source's harmonics, is lowest, on a grid of
// `samples`.
double deepest_time(const LinearSystem& system, const ExcitationSource& source, double speed, int index, double period,
                    int samples) {
  std::vector<std::pair<std::complex<double>, double>> terms;  // A_k e^{−iω_k τ}, ω_k
  for (int k = 1; k <= source.harmonic_count(); ++k) {
    const HarmonicLoad load = source.load(system, speed, k);
    const double omega = 2.0 * kPi * load.frequency_hz;
    for (const WheelInput& w : load.wheels)
      if (w.track_input == index) terms.emplace_back(w.amplitude(2) * std::polar(1.0, -omega * w.delay_s), omega);
  }
  double best_t = 0.0, best_u = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double t = period * i / samples;
    double u = 0.0;
    for (const auto& [a, omega] : terms) u += std::real(a * std::polar(1.0, omega * t));
    if (u < best_u) best_u = u, best_t = t;
  }
  return best_t;
}

LinearSystem coach() {
  return assemble(load_vehicle(test::data_file("manchester_benchmark_coach.toml")), DofSet::vertical);
}

// The leading wheel (no delay) meets the first joint at t = first_joint_at/V, and a flat
// θ ahead after the wheel has rolled θD/2: t = θD/(2V). Grid: 1 mm of track (joints) and
// 0.1 mm (flats) a sample, so the times agree to half a sample.
TEST(TrackStart, FirstJointAndFlatMeetTheLeadingWheelWhereTheKeysSay) {
  const LinearSystem system = coach();
  const double V = 20.0;
  RailJoints joints;
  joints.rail_length = 25.0;
  joints.dip_depth = 0.005;
  joints.dip_length = 1.0;
  joints.harmonics = 60;
  const int leading = 0;  // track inputs are listed from the front
  for (double d : {0.0, 2.5, 17.0}) {
    joints.first_joint_at = d;
    const auto source = make_source(joints);
    EXPECT_NEAR(deepest_time(system, *source, V, leading, 25.0 / V, 25000), d / V, 0.5e-3 / V) << d;
  }
  WheelFlat flat;
  flat.wheel_diameter = 0.92;
  flat.depth = 0.0006;
  flat.length = 0.06;
  flat.harmonics = 60;
  const double circumference = kPi * flat.wheel_diameter;
  for (double degrees : {0.0, 90.0, 300.0}) {
    flat.flat_angle = degrees * kPi / 180.0;
    const auto source = make_source(flat);
    EXPECT_NEAR(deepest_time(system, *source, V, leading, circumference / V, 28900),
                flat.flat_angle * flat.wheel_diameter / (2.0 * V), 0.5 * circumference / 28900 / V)
        << degrees;
  }
}

SimulationOptions run(double speed, double duration) {
  SimulationOptions o;
  o.speed = speed;
  o.duration = duration;
  o.time_step = 0.002;
  return o;
}

// Moving the first joint Δ further ahead moves the history Δ/V later. From rest the first
// moments differ (the track under the wheels at t = 0 is not the same); the coach's dampers
// (ζ ≈ 0.2 on the body) leave e^{−0.2·7.5·20} ≈ 1e-13 of that after 20 s, so over the last
// 2 s the two agree to the integrator's rounding; 1e-6 of the amplitude allows for it.
TEST(TrackStart, ShiftingTheFirstJointShiftsTheSimulatedHistory) {
  const LinearSystem system = coach();
  const double V = 25.0, delta = 2.5;  // Δ/V = 0.1 s, 50 steps of 2 ms
  RailJoints joints;
  joints.rail_length = 25.0;
  joints.dip_depth = 0.005;
  joints.dip_length = 2.0;
  joints.harmonics = 30;
  joints.first_joint_at = 4.0;
  const auto a = make_source(joints);
  joints.first_joint_at += delta;
  const auto b = make_source(joints);
  const TimeHistory ha = simulate_linear(system, {a.get()}, run(V, 20.0));
  const TimeHistory hb = simulate_linear(system, {b.get()}, run(V, 20.0));
  const int bounce = system.index_of("body.bounce"), shift = 50;
  double largest = 0.0, worst = 0.0;
  for (Eigen::Index i = ha.time.size() - 1000; i + shift < ha.time.size(); ++i) {
    largest = std::max(largest, std::abs(ha.displacement(i, bounce)));
    worst = std::max(worst, std::abs(hb.displacement(i + shift, bounce) - ha.displacement(i, bounce)));
  }
  EXPECT_GT(largest, 1e-5);  // the joints move the body
  EXPECT_LT(worst, 1e-6 * largest);
  // And the start matters: unshifted, the two histories differ by the order of the motion.
  double unshifted = 0.0;
  for (Eigen::Index i = ha.time.size() - 1000; i < ha.time.size(); ++i)
    unshifted = std::max(unshifted, std::abs(hb.displacement(i, bounce) - ha.displacement(i, bounce)));
  EXPECT_GT(unshifted, 0.1 * largest);
}

// The steady motion of the simulation is the harmonic path's Re(X e^{iωt}) with X solved from
// the same source (the path of railmodal critical-speed and the amplitude curves), so the two
// agree on the phase of a joint placed 7 m ahead. Tolerance: the linear path's O((ωΔt)²/12)
// sampling error, 2e-5 at 1.2 Hz and 2 ms, and the decayed start (as above), within 1e-4.
TEST(TrackStart, HarmonicPathAndSimulationAgreeOnThePhase) {
  const LinearSystem system = coach();
  const ModalResult modes = solve_modes(system);
  const double V = 30.0;
  RailJoints joints;
  joints.rail_length = 25.0;
  joints.dip_depth = 0.005;  // the whole-rail cosine: one harmonic, f = V/L = 1.2 Hz
  joints.first_joint_at = 7.0;
  const auto source = make_source(joints);
  const HarmonicLoad load = source->load(system, V, 1);
  const HarmonicResponse x = harmonic_response(system, modes, generalized_load(system, load), load.frequency_hz);
  const TimeHistory h = simulate_linear(system, {source.get()}, run(V, 20.0));
  const double omega = 2.0 * kPi * load.frequency_hz;
  for (const char* dof : {"body.bounce", "bogie1.bounce", "bogie2.pitch"}) {
    const int d = system.index_of(dof);
    double worst = 0.0;
    for (Eigen::Index i = h.time.size() - 1000; i < h.time.size(); ++i)
      worst = std::max(
          worst, std::abs(h.displacement(i, d) - std::real(x.displacement(d) * std::polar(1.0, omega * h.time(i)))));
    EXPECT_LT(worst, 1e-4 * std::abs(x.displacement(d))) << dof;
  }
}

// The scene keys reach the sources: first_joint_at, flat_angle and hunting's phase give the
// same harmonic inputs as the structs' fields (compared exactly: the same arithmetic).
TEST(TrackStart, SceneKeysPlaceTheSources) {
  const std::string vehicle = test::data_file("manchester_benchmark_coach.toml");
  const std::string scene = test::write_temp("start.toml", R"([scene]
vehicle = ")" + vehicle + R"("
[speed]
min = "10 km/h"
max = "150 km/h"
[[source]]
kind = "rail_joints"
rail_length = "25 m"
dip_depth = "5 mm"
dip_length = "1 m"
harmonics = 3
first_joint_at = "2.5 m"
[[source]]
kind = "wheel_flat"
wheel_diameter = "920 mm"
depth = "0.6 mm"
length = "60 mm"
harmonics = 3
flat_angle = "90 deg"
[[source]]
kind = "hunting"
model = "given"
wavelength = "20 m"
amplitude = "3 mm"
phase = "45 deg"
)");
  const Scene s = load_scene(scene);
  ASSERT_EQ(s.sources.size(), 3u);
  RailJoints joints;
  joints.rail_length = 25.0, joints.dip_depth = 0.005, joints.dip_length = 1.0, joints.harmonics = 3;
  joints.first_joint_at = 2.5;
  WheelFlat flat;
  flat.wheel_diameter = 0.92, flat.depth = 0.0006, flat.length = 0.06, flat.harmonics = 3;
  flat.flat_angle = kPi / 2.0;
  Hunting hunting;
  hunting.model = Hunting::Model::given, hunting.given_wavelength = 20.0, hunting.amplitude = 0.003;
  hunting.phase = kPi / 4.0;
  const std::unique_ptr<ExcitationSource> expected[] = {make_source(joints), make_source(flat), make_source(hunting)};
  joints.first_joint_at = 0.0, flat.flat_angle = 0.0, hunting.phase = 0.0;
  const std::unique_ptr<ExcitationSource> at_default[] = {make_source(joints), make_source(flat), make_source(hunting)};
  const LinearSystem system = assemble(load_vehicle(vehicle), DofSet::all);
  for (int i = 0; i < 3; ++i) {
    const HarmonicLoad read = s.sources[i]->load(system, 20.0, 1), made = expected[i]->load(system, 20.0, 1);
    ASSERT_EQ(read.wheels.size(), made.wheels.size());
    for (size_t w = 0; w < read.wheels.size(); ++w) EXPECT_EQ(read.wheels[w].amplitude, made.wheels[w].amplitude) << i;
    // and the place matters: the default start gives another phase
    EXPECT_NE(read.wheels[0].amplitude, at_default[i]->load(system, 20.0, 1).wheels[0].amplitude) << i;
  }
}

}  // namespace
}  // namespace railmodal
