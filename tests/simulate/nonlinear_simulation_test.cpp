// The nonlinear path: only the named effects are built, the curve of a progressive spring,
// and what it refuses (with a message that says why).
#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <sstream>
#include <string>

#include "response/friction_damping.hpp"
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

// What the nonlinear path refuses, with the reason: a progressive curve in series with other
// stages (its curve would split the force between the stages), and invalid options.
TEST(NonlinearSimulation, RefusesWhatItCannotModel) {
  const std::string vehicle = write_temp("series.toml", R"([vehicle]
name = "curve on coil"
[[body]]
name = "load"
weight = "1850 kgf"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "curve over coil"
upper = "load"
point = ["0 m", "0 m", "0 m"]
load = "1850 kgf"
vertical = [{ kind = "conical", load_deflection = { deflection = ["0 mm", "71 mm", "171 mm"], load = ["0 kgf", "1850 kgf", "5410 kgf"] } },
            { kind = "coil", stiffness = "500 kgf/cm" }]
)");
  const LinearSystem sys = assemble(load_vehicle(vehicle), DofSet::vertical);
  SimulationOptions o;
  o.duration = 0.1;
  o.time_step = 1e-3;
  try {
    simulate_nonlinear(sys, {}, o, NonlinearEffects{false, true});
    FAIL() << "a progressive stage in series was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("progressive spring in series with other stages"), std::string::npos)
        << e.what();
  }
  o.event_tolerance = 0.0;
  EXPECT_THROW(simulate_nonlinear(sys, {}, o, NonlinearEffects{}), std::invalid_argument);
}

// A load of 751 kgf on Speer's leaf spring (f = 145 mm, relative friction φ) in series with
// coils of the given stiffness (none: the leaf alone), released at rest `lift` above its
// static position.
LinearSystem leaf_over_coil(double phi, const std::string& coil) {
  std::ostringstream stages;
  stages << "{ kind = \"leaf\", static_deflection = \"145 mm\", relative_friction = " << phi << " }";
  if (!coil.empty()) stages << ", { kind = \"coil\", stiffness = \"" << coil << "\", count = 2 }";
  const std::string vehicle = write_temp("leaf_over_coil.toml", R"([vehicle]
name = "leaf over coil"
gravity = "981 cm/s^2"
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
vertical = [)" + stages.str() + "]\n");
  return assemble(load_vehicle(vehicle), DofSet::vertical);
}

TimeHistory released(const LinearSystem& sys, double lift, double duration, NonlinearEffects effects = {true, false}) {
  SimulationOptions o;
  o.duration = duration;
  o.time_step = 1e-3;
  o.initial.push_back({"load.bounce", lift, 0.0});
  return simulate_nonlinear(sys, {}, o, effects);
}

// A friction leaf in series with coils is one element with the leaf's deflection as its state
// (issue 17, item 1): built with the coils' series stiffness k_c (two springs side by side) and
// the leaf's own c_l, and with φ = 0 its force is the linear series spring's, P₀ + k_e·δ with
// 1/k_e = 1/c_l + 1/k_c, to rounding (1e-12 of the static load: a few operations on numbers of
// that size), on either edge and at any compression.
TEST(SeriesFriction, WithoutFrictionTheElementIsTheLinearSeriesSpring) {
  const LinearSystem sys = leaf_over_coil(0.06, "500 kgf/cm");
  const auto built = simulate::nonlinear_elements(sys, {}, NonlinearEffects{true, false});
  ASSERT_EQ(built.size(), 1u);
  simulate::NonlinearElement e = built.front();
  ASSERT_TRUE(e.in_series());
  EXPECT_NEAR(e.coil_stiffness, 1000 * kKgfPerCm, 1e-9 * kKgfPerCm);
  EXPECT_NEAR(e.leaf_stiffness, 751.0 / 14.5 * kKgfPerCm, 1e-9 * kKgfPerCm);
  EXPECT_NEAR(e.tangent, 1.0 / (1.0 / e.coil_stiffness + 1.0 / e.leaf_stiffness), 1e-9 * kKgfPerCm);
  e.friction = 0.0;
  for (double delta : {-0.3, -0.02, 0.0, 0.01, 0.2})
    for (int direction : {-1, 0, 1}) {
      const double s = e.sliding_leaf_deflection(delta, direction);
      EXPECT_NEAR(e.series_force(delta, s), e.static_load + e.tangent * delta, 1e-12 * e.static_load);
      EXPECT_NEAR(e.series_force(delta, s), e.leaf_reaction(s), 1e-12 * e.static_load);  // one force in series
    }
}

