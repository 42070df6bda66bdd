// Excitation sources: dip harmonics, wheelbase filtering, staggered joints, unbalance.
#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

// Simpson's rule on the dip itself: the reference for the closed forms of dip_harmonic.
double numerical_harmonic(DipShape shape, double h, double l, double period, int k) {
  const int n = 20000;  // even; the integrand is smooth on the dip, error ~ (l/n)⁴
  auto eta = [&](double s) {
    switch (shape) {
      case DipShape::cosine: return 0.5 * h * (1.0 + std::cos(2 * kPi * s / l));
      case DipShape::triangular: return h * (1.0 - 2.0 * std::abs(s) / l);
      case DipShape::parabolic: return h * (1.0 - 4.0 * s * s / (l * l));
    }
    return 0.0;
  };
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double s = -l / 2 + l * i / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * -eta(s) * std::cos(2 * kPi * k * s / period);
  }
  return 2.0 / period * sum * (l / n) / 3.0;
}

// The triangular dip has a kink at its centre where Simpson loses order: 1e-8 of the depth
// covers it; the smooth shapes agree to 1e-10.
TEST(DipHarmonic, ClosedFormsMatchQuadrature) {
  for (DipShape shape : {DipShape::cosine, DipShape::triangular, DipShape::parabolic})
    for (double l : {0.3, 1.5, 10.0})
      for (int k = 1; k <= 8; ++k) {
        const double closed = dip_harmonic(shape, 0.004, l, 10.0, k);
        EXPECT_NEAR(closed, numerical_harmonic(shape, 0.004, l, 10.0, k), 0.004 * 1e-8)
            << to_string(shape) << " l = " << l << " k = " << k;
      }
}

// The book's joint: a cosine over the whole rail, y = −y0 + a cos nt (163), has only the
// fundamental, of amplitude a = half the dip.
TEST(DipHarmonic, WholeRailCosineIsTheBooksPath) {
  EXPECT_NEAR(dip_harmonic(DipShape::cosine, 0.005, 10.0, 10.0, 1), -0.0025, 1e-15);
  for (int k = 2; k <= 5; ++k) EXPECT_NEAR(dip_harmonic(DipShape::cosine, 0.005, 10.0, 10.0, k), 0.0, 1e-18);
}

// Two-axle digest, Example 3 table: the wheelbase filters the joint input, bounce ∝
// |cos(π·2a1/L)| = 0.365 / 0.576 / 0.698 for L = 10 / 12.5 / 15 m, pitch ∝ |sin(π·2a1/L)| =
// 0.931 / 0.818 / 0.716. Checked on the generalised load of the assembled wagon against the
// load of all four springs moved together (4c·a) and tilted together (4c·a·a1); ±0.0005.
TEST(RailJoints, WheelbaseFiltersBounceAndPitch) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  const double c = series_stiffness(sys.vehicle.elements[0].vertical_stages);
  const double a1 = std::abs(sys.vehicle.elements[0].point.x());
  const int bounce = sys.index_of("body.bounce"), pitch = sys.index_of("body.pitch");
  const double expected_bounce[] = {0.365, 0.576, 0.698}, expected_pitch[] = {0.931, 0.818, 0.716};
  const double lengths[] = {10.0, 12.5, 15.0};
  for (int i = 0; i < 3; ++i) {
    RailJoints j;
    j.rail_length = lengths[i];
    j.dip_depth = 0.005;
    const auto source = make_source(j);
    const double a = 0.0025;
    const Eigen::VectorXcd Q = generalized_load(sys, source->load(sys, 20.0, 1));
    EXPECT_NEAR(std::abs(Q(bounce)) / (4 * c * a), expected_bounce[i], 5e-4) << "L = " << lengths[i];
    EXPECT_NEAR(std::abs(Q(pitch)) / (4 * c * a * a1), expected_pitch[i], 5e-4) << "L = " << lengths[i];
  }
}

// Two-axle digest §2.8: staggered joints excite roll too; opposite joints do not.
TEST(RailJoints, StaggeredJointsExciteRoll) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::all);
  const int roll = sys.index_of("body.roll");
  ASSERT_GE(roll, 0);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.005;
  const Eigen::VectorXcd square = generalized_load(sys, make_source(j)->load(sys, 20.0, 1));
  j.staggered = true;
  const Eigen::VectorXcd staggered = generalized_load(sys, make_source(j)->load(sys, 20.0, 1));
  EXPECT_LT(std::abs(square(roll)), 1e-9 * square.norm());
  EXPECT_GT(std::abs(staggered(roll)), 0.1 * staggered.norm());
}

