// The [driving_gear] reader: the bundled Су against the book's data, defaults, and errors that
// name the key and its line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "gear/su_gear.hpp"
#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal {
namespace {

std::string su_file() { return std::string(RAILMODAL_DATA_DIR) + "/locomotives/su.toml"; }

TEST(DrivingGearReader, BundledSuIsTheBooksEngine) {
  const DrivingGear g = load_driving_gear(su_file());
  const DrivingGear book = testing::su_engine();
  EXPECT_NEAR(g.design_speed, 100 / 3.6, 1e-12);
  EXPECT_DOUBLE_EQ(g.wheel_diameter, 1.85);
  EXPECT_DOUBLE_EQ(g.wheel_plane_half_spacing, 0.795);
  ASSERT_EQ(g.cylinders.size(), 2u);
  ASSERT_EQ(g.axles.size(), 3u);
  for (std::size_t i = 0; i < 2; ++i) {
    const GearCylinder &c = g.cylinders[i], &b = book.cylinders[i];
    EXPECT_EQ(c.axle, 1);
    EXPECT_DOUBLE_EQ(c.lateral, b.lateral);
    EXPECT_NEAR(c.crank_offset, b.crank_offset, 1e-15);
    EXPECT_DOUBLE_EQ(c.rod_length, b.rod_length);
    EXPECT_DOUBLE_EQ(c.reciprocating_mass, b.reciprocating_mass);
    // The file's kgf is the standard 9.80665 N, the tests' the digest's 9.81: J_G differs by
    // 71.665·(9.81 − 9.80665) = 0.24 kg·m² (of 157).
    EXPECT_NEAR(c.rod_inertia, b.rod_inertia, 71.665 * (9.81 - 9.80665) * 1.0001);
  }
  EXPECT_NEAR(g.axles[0].right.static_load, 9000 * 9.80665, 1e-9);
  EXPECT_NEAR(g.axles[1].left.crank_offset, -M_PI / 2, 1e-15);
  EXPECT_EQ(g.axles[1].right.masses.size(), 4u);  // web, pin, coupling rod, counter-crank
  EXPECT_NEAR(g.axles[1].right.masses[3].angle * 180 / M_PI, -12.45, 1e-12);
  EXPECT_DOUBLE_EQ(g.axles[2].left.masses[2].mass, 53.10);
  EXPECT_TRUE(g.is_valid(nullptr));
}

TEST(DrivingGearReader, LeadingLeftSideAndInertiaAboutTheCrankPin) {
  const std::string path = test::write_temp("gear.toml", R"(
[driving_gear]
wheel_diameter = "1.5 m"
wheel_plane_spacing = "1.5 m"
leading_side = "left"
[[driving_gear.axle]]
name = "a"
crank_radius = "0.3 m"
static_wheel_load = "80 kN"
[[driving_gear.cylinder]]
side = "left"
lateral = "1 m"
axle = "a"
crank_radius = "0.3 m"
rod_length = "2 m"
rod_mass = "200 kg"
rod_centre_of_mass = "1.5 m"
rod_inertia = "100 kg*m^2"
rod_inertia_about = "crank_pin"
reciprocating_mass = "300 kg"
)");
  const DrivingGear g = load_driving_gear(path);
  EXPECT_NEAR(g.cylinders[0].crank_offset, M_PI / 2, 1e-15);  // the left leads the right
  EXPECT_DOUBLE_EQ(g.cylinders[0].lateral, -1.0);
  EXPECT_DOUBLE_EQ(g.cylinders[0].rod_inertia, 100 - 200 * 0.5 * 0.5);  // about the crank pin, 0.5 m away
  EXPECT_EQ(g.design_speed, 0.0);
}

TEST(DrivingGearReader, ErrorsNameTheKeyAndItsLine) {
  const std::string path = test::write_temp("bad.toml", R"([driving_gear]
wheel_diameter = "1.5 m"
wheel_plane_spacing = "1.5 m"
[[driving_gear.axle]]
name = "a"
crank_radius = "0.3 m"
static_wheel_load = "-80 kN"
)");
  try {
    load_driving_gear(path);
    FAIL() << "a negative wheel load was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("static_wheel_load"), std::string::npos) << e.what();
  }
  // A vehicle file may carry the table: load_vehicle leaves it to load_driving_gear.
  std::ifstream car(test::data_file("fette_car.toml"));
  const std::string text((std::istreambuf_iterator<char>(car)), std::istreambuf_iterator<char>());
  const std::string vehicle = test::write_temp("loco.toml", text + "\n[driving_gear]\nwheel_diameter = \"1.5 m\"\n");
  EXPECT_NO_THROW(load_vehicle(vehicle));
}

}  // namespace
}  // namespace railmodal
