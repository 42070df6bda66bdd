#include "input/units.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace railmodal::input {
namespace {

constexpr double kStandardGravity = 9.80665;  // kgf → N, exact by definition
constexpr double kPi = 3.14159265358979323846;

Dimension dim(int m, int l, int t, int a = 0) { return Dimension{{m, l, t, a}}; }

struct UnitDefinition {
  double scale;  // SI value of one unit
  Dimension dimension;
};

// The units the book and SI users write. kg and t are masses here; their force reading is
// the fallback in parse_quantity.
const std::map<std::string, UnitDefinition>& unit_table() {
  static const std::map<std::string, UnitDefinition> table = {
      {"m", {1.0, dim(0, 1, 0)}},
      {"cm", {0.01, dim(0, 1, 0)}},
      {"mm", {0.001, dim(0, 1, 0)}},
      {"km", {1000.0, dim(0, 1, 0)}},
      {"s", {1.0, dim(0, 0, 1)}},
      {"Hz", {1.0, dim(0, 0, -1)}},
      {"ms", {1.0e-3, dim(0, 0, 1)}},
      {"min", {60.0, dim(0, 0, 1)}},
      {"h", {3600.0, dim(0, 0, 1)}},
      {"kg", {1.0, dim(1, 0, 0)}},
      {"t", {1000.0, dim(1, 0, 0)}},
      {"N", {1.0, dim(1, 1, -2)}},
      {"kN", {1000.0, dim(1, 1, -2)}},
      {"MN", {1.0e6, dim(1, 1, -2)}},
      {"kgf", {kStandardGravity, dim(1, 1, -2)}},
      {"tf", {1000.0 * kStandardGravity, dim(1, 1, -2)}},
      {"Pa", {1.0, dim(1, -1, -2)}},
      {"kPa", {1.0e3, dim(1, -1, -2)}},
      {"MPa", {1.0e6, dim(1, -1, -2)}},
      {"GPa", {1.0e9, dim(1, -1, -2)}},
      {"rad", {1.0, dim(0, 0, 0, 1)}},
      {"mrad", {1.0e-3, dim(0, 0, 0, 1)}},
      {"deg", {kPi / 180.0, dim(0, 0, 0, 1)}},
      {"°", {kPi / 180.0, dim(0, 0, 0, 1)}},
      {"%", {0.01, dim(0, 0, 0)}},  // a share: "40 %" is 0.4, as `balance --fraction 40%` reads it
  };
  return table;
}

struct Factor {
  std::string symbol;
  int exponent;
};

bool is_space(const std::string& s, size_t i) {
  return std::isspace(static_cast<unsigned char>(s[i])) != 0;
}

// Reads a unit expression: symbols joined by '*', '·', '.' or spaces; every symbol after a
// '/' is in the denominator ("kgf/cm·s" is kgf/(cm·s)); exponents as ^n, ^-n, ², ³ or ⁻¹.
std::vector<Factor> parse_unit_expression(const std::string& text) {
  std::vector<Factor> factors;
  int sign = 1;  // +1 numerator, -1 after '/'
  size_t i = 0;
  const std::string middle_dot = "\xC2\xB7";  // ·
  const std::string sup2 = "\xC2\xB2", sup3 = "\xC2\xB3", sup_minus_one = "\xE2\x81\xBB\xC2\xB9";
  while (i < text.size()) {
    if (is_space(text, i) || text[i] == '*' || text[i] == '.') { ++i; continue; }
    if (text.compare(i, middle_dot.size(), middle_dot) == 0) { i += middle_dot.size(); continue; }
    if (text[i] == '/') { sign = -1; ++i; continue; }
    // A symbol: letters, the degree sign or the percent sign.
    std::string symbol;
    const std::string degree = "\xC2\xB0";
    if (text.compare(i, degree.size(), degree) == 0) {
      symbol = "°";
      i += degree.size();
    } else if (text[i] == '%') {
      symbol = "%";
      ++i;
    } else {
      while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i]))) symbol += text[i++];
    }
    if (symbol.empty()) throw std::invalid_argument("cannot read the unit '" + text + "'");
    int exponent = 1;
    if (i < text.size() && text[i] == '^') {
      ++i;
      size_t used = 0;
      try {
        exponent = std::stoi(text.substr(i), &used);
      } catch (const std::exception&) {
        throw std::invalid_argument("cannot read the exponent in the unit '" + text + "'");
      }
      i += used;
    } else if (text.compare(i, sup2.size(), sup2) == 0) {
      exponent = 2; i += sup2.size();
    } else if (text.compare(i, sup3.size(), sup3) == 0) {
      exponent = 3; i += sup3.size();
    } else if (text.compare(i, sup_minus_one.size(), sup_minus_one) == 0) {
      exponent = -1; i += sup_minus_one.size();
    }
    factors.push_back({symbol, sign * exponent});
  }
  return factors;
}

