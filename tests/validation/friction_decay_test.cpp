// The nonlinear time-domain path against the books' friction and progressive-spring cases:
// Speer's leaf-spring drop tests (springs digest, Example 7 and Table 5), the Khanin conical
// spring (Example 10), and the loaded two-axle wagon over 10 m joints at its critical speed
// (two-axle digest, Example 3). Every case runs from its inputs through load_scene and
// simulate_scene, the path `railmodal simulate` takes.
#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "railmodal/critical_speed.hpp"
#include "response/friction_damping.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

constexpr double kGcm = 981.0;  // the book's g, cm/s², as the vehicle files give it

std::string scenes_dir() { return std::string(RAILMODAL_DATA_DIR) + "/scenes/"; }

int count(const TimeHistory& h, SimulationEvent::Kind kind) {
  return static_cast<int>(std::count_if(h.events.begin(), h.events.end(), [kind](const SimulationEvent& e) { return e.kind == kind; }));
}

// A load W on Speer's test leaf spring (f = 145 mm, relative friction φ), released at rest a₁
// above its static position, as in Table 5.
TimeHistory drop_test(double phi, double a1_mm, double duration_s) {
  std::ostringstream vehicle;
  vehicle << R"([vehicle]
name = "drop test"
gravity = "981 cm/s^2"
[[body]]
name = "load"
weight = "751 kgf"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "leaf spring"
upper = "load"
point = ["0 m", "0 m", "0 m"]
load = "751 kgf"
vertical = [{ kind = "leaf", static_deflection = "145 mm", relative_friction = )"
          << phi << " }]\n";
  write_temp("drop_vehicle.toml", vehicle.str());
  std::ostringstream scene;
  scene << R"([scene]
name = "drop"
vehicle = "drop_vehicle.toml"
dofs = "vertical"
[simulation]
duration = ")" << duration_s << R"( s"
time_step = "1 ms"
effects = ["leaf_friction"]
[[simulation.initial]]
dof = "load.bounce"
displacement = ")" << a1_mm << " mm\"\n";
  const Scene s = load_scene(write_temp("drop_scene.toml", scene.str()));
  return simulate_scene(s, load_vehicle(s.vehicle_file));
}

// The exact piecewise solution of eqs. (45)/(59): each stroke is a cosine arc about a centre
// shifted by the friction, φf/(1 + φ) while the spring is loaded (moving down) and −φf/(1 − φ)
// while it unloads; a turn inside the dead band −φf/(1 − φ) … φf/(1 + φ) is where it sticks
// (digest, Example 7, "Exact piecewise solution, recomputed").
std::vector<double> exact_extremes(double phi, double f, double a1) {
  std::vector<double> z{a1};
  bool loading = true;
  while (!(z.back() >= -phi * f / (1 - phi) && z.back() <= phi * f / (1 + phi))) {
    const double centre = loading ? phi * f / (1 + phi) : -phi * f / (1 - phi);
    z.push_back(2 * centre - z.back());
    loading = !loading;
  }
  return z;
}

// Row 1 (φ = 0.0625, a₁ = 39 mm): the digest's recomputed extremes 39 → 21.94 → 2.61 mm and
// half periods π/k₁ = 0.3705 s, π/k₂ = 0.3945 s, then the spring sticks.
TEST(FrictionDecay, SpeerDropTestRow1) {
  const TimeHistory h = drop_test(0.0625, 39.0, 2.0);
  const Swings sw = swings(h, 0);
  ASSERT_EQ(sw.turning_values.size(), 3u);  // the release, one reversal, the stop
  // The digest prints two decimals (mm): ±0.005 mm.
  EXPECT_NEAR(sw.turning_values[1] * 1e3, -21.94, 0.005);
  EXPECT_NEAR(sw.turning_values[2] * 1e3, 2.61, 0.005);
  // Four decimals (s): ±5e-5 s.
  const auto half = sw.half_periods_between_turns();
  ASSERT_EQ(half.size(), 2u);
  EXPECT_NEAR(half[0], 0.3705, 5e-5);
  EXPECT_NEAR(half[1], 0.3945, 5e-5);
  EXPECT_TRUE(sw.comes_to_rest);

  // The events carry the exact times: a reversal after π/k₁, k₁² = (g/f)(1 + φ) (eq. (51)),
  // and the stick π/k₂ later, k₂² = (g/f)(1 − φ) (eq. (63)). Event location is asked to
  // 1e-12 s and the integrator to 1e-10 of the state: 1e-9 s is far outside both.
  ASSERT_EQ(h.events.size(), 2u);
  const double k1 = std::sqrt(kGcm / 14.5 * 1.0625), k2 = std::sqrt(kGcm / 14.5 * 0.9375);
  EXPECT_EQ(h.events[0].kind, SimulationEvent::Kind::reversal);
  EXPECT_NEAR(h.events[0].time, kPi / k1, 1e-9);
  EXPECT_EQ(h.events[1].kind, SimulationEvent::Kind::stick);
  EXPECT_NEAR(h.events[1].time, kPi / k1 + kPi / k2, 1e-9);
  // The turns read from the history (samples and event states) agree with them: the reversal
  // is an event state, the cubic pieces never span one.
  EXPECT_NEAR(half[0], kPi / k1, 1e-9);
  EXPECT_NEAR(half[1], kPi / k2, 1e-9);
  // At rest it stays where it stuck (to rounding: the holding force cancels the rest exactly).
  EXPECT_NEAR(h.displacement(h.time.size() - 1, 0), h.displacement(h.time.size() - 200, 0), 1e-15);
}

// Every row of Table 5 against the exact chain, to 1e-8 m (the integrator keeps 1e-10 of
// the 0.04 m amplitude per step over a few thousand steps; Hermite reading of the turns is
// O(Δt⁴) ≈ 1e-12 m). The decrements alternate 2φf/(1 + φ), 2φf/(1 − φ), so a pair of them
// averages the book's 2φf to O(φ²) (eq. (67)); the number of swings before the stop is the
// digest's (row 5: 9 swings).
struct Table5Row {
  double phi, a1_mm;
  size_t swings;
};
class Table5 : public ::testing::TestWithParam<Table5Row> {};

TEST_P(Table5, DecayChainIsExact) {
  const auto row = GetParam();
  const double f = 0.145;
  const std::vector<double> exact = exact_extremes(row.phi, f, row.a1_mm * 1e-3);
  ASSERT_EQ(exact.size() - 1, row.swings);  // the reference chain itself, against the digest's count
  const TimeHistory h = drop_test(row.phi, row.a1_mm, 5.0);
  const Swings sw = swings(h, 0);
  ASSERT_EQ(sw.turning_values.size(), exact.size());
  for (size_t i = 0; i < exact.size(); ++i) EXPECT_NEAR(sw.turning_values[i], exact[i], 1e-8) << "turn " << i;
  EXPECT_TRUE(sw.comes_to_rest);
  EXPECT_EQ(count(h, SimulationEvent::Kind::stick), 1);
  EXPECT_EQ(count(h, SimulationEvent::Kind::slip), 0);
  // Each stroke is centred on φf/(1 + φ) while loading and on −φf/(1 − φ) while unloading, so
  // the decrements of a swing through the static position alternate 2φf/(1 ± φ); such a pair
  // averages 2φf/(1 − φ²), the book's 2φf (eq. (67)) to within φ² (0.4 % for row 1).
  for (size_t i = 0; i + 1 < exact.size(); ++i) {
    const double centre = i % 2 == 0 ? row.phi * f / (1 + row.phi) : -row.phi * f / (1 - row.phi);
    EXPECT_NEAR(0.5 * (sw.turning_values[i] + sw.turning_values[i + 1]), centre, 1e-8) << "stroke " << i;
  }
  const double pair = (std::abs(sw.turning_values[0]) - std::abs(sw.turning_values[2])) / 2;
  EXPECT_NEAR(pair / (2 * row.phi * f), 1.0, row.phi * row.phi * 1.01);
}

// Table 5: φ from the static tests, a₁ the first measured amplitude; the swing counts are those
// of the exact chain, row 5's (9) printed in the digest.
INSTANTIATE_TEST_SUITE_P(Speer, Table5,
                         ::testing::Values(Table5Row{0.0625, 39.0, 2}, Table5Row{0.0596, 39.5, 2},
                                           Table5Row{0.0276, 44.5, 6}, Table5Row{0.025, 44.5, 6},
                                           Table5Row{0.018, 46.0, 9}));

// Example 10: 1850 kgf on the Khanin spring, equilibrium at the kink of its two lines (260 and
// 356 kg/cm), released 20 mm up. Each side is half a cycle of its own linear oscillator: the
// half periods between passes through the static position alternate π/k (stiff side,
// k² = 356·981/1850) and π/k₁ (soft side, k₁² = 260·981/1850) — 0.2287 and 0.2676 s (digest,
// recomputed) — and the opposite excursion is √(260/356)·20 = 17.09 mm.
TEST(ProgressiveSpring, KhaninHalfPeriods) {
  const Scene s = load_scene(scenes_dir() + "khanin_spring_free_oscillation.toml");
  const TimeHistory h = simulate_scene(s, load_vehicle(s.vehicle_file));
  const Swings sw = swings(h, 0);
  const double stiff = kPi / std::sqrt(356.0 * kGcm / 1850.0), soft = kPi / std::sqrt(260.0 * kGcm / 1850.0);
  const auto half = sw.half_periods_between_crossings();
  ASSERT_GE(half.size(), 20u);
  // Crossings are read by Hermite interpolation of 2 ms samples: O(Δt⁴) ≈ 1e-9 s; the kink is
  // located to 1e-12 s.
  for (size_t i = 0; i < half.size(); ++i) EXPECT_NEAR(half[i], i % 2 == 0 ? stiff : soft, 1e-7) << i;
  // The digest's four figures: ±5e-5 s.
  EXPECT_NEAR(stiff, 0.2287, 5e-5);
  EXPECT_NEAR(soft, 0.2676, 5e-5);
  // A kink event every time the load passes its static position, nothing else.
  EXPECT_EQ(count(h, SimulationEvent::Kind::kink), static_cast<int>(sw.crossing_times.size()));
  EXPECT_EQ(h.events.size(), sw.crossing_times.size());
  // Energy is kept: every down swing reaches −√(260/356)·20 mm, every up swing 20 mm.
  for (size_t i = 1; i < sw.turning_values.size(); ++i)
    EXPECT_NEAR(sw.turning_values[i], i % 2 == 1 ? -std::sqrt(260.0 / 356.0) * 0.020 : 0.020, 1e-8) << i;
}

// Without "progressive_springs" the same scene runs the linear path on the tangent stiffness
// at the carried load (the stiffer line at the kink): one half period π/k throughout.
TEST(ProgressiveSpring, UnnamedCurveIsLinear) {
  Scene s = load_scene(scenes_dir() + "khanin_spring_free_oscillation.toml");
  s.simulation->effects.clear();
  const TimeHistory h = simulate_scene(s, load_vehicle(s.vehicle_file));
  EXPECT_TRUE(h.events.empty());
  const auto half = swings(h, 0).half_periods_between_crossings();
  ASSERT_GE(half.size(), 20u);
  const double stiff = kPi / std::sqrt(356.0 * kGcm / 1850.0);
  // The linear path is exact for free motion; the crossings are read to O(Δt⁴).
  for (double p : half) EXPECT_NEAR(p, stiff, 1e-7);
}

// Example 3: the loaded two-axle wagon at its bounce critical speed over 10 m joints with a
// 5 mm dip, released 25 mm down. The book: "the forced oscillations decay" with friction
// springs (Fig. 64). The digest's check (constant Coulomb force, bounce only) finds extremes
// of 17.74, 10.50, 3.27 mm and then sticking; here friction is the book's φR law on both axles
// and pitch is coupled, so the figures differ and the conclusion is the one tested: the swing
// falls below the 25 mm release within a half period, keeps falling, the springs stick, and
// what remains is the forced motion of about the track's own input a·|cos(π·2a₁/L)| = 0.91 mm
// (digest), not a resonance.
TEST(FrictionDecay, TwoAxleWagonAtCriticalSpeedStaysOutOfResonance) {
  Scene s = load_scene(scenes_dir() + "two_axle_freight_wagon_joints_friction.toml");
  s.simulation->duration = 12.0;
  const Vehicle v = load_vehicle(s.vehicle_file);
  const TimeHistory with = simulate_scene(s, v);
  const int bounce = 0;
  ASSERT_EQ(with.labels[bounce], "body.bounce");
  const Swings sw = swings(with, bounce);
  ASSERT_GE(sw.turning_values.size(), 4u);
  EXPECT_LT(std::abs(sw.turning_values[1]), 0.020);
  EXPECT_LT(std::abs(sw.turning_values[2]), std::abs(sw.turning_values[1]));
  EXPECT_LT(std::abs(sw.turning_values[3]), std::abs(sw.turning_values[2]));
  EXPECT_GE(count(with, SimulationEvent::Kind::stick), 2);
  auto peak_between = [&](const TimeHistory& h, double from, double to) {
    double peak = 0.0;
    for (int i = 0; i < h.time.size(); ++i)
      if (h.time(i) >= from && h.time(i) <= to) peak = std::max(peak, std::abs(h.displacement(i, bounce)));
    return peak;
  };
  const double late = peak_between(with, 10.0, 12.0);
  EXPECT_LT(late, 1.2 * 0.91e-3);  // within 20 % of the track's input: the springs mostly stuck
  EXPECT_GT(late, 0.5 * 0.91e-3);  // and it does ride over the joints

  // The same run without friction: undamped at the critical speed, the response grows without
  // bound (linearly in time) and passes the release amplitude within 12 s.
  s.simulation->effects.clear();
  const TimeHistory without = simulate_scene(s, v);
  EXPECT_TRUE(without.events.empty());
  EXPECT_GT(peak_between(without, 10.0, 12.0), 0.025);
  EXPECT_GT(peak_between(without, 10.0, 12.0), 1.5 * peak_between(without, 5.0, 7.0));
}

}  // namespace
}  // namespace railmodal::test