// With friction the sliding leaf sits on an edge of its band, F = (1 ± φ)R (the book's law,
// eqs. (40), (58)), and is the book's (192e) split of the stretch; a leaf in tension has no band.
TEST(SeriesFriction, SlidingLeafIsOnTheEdgeOfItsBand) {
  const LinearSystem sys = leaf_over_coil(0.06, "500 kgf/cm");
  const simulate::NonlinearElement e = simulate::nonlinear_elements(sys, {}, NonlinearEffects{true, false}).front();
  for (double delta : {-0.05, 0.0, 0.03})
    for (int direction : {-1, 1}) {
      const double s = e.sliding_leaf_deflection(delta, direction);
      EXPECT_NEAR(e.series_force(delta, s), (1 + direction * 0.06) * e.leaf_reaction(s), 1e-12 * e.static_load);
      // (192e) per unit: s = (k_c·δ ∓ φc_l·f)/(k_c + (1 ± φ)c_l), f = P₀/c_l.
      const double f = e.static_load / e.leaf_stiffness;
      EXPECT_NEAR(s,
                  (e.coil_stiffness * delta - direction * 0.06 * e.leaf_stiffness * f) /
                      (e.coil_stiffness + (1 + direction * 0.06) * e.leaf_stiffness),
                  1e-15);
    }
  const double tension = -2 * e.static_load / e.tangent;  // the pair stretched to twice its static load, in tension
  const double s = e.sliding_leaf_deflection(tension, 1);
  EXPECT_LT(e.leaf_reaction(s), 0.0);
  EXPECT_EQ(s, e.sliding_leaf_deflection(tension, 0));
}

// φ → 0 through the whole simulation (φ = 1e-15: built as a series element, its band narrower
// than the rounding of the forces it separates, so it never sticks) against the linear path: the same undamped
// oscillation on the series stiffness. Tolerance 1e-7 of the 39 mm lift: Dormand–Prince at the default tolerance 1e-9
// (relative) over 2 s, four periods, against the exact state transition of the linear path.
TEST(SeriesFriction, ZeroFrictionSimulatesTheLinearSeriesSpring) {
  const LinearSystem sys = leaf_over_coil(1e-15, "500 kgf/cm");  // built as friction, φ ≈ 0
  const TimeHistory nonlinear = released(sys, 0.039, 2.0);
  SimulationOptions o;
  o.duration = 2.0;
  o.time_step = 1e-3;
  o.initial.push_back({"load.bounce", 0.039, 0.0});
  const TimeHistory linear = simulate_linear(sys, {}, o);
  ASSERT_EQ(nonlinear.displacement.rows(), linear.displacement.rows());
  EXPECT_LT((nonlinear.displacement - linear.displacement).cwiseAbs().maxCoeff(), 1e-7 * 0.039);
  EXPECT_EQ(nonlinear.events.size(),
            std::count_if(nonlinear.events.begin(), nonlinear.events.end(), [](const SimulationEvent& e) {
              return e.kind == SimulationEvent::Kind::reversal;
            }));  // a closed band: it turns, never sticks
}

