// Wheelsets and series dampers in the assembly: the series-damper rows, the checks of
// Vehicle::wheelsets and SeriesDamper, the track inputs through wheelsets, an unchanged
// suspension above the wheelsets, and what the analyses built on M, C and K do with them.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <functional>
#include <limits>
#include <sstream>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

// A frame on four springs to the track, with one series damper between it and a second body
// at a point off both reference points, so that every rotation enters the stretch.
Vehicle damped_pair(Motion direction) {
  Vehicle v;
  Body frame;
  frame.name = "frame";
  frame.mass = 2000.0;
  frame.inertia = {1000.0, 1500.0, 1500.0};
  frame.centre_of_gravity = {0.0, 0.0, 0.5};
  Body body = frame;
  body.name = "body";
  body.centre_of_gravity = {0.0, 0.0, 1.5};
  body.reference_point = {0.0, 0.0, 1.0};
  v.bodies = {frame, body};
  for (const char* upper : {"frame", "body"})
    for (double x : {-1.0, 1.0})
      for (double y : {-0.8, 0.8}) {
        Element e;
        e.name = std::string(upper) + " spring";
        e.upper = upper;
        e.lower = std::string(upper) == "body" ? "frame" : "";
        e.point = {x, y, std::string(upper) == "body" ? 1.0 : 0.0};
        e.vertical_stages = {{"coil", 1e6, 1}};
        e.lateral_stages = {{"coil", 5e5, 1}};
        e.longitudinal_stages = {{"coil", 5e5, 1}};
        v.elements.push_back(e);
      }
  Element damper;
  damper.name = "yaw damper";
  damper.upper = "body";
  damper.lower = "frame";
  damper.point = {2.0, 1.2, 0.7};
  damper.series_dampers = {{direction, 3e5, 7e6}};
  v.elements.push_back(damper);
  return v;
}

// The displacement of a body-fixed point r (from the reference point) is u + θ × r; its
// component along the damper is the stretch per motion, read here from that cross product.
double expected_stretch(Motion direction, Motion motion, const Eigen::Vector3d& r) {
  Eigen::Vector3d u = Eigen::Vector3d::Zero(), theta = Eigen::Vector3d::Zero();
  switch (motion) {
    case Motion::longitudinal:
      u.x() = 1.0;
      break;
    case Motion::lateral:
      u.y() = 1.0;
      break;
    case Motion::bounce:
      u.z() = 1.0;
      break;
    case Motion::roll:
      theta.x() = 1.0;
      break;
    case Motion::pitch:
      theta.y() = 1.0;
      break;
    case Motion::yaw:
      theta.z() = 1.0;
      break;
    case Motion::bending:  // these rigid bodies carry no bending mode
      break;
  }
  const Eigen::Vector3d d = u + theta.cross(r);
  return direction == Motion::longitudinal ? d.x() : direction == Motion::lateral ? d.y() : d.z();
}

TEST(SeriesDamperAssembly, StretchRowIsTheRelativeMotionAlongTheDamper) {
  for (Motion direction : {Motion::longitudinal, Motion::lateral, Motion::bounce}) {
    const Vehicle v = damped_pair(direction);
    const LinearSystem s = assemble(v, DofSet::all);
    ASSERT_EQ(s.series_dampers.size(), 1u) << to_string(direction);
    const SeriesDamperRow& row = s.series_dampers[0];
    EXPECT_EQ(row.element, 8);
    EXPECT_EQ(row.direction, direction);
    EXPECT_EQ(row.damping, 3e5);
    EXPECT_EQ(row.stiffness, 7e6);
    ASSERT_EQ(row.stretch.size(), s.size());
    for (int i = 0; i < s.size(); ++i) {
      const Body& b = v.bodies[s.dofs[i].body];
      const double sign = b.name == "body" ? 1.0 : -1.0;  // upper minus lower
      // Exact: each entry is one product of the point's lever arms (1e-15 covers their rounding).
      EXPECT_NEAR(row.stretch(i),
                  sign * expected_stretch(direction, s.dofs[i].motion, v.elements[8].point - b.reference_point), 1e-15)
          << to_string(direction) << " " << s.dofs[i].label;
    }
  }
}

// A damper no kept motion stretches is no row: a lateral damper among the vertical motions
// (bounce, pitch and surge move no point sideways). A vertical damper off the centre line is
// stretched by roll, a lateral motion.
TEST(SeriesDamperAssembly, OnlyRowsSomeKeptMotionStretches) {
  EXPECT_TRUE(assemble(damped_pair(Motion::lateral), DofSet::vertical).series_dampers.empty());
  EXPECT_EQ(assemble(damped_pair(Motion::bounce), DofSet::lateral).series_dampers.size(), 1u);
  // A longitudinal damper off the centre line is stretched by yaw (lateral set) and pitch
  // (vertical set, the point being above the frame's reference point).
  EXPECT_EQ(assemble(damped_pair(Motion::longitudinal), DofSet::lateral).series_dampers.size(), 1u);
  EXPECT_EQ(assemble(damped_pair(Motion::longitudinal), DofSet::vertical).series_dampers.size(), 1u);
}