namespace railmodal::test {
namespace {

// Example 3 as the digest checks it independently: bounce only, a constant Coulomb force
// (the book's 1 ± φ ≈ 1, friction_law = "constant") with φf = 4.3 mm, f = 57.2 mm, at exactly the
// critical speed n = k₁, forcing k₁²(a/2)[cos nt + cos(nt + ψ)], ψ = 2π·2a₁/L = 2π·0.381, released
// 25 mm down: extrema −17.74 mm at 0.242 s, +10.50 mm at 0.484 s, −3.27 mm at 0.729 s (z down),
// then the spring sticks. The digest's forcing has the trailing wheel at a joint at t = 0; here
// the leading wheel is, and a bounce-only model sees the wheelbase only through the phase ψ mod
// 2π, so the axles are put L − 2a₁ = 6.19 m apart: the rear input lags by 2π·0.619 ≡ leads by ψ.
TEST(FrictionDecay, TwoAxleExample3ConstantCoulombCheck) {
  // The bundled scene (data/scenes/two_axle_example3_constant_friction.toml) and its vehicle:
  // speed L·k₁/2π written to 16 digits, k₁ = √(981/5.72) 1/s.
  const Scene s = load_scene(scenes_dir() + "two_axle_example3_constant_friction.toml");
  ASSERT_NEAR(s.simulation->speed, std::sqrt(981.0 / 5.72) * 10.0 / (2 * kPi), 1e-12);
  const TimeHistory h = simulate_scene(s, load_vehicle(s.vehicle_file));
  const Swings sw = swings(h, 0);
  ASSERT_GE(sw.turning_values.size(), 4u);
  // Up is positive here, down there. The digest's model puts the friction against the body's
  // own velocity, sgn(ż); here each axle's spring slides against the relative velocity of its
  // ends, ż − u̇ (the wheel rides the dip at up to n·a = 33 mm/s). Early, while the body moves
  // at ~260 mm/s, the two agree: the first extremes to 0.02 mm (the digest prints two decimals)
  // and their times to 3 ms; the later, slower swings feel the difference (the third turn comes
  // 9 ms early, and with two springs that cannot both stick while their wheels move apart the
  // motion goes on in slips of 2–3 mm instead of stopping).
  EXPECT_NEAR(sw.turning_values[1] * 1e3, 17.74, 0.02);
  EXPECT_NEAR(sw.turning_values[2] * 1e3, -10.50, 0.02);
  EXPECT_NEAR(sw.turning_values[3] * 1e3, 3.27, 0.02);
  EXPECT_NEAR(sw.turning_times[1], 0.242, 3e-3);
  EXPECT_NEAR(sw.turning_times[2], 0.484, 3e-3);
  EXPECT_NEAR(sw.turning_times[3], 0.729, 1e-2);
  // After the third turn the resonance does not build up again: no later swing reaches it.
  for (size_t i = 4; i < sw.turning_values.size(); ++i) EXPECT_LT(std::abs(sw.turning_values[i]), 3.27e-3) << i;
  EXPECT_GE(count(h, SimulationEvent::Kind::stick), 1);
}

}  // namespace
}  // namespace railmodal::test

