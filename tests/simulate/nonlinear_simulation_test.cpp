// The nonlinear path: only the named effects are built, the curve of a progressive spring,
// and what it refuses (with a message that says why).
#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <string>

#include "simulate/nonlinear_elements.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string scene_file(const std::string& name) { return std::string(RAILMODAL_DATA_DIR) + "/scenes/" + name; }

// The loads of a scene's sources, as the simulation builds them.
std::vector<HarmonicLoad> source_loads(const Scene& s, const LinearSystem& sys) {
  std::vector<HarmonicLoad> loads;
  for (const auto& source : s.sources)
    for (int k = 1; k <= source->harmonic_count(); ++k) loads.push_back(source->load(sys, s.simulation->speed, k));
  return loads;
}

// A scene builds exactly the nonlinear elements its effects name: the two-axle wagon's four
// leaf springs carry friction only under "leaf_friction"; it has no load–deflection curves,
// so "progressive_springs" builds nothing, and nothing named builds nothing.
TEST(NonlinearElements, OnlyTheNamedEffectsAreBuilt) {
  const Scene s = load_scene(scene_file("two_axle_freight_wagon_joints_friction.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  const LinearSystem sys = scene_system(s, v);
  const auto loads = source_loads(s, sys);

  const auto friction = simulate::nonlinear_elements(sys, loads, NonlinearEffects{true, false});
  ASSERT_EQ(friction.size(), 4u);
  for (const auto& e : friction) {
    EXPECT_GT(e.friction, 0.0);
    EXPECT_FALSE(e.curve);
    EXPECT_EQ(e.track.size(), loads.size());  // every harmonic of the joints under every wheel
  }
  EXPECT_TRUE(simulate::nonlinear_elements(sys, loads, NonlinearEffects{false, true}).empty());
  EXPECT_TRUE(simulate::nonlinear_elements(sys, loads, NonlinearEffects{}).empty());
}

// Dampers are built only when the scene names "viscous_dampers": the Manchester coach's
// (primary and secondary, vertical and lateral) give C ≠ 0 with the name and exactly C = 0
// without it, while M and K stay bit for bit the same.
TEST(NonlinearElements, DampersOnlyWhenNamed) {
  const Vehicle v = load_vehicle(std::string(RAILMODAL_DATA_DIR) + "/vehicles/manchester_benchmark_coach.toml");
  const std::string head = "[scene]\nname = \"coach\"\ndofs = \"all\"\n[simulation]\nduration = \"1 s\"\ntime_step = \"1 ms\"\n";
  const Scene without = load_scene(write_temp("coach_plain.toml", head + "effects = []\n"));
  const Scene with = load_scene(write_temp("coach_damped.toml", head + "effects = [\"viscous_dampers\"]\n"));
  const LinearSystem plain = scene_system(without, v), damped = scene_system(with, v);
  EXPECT_EQ(plain.damping.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(damped.damping.cwiseAbs().maxCoeff(), 1e3);  // N·s/m: the coach's dampers are kN·s/m
  EXPECT_EQ(plain.mass, damped.mass);
  EXPECT_EQ(plain.stiffness, damped.stiffness);
}

// The Khanin spring's curve is followed only under "progressive_springs"; its friction-free
// coil builds no friction even when "leaf_friction" is named.
TEST(NonlinearElements, CurvesOnlyUnderProgressiveSprings) {
  const Scene s = load_scene(scene_file("khanin_spring_free_oscillation.toml"));
  const LinearSystem sys = scene_system(s, load_vehicle(s.vehicle_file));
  const auto both = simulate::nonlinear_elements(sys, {}, NonlinearEffects{true, true});
  ASSERT_EQ(both.size(), 1u);
  EXPECT_TRUE(both[0].curve);
  EXPECT_EQ(both[0].friction, 0.0);
  EXPECT_TRUE(simulate::nonlinear_elements(sys, {}, NonlinearEffects{true, false}).empty());
}

// With every nonlinearity left out, the nonlinear integrator and the linear path solve the
// same equations. Free motion: the linear path is exact, so they agree to the integrator's
// tolerance (1e-10 relative per step, a few hundred steps: 1e-8 of the 25 mm release).
// Forced: the linear path samples the load (first-order hold, O(Δt²)), so the difference is
// its error and falls by 4 when its step is halved.
TEST(NonlinearSimulation, NothingNamedMatchesTheLinearPath) {
  const Scene s = load_scene(scene_file("two_axle_freight_wagon_joints_friction.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  const LinearSystem sys = scene_system(s, v);
  SimulationOptions o;
  o.speed = s.simulation->speed;
  o.duration = 1.0;
  o.time_step = 2e-3;
  o.initial = s.simulation->initial;
  const TimeHistory free_linear = simulate_linear(sys, {}, o);
  const TimeHistory free_nonlinear = simulate_nonlinear(sys, {}, o, NonlinearEffects{});
  EXPECT_TRUE(free_nonlinear.events.empty());
  EXPECT_GT(free_nonlinear.steps_taken, 0);
  EXPECT_LT((free_linear.displacement - free_nonlinear.displacement).cwiseAbs().maxCoeff(), 1e-8 * 0.025);

  std::vector<const ExcitationSource*> sources;
  for (const auto& source : s.sources) sources.push_back(source.get());
  const TimeHistory reference = simulate_nonlinear(sys, sources, o, NonlinearEffects{});
  const TimeHistory coarse = simulate_linear(sys, sources, o);
  o.time_step = 1e-3;
  const TimeHistory fine = simulate_linear(sys, sources, o);
  double coarse_error = 0.0, fine_error = 0.0;
  for (int i = 0; i < reference.time.size(); ++i) {
    coarse_error = std::max(coarse_error, (coarse.displacement.row(i) - reference.displacement.row(i)).cwiseAbs().maxCoeff());
    fine_error = std::max(fine_error, (fine.displacement.row(2 * i) - reference.displacement.row(i)).cwiseAbs().maxCoeff());
  }
  EXPECT_NEAR(coarse_error / fine_error, 4.0, 0.6);  // second order; ±15 % for the higher-order terms
}

// The scene's choice decides the path: leaf_friction named → events; dropped → none.
TEST(NonlinearSimulation, SceneEffectsChooseThePath) {
  Scene s = load_scene(scene_file("leaf_spring_drop_test.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  EXPECT_TRUE(scene_effects(s).leaf_friction);
  EXPECT_FALSE(scene_effects(s).progressive_springs);
  EXPECT_FALSE(simulate_scene(s, v).events.empty());
  s.simulation->effects.clear();
  EXPECT_FALSE(scene_effects(s).any());
  const TimeHistory h = simulate_scene(s, v);
  EXPECT_TRUE(h.events.empty());
  // Undamped and frictionless: it swings back to the full 39 mm (exact linear path).
  EXPECT_NEAR(h.displacement.col(0).maxCoeff(), 0.039, 1e-9);
}

// A run's events are held with their states, and their number follows the motion, not the
// step count: past max_events the run stops with the limit in the message instead of growing
// the list without bound (issue 18, review of item 4). The wagon over joints with friction
// has many more than 5 events in a second.
TEST(NonlinearSimulation, EventsBeyondTheLimitAreRefused) {
  const Scene s = load_scene(scene_file("two_axle_freight_wagon_joints_friction.toml"));
  const LinearSystem system = scene_system(s, load_vehicle(s.vehicle_file));
  std::vector<const ExcitationSource*> sources;
  for (const auto& source : s.sources) sources.push_back(source.get());
  SimulationOptions o;
  o.speed = s.simulation->speed;
  o.duration = 1.0;
  o.time_step = s.simulation->time_step;
  const size_t all = simulate_nonlinear(system, sources, o, scene_effects(s)).events.size();
  ASSERT_GT(all, 5u);
  o.max_events = 5;
  try {
    simulate_nonlinear(system, sources, o, scene_effects(s));
    FAIL() << "a run with more events than max_events was not refused";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("more than 5 stick/slip/kink events"), std::string::npos) << e.what();
  }
  o.max_events = all;
  EXPECT_EQ(simulate_nonlinear(system, sources, o, scene_effects(s)).events.size(), all);
}

// A Khanin-type curve: 260 kg/cm to the kink at 70 mm, 356 kg/cm beyond (Example 10).
TEST(LoadDeflectionCurve, PiecewiseLinearWithKink) {
  LoadDeflectionCurve c;
  c.deflection = {0.0, 0.070, 0.170};
  c.load = {0.0, 260 * 7.0 * kKgf, (260 * 7.0 + 356 * 10.0) * kKgf};
  EXPECT_NEAR(c.load_at(0.035), 260 * 3.5 * kKgf, 1e-9);
  EXPECT_NEAR(c.load_at(0.120), (260 * 7.0 + 356 * 5.0) * kKgf, 1e-9);
  EXPECT_NEAR(c.load_at(0.200), (260 * 7.0 + 356 * 13.0) * kKgf, 1e-9);  // the last segment continues
  EXPECT_NEAR(c.deflection_at(c.load_at(0.120)), 0.120, 1e-15);
  // At the kink the stiffer segment above it carries the load (the linear models then use the
  // stiffness the first dynamic compression meets).
  EXPECT_NEAR(c.stiffness_at(260 * 7.0 * kKgf), 356 * kKgfPerCm, 1e-9);
  EXPECT_NEAR(c.stiffness_at(100 * kKgf), 260 * kKgfPerCm, 1e-9);
}

// What the nonlinear path refuses, with the reason.
TEST(NonlinearSimulation, RefusesWhatItCannotModel) {
  const std::string vehicle = write_temp("series.toml", R"([vehicle]
name = "leaf on coil"
[[body]]
name = "load"
weight = "751 kgf"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "leaf over coil"
upper = "load"
point = ["0 m", "0 m", "0 m"]
load = "751 kgf"
vertical = [{ kind = "leaf", static_deflection = "145 mm", relative_friction = 0.06 },
            { kind = "coil", stiffness = "500 kgf/cm" }]
)");
  const LinearSystem sys = assemble(load_vehicle(vehicle), DofSet::vertical);
  SimulationOptions o;
  o.duration = 0.1;
  o.time_step = 1e-3;
  try {
    simulate_nonlinear(sys, {}, o, NonlinearEffects{true, false});
    FAIL() << "a friction stage in series was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("in series with other stages"), std::string::npos) << e.what();
  }
  o.event_tolerance = 0.0;
  EXPECT_THROW(simulate_nonlinear(sys, {}, o, NonlinearEffects{}), std::invalid_argument);
}

// An event tolerance finer than time can be resolved over the run (issue 18, item 2: 1e-30 s
// never returned) is raised to ε·duration, and the summary says so. The run then locates the
// same events as one asked for that limit: bit for bit, since the options it runs with are the same.
TEST(NonlinearSimulation, EventToleranceBelowTheResolutionIsRaised) {
  Scene s = load_scene(scene_file("two_axle_freight_wagon_joints_friction.toml"));
  const Vehicle v = load_vehicle(s.vehicle_file);
  s.simulation->duration = 1.0;
  s.simulation->event_tolerance = 1e-30;
  const TimeHistory fine = simulate_scene(s, v);
  const double limit = resolvable_event_tolerance(1.0);
  EXPECT_EQ(limit, std::ldexp(1.0, -52));
  const auto raised = std::find_if(fine.summary.checks.begin(), fine.summary.checks.end(),
                                   [](const Check& c) { return c.name.find("event tolerance raised") == 0; });
  ASSERT_NE(raised, fine.summary.checks.end());
  EXPECT_EQ(raised->value, limit);
  s.simulation->event_tolerance = limit;
  const TimeHistory at_limit = simulate_scene(s, v);
  ASSERT_FALSE(fine.events.empty());
  ASSERT_EQ(fine.events.size(), at_limit.events.size());
  for (size_t e = 0; e < fine.events.size(); ++e) EXPECT_EQ(fine.events[e].time, at_limit.events[e].time);
  EXPECT_EQ(fine.displacement, at_limit.displacement);
}

}  // namespace
}  // namespace railmodal::test

namespace railmodal::test {
namespace {

// m = 1000 kg on k = 1 MN/m and c = 10 kN·s/m (ζ = 0.16) over rail joints on an elastic
// track (so the input amplitude follows the speed, ρ²/(ρ² − n²)), two harmonics.
struct RampCase {
  LinearSystem system;
  std::unique_ptr<ExcitationSource> source;
  RampCase() {
    system = assemble(load_vehicle(write_temp("ramp_sdof.toml", R"([vehicle]
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
vertical_damping = "10 kN*s/m"
)")),
                      DofSet::vertical);
    RailJoints j;
    j.rail_length = 10.0;
    j.dip_depth = 0.005;
    j.harmonics = 2;
    j.track_stiffness = 5e7;
    j.half_wheelset_mass = 700.0;
    source = make_source(j);
  }
};

// A speed ramp through the resonance (5.03 Hz: 50 m/s on 10 m rails), 30 → 70 m/s in 4 s,
// against an independent integration: classic RK4 at 20 µs of m ẍ + c ẋ + k x = Σ Re(Q_k e^{iθ_k})
// with Q_k from ExcitationSource::load at the instantaneous speed and θ_k = 2πk·x(t)/L. The
// adaptive path (tolerance 1e-10) and RK4 (error ~ (ωΔt)⁴ ≈ 1e-10 relative) agree to 1e-7 of
// the peak.
TEST(SpeedRamp, MatchesAnIndependentIntegration) {
  const RampCase c;
  SimulationOptions o;
  o.speed = 30.0;
  o.final_speed = 70.0;
  o.duration = 4.0;
  o.time_step = 1e-3;
  const TimeHistory h = simulate_nonlinear(c.system, {c.source.get()}, o, NonlinearEffects{});
  EXPECT_THROW(simulate_linear(c.system, {c.source.get()}, o), std::invalid_argument);

  const double m = c.system.mass(0, 0), k = c.system.stiffness(0, 0), d = c.system.damping(0, 0);
  const double a = (o.final_speed - o.speed) / o.duration;
  auto force = [&](double t) {
    const double V = o.speed + a * t, x = (o.speed + 0.5 * a * t) * t;
    double f = 0.0;
    for (int n = 1; n <= 2; ++n) {
      const HarmonicLoad load = c.source->load(c.system, V, n);
      const std::complex<double> Q = generalized_load(c.system, load)(0);
      f += (Q * std::exp(std::complex<double>(0.0, 2 * kPi * n * x / 10.0))).real();
    }
    return f;
  };
  auto rhs = [&](double t, double x, double v, double* dx, double* dv) {
    *dx = v;
    *dv = (force(t) - k * x - d * v) / m;
  };
  const double dt = 2e-5;
  double x = 0.0, v = 0.0, worst = 0.0, peak = 0.0;
  for (int i = 0; i < static_cast<int>(std::llround(o.duration / dt)); ++i) {
    const double t = i * dt;
    double k1x, k1v, k2x, k2v, k3x, k3v, k4x, k4v;
    rhs(t, x, v, &k1x, &k1v);
    rhs(t + dt / 2, x + dt / 2 * k1x, v + dt / 2 * k1v, &k2x, &k2v);
    rhs(t + dt / 2, x + dt / 2 * k2x, v + dt / 2 * k2v, &k3x, &k3v);
    rhs(t + dt, x + dt * k3x, v + dt * k3v, &k4x, &k4v);
    x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    const int sample = i + 1;
    if (sample % 50 == 0) {
      worst = std::max(worst, std::abs(h.displacement(sample / 50, 0) - x));
      peak = std::max(peak, std::abs(x));
    }
  }
  EXPECT_GT(peak, 1e-3);  // it did pass through the resonance
  EXPECT_LT(worst, 1e-7 * peak);
}

// The track under a ramp: the element's u, u̇, ü are consistent (u̇ and ü against central
// differences of u and u̇ at 1 µs: error ~ (ωh)² ≈ 1e-9 relative), including the amplitude's
// dependence on the speed on an elastic track.
TEST(SpeedRamp, TrackMotionDerivativesAreConsistent) {
  const RampCase c;
  std::vector<HarmonicLoad> loads{c.source->load(c.system, 30.0, 1), c.source->load(c.system, 30.0, 2)};
  simulate::SpeedProfile profile;
  profile.initial = 30.0;
  profile.acceleration = 10.0;
  // The element only becomes a nonlinear one with friction: give its stage some.
  LinearSystem sys = c.system;
  sys.vehicle.elements[0].vertical_stages[0].relative_friction = 0.05;
  const auto elements = simulate::nonlinear_elements(sys, loads, NonlinearEffects{true, false},
                                                     {c.source.get(), c.source.get()}, profile);
  ASSERT_EQ(elements.size(), 1u);
  ASSERT_FALSE(elements[0].track.empty());  // (a whole-rail cosine dip has no second harmonic)
  const double h = 1e-6;
  for (double t : {0.1, 1.3, 2.7}) {
    double u, du, ddu, up, dup, dd, um, dum;
    elements[0].track_motion(t, &u, &du, &ddu);
    elements[0].track_motion(t + h, &up, &dup, &dd);
    elements[0].track_motion(t - h, &um, &dum, &dd);
    EXPECT_NEAR(du, (up - um) / (2 * h), 1e-6 * std::abs(du) + 1e-9);
    EXPECT_NEAR(ddu, (dup - dum) / (2 * h), 1e-5 * std::abs(ddu) + 1e-6);
  }
}

}  // namespace
}  // namespace railmodal::test