// The second wheelset meets the profile 2a1/V later.
TEST(RailJoints, WheelDelaysFollowTheWheelbase) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.005;
  const HarmonicLoad load = make_source(j)->load(sys, 20.0, 1);
  ASSERT_EQ(load.wheels.size(), 4u);
  double longest = 0.0;
  for (const auto& w : load.wheels) longest = std::max(longest, w.delay_s);
  EXPECT_NEAR(longest, 3.81 / 20.0, 1e-12);
}

// A source keeps its wheelset list per thread from load to load; a system whose wheels stand
// elsewhere (another wheelbase, as a study's variant may have) gets its own. Loads on the wagon,
// on a copy with the rear axle 1 m further back, and on the wagon again: each load's longest
// delay is its own wheelbase over the speed (the same bits as the first load on the wagon).
TEST(RailJoints, WheelsetsFollowTheSystemFromLoadToLoad) {
  const LinearSystem wagon = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  LinearSystem longer = wagon;
  double rear = longer.track_inputs.front().point.x();
  for (const auto& t : longer.track_inputs) rear = std::min(rear, t.point.x());
  for (auto& t : longer.track_inputs)
    if (t.point.x() <= rear + 1e-3) t.point.x() -= 1.0;  // both wheels of the rear axle
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.005;
  const auto source = make_source(j);
  auto longest = [&](const LinearSystem& system) {
    double delay = 0.0;
    for (const auto& w : source->load(system, 20.0, 1).wheels) delay = std::max(delay, w.delay_s);
    return delay;
  };
  const double first = longest(wagon);
  EXPECT_NEAR(first, 3.81 / 20.0, 1e-12);
  EXPECT_NEAR(longest(longer), 4.81 / 20.0, 1e-12);
  EXPECT_EQ(longest(wagon), first);
}

// Unbalance digest §3: two cranks at 90° (left lags right) give a vertical force on the axle
// of √2·m ρ ω², ω = 2V/D.
TEST(Unbalance, QuadratureCranksSumToRootTwo) {
  const std::string file = write_temp("unbalance.toml", R"toml(
[vehicle]
name = "unbalanced wheelset on a frame"
[[body]]
name = "frame"
mass = "10 t"
inertia = { roll = "1e4 kg*m^2", pitch = "1e4 kg*m^2", yaw = "1e4 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
[[element]]
upper = "frame"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "1 MN/m" }
lateral = { stiffness = "1 MN/m" }
rotational = { roll = "1 MN*m/rad", pitch = "1 MN*m/rad", yaw = "1 MN*m/rad" }
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::vertical);
  Unbalance u;
  u.body = "frame";
  u.wheel_diameter = 1.85;
  u.rotating.push_back({0.0, 0.795, 0.0, 2.0, 0.0});
  u.rotating.push_back({0.0, -0.795, 0.0, 2.0, -kPi / 2});
  const double V = 100.0 / 3.6, omega = 2 * V / 1.85;
  const Eigen::VectorXcd Q = generalized_load(sys, make_source(u)->load(sys, V, 1));
  EXPECT_NEAR(std::abs(Q(sys.index_of("frame.bounce"))), std::sqrt(2.0) * 2.0 * omega * omega, 1e-9 * omega * omega);
}

// Two-axle digest, Example 1: K = 22 000 kgf/cm, half wheelset 733 kgf (m = 733/g), 10 m rails
// at 100 km/h: ρ² = 29 443 s⁻² (book 29 300), n² = 304.6 s⁻², n²/ρ² = 1.03 %, so the wheel
// follows the dip 1/(1 − 0.0103) = 1.0105 times over. ±1e-4 (the digest's 3 figures).
TEST(RailJoints, TrackStiffnessExample1) {
  const LinearSystem sys = assemble(load_vehicle(data_file("two_axle_freight_wagon.toml")), DofSet::vertical);
  RailJoints j;
  j.rail_length = 10.0;
  j.dip_depth = 0.005;
  const double V = 100 / 3.6;
  const double rigid = std::abs(make_source(j)->load(sys, V, 1).wheels[0].amplitude(2));
  j.track_stiffness = 22000 * kKgfPerCm;
  j.half_wheelset_mass = 733 * kKgf / 9.81;
  const double elastic = std::abs(make_source(j)->load(sys, V, 1).wheels[0].amplitude(2));
  EXPECT_NEAR(elastic / rigid, 1.0105, 1e-4);
}