namespace railmodal::test {
namespace {

// The double suspension of the springs digest §2.5 (eqs. (70)–(86)): a load on a leaf spring
// (f₁ = 8 cm, φ = 0.05) in series with a coil spring (f₂ = 4 cm), released 6 cm above its
// static position. The book lets the leaf always slide (decrement 2φf₁ = 0.80 cm per swing);
// the digest's own stick–slip simulation of the massless joint (§2.5, "a modelling gap")
// finds, and the series element here reproduces (issue 17, item 1):
//  - decrements 0.76, 0.77, 0.75, 0.76, 0.73, 0.72, 0.66, 0.53 cm per swing (printed to 0.01 cm:
//    ±0.005 cm, and 0.001 cm for reading our turns by cubic Hermite pieces);
//  - half periods 0.339–0.346 s at large amplitude (the book's 0.347 s, eq. (86)), then
//    0.28 s and 0.21 s, then π√(f₂/g) = 0.2006 s;
//  - a persistent oscillation on the coil alone, of 0.17–0.21 cm (≈ φf₂), period 0.401 s.
TEST(SeriesFrictionDecay, DoubleSuspensionStickSlip) {
  write_temp("double_suspension.toml", R"([vehicle]
name = "double suspension"
gravity = "981 cm/s^2"
[[body]]
name = "load"
weight = "1000 kgf"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "leaf over coil"
upper = "load"
point = ["0 m", "0 m", "0 m"]
load = "1000 kgf"
vertical = [{ kind = "leaf", static_deflection = "80 mm", relative_friction = 0.05 },
            { kind = "coil", static_deflection = "40 mm" }]
)");
  const Scene s = load_scene(write_temp("double_suspension_scene.toml", R"([scene]
name = "double suspension released"
vehicle = "double_suspension.toml"
dofs = "vertical"
[simulation]
duration = "6 s"
time_step = "1 ms"
effects = ["leaf_friction"]
[[simulation.initial]]
dof = "load.bounce"
displacement = "60 mm"
)"));
  const TimeHistory h = simulate_scene(s, load_vehicle(s.vehicle_file));
  const Swings sw = swings(h, 0);
  ASSERT_GE(sw.turning_values.size(), 14u);
  const std::vector<double> decrements_cm{0.76, 0.77, 0.75, 0.76, 0.73, 0.72, 0.66, 0.53};
  for (size_t k = 0; k < decrements_cm.size(); ++k)
    EXPECT_NEAR((std::abs(sw.turning_values[k]) - std::abs(sw.turning_values[k + 1])) * 100, decrements_cm[k], 0.006)
        << "swing " << k + 1;
  const auto half = sw.half_periods_between_turns();
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_GE(half[k], 0.339 - 5e-4) << k;
    EXPECT_LE(half[k], 0.346 + 5e-4) << k;
  }
  EXPECT_NEAR(half[7], 0.28, 5e-3);
  EXPECT_NEAR(half[8], 0.21, 5e-3);
  const double coil_alone = kPi * std::sqrt(4.0 / kGcm);  // π√(f₂/g) = 0.2006 s
  for (size_t k = 9; k < half.size(); ++k) EXPECT_NEAR(half[k], coil_alone, 1e-4) << k;
  for (size_t k = 10; k < sw.turning_values.size(); ++k) {
    EXPECT_GE(std::abs(sw.turning_values[k]) * 100, 0.17 - 0.005) << k;
    EXPECT_LE(std::abs(sw.turning_values[k]) * 100, 0.21 + 0.005) << k;
  }
}

// The resort car's free decay with its triple suspension (bogie-wagons-natural digest,
// Example 2, Table 11): the bundled scene, released 70 mm (body) and 31 mm (bogies) up.
struct ResortCarFriction {
  double phi1f1 = 0, phi3f3 = 0, phi1 = 0, phi3 = 0;  // the friction arrows φf (m) from the model's static loads
  double f1 = 0, f2 = 0, f3 = 0;                      // static deflections of leaf, coils, cradle springs (m)
};

ResortCarFriction resort_car_friction(const LinearSystem& sys) {
  ResortCarFriction r;
  for (size_t k = 0; k < sys.vehicle.elements.size(); ++k) {
    const auto& stages = sys.vehicle.elements[k].vertical_stages;
    const double P = sys.element_loads[k];
    if (stages.size() == 2) {  // axlebox: leaf in series with the coils
      r.phi1 = stages[0].relative_friction;
      r.f1 = P / (stages[0].stiffness * stages[0].count);
      r.f2 = P / (stages[1].stiffness * stages[1].count);
    } else if (stages.size() == 1 && stages[0].relative_friction > 0.0) {  // cradle
      r.phi3 = stages[0].relative_friction;
      r.f3 = P / (stages[0].stiffness * stages[0].count);
    }
  }
  r.phi1f1 = r.phi1 * r.f1;
  r.phi3f3 = r.phi3 * r.f3;
  return r;
}

// Table 11 prints the book's mean-friction solution (1 ± φ ≈ 1, the leaves always sliding):
// body 70 → 47.6 → 25.2 → 2.8 mm, losing 2(φ₁f₁ + φ₃f₃) = 22.4 mm per half period, bogies
// 31 → 17.8 → 4.6 mm. Here each leaf follows its law exactly. The first stroke loads every
// spring, the leaves sliding from the release: the body loses 2φ₁f₁/(1 + φ₁) + 2φ₃f₃/(1 + φ₃)
// (eq. (52) for each friction stage; 20.8 mm) in the half period (198c) gives the loading
// stroke (0.462 s). Ours: 70 → 49.38 mm in 0.4624 s; the bogie mode the friction offsets excite
// moves it by 0.2 mm, so 0.5 mm; 2 mm against the printed 47.6 (its 1 ± φ ≈ 1 and rounded φf).
// After that every reversal makes each axlebox leaf hold while the coils alone take the force
// across its band: the losses fall below the always-sliding ones (19.9, 16.5, 10.6 mm against
// the book's 22.4), and the car ends with the leaves stuck, moving a fraction of a mm on its coils.
TEST(SeriesFrictionDecay, ResortCarTable11) {
  const Scene s = load_scene(scenes_dir() + "resort_car_friction_decay.toml");
  const Vehicle v = load_vehicle(s.vehicle_file);
  const TimeHistory h = simulate_scene(s, v);
  const ResortCarFriction r = resort_car_friction(scene_system(s, v));
  const Swings body = swings(h, 0), bogie = swings(h, 2);
  ASSERT_EQ(h.labels[2], "bogie1.bounce");
  ASSERT_GE(body.turning_values.size(), 5u);
  const double loading = 2 * r.phi1f1 / (1 + r.phi1) + 2 * r.phi3f3 / (1 + r.phi3);
  EXPECT_NEAR(-body.turning_values[1], 0.070 - loading, 0.5e-3);
  EXPECT_NEAR(-body.turning_values[1], 0.0476, 2e-3);  // Table 11, t = T/2
  // The loading stroke's half period: the consistent T₂/2 = 0.9447/2 s (digest, Ex. 2) scaled
  // as (198c) scales it, √(Σ f/(1 + φ) / Σ f) (the springs stiffer by 1 + φ while loaded).
  const double loading_scale = std::sqrt((r.f1 / (1 + r.phi1) + r.f2 + r.f3 / (1 + r.phi3)) / (r.f1 + r.f2 + r.f3));
  EXPECT_NEAR(body.turning_times[1], 0.9447 / 2 * loading_scale, 2e-3);
  EXPECT_NEAR(-bogie.turning_values[1], 0.0178, 1e-3);  // Table 11: the bogie mode's 0.41 of the body's
  // Holds only take from the loss: every later swing loses less than the leaves would sliding
  // all the way, 2φ₁f₁/(1 ∓ φ₁) + 2φ₃f₃/(1 ∓ φ₃), and the book's 2Σφf is an upper bound too.
  for (size_t k = 1; k + 1 < 4; ++k) {
    const double lost = std::abs(body.turning_values[k]) - std::abs(body.turning_values[k + 1]);
    EXPECT_LT(lost, 2 * (r.phi1f1 + r.phi3f3)) << k;
    EXPECT_GT(lost, 0.4 * 2 * (r.phi1f1 + r.phi3f3)) << k;  // still the friction that decays it
  }
  double low = INFINITY, high = -INFINITY;
  for (int i = 0; i < h.time.size(); ++i)
    if (h.time(i) >= 2.0) low = std::min(low, h.displacement(i, 0)), high = std::max(high, h.displacement(i, 0));
  EXPECT_LT(high - low, 0.5e-3);  // the last second: a ripple of the body on the coils
}

// The resort car at its joint-critical speed (bundled scene, 38.11 km/h over 10 m joints with a
// 5 mm dip): the frictionless car grows by 0.94 mm per half period; with its leaves it settles.
// The series model says why: friction does work only where a leaf slips, and an axlebox leaf
// slips only once its element's stretch exceeds the hold stretch T/k_c the coils take alone
// (response::leaf_hold_stretch, 2.3 mm here; the energy balance πF₀A = Σ 4T·share·(|d|A − T/k_c)).
// The joints' 2.5 mm half-dip keeps the axlebox stretch about there, so the leaves hold nearly
// all the time and the car rides on its coils, the cradle springs (alone, 9 times the friction
// the input needs) held but for moments: the response is the forced motion of that stiffer car,
// not a resonance. Starting in equilibrium with every leaf stuck mid-band, measured after 5 s:
// the axlebox leaves never slip (0 ms summed over the 8; before the start was fixed, 6 of the 8
// slid from t = 0), the cradle springs slip 110 ms summed over the 4; body 0.86 mm over 15–20 s.
// Asserted: the body's bounce equal within 5 % over the last two 5 s windows (the joints' beat
// with the residual free motion on the coils moves it by about 2 %), below 1 mm, the axlebox
// leaves and the cradle springs each slipping less than 1 % of the time after 5 s.
TEST(SeriesFrictionDecay, ResortCarAtTheJointCriticalSpeedSettles) {
  Scene s = load_scene(scenes_dir() + "resort_car_friction_38kmh.toml");
  const Vehicle v = load_vehicle(s.vehicle_file);
  const TimeHistory with = simulate_scene(s, v);
  auto amplitude = [](const TimeHistory& h, int dof, double from, double to) {
    double low = INFINITY, high = -INFINITY;
    for (int i = 0; i < h.time.size(); ++i)
      if (h.time(i) >= from && h.time(i) <= to)
        low = std::min(low, h.displacement(i, dof)), high = std::max(high, h.displacement(i, dof));
    return 0.5 * (high - low);
  };
  const double early = amplitude(with, 0, 10.0, 15.0), late = amplitude(with, 0, 15.0, 20.0);
  EXPECT_NEAR(late / early, 1.0, 0.05);
  EXPECT_LT(late, 1e-3);
  const LinearSystem sys = scene_system(s, v);
  const auto& elements = sys.vehicle.elements;
  // Slipping time after 5 s, summed over the axlebox elements and over the cradle springs (a
  // slip still open at the end of the run counts to its end).
  std::vector<double> slipping_since(elements.size(), -1.0);
  double slipping = 0.0, cradle_slipping = 0.0;
  auto close = [&](int element, double until) {
    const double slipped = std::max(until - std::max(slipping_since[element], 5.0), 0.0);
    (elements[element].vertical_stages.size() == 2 ? slipping : cradle_slipping) += slipped;
    slipping_since[element] = -1.0;
  };
  for (const SimulationEvent& e : with.events) {
    if (e.kind == SimulationEvent::Kind::slip)
      slipping_since[e.element] = e.time;
    else if (e.kind == SimulationEvent::Kind::stick && slipping_since[e.element] >= 0.0)
      close(e.element, e.time);
  }
  for (size_t k = 0; k < elements.size(); ++k)
    if (slipping_since[k] >= 0.0) close(static_cast<int>(k), with.time(with.time.size() - 1));
  std::cout << "after 5 s: axlebox leaves slipping " << slipping * 1e3 << " ms, cradle springs "
            << cradle_slipping * 1e3 << " ms (summed over elements); body " << late * 1e3 << " mm\n";
  EXPECT_LT(cradle_slipping, 0.01 * 4 * 15.0);  // four cradle springs, held but for moments
  int axleboxes = 0;
  for (size_t k = 0; k < elements.size(); ++k)
    if (elements[k].vertical_stages.size() == 2) {
      ++axleboxes;
      EXPECT_NEAR(response::leaf_hold_stretch(sys, k), 2.3e-3, 0.1e-3);
    }
  EXPECT_LT(slipping, 0.01 * axleboxes * 15.0);

  s.simulation->effects.clear();
  const TimeHistory without = simulate_scene(s, v);
  EXPECT_GT(amplitude(without, 0, 15.0, 20.0), 10 * late);
  EXPECT_GT(amplitude(without, 0, 15.0, 20.0), 1.2 * amplitude(without, 0, 10.0, 15.0));  // growing
}

// A single mass of 1000 kgf on a leaf (f₁ = 80 mm, φ) in series with a coil (f₂ = 40 mm), over
// 10 m rails (1.7 m from a joint, where the track moves at t = 0): the friction-limited amplitude of docs/scenes.md,
// πF₀A = 4T·share·(A − h), is an upper bound of where a resonance friction stops settles, not its value. Its equivalent
// linearisation keeps the damping of the leaf-and-coil loop but not the stiffening while the
// leaf holds (stiffness k_e rising toward k_c as X → h), which detunes the resonance. In the
// bound's terms, g/D the growth over the decrement per half period (the critical-speed row),
// A ≤ h/(1 − g/D), h = φf₂ the hold stretch (response::leaf_hold_stretch). Measured (the
// resonant harmonic over 50–60 s): φ = 0.05, 2 mm dip: g/D = 0.196, bound 2.49 mm, settled
// 1.50 mm (40 % below); φ = 0.05, 5 mm: g/D = 0.491, 3.93 mm, 3.76 mm (4 % below); φ = 0.10,
// 5 mm: g/D = 0.245, 5.30 mm, 3.74 mm (29 % below). The bound is asserted as it stands: it
// must never be exceeded.
std::string leaf_over_coil_scene(double phi, double dip_mm, const std::string& initial) {
  std::ostringstream vehicle;
  vehicle << R"([vehicle]
name = "leaf over coil"
gravity = "981 cm/s^2"
[[body]]
name = "load"
weight = "1000 kgf"
inertia = { roll = "0 kg*m^2", pitch = "0 kg*m^2", yaw = "0 kg*m^2" }
centre_of_gravity = ["1.7 m", "0 m", "0 m"]
held = ["lateral", "roll", "pitch", "yaw"]
[[element]]
name = "leaf over coil"
upper = "load"
point = ["1.7 m", "0 m", "0 m"]
load = "1000 kgf"
vertical = [{ kind = "leaf", static_deflection = "80 mm", relative_friction = )"
          << phi << R"( },
            { kind = "coil", static_deflection = "40 mm" }]
)";
  write_temp("leaf_over_coil.toml", vehicle.str());
  std::ostringstream scene;
  scene << R"([scene]
name = "leaf over coil on 10 m rails"
vehicle = "leaf_over_coil.toml"
dofs = "vertical"
[speed]
min = "30 km/h"
max = "80 km/h"
step = "0.5 km/h"
[[source]]
kind = "rail_joints"
rail_length = "10 m"
joints = "opposite"
dip_depth = ")"
        << dip_mm << R"( mm"
[simulation]
speed = "51.8 km/h"
duration = "60 s"
time_step = "5 ms"
effects = ["leaf_friction"]
)" << initial;
  return write_temp("leaf_over_coil_scene.toml", scene.str());
}