// Series dampers carry no static force and are not in M, C or K: those are bit for bit the
// matrices of the vehicle without them.
TEST(SeriesDamperAssembly, MatricesUnchangedBitForBit) {
  const Vehicle with = damped_pair(Motion::longitudinal);
  Vehicle without = with;
  without.elements.pop_back();
  for (DofSet set : {DofSet::vertical, DofSet::lateral, DofSet::all}) {
    const LinearSystem a = assemble(with, set), b = assemble(without, set);
    EXPECT_TRUE(a.mass == b.mass && a.damping == b.damping && a.stiffness == b.stiffness &&
                a.gravity_stiffness == b.gravity_stiffness)
        << to_string(set);
    EXPECT_TRUE(b.series_dampers.empty());
  }
}

TEST(SeriesDamperAssembly, ValuesAreChecked) {
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    Vehicle v = damped_pair(Motion::longitudinal);
    v.elements.back().series_dampers[0].damping = bad;
    EXPECT_THROW(assemble(v, DofSet::all), std::invalid_argument) << bad;
    v = damped_pair(Motion::longitudinal);
    v.elements.back().series_dampers[0].stiffness = bad;
    EXPECT_THROW(assemble(v, DofSet::all), std::invalid_argument) << bad;
  }
  Vehicle v = damped_pair(Motion::yaw);  // a rotation is no direction of a damper
  EXPECT_THROW(assemble(v, DofSet::all), std::invalid_argument);
}

// The wheelset of wheelset_on_springs.toml, built in code.
Vehicle one_wheelset() {
  Vehicle v;
  Body ws;
  ws.name = "ws";
  ws.mass = 1500.0;
  ws.inertia = {700.0, 100.0, 800.0};
  ws.held = {Motion::bounce, Motion::roll, Motion::pitch};
  v.bodies = {ws};
  for (double y : {-1.0, 1.0}) {
    Element e;
    e.name = "axlebox";
    e.upper = "ws";
    e.point = {0.0, y, 0.0};
    e.lateral_stages = {{"spring", 5.0e5, 1}};
    e.longitudinal_stages = {{"spring", 1.0e6, 1}};
    v.elements.push_back(e);
  }
  Wheelset w;
  w.body = "ws";
  w.spin_inertia = 100.0;
  w.contact.rolling_radius = 0.46;
  w.contact.contact_half_spacing = 0.75;
  w.contact.conicity = 0.15;
  w.contact.axle_load = 1.0e5;
  w.contact.creep = CreepCoefficients{1e7, 0.9e7, 1e4, 100.0};
  v.wheelsets = {w};
  return v;
}

