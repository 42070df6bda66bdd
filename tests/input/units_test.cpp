// Quantities with units: SI, the book's technical units, and clear errors.
#include "input/units.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <tuple>

namespace railmodal::input {
namespace {

// Conversions are exact products of defined factors; 1e-15 relative is round-off.
void expect_si(const std::string& text, Quantity q, double si) {
  EXPECT_NEAR(parse_quantity(text, q) / si, 1.0, 1e-15) << text;
}

TEST(Units, SiAndTechnicalUnits) {
  expect_si("57.2 mm", Quantity::length, 0.0572);
  expect_si("100 cm", Quantity::length, 1.0);
  expect_si("34 t", Quantity::mass, 34000.0);
  expect_si("5660 kgf", Quantity::force, 5660 * 9.80665);
  expect_si("1.5 tf", Quantity::force, 1500 * 9.80665);
  expect_si("910 kgf/cm", Quantity::stiffness, 910 * 980.665);
  expect_si("1.1 tf/cm", Quantity::stiffness, 1100 * 980.665);
  expect_si("2.2e6 kgf/cm^2", Quantity::modulus, 2.2e6 * 9.80665e4);
  expect_si("1.6e6 kgf*cm*s^2", Quantity::inertia, 1.6e6 * 9.80665 * 0.01);
  expect_si("1.6e6 kgf·cm·s²", Quantity::inertia, 1.6e6 * 9.80665 * 0.01);
  expect_si("75 km/h", Quantity::speed, 75 / 3.6);
  expect_si("14 deg", Quantity::angle, 14 * 3.14159265358979323846 / 180);
  expect_si("14°", Quantity::angle, 14 * 3.14159265358979323846 / 180);
  expect_si("981 cm/s^2", Quantity::acceleration, 9.81);
  expect_si("20 kN*s/m", Quantity::damping, 2.0e4);
  expect_si("940 kN*m/rad", Quantity::rotational_stiffness, 9.4e5);
  expect_si("8.9e5", Quantity::stiffness, 8.9e5);  // a bare number is SI
  // A share as a percentage, as `balance --fraction 40%` takes it (user audit 2026-11-27c, F5).
  expect_si("40 %", Quantity::dimensionless, 0.4);
  expect_si("40%", Quantity::dimensionless, 0.4);
  expect_si("0.4", Quantity::dimensionless, 0.4);
  EXPECT_THROW(parse_quantity("40 %", Quantity::length), std::invalid_argument);  // not a length
}

// The book writes kg and t for kilogram-force and tonne-force in stiffness and flexibility.
TEST(Units, BookKgAndTonneAsForce) {
  expect_si("650 kg/cm", Quantity::stiffness, 650 * 980.665);
  expect_si("10.5 mm/t", Quantity::flexibility, 10.5e-3 / 9806.65);
  expect_si("62.5 kg/mm", Quantity::stiffness, 62.5 * 9806.65);
}

// ... but a mass alone where a force is wanted ("34000 kg" for a weight) may mean the mass as well
// as the kilogram-force: refused, saying both ways to write it (the audit of 2026-11-27).
TEST(Units, MassAloneIsNotAForce) {
  for (const auto& [text, force, mass] : {std::tuple<const char*, const char*, const char*>{"34000 kg", "\"34000 kgf\"", "\"34000 kg\""},
                                          {"34 t", "\"34 tf\"", "\"34 t\""}}) {
    try {
      parse_quantity(text, Quantity::force);
      FAIL() << text << ": no error";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("expected a force, got a mass"), std::string::npos) << what;
      EXPECT_NE(what.find("write " + std::string(force)), std::string::npos) << what;
      EXPECT_NE(what.find("mass = " + std::string(mass)), std::string::npos) << what;
    }
  }
  expect_si("34 t", Quantity::mass, 34000.0);  // as a mass it stays one
}

TEST(Units, WrongDimensionSaysWhatWasExpected) {
  try {
    parse_quantity("910 kgf/cm", Quantity::mass);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("expected a mass"), std::string::npos) << what;
    EXPECT_NE(what.find("force/length"), std::string::npos) << what;
  }
  EXPECT_THROW(parse_quantity("12 furlongs", Quantity::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("mm", Quantity::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("nan mm", Quantity::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("inf mm", Quantity::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("1e308 km", Quantity::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("5 m^x", Quantity::length), std::invalid_argument);
}

}  // namespace
}  // namespace railmodal::input