// Scale and dimension of the factors, reading kg and t as kgf and tf when as_force is set.
UnitDefinition evaluate(const std::vector<Factor>& factors, bool as_force) {
  UnitDefinition total{1.0, Dimension{}};
  for (const auto& f : factors) {
    std::string symbol = f.symbol;
    if (as_force && symbol == "kg") symbol = "kgf";
    if (as_force && symbol == "t") symbol = "tf";
    auto it = unit_table().find(symbol);
    if (it == unit_table().end()) throw std::invalid_argument("unknown unit '" + f.symbol + "'");
    total.scale *= std::pow(it->second.scale, f.exponent);
    for (int k = 0; k < 4; ++k) total.dimension.exponent[k] += f.exponent * it->second.dimension.exponent[k];
  }
  return total;
}

bool mentions_mass_units(const std::vector<Factor>& factors) {
  for (const auto& f : factors)
    if (f.symbol == "kg" || f.symbol == "t") return true;
  return false;
}

}  // namespace

Dimension dimension_of(Quantity q) {
  switch (q) {
    case Quantity::length: return dim(0, 1, 0);
    case Quantity::mass: return dim(1, 0, 0);
    case Quantity::force: return dim(1, 1, -2);
    case Quantity::stiffness: return dim(1, 0, -2);
    case Quantity::flexibility: return dim(-1, 0, 2);
    case Quantity::inertia: return dim(1, 2, 0);
    case Quantity::angle: return dim(0, 0, 0, 1);
    case Quantity::acceleration: return dim(0, 1, -2);
    case Quantity::damping: return dim(1, 0, -1);
    case Quantity::modulus: return dim(1, -1, -2);
    case Quantity::speed: return dim(0, 1, -1);
    case Quantity::velocity: return dim(0, 1, -1);
    case Quantity::rotational_stiffness: return dim(1, 2, -2, -1);
    case Quantity::dimensionless: return dim(0, 0, 0);
    case Quantity::time: return dim(0, 0, 1);
    case Quantity::angular_speed: return dim(0, 0, -1, 1);
    case Quantity::moment: return dim(1, 2, -2);
    case Quantity::force_area: return dim(1, 3, -2);
    case Quantity::mass_per_length: return dim(1, -1, 0);
    case Quantity::frequency: return dim(0, 0, -1);
  }
  return dim(0, 0, 0);
}

const char* name_of(Quantity q) {
  switch (q) {
    case Quantity::length: return "a length";
    case Quantity::mass: return "a mass";
    case Quantity::force: return "a force";
    case Quantity::stiffness: return "a stiffness (force/length)";
    case Quantity::flexibility: return "a flexibility (length/force)";
    case Quantity::inertia: return "a moment of inertia (mass·length²)";
    case Quantity::angle: return "an angle";
    case Quantity::acceleration: return "an acceleration";
    case Quantity::damping: return "a damping coefficient (force·time/length)";
    case Quantity::modulus: return "a modulus (force/area)";
    case Quantity::speed: return "a speed";
    case Quantity::velocity: return "a velocity";
    case Quantity::rotational_stiffness: return "a rotational stiffness (moment/angle)";
    case Quantity::dimensionless: return "a plain number";
    case Quantity::time: return "a time";
    case Quantity::angular_speed: return "an angular speed";
    case Quantity::moment: return "a moment (force·length)";
    case Quantity::force_area: return "a force·length²";
    case Quantity::mass_per_length: return "a mass per length";
    case Quantity::frequency: return "a frequency";
  }
  return "a quantity";
}

const char* example_of(Quantity q) {
  switch (q) {
    case Quantity::length: return "\"57.2 mm\" or 0.0572 (m)";
    case Quantity::mass: return "\"34 t\" or 34000 (kg)";
    case Quantity::force: return "\"5660 kgf\" or 55500 (N)";
    case Quantity::stiffness: return "\"910 kgf/cm\" or 8.9e5 (N/m)";
    case Quantity::flexibility: return "\"10.5 mm/t\" or 1.07e-6 (m/N)";
    case Quantity::inertia: return "\"1.2e5 kg*m^2\", \"kgf*cm*s^2\" or a number in kg·m²";
    case Quantity::angle: return "\"14 deg\" or 0.244 (rad)";
    case Quantity::acceleration: return "\"981 cm/s^2\" or 9.81 (m/s²)";
    case Quantity::damping: return "\"20 kN*s/m\" or 2.0e4 (N·s/m)";
    case Quantity::modulus: return "\"2.2e6 kgf/cm^2\" or 2.16e11 (Pa)";
    case Quantity::speed: return "\"75 km/h\" or \"20.8 m/s\"";  // a speed needs its unit (table_reader.cpp)
    case Quantity::velocity: return "\"0.05 m/s\" or 0.05 (m/s)";
    case Quantity::rotational_stiffness: return "\"940 kN*m/rad\" or 9.4e5 (N·m/rad)";
    case Quantity::dimensionless: return "a number";
    case Quantity::time: return "\"2 ms\" or 0.002 (s)";
    case Quantity::angular_speed: return "\"0.1 rad/s\" or 0.1 (rad/s)";
    case Quantity::moment: return "\"2.1 kN*m\" or 2100 (N·m)";
    case Quantity::force_area: return "\"120 N*m^2\" or 120 (N·m²)";
    case Quantity::mass_per_length: return "\"1.3 t/m\" or 1300 (kg/m)";
    case Quantity::frequency: return "\"9 Hz\" or 9 (Hz)";
  }
  return "";
}