// Amplitude of the component at ω of a DOF's displacement over whole periods from `from`
// within `to` (trapezoidal sums at the output step, 200 samples a period here).
double harmonic_amplitude(const TimeHistory& h, int dof, double omega, double from, double to) {
  const double period = 2 * kPi / omega, end = from + std::floor((to - from) / period) * period;
  std::complex<double> sum = 0.0;
  double span = 0.0;
  for (int i = 1; i < h.time.size(); ++i)
    if (h.time(i - 1) >= from && h.time(i) <= end) {
      const double dt = h.time(i) - h.time(i - 1);
      sum += 0.5 * dt *
             (h.displacement(i - 1, dof) * std::exp(std::complex<double>(0, -omega * h.time(i - 1))) +
              h.displacement(i, dof) * std::exp(std::complex<double>(0, -omega * h.time(i))));
      span += dt;
    }
  return 2.0 * std::abs(sum) / span;
}

struct FrictionLimited {
  double phi, dip_mm;
};
class FrictionLimitedAmplitude : public ::testing::TestWithParam<FrictionLimited> {};

TEST_P(FrictionLimitedAmplitude, IsAnUpperBoundOfTheSettledStretch) {
  Scene s = load_scene(leaf_over_coil_scene(GetParam().phi, GetParam().dip_mm, ""));
  const Vehicle v = load_vehicle(s.vehicle_file);
  const CriticalSpeedStudy study = study_critical_speeds(s, v);
  const CriticalSpeed* r = nullptr;
  for (const auto& c : study.critical_speeds)
    if (c.harmonic == 1) r = &c;
  ASSERT_NE(r, nullptr);
  ASSERT_TRUE(r->friction_stops);
  const double ratio = r->growth_per_half_period / r->friction_decrement_per_half_period;
  const double hold = response::leaf_hold_stretch(scene_system(s, v), 0);
  EXPECT_NEAR(hold, GetParam().phi * 0.040, 1e-6);  // h = T/k_c = φP·f₂/P
  const double bound = hold / (1.0 - ratio);
  s.simulation->speed = r->speed;  // the frictionless resonance, 51.8 km/h
  const TimeHistory h = simulate_scene(s, v);
  // The resonant harmonic's amplitude (the bound's A), projected over whole periods: the
  // joints' other harmonics add forced motion that no energy balance of one harmonic counts.
  const double omega = 2 * kPi * r->speed / 10.0;
  const double settled = harmonic_amplitude(h, 0, omega, 50.0, 60.0);
  EXPECT_NEAR(settled / harmonic_amplitude(h, 0, omega, 40.0, 50.0), 1.0,
              0.05);  // settled: two 10 s windows within 5 %
  EXPECT_LE(settled, bound);
  std::cout << "phi " << GetParam().phi << " dip " << GetParam().dip_mm << " mm: g/D " << ratio << ", bound "
            << bound * 1e3 << " mm, settled " << settled * 1e3 << " mm (" << 100 * (1 - settled / bound)
            << " % below)\n";
}

