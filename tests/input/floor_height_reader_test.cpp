// A car body's floor height in vehicle files (docs/input.md, "Floor height"): read in every form
// as every length is, SI inside, and every bad value refused at its file, line and key.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

// Line 6 holds the key the tests replace.
const std::string kWagon = R"([vehicle]
name = "test wagon"
template = "two-axle"
[body]
weight = "20000 kgf"
floor_height = "1250 mm"
cg_height = "100 cm"
radius_of_gyration = { roll = "110 cm", pitch = "260 cm" }
[suspension]
wheelbase = "400 cm"
spring_spacing = "200 cm"
spring = { kind = "coil", stiffness = "1000 kgf/cm" }
)";

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string with_floor(const std::string& line) {
  std::string text = kWagon;
  const std::string from = "floor_height = \"1250 mm\"";
  text.replace(text.find(from), from.size(), line);
  return text;
}

// Expects an InputError at line 6 of the file, naming the key and containing `part`.
void expect_error_at_the_key(const std::string& line, const std::string& key, const std::string& part) {
  const std::string path = write_temp("bad_floor.toml", with_floor(line));
  try {
    load_vehicle(path);
    FAIL() << "no error for " << line;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 6) << e.what();
    EXPECT_NE(std::string(e.what()).find(path + ":6:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("key '" + key + "'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(FloorHeightReader, TemplatesAndTheGeneralFormReadItInSI) {
  const Vehicle wagon = load_vehicle(write_temp("floor.toml", kWagon));
  ASSERT_TRUE(wagon.bodies[0].floor_height.has_value());
  EXPECT_DOUBLE_EQ(*wagon.bodies[0].floor_height, 1.25);  // "1250 mm": 1250 × 0.001, one rounding
  EXPECT_FALSE(load_vehicle(write_temp("no_floor.toml", with_floor(""))).bodies[0].floor_height.has_value());
  // A coordinate: a floor below the axle plane is read as written.
  EXPECT_EQ(*load_vehicle(write_temp("low.toml", with_floor("floor_height = -0.1"))).bodies[0].floor_height, -0.1);

  // The bogie template's [body]: above the axle plane, not the bolster plane (the coach's is
  // 0.3675 m up; the floor stays where it is written).
  std::string coach = file_text(data_file("manchester_benchmark_coach.toml"));
  coach.replace(coach.find("bogie_spacing ="), 0, "floor_height = \"0.84 m\"\n");
  const Vehicle c = load_vehicle(write_temp("coach_floor.toml", coach));
  EXPECT_EQ(*c.bodies[0].floor_height, 0.84);
  EXPECT_FALSE(c.bodies[1].floor_height.has_value());  // the bogie frames give none

  // The general form's [[body]].
  const Vehicle g = load_vehicle(write_temp("general_floor.toml", R"([vehicle]
name = "body on four springs"
[[body]]
name = "body"
mass = "32 t"
inertia = { roll = "56800 kg*m^2", pitch = "1970000 kg*m^2", yaw = "1970000 kg*m^2" }
centre_of_gravity = ["0 m", "0 m", "1.8 m"]
reference_point = ["0 m", "0 m", "0.8 m"]
floor_height = "130 cm"
[[element]]
upper = "body"
point = ["9.5 m", "1 m", "0.8 m"]
vertical = { stiffness = "430 kN/m" }
)"));
  EXPECT_DOUBLE_EQ(*g.bodies[0].floor_height, 1.3);
  EXPECT_EQ(g.bodies[0].reference_point.z(), 0.8);  // unchanged by it
}

TEST(FloorHeightReader, BadValuesAreRefusedAtTheirKey) {
  expect_error_at_the_key("floor_height = \"1.25 kg\"", "body.floor_height", "expected a length");
  expect_error_at_the_key("floor_height = true", "body.floor_height", "expected a length");
  expect_error_at_the_key("floor_height = \"high\"", "body.floor_height", "");
  expect_error_at_the_key("floor_height = \"1.25 furlong\"", "body.floor_height", "");
  expect_error_at_the_key("floor_height = { z = \"1 m\" }", "body.floor_height", "got a table");
  // Misspelt: an unknown key, named where it is.
  expect_error_at_the_key("flor_height = \"1.25 m\"", "body.flor_height", "");
}

// A bare 1250 meant in mm is 1250 m: read, and warned beyond a body's scale like the other heights.
TEST(FloorHeightReader, ABodyScaleLengthIsWarned) {
  const std::string path = write_temp("warned_floor.toml", with_floor("floor_height = 1250"));
  std::vector<std::string> warnings;
  const Vehicle v = load_vehicle(path, &warnings);
  EXPECT_EQ(*v.bodies[0].floor_height, 1250.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind(path + ":6:16: warning: key 'body.floor_height': read as 1250 m", 0), 0u) << warnings[0];
  warnings.clear();
  load_vehicle(write_temp("quiet_floor.toml", kWagon), &warnings);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace railmodal::test