std::string describe(const Dimension& d) {
  // Name the common combinations the way engineers say them.
  static const std::vector<std::pair<Dimension, std::string>> names = {
      {dim(0, 1, 0), "length"},          {dim(1, 0, 0), "mass"},
      {dim(1, 1, -2), "force"},          {dim(1, 0, -2), "force/length"},
      {dim(-1, 0, 2), "length/force"},   {dim(1, 2, 0), "mass·length²"},
      {dim(0, 0, 0, 1), "angle"},        {dim(0, 1, -2), "acceleration"},
      {dim(1, 0, -1), "force·time/length"}, {dim(1, -1, -2), "force/area"},
      {dim(0, 1, -1), "speed"},          {dim(0, 0, 1), "time"},
      {dim(0, 0, 0), "a plain number"},  {dim(1, -1, 0), "mass/length"},
      {dim(0, 1, 0, 0), "length"},       {dim(-1, 1, 0), "length/mass"},
      {dim(1, 1, 0), "mass·length"},     {dim(1, 2, -2), "force·length (moment)"},
      {dim(1, 2, -2, -1), "moment/angle"}, {dim(1, 3, -2), "force·length²"},
      {dim(0, 0, -1), "frequency"},
  };
  for (const auto& [dimension, name] : names)
    if (dimension == d) return name;
  std::ostringstream out;
  const char* base[] = {"kg", "m", "s", "rad"};
  bool first = true;
  for (int k = 0; k < 4; ++k) {
    if (d.exponent[k] == 0) continue;
    if (!first) out << "·";
    out << base[k];
    if (d.exponent[k] != 1) out << "^" << d.exponent[k];
    first = false;
  }
  return out.str();
}

double parse_quantity(const std::string& text, Quantity expected) {
  const char* start = text.c_str();
  while (*start && std::isspace(static_cast<unsigned char>(*start))) ++start;
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  if (end == start)
    throw std::invalid_argument("expected " + std::string(name_of(expected)) + " such as " +
                                example_of(expected) + ", got \"" + text + "\"");
  if (!std::isfinite(value))
    throw std::invalid_argument("the value \"" + text + "\" is not a finite number");
  // "1,2 MN/m": a decimal comma (the user audit of 2026-11-28b), which the unit reader would
  // report as the unit ',2 MN/m'. Said as what it most likely is, with the value rewritten.
  if (*end == ',' && std::isdigit(static_cast<unsigned char>(end[1]))) {
    std::string with_point(start);
    with_point[static_cast<size_t>(end - start)] = '.';
    throw std::invalid_argument("cannot read \"" + text + "\": a decimal comma? write a decimal point, \"" +
                                with_point + "\"");
  }
  const std::string unit_text(end);
  const auto factors = parse_unit_expression(unit_text);
  if (factors.empty()) return value;  // a bare number is SI
  const Dimension wanted = dimension_of(expected);
  UnitDefinition unit = evaluate(factors, false);
  // A mass where a force is wanted ("34000 kg" for a weight or a load) is refused: a compound
  // unit reads kg and t as the book's kilogram- and tonne-force below ("910 kg/cm", unambiguous:
  // no mass per length is asked for), but alone it may as well mean the mass (the audit of
  // 2026-11-27 met weight = "34000 kg").
  if (wanted == dimension_of(Quantity::force) && unit.dimension == dimension_of(Quantity::mass)) {
    const std::string number(start, static_cast<size_t>(end - start));
    const bool tonnes = factors.size() == 1 && factors[0].symbol == "t";
    throw std::invalid_argument("expected a force, got a mass in \"" + text + "\": a weight or a load is a force; write \"" +
                                number + (tonnes ? " tf" : " kgf") + "\" (" + (tonnes ? "tonne" : "kilogram") +
                                "-force), or give the mass as a mass (a body's mass = \"" + number + " " +
                                (tonnes ? "t" : "kg") + "\")");
  }
  if (unit.dimension != wanted && mentions_mass_units(factors)) {
    // The book's "kg/cm" and "mm/t": kilogram-force and tonne-force.
    UnitDefinition as_force = evaluate(factors, true);
    if (as_force.dimension == wanted) unit = as_force;
  }
  if (unit.dimension != wanted) {
    const std::string got = describe(unit.dimension);
    throw std::invalid_argument("expected " + std::string(name_of(expected)) + " such as " +
                                example_of(expected) + ", got " + got + " in \"" + text + "\"");
  }
  const double si = value * unit.scale;
  if (!std::isfinite(si))
    throw std::invalid_argument("the value \"" + text + "\" overflows when converted to SI");
  return si;
}

}  // namespace railmodal::input