// Unbalance digest §3: with the cranks of the two sides at 90°, the first-order horizontal
// forces are in quadrature (yaw moment √2·b·F₁) and the second-order ones in antiphase, so
// they cancel in surge and double in yaw (2·b·F₂), F_n = m r ω² A_n. On a frame whose yaw is
// free, through the generalised load; 1e-9 relative.
TEST(Unbalance, SecondOrderDoublesInYaw) {
  const std::string file = write_temp("frame.toml", R"toml(
[vehicle]
name = "frame"
[[body]]
name = "frame"
mass = "60 t"
inertia = { roll = "9e4 kg*m^2", pitch = "6e5 kg*m^2", yaw = "6e5 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "0 m"]
[[element]]
upper = "frame"
point = ["0 m", "0 m", "0 m"]
vertical = { stiffness = "5 MN/m" }
lateral = { stiffness = "5 MN/m" }
rotational = { roll = "5 MN*m/rad", pitch = "5 MN*m/rad", yaw = "5 MN*m/rad" }
)toml");
  const LinearSystem sys = assemble(load_vehicle(file), DofSet::all);
  Unbalance u;
  u.body = "frame";
  u.wheel_diameter = 1.85;
  const double m = 365.75, r = 0.35, lambda = 0.35 / 2.35, b = 1.14;
  u.reciprocating.push_back({0.0, -b, 0.9, m, r, lambda, 0.0});
  u.reciprocating.push_back({0.0, b, 0.9, m, r, lambda, -kPi / 2});
  const auto source = make_source(u);
  const double V = 100 / 3.6, w = 2 * V / 1.85;
  const int yaw = sys.index_of("frame.yaw");
  const Eigen::VectorXcd Q1 = generalized_load(sys, source->load(sys, V, 1));
  const Eigen::VectorXcd Q2 = generalized_load(sys, source->load(sys, V, 2));
  EXPECT_NEAR(std::abs(Q1(yaw)), std::sqrt(2.0) * b * m * r * w * w, 1e-9 * std::abs(Q1(yaw)));
  EXPECT_NEAR(std::abs(Q2(yaw)), 2.0 * b * m * r * w * w * reciprocating_coefficient(lambda, 2), 1e-9 * std::abs(Q2(yaw)));
}

// An out-of-round wheel with n lobes is the eccentric wheel's sinusoid at the wavelength πD/n
// (bogie-wagons-forced digest §2.9): at speed V it loads the wagon exactly as an eccentric wheel
// at n·V (same frequency, same amplitude, no delay between wheels that turn together), and its
// critical speeds fall to V = πD·f/n.
TEST(WheelEccentricity, LobesDivideTheWavelength) {
  const Vehicle car = load_vehicle(data_file("resort_car.toml"));
  const LinearSystem sys = assemble(car, DofSet::vertical);
  const ModalResult modes = solve_modes(sys);
  WheelEccentricity round;
  round.wheel_diameter = 1.05;
  round.eccentricity = 0.0015;
  WheelEccentricity triangular = round;
  triangular.lobes = 3;
  const auto e1 = make_source(round), e3 = make_source(triangular);
  EXPECT_DOUBLE_EQ(e3->wavelength(), kPi * 1.05 / 3);
  EXPECT_NE(e3->description().find("3 lobes"), std::string::npos) << e3->description();
  const HarmonicLoad slow = e3->load(sys, 10.0, 1), fast = e1->load(sys, 30.0, 1);
  EXPECT_NEAR(slow.frequency_hz, fast.frequency_hz, 1e-12 * fast.frequency_hz);
  const Eigen::VectorXcd q3 = generalized_load(sys, slow), q1 = generalized_load(sys, fast);
  EXPECT_LE((q3 - q1).norm(), 1e-12 * q1.norm());
  CriticalSpeedOptions range;
  range.min_speed = 1.0;
  range.max_speed = 80.0;
  const auto c1 = find_critical_speeds(sys, modes, {e1.get()}, range);
  const auto c3 = find_critical_speeds(sys, modes, {e3.get()}, range);
  ASSERT_FALSE(c3.empty());
  for (const CriticalSpeed& c : c3) {
    EXPECT_NEAR(c.speed, kPi * 1.05 * c.frequency_hz / 3, 1e-9 * c.speed) << c.mode_name;
    // Each is the eccentric wheel's critical speed of the same mode divided by 3, where that
    // one is in range.
    for (const CriticalSpeed& d : c1) {
      if (d.mode == c.mode) {
        EXPECT_NEAR(c.speed, d.speed / 3, 1e-9 * c.speed) << c.mode_name;
      }
    }
  }
  triangular.lobes = 0;
  EXPECT_THROW(make_source(triangular), std::invalid_argument);
}

TEST(Sources, RejectNonPhysicalParameters) {
  RailJoints j;
  EXPECT_THROW(make_source(j), std::invalid_argument);  // no rail length
  WheelFlat f;
  f.wheel_diameter = 1.0;
  f.depth = 0.001;
  f.length = 4.0;  // longer than the circumference
  EXPECT_THROW(make_source(f), std::invalid_argument);
  Hunting h;
  h.amplitude = 0.01;
  EXPECT_THROW(make_source(h), std::invalid_argument);  // no conicity
}

// The message of make_source, or "" when it makes the source.
template <class Source>
std::string refusal(const Source& source) {
  try {
    make_source(source);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Each rule of RailJoints::is_valid and its twins, broken alone from a valid description: the
// check names the field (the scene key the reader fails at), and make_source throws its words.
TEST(Sources, IsValidNamesTheFieldItsRuleIsOn) {
  RailJoints joints;
  joints.rail_length = 12.5;
  joints.dip_depth = 0.005;
  std::string why;
  EXPECT_TRUE(joints.is_valid(&why)) << why;
  const auto joints_refusal = [&](auto change) {
    RailJoints j = joints;
    change(j);
    EXPECT_FALSE(j.is_valid(nullptr));  // a null `why` is allowed
    return refusal(j);
  };
  EXPECT_EQ(joints_refusal([](RailJoints& j) { j.rail_length = INFINITY; }),
            "rail joints: rail_length must be positive and finite");
  EXPECT_EQ(joints_refusal([](RailJoints& j) { j.dip_depth = -1e-3; }),
            "rail joints: dip_depth must be finite and not negative");
  EXPECT_EQ(joints_refusal([](RailJoints& j) { j.dip_length = 13.0; }),
            "rail joints: dip_length cannot exceed the rail length");
  EXPECT_EQ(joints_refusal([](RailJoints& j) { j.harmonics = 0; }), "rail joints: harmonics must be at least 1");
  EXPECT_EQ(joints_refusal([](RailJoints& j) { j.half_wheelset_mass = 600.0; }),
            "rail joints: track_stiffness missing: the track's dynamics need both track_stiffness and "
            "half_wheelset_mass");
  EXPECT_EQ(joints_refusal([](RailJoints& j) { j.first_joint_at = 12.5; }),
            "rail joints: first_joint_at must be shorter than the rail length (the next joint is the first)");

  WheelEccentricity eccentric;
  eccentric.wheel_diameter = 0.95;
  eccentric.eccentricity = 1e-3;
  EXPECT_TRUE(eccentric.is_valid(&why)) << why;
  eccentric.phases = {0.0, NAN};
  EXPECT_EQ(refusal(eccentric), "wheel eccentricity: phases must be finite angles");

  WheelFlat flat;
  flat.wheel_diameter = 0.95;
  flat.depth = 1e-3;
  flat.length = 3.14159265358979323846 * 0.95;  // the whole revolution, as the reader's default
  EXPECT_TRUE(flat.is_valid(&why)) << why;
  flat.flat_angle = 2.0 * 3.14159265358979323846;
  EXPECT_EQ(refusal(flat), "wheel flat: flat_angle must lie in [0, 2π)");
}

}  // namespace
}  // namespace railmodal::test
