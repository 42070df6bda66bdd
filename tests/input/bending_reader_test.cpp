// A body's bending mode in vehicle files (docs/input.md, "Car-body bending"): the general form's
// `bending = {...}` and the templates' [body.bending], both forms of the mode, the units, and
// every error at its file, line and key.
#include <gtest/gtest.h>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kGeneral = R"([vehicle]
name = "flexible body on four springs"
[[body]]
name = "body"
mass = "32 t"
inertia = { roll = "56800 kg*m^2", pitch = "1970000 kg*m^2", yaw = "1970000 kg*m^2" }
centre_of_gravity = ["0.5 m", "0 m", "1.8 m"]
held = ["lateral", "yaw"]
bending = { length = "24 m", bending_stiffness = "2.5e9 N*m^2", mass_per_length = "1.3 t/m", damping_ratio = 0.02 }
[[element]]
name = "front left"
upper = "body"
point = ["9.5 m", "1 m", "0.8 m"]
vertical = { stiffness = "430 kN/m" }
[[element]]
name = "rear left"
upper = "body"
point = ["-9.5 m", "1 m", "0.8 m"]
vertical = { stiffness = "430 kN/m" }
[[element]]
name = "front right"
upper = "body"
point = ["9.5 m", "-1 m", "0.8 m"]
vertical = { stiffness = "430 kN/m" }
[[element]]
name = "rear right"
upper = "body"
point = ["-9.5 m", "-1 m", "0.8 m"]
vertical = { stiffness = "430 kN/m" }
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

const std::string kBeam =
    R"(bending = { length = "24 m", bending_stiffness = "2.5e9 N*m^2", mass_per_length = "1.3 t/m", damping_ratio = 0.02 })";

std::string with_bending(const std::string& table) { return replaced(kGeneral, kBeam, table); }

// Expects an InputError containing each of `parts` for the file `text`.
void expect_error(const std::string& text, const std::vector<std::string>& parts) {
  const std::string path = write_temp("bad_bending.toml", text);
  try {
    load_vehicle(path);
    FAIL() << "no error for\n" << text;
  } catch (const InputError& e) {
    for (const auto& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(BendingReader, BeamFormReadsEveryKeyInSI) {
  const Vehicle v = load_vehicle(write_temp("beam.toml", kGeneral));
  ASSERT_TRUE(v.bodies[0].bending.has_value());
  const BodyBending& b = *v.bodies[0].bending;
  EXPECT_EQ(b.length, 24.0);
  EXPECT_FALSE(b.centre.has_value());  // the CG's x, 0.5 m, by default
  ASSERT_TRUE(b.beam.has_value());
  EXPECT_FALSE(b.mode.has_value());
  EXPECT_EQ(b.beam->bending_stiffness, 2.5e9);
  EXPECT_EQ(b.beam->mass_per_length, 1300.0);
  EXPECT_EQ(b.damping_ratio, 0.02);
  const LinearSystem s = assemble(v, DofSet::vertical);
  EXPECT_GE(s.index_of("body.bending"), 0);
}

TEST(BendingReader, ModeFormAndCentre) {
  const Vehicle v = load_vehicle(write_temp(
      "mode.toml", with_bending(R"(bending = { length = "23 m", centre = "0.2 m", frequency = "9.5 Hz", modal_mass = "8 t", damping_ratio = 0 })")));
  const BodyBending& b = *v.bodies[0].bending;
  ASSERT_TRUE(b.mode.has_value());
  EXPECT_EQ(b.mode->frequency, 9.5);
  EXPECT_EQ(b.mode->modal_mass, 8000.0);
  EXPECT_EQ(*b.centre, 0.2);
  EXPECT_EQ(b.damping_ratio, 0.0);
}

TEST(BendingReader, WithoutTheTableTheBodyIsRigid) {
  const Vehicle v = load_vehicle(write_temp("rigid.toml", with_bending("")));
  EXPECT_FALSE(v.bodies[0].bending.has_value());
  EXPECT_LT(assemble(v, DofSet::vertical).index_of("body.bending"), 0);
}

TEST(BendingReader, TemplatesReadBodyBending) {
  // The Manchester coach with [body.bending]: the bogie template's body.
  const Vehicle v = load_vehicle(data_file("manchester_benchmark_coach_flexible.toml"));
  ASSERT_TRUE(v.bodies[0].bending.has_value());
  EXPECT_EQ(v.bodies[0].name, "body");
  const std::string two_axle = R"([vehicle]
name = "two-axle"
template = "two-axle"
[body]
mass = "20 t"
radius_of_gyration = { roll = "1 m", pitch = "3 m" }
cg_height = "1 m"
bending = { length = "12 m", frequency = "11 Hz", modal_mass = "4 t", damping_ratio = 0.03 }
[suspension]
wheelbase = "6 m"
spring_spacing = "2 m"
spring = { kind = "leaf", stiffness = "900 kN/m" }
)";
  const Vehicle w = load_vehicle(write_temp("two_axle.toml", two_axle));
  ASSERT_TRUE(w.bodies[0].bending.has_value());
  EXPECT_EQ(w.bodies[0].bending->mode->frequency, 11.0);
}

TEST(BendingReader, ErrorsNameTheKey) {
  expect_error(with_bending(R"(bending = { length = "24 m", damping_ratio = 0.02 })"),
               {"bad_bending.toml:", "key 'body[0].bending.bending_stiffness': missing: give the beam"});
  expect_error(with_bending(
                   R"(bending = { length = "24 m", bending_stiffness = 2.5e9, mass_per_length = 1300, frequency = "9 Hz", modal_mass = "8 t", damping_ratio = 0.02 })"),
               {"key 'body[0].bending.frequency': give the beam", "not both"});
  expect_error(with_bending(R"(bending = { length = "24 m", frequency = "9 Hz", damping_ratio = 0.02 })"),
               {"bending.modal_mass", "missing"});
  expect_error(with_bending(R"(bending = { length = "24 m", frequency = "9 Hz", modal_mass = "8 t" })"),
               {"bending.damping_ratio", "missing"});
  expect_error(with_bending(R"(bending = { length = "24 m", frequency = "9 Hz", modal_mass = "8 t", damping_ratio = 1.5 })"),
               {"bending.damping_ratio", "must be below 1"});
  expect_error(with_bending(R"(bending = { length = "24 m", frequency = "9 kg", modal_mass = "8 t", damping_ratio = 0.02 })"),
               {"bending.frequency", "a frequency"});
  expect_error(with_bending(R"(bending = { length = "24 m", frequency = "9 Hz", modal_mass = "8 t", damping_ratio = 0.02, stiffness = 3 })"),
               {"bending.stiffness"});
  // A beam that does not reach the springs: named at its length, with the element. Centred on
  // the CG (x = 0.5 m), it reaches from −8.5 m to 9.5 m: the front springs stand at its end.
  expect_error(with_bending(R"(bending = { length = "18 m", frequency = "9 Hz", modal_mass = "8 t", damping_ratio = 0.02 })"),
               {"key 'body[0].bending.length'", "element 'rear left'", "beyond the ends of the bending beam (x = -8.5 m to 9.5 m)"});
  expect_error(replaced(kGeneral, R"(held = ["lateral", "yaw"])", R"(held = ["lateral", "bending"])"),
               {"key 'body[0].held'", "cannot be held"});
}

}  // namespace
}  // namespace railmodal::test