// Coils 10⁴ times stiffer than the leaf leave the leaf alone: the drop test (φ = 0.0625, 39 mm,
// Table 5 row 1) gives the single leaf's extremes. The coils change the motion by O(c_l/k_c)
// of the amplitude (4 µm) and, while the leaf holds, add their own travel across the band
// (2φP₀/k_c = 1.8 µm) and a residual ripple of that size: 0.02 mm covers both with margin,
// and is far below the 17–19 mm lost per swing.
TEST(SeriesFriction, StiffCoilsReproduceTheLeafAlone) {
  const double c_l = 751.0 / 14.5;  // kgf/cm
  const TimeHistory alone = released(leaf_over_coil(0.0625, ""), 0.039, 1.5);
  const TimeHistory series =
      released(leaf_over_coil(0.0625, std::to_string(0.5e4 * c_l) + " kgf/cm"), 0.039, 1.5);  // 2 × 0.5e4 c_l
  const Swings a = swings(alone, 0), b = swings(series, 0);
  ASSERT_GE(a.turning_values.size(), 2u);
  ASSERT_GE(b.turning_values.size(), 2u);
  for (size_t k = 0; k < 2; ++k) EXPECT_NEAR(b.turning_values[k], a.turning_values[k], 2e-5) << "extreme " << k;
  EXPECT_NEAR(series.displacement(series.displacement.rows() - 1, 0),
              alone.displacement(alone.displacement.rows() - 1, 0),
              2e-5);  // both at rest in the dead band, at the same point
}

// The criterion's series model is the simulation's (issue 17, item 1): the resort car's axlebox
// element (leaf c₁ = 700 kgf/cm, φ₁ = 0.0843, in series with two coils of 1000 kgf/cm) driven
// quasi-statically through X sin θ by the simulation's own element law dissipates per cycle
// what its equivalent damper does, πcωX² = 4T·share·(X − T/k_c) (src/response/leaf_friction.cpp),
// and nothing when X is below the hold stretch T/k_c. The constant law (T = φP₀) is the
// criterion's 1 ± φ ≈ 1; the loop is then an exact parallelogram, and 20 000 steps a cycle
// place its four corners to 1e-4 of the travel: 1e-3 of the work covers it.
TEST(SeriesFriction, EquivalentDampingIsTheHysteresisLoopOfTheElement) {
  const LinearSystem sys =
      assemble(load_vehicle(std::string(RAILMODAL_DATA_DIR) + "/vehicles/resort_car.toml"), DofSet::vertical);
  NonlinearEffects coulomb{true, false};
  coulomb.constant_friction = true;
  const auto built = simulate::nonlinear_elements(sys, {}, coulomb);
  const auto series = std::find_if(built.begin(), built.end(), [](const auto& e) { return e.in_series(); });
  ASSERT_NE(series, built.end());
  const simulate::NonlinearElement& e = *series;
  const double T = e.friction * e.static_load, hold = T / e.coil_stiffness;
  EXPECT_NEAR(response::leaf_hold_stretch(sys, e.element), hold, 1e-12 * hold);
  const double omega = 2.0 * kPi;
  for (double X : {0.5 * hold, 3.0 * hold, 0.02}) {
    constexpr int kSteps = 20000;
    double s = 0.0, work = 0.0, previous_delta = 0.0, previous_force = e.static_load;
    for (int k = 1; k <= 2 * kSteps; ++k) {  // two cycles from the band's middle; the second is counted
      const double delta = X * std::sin(2.0 * kPi * k / kSteps);
      const double excess = e.series_force(delta, s) - e.leaf_reaction(s);
      if (std::abs(excess) > T) s = e.sliding_leaf_deflection(delta, excess > 0.0 ? 1 : -1);
      const double force = e.series_force(delta, s);
      if (k > kSteps) work += 0.5 * (force + previous_force) * (delta - previous_delta);
      previous_delta = delta, previous_force = force;
    }
    const double damper = kPi * omega * X * X * response::equivalent_friction_damping(sys, e.element, omega, X);
    EXPECT_NEAR(work, damper, 1e-3 * 4.0 * T * X) << "X = " << X;
    if (X < hold) {
      EXPECT_EQ(damper, 0.0);
    }
  }
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