void expect_refused(const Vehicle& v, const std::string& part) {
  try {
    assemble(v, DofSet::all);
    FAIL() << "no error; expected " << part;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(WheelsetAssembly, WheelsetIsChecked) {
  const LinearSystem s = assemble(one_wheelset(), DofSet::all);
  ASSERT_EQ(s.size(), 2);  // lateral and yaw
  EXPECT_EQ(s.dofs[0].label, "ws.lateral");
  EXPECT_EQ(s.dofs[1].label, "ws.yaw");
  // Yaw stiffness of the longitudinal springs at the axlebox spacing: 2·k_x·b² (exact sums).
  EXPECT_DOUBLE_EQ(s.stiffness(1, 1), 2 * 1.0e6 * 1.0);
  EXPECT_DOUBLE_EQ(s.stiffness(0, 0), 2 * 5.0e5);

  Vehicle v = one_wheelset();
  v.wheelsets[0].body = "frame";
  expect_refused(v, "wheelset 'frame': no body of that name");
  v = one_wheelset();
  v.wheelsets.push_back(v.wheelsets[0]);
  expect_refused(v, "wheelset 'ws': listed twice as a wheelset");
  v = one_wheelset();
  v.wheelsets[0].spin_inertia = -1.0;
  expect_refused(v, "wheelset 'ws': spin inertia must be non-negative");
  for (Motion m : {Motion::bounce, Motion::roll, Motion::pitch}) {
    v = one_wheelset();
    v.bodies[0].held.erase(std::find(v.bodies[0].held.begin(), v.bodies[0].held.end(), m));
    expect_refused(v, std::string("wheelset 'ws': its ") + to_string(m) + " must be held");
  }
  for (Motion m : {Motion::lateral, Motion::yaw}) {
    v = one_wheelset();
    v.bodies[0].held.push_back(m);
    expect_refused(v, std::string("wheelset 'ws': its lateral and yaw motions must be free (the wheel–rail contact "
                              "acts on them), and its body holds its ") +
                          to_string(m));
  }
  v = one_wheelset();
  v.bodies[0].longitudinal_free = true;
  expect_refused(v, "wheelset 'ws': its longitudinal motion must be held");
}

// On wheelsets the suspension above them is the suspension on rigid track: the bogies' and the
// body's blocks of M, C and K, the element loads and the vertical track inputs are those of the
// coach without wheelsets. The static solve has the wheelsets' lateral and yaw coordinates
// besides (a larger Cholesky factorisation), so loads agree to round-off, 1e-12 relative.
TEST(WheelsetAssembly, SuspensionAboveTheWheelsetsIsUnchanged) {
  const LinearSystem rigid = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::all);
  const LinearSystem on = assemble(load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  EXPECT_EQ(on.size(), rigid.size() + 8);  // four wheelsets, lateral and yaw each
  for (int i = 0; i < rigid.size(); ++i)
    for (int j = 0; j < rigid.size(); ++j) {
      const int a = on.index_of(rigid.dofs[i].label), b = on.index_of(rigid.dofs[j].label);
      ASSERT_GE(a, 0) << rigid.dofs[i].label;
      const double scale = std::max(1.0, rigid.stiffness.cwiseAbs().maxCoeff());
      EXPECT_EQ(on.mass(a, b), rigid.mass(i, j));
      EXPECT_EQ(on.damping(a, b), rigid.damping(i, j));
      EXPECT_NEAR(on.stiffness(a, b), rigid.stiffness(i, j), 1e-12 * scale)
          << rigid.dofs[i].label << " " << rigid.dofs[j].label;
    }
  ASSERT_EQ(on.element_loads.size(), rigid.element_loads.size());
  for (size_t k = 0; k < rigid.element_loads.size(); ++k)
    EXPECT_NEAR(on.element_loads[k], rigid.element_loads[k], 1e-12 * std::abs(rigid.element_loads[k]) + 1e-9);
  // The axleboxes take the rail's vertical and longitudinal displacement as before; the lateral
  // acts through the contact, not through the springs.
  ASSERT_EQ(on.track_inputs.size(), rigid.track_inputs.size());
  for (size_t k = 0; k < rigid.track_inputs.size(); ++k) {
    const TrackInput &a = on.track_inputs[k], &b = rigid.track_inputs[k];
    EXPECT_EQ(a.element, b.element);
    EXPECT_TRUE(a.load_per_displacement.col(1).isZero(0.0));
    EXPECT_TRUE(a.load_per_velocity.col(1).isZero(0.0));
    for (int i = 0; i < rigid.size(); ++i) {
      const int r = on.index_of(rigid.dofs[i].label);
      for (int d : {0, 2}) {
        EXPECT_EQ(a.load_per_displacement(r, d), b.load_per_displacement(i, d));
        EXPECT_EQ(a.load_per_velocity(r, d), b.load_per_velocity(i, d));
      }
    }
  }
}

TEST(WheelsetAnalyses, ModesSayWhatTheyLeaveOut) {
  const LinearSystem rigid = assemble(load_vehicle(data_file("manchester_benchmark_coach.toml")), DofSet::lateral);
  EXPECT_TRUE(solve_modes(rigid).notes.empty());
  const LinearSystem on =
      assemble(load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::lateral);
  const ModalResult modes = solve_modes(on);
  ASSERT_EQ(modes.notes.size(), 1u);
  EXPECT_NE(modes.notes[0].find("without the wheel–rail contact terms"), std::string::npos);
  for (OutputFormat format : {OutputFormat::table, OutputFormat::csv, OutputFormat::json}) {
    std::ostringstream out;
    write_modes(out, on, modes, format);
    EXPECT_NE(out.str().find("wheelsets: suspension modes only"), std::string::npos) << to_string(format);
  }
  const ModalResult damped_pair_modes = solve_modes(assemble(damped_pair(Motion::longitudinal), DofSet::all));
  ASSERT_EQ(damped_pair_modes.notes.size(), 1u);
  EXPECT_NE(damped_pair_modes.notes[0].find("series dampers: left out"), std::string::npos);
}

void expect_series_damper_refused(const std::function<void()>& run, const std::string& analysis) {
  try {
    run();
    FAIL() << analysis << " ran";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), analysis + ": element 'yaw damper' has a series damper, which this analysis "
                                         "does not represent (the hunting stability, the damped modes and the "
                                         "linear ride do)");
  }
}

TEST(WheelsetAnalyses, SeriesDampersAreRefusedNotDropped) {
  const LinearSystem s = assemble(damped_pair(Motion::longitudinal), DofSet::all);
  const ModalResult modes = solve_modes(s);
  // the damped modes carry it (tests/solve/damped_modal_test.cpp, "SeriesDamper")
  const DampedModalResult damped = solve_damped_modes(s);
  ASSERT_EQ(damped.notes.size(), 1u);
  EXPECT_NE(damped.notes[0].find("series dampers: in"), std::string::npos);
  // Its undamped solve's notes mean what ModalResult::notes means: the dampers left out.
  EXPECT_EQ(damped.undamped.notes, modes.notes);
  ASSERT_EQ(modes.notes.size(), 1u);
  EXPECT_NE(modes.notes[0].find("series dampers: left out"), std::string::npos);
  const Eigen::VectorXcd load = Eigen::VectorXcd::Ones(s.size());
  expect_series_damper_refused([&] { harmonic_response(s, modes, load, 1.0); }, "harmonic response");
  expect_series_damper_refused([&] { modal_harmonic_response(s, modes, load, 1.0, 2); }, "harmonic response");
  RailJoints joints;
  joints.rail_length = 25.0;
  joints.dip_depth = 0.002;
  const auto source = make_source(joints);
  CriticalSpeedOptions options;
  options.min_speed = 1.0;
  options.max_speed = 50.0;
  expect_series_damper_refused([&] { find_critical_speeds(s, modes, {source.get()}, options); }, "critical speeds");
  SimulationOptions sim;
  sim.duration = 0.1;
  sim.time_step = 1e-3;
  expect_series_damper_refused([&] { simulate_linear(s, {}, sim); }, "simulation");
  expect_series_damper_refused([&] { simulate_nonlinear(s, {}, sim, NonlinearEffects{}); }, "simulation");
  // Where no kept motion stretches the damper, nothing is left out: the vertical motions of a
  // lateral damper.
  const LinearSystem vertical = assemble(damped_pair(Motion::lateral), DofSet::vertical);
  ASSERT_TRUE(vertical.series_dampers.empty());
  EXPECT_NO_THROW(harmonic_response(vertical, solve_modes(vertical), Eigen::VectorXcd::Ones(vertical.size()), 1.0));
}

// A lateral track input reaches a wheelset through the contact, which these analyses leave out:
// refused, naming the wheelset and the analysis that models it. Vertical inputs pass.
TEST(WheelsetAnalyses, LateralTrackInputOnWheelsetsIsRefused) {
  const LinearSystem s = assemble(load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  Hunting hunting;
  hunting.conicity = 0.05;
  hunting.rolling_circle_spacing = 1.5;
  hunting.rolling_radius = 0.46;
  hunting.amplitude = 0.005;
  const auto lateral = make_source(hunting);
  try {
    lateral->load(s, 30.0, 1);
    FAIL() << "a lateral input under wheelsets was taken";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("hunting: a lateral track input under wheelset 'wheelset1'"), std::string::npos) << what;
    EXPECT_NE(what.find("`railmodal stability`"), std::string::npos) << what;
  }
  RailJoints joints;
  joints.rail_length = 25.0;
  joints.dip_depth = 0.002;
  const HarmonicLoad load = make_source(joints)->load(s, 30.0, 1);
  EXPECT_GT(generalized_load(s, load).norm(), 0.0);  // the vertical input reaches the bogies
  // A wheelset held by springs to a fixed frame (the track): the frame's lateral motion is no
  // rail's, and the contact is still left out: refused as well.
  const LinearSystem one = assemble(load_vehicle(data_file("wheelset_on_springs.toml")), DofSet::lateral);
  try {
    lateral->load(one, 30.0, 1);
    FAIL() << "a lateral input on a vehicle with wheelsets was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("hunting: a lateral track input on a vehicle with wheelsets"),
              std::string::npos)
        << e.what();
  }
}

// The bundled coach on wheelsets: the contact (helper "contact") resolves each wheelset's axle
// load from the assembly's static loads, (32000 + 2 × 2615 + 4 × 1813) kg × g / 4 on each of four
// equal axles, and computes its creep coefficients from Hertz (the file gives no creep). 1e-9
// relative: the loads come from a Cholesky solve of the static equilibrium.
TEST(WheelsetAssembly, BundledCoachAxleLoadsAreTheBenchmarksMasses) {
  const Vehicle v = load_vehicle(data_file("manchester_benchmark_coach_wheelsets.toml"));
  const ContactMatrices c = contact_matrices(assemble(v, DofSet::lateral));
  ASSERT_EQ(c.wheelsets.size(), 4u);
  const double axle = (32000.0 + 2 * 2615.0 + 4 * 1813.0) / 4.0 * v.gravity;
  for (const ResolvedContact& w : c.wheelsets) {
    EXPECT_NEAR(w.axle_load, axle, 1e-9 * axle) << w.body;
    EXPECT_TRUE(w.ellipse) << w.body;
    EXPECT_GT(w.creep.f22, 0.0) << w.body;
  }
}

}  // namespace
}  // namespace railmodal::test