INSTANTIATE_TEST_SUITE_P(LeafOverCoil, FrictionLimitedAmplitude,
                         ::testing::Values(FrictionLimited{0.05, 2.0}, FrictionLimited{0.05, 5.0},
                                           FrictionLimited{0.10, 5.0}));

// A car standing in equilibrium while the track moves under it starts with each series leaf
// stuck in the middle of its band (docs/scenes.md), whatever the track's rate at t = 0: the
// first event of the element is a stick at t = 0. Released from a displacement given in
// [[simulation.initial]], the leaf slides from the release (the book's initial condition).
TEST(SeriesFrictionStart, InEquilibriumTheLeafStartsStuckReleasedItSlides) {
  for (const bool released : {false, true}) {
    Scene s = load_scene(leaf_over_coil_scene(
        0.05, 5.0, released ? "[[simulation.initial]]\ndof = \"load.bounce\"\ndisplacement = \"20 mm\"\n" : ""));
    s.simulation->duration = 1.0;
    const TimeHistory h = simulate_scene(s, load_vehicle(s.vehicle_file));
    const bool stuck_at_start =
        !h.events.empty() && h.events.front().time == 0.0 && h.events.front().kind == SimulationEvent::Kind::stick;
    EXPECT_EQ(stuck_at_start, !released) << (released ? "released" : "in equilibrium");
  }
}

// A leaf whose static load is tension carries no friction in the frequency domain either: the
// law is φ × a compressive load, and the simulation gives such a leaf none (issue 17, F3).
TEST(SeriesFrictionCriterion, ALeafInTensionCarriesNoFriction) {
  const Scene s = load_scene(leaf_over_coil_scene(0.05, 5.0, ""));
  LinearSystem sys = scene_system(s, load_vehicle(s.vehicle_file));
  ASSERT_TRUE(has_leaf_friction(sys));
  EXPECT_GT(response::equivalent_friction_damping(sys, 0, 9.0, 5e-3), 0.0);
  sys.element_loads[0] = -sys.element_loads[0];
  EXPECT_FALSE(has_leaf_friction(sys));
  EXPECT_EQ(response::equivalent_friction_damping(sys, 0, 9.0, 5e-3), 0.0);
  EXPECT_EQ(response::leaf_hold_stretch(sys, 0), 0.0);
}

}  // namespace
}  // namespace railmodal::test
