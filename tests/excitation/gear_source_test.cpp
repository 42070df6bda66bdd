// The driving gear as an excitation source (issue 22 item 4; docs/driving_gear.md, "As an
// excitation"): the generalised load against the gear's own forces, and the simple form it
// degenerates to.
#include <cmath>
#include <complex>

#include "test_support.hpp"

namespace railmodal {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::complex<double> kI(0.0, 1.0);

std::string scene_file(const std::string& name) { return std::string(RAILMODAL_DATA_DIR) + "/scenes/" + name; }

int dof(const LinearSystem& system, const std::string& label) {
  for (int i = 0; i < system.size(); ++i)
    if (system.dofs[i].label == label) return i;
  ADD_FAILURE() << "no degree of freedom " << label;
  return 0;
}

// Harmonic k of a GearHarmonic series as the phasor of Re(A e^{ikωt}), φ = ωt (φ₀ = 0, forward).
std::complex<double> phasor(const GearHarmonic& h) { return {h.cosine, -h.sine}; }

// The Су scene: the generalised load of the gear source at one speed carries exactly the
// gear's own ΣX, ΣMX and wheel loads (the same numbers through both paths).
TEST(GearSource, GeneralizedLoadEqualsTheGearsForces) {
  const Scene scene = load_scene(scene_file("su_driving_gear.toml"));
  ASSERT_EQ(scene.sources.size(), 1u);
  const ExcitationSource& source = *scene.sources[0];
  EXPECT_EQ(source.kind(), "driving_gear");
  const LinearSystem system = assemble(load_vehicle(scene.vehicle_file), scene.dofs);
  const double speed = 100 / 3.6;
  const DrivingGear description = load_driving_gear(std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml");
  GearOptions options;
  options.harmonics = 3;
  const GearResult gear = solve_driving_gear(description, speed, options);
  ASSERT_EQ(source.harmonic_count(), 3);
  for (int k = 1; k <= 3; ++k) {
    const Eigen::VectorXcd q = generalized_load(system, source.load(system, speed, k));
    // Forces of 10³–10⁵ N summed over a dozen points: 1e-9 relative is round-off, far below
    // any error of placement (a misplaced force changes a term by its whole size).
    const double scale = 1e-9 * std::abs(phasor(gear.surging_harmonics[1]));
    EXPECT_LT(std::abs(q(dof(system, "frame.longitudinal")) - phasor(gear.surging_harmonics[k])), scale) << k;
    // The vehicle's yaw is + to the left; the book's nosing ΣMX + turns the engine to the right.
    EXPECT_LT(std::abs(q(dof(system, "frame.yaw")) + phasor(gear.nosing_harmonics[k])), scale) << k;
    // Each axle body carries its wheels' vertical forces, minus their dynamic loads ΔP, and
    // their moment about x (y + left): −S·(−ΔP_right) + S·(−ΔP_left).
    const double S = 0.795;
    for (int a = 0; a < 3; ++a) {
      const std::string axle = "axle" + std::to_string(a + 1);
      const auto right = phasor(gear.wheels[2 * a].harmonics[k]);
      const auto left = phasor(gear.wheels[2 * a + 1].harmonics[k]);
      EXPECT_LT(std::abs(q(dof(system, axle + ".bounce")) + right + left), scale) << axle << " k " << k;
      EXPECT_LT(std::abs(q(dof(system, axle + ".roll")) - (right - left) * S), scale) << axle << " k " << k;
    }
    // The frame's bounce carries only the guide-bar forces Z.
    std::complex<double> guides = 0.0;
    for (const auto& z : gear.guide_harmonics) guides += phasor(z[k]);
    EXPECT_LT(std::abs(q(dof(system, "frame.bounce")) - guides), scale) << k;
    // Z acts at (x_axle + L, −lateral, 0), on the frame's reference point's plane z = 0 (where X
    // and the masses' horizontal pulls act too, so they add no pitch): its moment about the
    // reference point is r × (0, 0, Z) = (y·Z, −x·Z, 0), so frame pitch −Σ Z·(x_axle + L) and
    // frame roll Σ (−lateral)·Z. The scene places the axles where su.toml does.
    std::complex<double> pitch = 0.0, roll = 0.0;
    for (size_t c = 0; c < description.cylinders.size(); ++c) {
      const GearCylinder& cyl = description.cylinders[c];
      const double x = description.axles[cyl.axle].position + cyl.rod_length;
      pitch -= phasor(gear.guide_harmonics[c][k]) * x;
      roll -= phasor(gear.guide_harmonics[c][k]) * cyl.lateral;
    }
    // The moments are forces of the same size times metres: the same round-off, times 10 m.
    EXPECT_LT(std::abs(q(dof(system, "frame.pitch")) - pitch), 10 * scale) << k;
    EXPECT_LT(std::abs(q(dof(system, "frame.roll")) - roll), 10 * scale) << k;
    // A check of something: Z pitches the frame in harmonics 1 and 3; the second cancels
    // between cranks at 90° (both guides at the same x), as in bounce.
    if (k != 2) {
      EXPECT_GT(std::abs(pitch), 1e2) << k;
    }
    EXPECT_GT(std::abs(roll), 1e2) << k;
  }
  // The second harmonic is there, and its surging cancels between cranks at 90°; the third's
  // wheel loads do not (the default harmonics = 3 keeps them).
  const Eigen::VectorXcd q2 = generalized_load(system, source.load(system, speed, 2));
  EXPECT_GT(std::abs(q2(dof(system, "axle2.roll"))), 1e3);
  EXPECT_LT(std::abs(q2(dof(system, "frame.longitudinal"))), 1e-9 * std::abs(phasor(gear.surging_harmonics[1])));
  const Eigen::VectorXcd q3 = generalized_load(system, source.load(system, speed, 3));
  EXPECT_GT(std::abs(q3(dof(system, "axle2.bounce"))), 1e3);
}

std::string gear_scene(const std::string& source_keys) {
  return test::write_temp("gear_scene.toml", "[scene]\nvehicle = \"" + std::string(RAILMODAL_DATA_DIR) +
                                                 "/vehicles/su_locomotive.toml\"\ndofs = \"all\"\n"
                                                 "[speed]\nmin = \"10 km/h\"\nmax = \"20 km/h\"\nstep = \"10 km/h\"\n"
                                                 "[[source]]\nkind = \"driving_gear\"\ngear = \"" +
                                                 std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml\"\n"
                                                 "body = \"frame\"\n" + source_keys);
}

// Without `harmonics` the source takes three: the third does not cancel (docs/scenes.md); a
// GearExcitation built in code takes the same default as the scene.
TEST(GearSource, DefaultsToThreeHarmonics) {
  const Scene scene = load_scene(gear_scene(""));
  ASSERT_EQ(scene.sources.size(), 1u);
  EXPECT_EQ(scene.sources[0]->harmonic_count(), 3);
  GearExcitation in_code;
  in_code.gear = load_driving_gear(std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml");
  EXPECT_EQ(make_source(in_code)->harmonic_count(), 3);
}

// balance_fraction balances that share of the reciprocating masses, as `balance --fraction`:
// the scene's load equals the gear balanced by balance_driving_gear with the same options, and
// differs from the unbalanced and from the fraction-0 balance.
TEST(GearSource, BalanceFractionBalancesThatShare) {
  const DrivingGear description = load_driving_gear(std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml");
  BalanceOptions options;
  options.rule = VerticalRule::book;
  options.reciprocating_fraction = 0.5;
  options.trade_off_fractions.clear();
  GearExcitation p;
  p.gear = balance_driving_gear(description, description.design_speed, options).balanced;
  p.body = "frame";
  p.harmonics = 3;
  const auto expected = make_source(p);
  const Scene half = load_scene(gear_scene("balance = \"book\"\nbalance_fraction = 0.5\n"));
  const Scene none = load_scene(gear_scene("balance = \"book\"\nbalance_fraction = 0\n"));
  const LinearSystem system = assemble(load_vehicle(half.vehicle_file), half.dofs);
  const int surge = dof(system, "frame.longitudinal");
  const auto qe = generalized_load(system, expected->load(system, 25.0, 1))(surge);
  const auto qh = generalized_load(system, half.sources[0]->load(system, 25.0, 1))(surge);
  const auto q0 = generalized_load(system, none.sources[0]->load(system, 25.0, 1))(surge);
  // The same numbers through both paths: round-off only.
  EXPECT_LT(std::abs(qh - qe), 1e-9 * std::abs(qe));
  // Balancing half the reciprocating masses takes a sizeable share off the surging.
  EXPECT_LT(std::abs(qh), 0.9 * std::abs(q0));
}

// An axle the gear file does not place needs an x in the scene: no silent x = 0.
TEST(GearSource, AxleWithoutPositionNeedsX) {
  const std::string gear = test::write_temp("unplaced_gear.toml", R"toml(
[driving_gear]
wheel_diameter = "1850 mm"
wheel_plane_spacing = "1590 mm"
[[driving_gear.axle]]
name = "driving"
crank_radius = "350 mm"
static_wheel_load = "9000 kgf"
)toml");
  const auto scene = [&](const std::string& axle_tables) {
    return test::write_temp("unplaced_scene.toml", "[scene]\nvehicle = \"" + std::string(RAILMODAL_DATA_DIR) +
                                                       "/vehicles/su_locomotive.toml\"\n[speed]\nmin = \"10 km/h\"\n"
                                                       "max = \"20 km/h\"\n[[source]]\nkind = \"driving_gear\"\ngear = \"" +
                                                       gear + "\"\nbody = \"frame\"\n" + axle_tables);
  };
  EXPECT_THROW(load_scene(scene("")), InputError);
  EXPECT_THROW(load_scene(scene("[[source.axle]]\nname = \"driving\"\nbody = \"axle2\"\n")), InputError);
  EXPECT_NO_THROW(load_scene(scene("[[source.axle]]\nname = \"driving\"\nx = \"0 m\"\nbody = \"axle2\"\n")));
}

TEST(GearSource, BalanceFractionOutsideZeroToOneIsRefused) {
  EXPECT_THROW(load_scene(gear_scene("balance = \"book\"\nbalance_fraction = 1.5\n")), InputError);
  EXPECT_THROW(load_scene(gear_scene("balance_fraction = 0.5\n")), InputError);
  EXPECT_THROW(load_scene(gear_scene("balance = \"book\"\nbalance_fraction = 0.5\nbalance_alpha = 0.3\n")),
               InputError);
}

// The crank angle at t = 0 turns harmonic k by k·φ₀ (the scene's phase convention); running
// backward conjugates it; the forces grow as V².
TEST(GearSource, PhaseAtTimeZeroAndSpeedScaling) {
  GearExcitation p;
  p.gear = load_driving_gear(std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml");
  p.body = "frame";
  const Scene scene = load_scene(scene_file("su_driving_gear.toml"));
  const LinearSystem system = assemble(load_vehicle(scene.vehicle_file), scene.dofs);
  const int surge = dof(system, "frame.longitudinal");
  const auto base = make_source(p);
  p.crank_angle = 0.3;
  const auto turned = make_source(p);
  p.gear.rotation = GearRotation::backward;
  const auto backward = make_source(p);
  for (int k = 1; k <= 2; ++k) {
    const auto q0 = generalized_load(system, base->load(system, 20.0, k))(surge);
    const auto q1 = generalized_load(system, turned->load(system, 20.0, k))(surge);
    const auto qb = generalized_load(system, backward->load(system, 20.0, k))(surge);
    const auto q40 = generalized_load(system, base->load(system, 40.0, k))(surge);
    const double tol = 1e-12 * std::abs(q0) + 1e-9;  // round-off of one complex product
    EXPECT_LT(std::abs(q1 - q0 * std::exp(kI * (0.3 * k))), tol) << k;
    EXPECT_LT(std::abs(qb - std::conj(q1)), tol) << k;
    EXPECT_LT(std::abs(q40 - 4.0 * q0), 4 * tol) << k;
  }
  EXPECT_DOUBLE_EQ(base->load_scale(2.0, 1.0), 4.0);
}

// A rod with J_G = m·d·(L − d) is dynamically two masses (Kvasnikov (33)–(34)): on one rigid
// body the gear then loads surge and bounce exactly as the simple form's rotating mass m·d/L on
// the crank pin and reciprocating mass m_k + m(1 − d/L). The simple form's rotating mass turns
// as a wheel turns running backward, its angle from the front dead centre: it is the gear
// running backward with φ₀ = π − φ (docs/driving_gear.md, "The simple form").
TEST(GearSource, TwoMassRodRecoversTheSimpleForm) {
  GearCylinder c;
  c.name = "right";
  c.lateral = 1.0;
  c.crank_radius = 0.35;
  c.rod_length = 2.35;
  c.rod_mass = 225.0;
  c.rod_centre_of_mass = 1.5;
  c.rod_inertia = c.rod_mass * c.rod_centre_of_mass * (c.rod_length - c.rod_centre_of_mass);
  c.reciprocating_mass = 360.0;
  DrivingGear gear;
  gear.wheel_diameter = 1.85;
  gear.wheel_plane_half_spacing = 0.795;
  gear.rotation = GearRotation::backward;
  gear.cylinders = {c};
  gear.axles.resize(1);
  gear.axles[0].name = "driving";
  gear.axles[0].crank_radius = 0.35;
  gear.axles[0].right.static_load = gear.axles[0].left.static_load = 9000 * 9.81;
  const double phi = 0.4;  // the simple form's angle at t = 0
  GearExcitation p;
  p.gear = gear;
  p.body = "frame";
  p.crank_angle = kPi - phi;
  p.harmonics = 4;
  const auto exact = make_source(p);

  Unbalance u;
  u.body = "frame";
  u.wheel_diameter = 1.85;
  u.harmonics = 4;
  const double pin_share = c.rod_mass * c.rod_centre_of_mass / c.rod_length;
  u.rotating.push_back({0.0, -1.0, 0.0, pin_share * c.crank_radius, phi});
  u.reciprocating.push_back({c.rod_length, -1.0, 0.0, c.reciprocating_mass + c.rod_mass - pin_share, c.crank_radius,
                             c.crank_radius / c.rod_length, phi});
  const auto simple = make_source(u);

  const std::string file = test::write_temp("frame.toml", R"toml(
[vehicle]
name = "a frame free to surge and bounce"
[[body]]
name = "frame"
mass = "60 t"
inertia = { roll = "1e5 kg*m^2", pitch = "6e5 kg*m^2", yaw = "6e5 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
free = ["longitudinal"]
[[element]]
upper = "frame"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "5 MN/m" }
lateral = { stiffness = "5 MN/m" }
longitudinal = { stiffness = "5 MN/m" }
)toml");
  const LinearSystem system = assemble(load_vehicle(file), DofSet::all);
  for (int k = 1; k <= 4; ++k) {
    const Eigen::VectorXcd qe = generalized_load(system, exact->load(system, 25.0, k));
    const Eigen::VectorXcd qs = generalized_load(system, simple->load(system, 25.0, k));
    // Both are exact to round-off (a 360-point and a 256-point Fourier sum of analytic
    // functions whose harmonics fall as λ^k); 1e-8 of the first harmonic's surging.
    const double tol = 1e-8 * std::abs(generalized_load(system, simple->load(system, 25.0, 1))(dof(system, "frame.longitudinal")));
    for (const char* d : {"frame.longitudinal", "frame.bounce"})
      EXPECT_LT(std::abs(qe(dof(system, d)) - qs(dof(system, d))), tol) << d << " k " << k;
  }
}

TEST(GearSource, RefusesAxlePlacesThatDoNotMatch) {
  GearExcitation p;
  p.gear = load_driving_gear(std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml");
  p.axles.resize(2);
  EXPECT_THROW(make_source(p), std::invalid_argument);
  p.axles.clear();
  p.harmonics = 0;
  EXPECT_THROW(make_source(p), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal
