// Mode names are stable under small changes of the design (issue 17 item 8): a ±1 % change of
// any numeric parameter of a bundled vehicle may change a mode's name only where the mode's shape
// changes too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "test_support.hpp"

namespace railmodal {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Where each numeric value of a TOML file is: offset and length of every number on the value
// side of a line (after its first '='), outside comments, not part of a key or a unit's power
// ("bogie1", "cm/s^2").
std::vector<std::pair<size_t, size_t>> numbers_in(const std::string& text) {
  std::vector<std::pair<size_t, size_t>> found;
  const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  size_t line_start = 0;
  while (line_start < text.size()) {
    size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos) line_end = text.size();
    const std::string line = text.substr(line_start, line_end - line_start);
    bool quoted = false;
    size_t value_start = std::string::npos, end = line.size();
    for (size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '"') quoted = !quoted;
      if (!quoted && line[i] == '#') {
        end = i;
        break;
      }
      if (!quoted && line[i] == '=' && value_start == std::string::npos) value_start = i + 1;
    }
    if (value_start != std::string::npos && line.find('[') != 0) {
      const std::string value = line.substr(value_start, end - value_start);
      for (std::sregex_iterator it(value.begin(), value.end(), number), stop; it != stop; ++it) {
        const size_t at = static_cast<size_t>(it->position());
        const char before = at > 0 ? value[at - 1] : ' ';
        if (std::isalpha(static_cast<unsigned char>(before)) || before == '_' || before == '^') continue;
        found.emplace_back(line_start + value_start + at, static_cast<size_t>(it->length()));
      }
    }
    line_start = line_end + 1;
  }
  return found;
}

// The issue's first case: a body held laterally whose only free motion is roll (a two-axle
// wagon's body) rolls about its fixed axis, the book's side rocking, even with its CG so high
// that the CG moves more than the body turns. It was named "body lateral", with no centre.
TEST(ModeNames, BodyHeldLaterallyRollsAboutItsAxis) {
  Vehicle v = load_vehicle(test::data_file("two_axle_freight_wagon.toml"));
  Body* body = test::body_named(v, "body");
  ASSERT_NE(body, nullptr);
  body->centre_of_gravity.z() = 2.5;  // m above the axle plane, far above the radius of gyration
  const LinearSystem system = assemble(v, DofSet::lateral);
  ASSERT_EQ(system.dofs.size(), 1u);  // body.roll only
  const ModalResult r = solve_modes(system);
  const Mode& m = r.modes.at(0);
  EXPECT_EQ(m.name, "body roll");
  ASSERT_TRUE(m.centre.has_value());
  EXPECT_EQ(m.centre->about, "roll");
  EXPECT_FALSE(m.centre->at_infinity);
  EXPECT_NEAR(m.centre->position, body->reference_point.z(), 1e-12);  // the fixed axis
}

// The issue's second case: a sway pair was "lateral"/"roll" once either share fell below 10 %
// and "lower sway"/"upper sway" above it. Lowering the frame's CG towards its spring plane
// weakens the coupling continuously; the pair keeps its names, the lower sway's centre below
// the CG and the upper's above, down to a coupling of a few per cent.
TEST(ModeNames, SwayPairKeepsItsNamesAsTheCouplingWeakens) {
  for (double scale : {1.0, 0.5, 0.2, 0.1, 0.05}) {
    Vehicle v = load_vehicle(test::data_file("steam_locomotive_frame.toml"));
    Body* frame = test::body_named(v, "frame");
    ASSERT_NE(frame, nullptr);
    frame->centre_of_gravity.z() *= scale;
    const ModalResult r = solve_modes(assemble(v, DofSet::lateral));
    int lower = 0, upper = 0;
    for (const Mode& m : r.modes) {
      EXPECT_EQ(m.name.find("lateral"), std::string::npos) << scale << ": " << m.name;
      EXPECT_NE(m.name, "frame roll") << scale;
      if (m.name != "frame lower sway" && m.name != "frame upper sway") continue;
      ASSERT_TRUE(m.centre && !m.centre->at_infinity);
      const bool below = m.centre->position < frame->centre_of_gravity.z();
      EXPECT_EQ(below, m.name == "frame lower sway") << scale;
      ++(below ? lower : upper);
    }
    EXPECT_EQ(lower, 1) << scale;
    EXPECT_EQ(upper, 1) << scale;
  }
}

// A body with its surge free (issue 17 item 11) has a mode that is mostly surge: it is named
// "body longitudinal", and its pitch mode, whose CG moves longitudinally too (the draw gear
// holds the body 0.4 m below its CG), stays "body pitch". Draw gear 2 × 8 MN/m on 20 t: surge
// at √(1.6e7 / 2e4) / 2π ≈ 4.5 Hz, well apart from bounce (2.2 Hz) and pitch (≈ 1.6 Hz).
TEST(ModeNames, SurgeOfABodyFreeLongitudinallyIsNamedLongitudinal) {
  const std::string wagon = R"([vehicle]
name = "wagon with draw gear"
template = "two-axle"
[body]
weight = "20000 kgf"
cg_height = "100 cm"
radius_of_gyration = { roll = "110 cm", pitch = "260 cm" }
free = ["longitudinal"]
[suspension]
wheelbase = "400 cm"
spring_spacing = "200 cm"
spring = { kind = "coil", stiffness = "1000 kgf/cm" }
[draw_gear]
spacing = "12 m"
height = "0.6 m"
spring = { stiffness = "8 MN/m" }
)";
  const LinearSystem system = assemble(load_vehicle(test::write_temp("draw_gear.toml", wagon)), DofSet::vertical);
  const int surge = system.index_of("body.longitudinal");
  ASSERT_GE(surge, 0);
  std::vector<std::string> names;
  for (const Mode& m : solve_modes(system).modes) {
    names.push_back(m.name);
    const bool mostly_surge = m.kinetic_energy_share(surge) > 0.5;
    EXPECT_EQ(m.name == "body longitudinal", mostly_surge) << m.name;
    if (m.name == "body pitch") {
      EXPECT_TRUE(m.centre && m.centre->about == "pitch");
    }
  }
  EXPECT_EQ(names, (std::vector<std::string>{"body pitch", "body bounce", "body longitudinal"}));
}

// The Fette car's bogies pitch at one frequency: the solver's two shapes are an arbitrary basis
// of the pair's subspace, each printed with one bogie's pivot as its centre (x = ±7 m). Only the
// subspace is determined: one name, and no centre of oscillation.
TEST(ModeNames, RepeatedTwinModesHaveOneNameAndNoCentre) {
  const ModalResult r = solve_modes(assemble(load_vehicle(test::data_file("fette_car.toml")), DofSet::all));
  int repeated = 0;
  for (const Mode& m : r.modes) {
    if (!m.repeated) continue;
    ++repeated;
    EXPECT_EQ(m.name, "bogies pitch (repeated)");
    EXPECT_FALSE(m.centre.has_value()) << m.name << " " << m.centre->position;
  }
  EXPECT_EQ(repeated, 2);
}

// The Manchester coach on wheelsets: the two lowest oscillating modes (0.85 Hz) are each bogie
// yawing on the secondary with its wheelsets carried rigidly: their yaw is the bogie's and their
// lateral motion the bogie's yaw times the semi-wheelbase. They were named "wheelsets lateral,
// antiphase" (user audit 2026-11-27b, item 3.5): the carried wheelsets, of more energy than the
// frame, took the name. The carried motion is the bogie's: "bogies yaw", their phase that of the
// bogies' yaw.
TEST(ModeNames, WheelsetsCarriedByAYawingBogieNameTheBogie) {
  const LinearSystem system =
      assemble(load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  const ModalResult r = solve_modes(system);
  const auto at = [&](const Mode& m, const std::string& dof) { return m.shape(system.index_of(dof)); };
  const Vehicle& v = system.vehicle;
  const auto x_of = [&](const std::string& name) {
    for (const Body& b : v.bodies)
      if (b.name == name) return b.reference_point.x();
    ADD_FAILURE() << "no body " << name;
    return 0.0;
  };
  std::vector<std::string> names;
  for (int i : {2, 3}) {  // after the body's two rigid-body modes
    const Mode& m = r.modes.at(i);
    ASSERT_EQ(m.kind, ModeKind::oscillatory);
    // The premise, from the shape: each wheelset is carried. Its yaw is its bogie's and its
    // lateral motion the bogie's lateral motion plus yaw × lever, within 2 % of the wheelset's
    // own (the primary springs deflect a little under the wheelsets' inertia: 0.9 % measured;
    // the bogies' roll, 1e-3 of their yaw, moves the axle by less).
    const std::vector<std::pair<std::string, std::string>> carried{
        {"bogie1", "wheelset1"}, {"bogie1", "wheelset2"}, {"bogie2", "wheelset3"}, {"bogie2", "wheelset4"}};
    for (const auto& [bogie, wheelset] : carried) {
      const double yaw = at(m, bogie + ".yaw"), lever = x_of(wheelset) - x_of(bogie);
      const double lateral = at(m, wheelset + ".lateral");
      EXPECT_NEAR(at(m, wheelset + ".yaw"), yaw, 0.02 * std::abs(yaw)) << m.index << " " << wheelset;
      EXPECT_NEAR(lateral, at(m, bogie + ".lateral") + yaw * lever, 0.02 * std::abs(lateral)) << m.index << " " << wheelset;
      EXPECT_GT(std::abs(lateral), std::abs(at(m, bogie + ".lateral")));  // the wheelsets move most
    }
    const bool in_phase = at(m, "bogie1.yaw") * at(m, "bogie2.yaw") > 0.0;
    EXPECT_EQ(m.name, in_phase ? "bogies yaw, in phase" : "bogies yaw, antiphase") << m.index;
    names.push_back(m.name);
  }
  EXPECT_NE(names[0], names[1]);  // one of each phase
}

// A wheelset moving in a frame that does not move keeps the wheelset's name: the coach's bogie
// frames held still (every motion), the wheelsets sway and yaw on the primary suspension alone.
TEST(ModeNames, WheelsetsMovingInAFrameHeldStillNameTheWheelsets) {
  Vehicle v = load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml"));
  for (const char* bogie : {"bogie1", "bogie2"})
    test::body_named(v, bogie)->held = {Motion::lateral, Motion::bounce, Motion::roll, Motion::pitch, Motion::yaw};
  const LinearSystem system = assemble(v, DofSet::lateral);
  ASSERT_LT(system.index_of("bogie1.yaw"), 0);
  int lateral = 0, yaw = 0;
  for (const Mode& m : solve_modes(system).modes) {
    // Which motion leads, from the shape: the wheelsets' lateral or yaw kinetic energy.
    double wheelset_lateral = 0.0, wheelset_yaw = 0.0;
    for (int i = 0; i < system.size(); ++i) {
      const Dof& d = system.dofs[i];
      if (v.bodies[d.body].name.rfind("wheelset", 0) != 0) continue;
      (d.motion == Motion::lateral ? wheelset_lateral : wheelset_yaw) += m.kinetic_energy_share(i);
    }
    if (wheelset_lateral + wheelset_yaw < 0.5) continue;  // the body's modes
    const bool by_lateral = wheelset_lateral > wheelset_yaw;
    EXPECT_EQ(m.name.rfind(by_lateral ? "wheelsets lateral" : "wheelsets yaw", 0), 0u) << m.index << " " << m.name;
    ++(by_lateral ? lateral : yaw);
  }
  EXPECT_EQ(lateral, 4);  // four wheelsets, each with a lateral and a yaw motion
  EXPECT_EQ(yaw, 4);
}

// In the coach's modes at 14.9 Hz the bogies yaw too, but the wheelsets move laterally against
// what the yaw would carry them, twice as far relative to the frame: the primary lateral springs'
// mode, named by the wheelsets' relative motion (each wheelset's relative energy alone is about
// the bogie's with its carried share, so they count together against it).
TEST(ModeNames, WheelsetsMovingAgainstTheirYawingFrameNameTheWheelsets) {
  const LinearSystem system =
      assemble(load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  int found = 0;
  for (const Mode& m : solve_modes(system).modes) {
    if (m.frequency_hz < 14.0 || m.frequency_hz > 16.0) continue;
    const double yaw = m.shape(system.index_of("bogie1.yaw")), lateral = m.shape(system.index_of("wheelset1.lateral"));
    if (std::abs(yaw) < 1e-3) continue;  // another bogie's mode
    // The premise: wheelset1, 1.28 m ahead of bogie1's centre, moves against its carried motion.
    EXPECT_LT(lateral * yaw, 0.0) << m.index;
    EXPECT_EQ(m.name, "wheelsets lateral, antiphase") << m.index;
    ++found;
  }
  EXPECT_EQ(found, 2);
}

// In the coach's modes at 16.36 Hz each bogie frame sways one way and its wheelsets the other
// (the primary lateral springs take both): nothing of the wheelsets' motion is what the frame
// would carry (the carried share α is kept at 0, not let go negative), so each keeps its own
// energy and the frame, which moves with more, names the mode. Before the share was bounded, the
// wheelsets' motion relative to the frame (the sum of both, 1.6e-2 against their own 7.4e-3)
// counted for more energy than they had and named it "wheelsets lateral".
TEST(ModeNames, AFrameSwayingAgainstItsWheelsetsKeepsTheFramesName) {
  const LinearSystem system =
      assemble(load_vehicle(test::data_file("manchester_benchmark_coach_wheelsets.toml")), DofSet::all);
  const ModalResult r = solve_modes(system);
  int seen = 0;
  for (const Mode& m : r.modes) {
    if (m.kind != ModeKind::oscillatory || std::abs(m.frequency_hz - 16.36) > 0.05) continue;
    const double frame = m.shape(system.index_of("bogie1.lateral")), wheelset = m.shape(system.index_of("wheelset1.lateral"));
    EXPECT_LT(frame * wheelset, 0.0) << m.index;  // the premise: against each other
    EXPECT_EQ(m.name.rfind("bogies upper sway", 0), 0u) << m.index << ": " << m.name;
    ++seen;
  }
  EXPECT_EQ(seen, 2);
}

// A two-axle wagon's body carries its wheelsets directly: its own modes keep the body's names and
// the wheelsets' modes (they sway and yaw in the body's suspension) theirs, as before the carried
// motion was credited to the carrier.
TEST(ModeNames, TwoAxleWagonOnWheelsetsKeepsItsNames) {
  const std::string wagon = R"([vehicle]
name = "two-axle wagon on wheelsets"
template = "two-axle"
[body]
mass = "20 t"
inertia = { roll = "3e4 kg*m^2", pitch = "1.2e5 kg*m^2", yaw = "1.2e5 kg*m^2" }
cg_height = "1 m"
[suspension]
wheelbase = "4 m"
spring_spacing = "2 m"
spring = { stiffness = "900 kN/m" }
lateral = { stiffness = "2 MN/m" }
longitudinal = { stiffness = "20 MN/m" }
[wheelset]
mass = "1.2 t"
inertia = { roll = "700 kg*m^2", yaw = "700 kg*m^2" }
spin_inertia = "80 kg*m^2"
rolling_radius = "0.45 m"
contact_half_spacing = "0.75 m"
conicity = 0.2
hertz = { rail_head_radius = "0.3 m" }
)";
  const ModalResult r = solve_modes(assemble(load_vehicle(test::write_temp("two_axle_ws.toml", wagon)), DofSet::all));
  std::vector<std::string> names;
  for (const Mode& m : r.modes)
    if (m.kind == ModeKind::oscillatory) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"body pitch", "body lower sway", "body bounce", "wheelsets lateral, antiphase",
                                             "wheelsets lateral, in phase", "wheelsets yaw, antiphase",
                                             "wheelsets yaw, in phase"}));
}

// MAC of two shapes weighted by the unperturbed mass matrix.
double mac(const Eigen::MatrixXd& M, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double ab = a.dot(M * b);
  return ab * ab / (a.dot(M * a) * b.dot(M * b));
}

struct Variant {
  std::string file;
  DofSet set;
};
void PrintTo(const Variant& v, std::ostream* out) { *out << v.file << " (" << to_string(v.set) << ")"; }

class NamesUnderPerturbation : public ::testing::TestWithParam<Variant> {};

// For each perturbed mode, the unperturbed mode most like it (largest MAC): where they are alike
// (MAC ≥ 0.9, the issue's threshold) they must have the same name. Modes whose shape changes
// (near-repeated pairs that an asymmetric change splits, modes whose order crosses) may be
// renamed. Values that cannot be scaled (counts, which must stay integers) are skipped.
TEST_P(NamesUnderPerturbation, NameChangesOnlyWithTheShape) {
  const std::string path = test::data_file(GetParam().file);
  const std::string text = read_text(path);
  const LinearSystem base_system = assemble(load_vehicle(path), GetParam().set);
  const ModalResult base = solve_modes(base_system);
  int perturbed = 0, invalid = 0;
  std::vector<std::string> failures;
  for (const auto& [at, length] : numbers_in(text)) {
    const double value = std::stod(text.substr(at, length));
    if (value == 0.0) continue;
    for (double factor : {1.01, 0.99}) {
      char scaled[40];
      std::snprintf(scaled, sizeof scaled, "%.15g", value * factor);
      const std::string changed = text.substr(0, at) + scaled + text.substr(at + length);
      LinearSystem system;
      try {
        const std::string file = test::write_temp(std::filesystem::path(path).filename().string(), changed);
        system = assemble(load_vehicle(file), GetParam().set);
      } catch (const InputError&) {
        ++invalid;  // an integer count scaled, or a value the change takes out of its range
        continue;
      }
      // A numerical failure of a design 1 % away from a bundled one is a defect: not caught.
      ASSERT_EQ(system.dofs.size(), base_system.dofs.size()) << "'" << text.substr(at, length) << "' at offset " << at;
      const ModalResult r = solve_modes(system);
      ++perturbed;
      for (const Mode& m : r.modes) {
        double best = 0.0;
        const Mode* like = nullptr;
        for (const Mode& b : base.modes) {
          const double v = mac(base_system.mass, b.shape, m.shape);
          if (v > best) best = v, like = &b;
        }
        if (best >= 0.9 && like->name != m.name)
          failures.push_back("'" + text.substr(at, length) + "' ×" + (factor > 1 ? "1.01" : "0.99") + " at offset " +
                             std::to_string(at) + ": '" + like->name + "' became '" + m.name + "' with MAC " +
                             std::to_string(best));
      }
    }
  }
  // The file's parameters were found and changed: the smallest bundled file has 5 nonzero
  // numbers (pullman_coil_spring.toml), 10 perturbations.
  EXPECT_GE(perturbed, 10);
  // Invalid perturbations are integer counts (leaves of a spring) and values at a bound of their
  // range: at most 2 in a bundled file (measured: 2 of 36 to 46 in the Fette, Khanin and resort
  // cars, 0 elsewhere). A quarter of the valid ones is well above that and well below "the reader
  // refuses most changes", which would leave the test checking little.
  std::printf("%s (%s): %d perturbations, %d refused as invalid input\n", GetParam().file.c_str(),
              to_string(GetParam().set), perturbed, invalid);
  EXPECT_LE(4 * invalid, perturbed);
  for (const auto& f : failures) ADD_FAILURE() << GetParam().file << " (" << to_string(GetParam().set) << "): " << f;
}

// Each bundled vehicle with each set of its DOFs that is not empty (a two-axle wagon held
// laterally has no lateral set): no instance is skipped.
std::vector<Variant> bundled_vehicles() {
  std::vector<Variant> v;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RAILMODAL_DATA_DIR) + "/vehicles"))
    if (entry.path().extension() == ".toml") {
      const Vehicle vehicle = load_vehicle(entry.path().string());
      for (DofSet set : {DofSet::all, DofSet::vertical, DofSet::lateral})
        if (!assemble(vehicle, set).dofs.empty()) v.push_back({entry.path().filename().string(), set});
    }
  std::sort(v.begin(), v.end(), [](const Variant& a, const Variant& b) {
    return a.file != b.file ? a.file < b.file : static_cast<int>(a.set) < static_cast<int>(b.set);
  });
  return v;
}

INSTANTIATE_TEST_SUITE_P(BundledVehicles, NamesUnderPerturbation, ::testing::ValuesIn(bundled_vehicles()),
                         [](const ::testing::TestParamInfo<Variant>& info) {
                           std::string name =
                               info.param.file.substr(0, info.param.file.size() - 5) + "_" + to_string(info.param.set);
                           return name;
                         });

}  // namespace
}  // namespace railmodal
