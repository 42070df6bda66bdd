#include "input/body_reader.hpp"

#include "input/input_warnings.hpp"

#include <cmath>
#include <string>

#include "railmodal/vehicle.hpp"
#include "shortest_text.hpp"

namespace railmodal::input {

double read_mass(TableReader& t, double gravity) {
  if (!t.has("mass") && !t.has("weight")) {
    t.refuse_misspelling("weight");  // "wieght", "mas": point at it (the audit of 2026-11-27)
    t.refuse_misspelling("mass");
  }
  if (t.has("mass") == t.has("weight"))
    t.fail("mass", t.has("mass") ? "give mass or weight, not both" : "missing: give mass (\"34 t\") or weight (\"34000 kgf\")");
  if (t.has("mass")) {
    const double mass = t.positive("mass", Quantity::mass);
    warn_implausible_mass(t, "mass", mass);  // a bare 42.2 meant in tonnes: 42.2 kg
    return mass;
  }
  const double mass = t.positive("weight", Quantity::force) / gravity;  // the book's m = P/g
  if (!within_magnitudes(mass)) t.fail("weight", "divided by the gravity gives a mass: " + magnitude_complaint(mass));
  return mass;
}

Eigen::Vector3d read_inertia(TableReader& t, double mass) {
  if (t.has("inertia") && t.has("radius_of_gyration"))
    t.fail("inertia", "give inertia or radius_of_gyration, not both");
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();
  const bool radii = t.has("radius_of_gyration");
  if (!radii && !t.has("inertia")) {
    t.refuse_misspelling("radius_of_gyration");  // "radius_of_gyraton", "inertai": point at it
    t.refuse_misspelling("inertia");
    t.fail("radius_of_gyration", "missing: give radius_of_gyration = {roll, pitch, yaw} or inertia = {roll, pitch, yaw}");
  }
  TableReader sub = t.table(radii ? "radius_of_gyration" : "inertia");
  const char* names[] = {"roll", "pitch", "yaw"};
  for (int k = 0; k < 3; ++k) {
    if (radii) {
      const auto r = sub.optional_positive(names[k], Quantity::length, true);
      if (r) warn_implausible_length(sub, names[k], *r, kBodyLength);
      inertia(k) = r ? mass * *r * *r : 0.0;
      if (!within_magnitudes(inertia(k)))
        sub.fail(names[k], "with the mass gives a moment of inertia: " + magnitude_complaint(inertia(k)));
    } else {
      inertia(k) = sub.optional_positive(names[k], Quantity::inertia, true).value_or(0.0);
    }
  }
  sub.finish();
  return inertia;
}

bool read_longitudinal_free(TableReader& t) {
  if (!t.has("free")) return false;
  const auto words = t.strings("free");
  // An empty list frees nothing: refused rather than read as freeing surge (issue 17 review).
  if (words.empty()) t.fail("free", "is empty: write free = [\"longitudinal\"] or leave the key out");
  for (const auto& word : words)
    if (word != "longitudinal")
      t.fail("free", motion_from_string(word) && word != "bending"
                         ? "'" + word + "' is free unless held; only longitudinal motion is held unless freed"
                         : "unknown motion '" + word + "' (only \"longitudinal\" is held unless freed)");
  return true;
}

std::optional<BodyBending> read_bending(TableReader& parent) {
  if (!parent.has("bending")) return std::nullopt;
  TableReader t = parent.table("bending");
  BodyBending b;
  b.length = t.positive("length", Quantity::length);
  b.centre = t.optional_quantity("centre", Quantity::length);
  const bool beam = t.has("bending_stiffness") || t.has("mass_per_length");
  const bool mode = t.has("frequency") || t.has("modal_mass");
  if (!beam && !mode)
    for (const char* key : {"bending_stiffness", "mass_per_length", "frequency", "modal_mass"}) t.refuse_misspelling(key);
  if (beam == mode)
    t.fail(beam ? "frequency" : "bending_stiffness",
           beam ? "give the beam (bending_stiffness and mass_per_length) or the mode (frequency and modal_mass), "
                  "not both"
                : "missing: give the beam, bending_stiffness = \"2.5e9 N*m^2\" and mass_per_length = \"1.3 t/m\", "
                  "or the mode, frequency = \"9 Hz\" and modal_mass = \"8 t\"");
  // Filled as plain structs and then assigned: clang decides std::optional<Beam>::emplace() is
  // not viable (it judges the nested struct's default constructor while BodyBending is still
  // incomplete), so emplace() builds with g++ only.
  if (beam) {
    BodyBending::Beam given;
    given.bending_stiffness = t.positive("bending_stiffness", Quantity::force_area);
    given.mass_per_length = t.positive("mass_per_length", Quantity::mass_per_length);
    b.beam = given;
  } else {
    BodyBending::Mode given;
    given.frequency = t.positive("frequency", Quantity::frequency);
    given.modal_mass = t.positive("modal_mass", Quantity::mass);
    b.mode = given;
  }
  // Required: an undamped bending mode has an unbounded resonance, and no default is right.
  b.damping_ratio = t.positive("damping_ratio", Quantity::dimensionless, true);
  if (!(b.damping_ratio < 1.0))
    t.fail("damping_ratio", "must be below 1 (a fraction of critical damping: 0.02 is 2 %)");
  t.finish();
  return b;
}

std::optional<double> read_floor_height(TableReader& t) {
  if (!t.has("floor_height")) return std::nullopt;
  // A coordinate, so any sign is read (a low-floor car on small wheels may have its floor below
  // the axles); a length beyond a body's scale is warned, as the templates' heights are.
  const double z = t.quantity("floor_height", Quantity::length);
  warn_implausible_length(t, "floor_height", z, kBodyLength);
  return z;
}

void check_bending_reach(TableReader& body_table, const Body& body, const std::vector<Element>& elements) {
  if (!body.bending) return;
  const double centre = body.bending->centre.value_or(body.centre_of_gravity.x());
  const double half = 0.5 * body.bending->length;
  for (const Element& e : elements) {
    if (e.upper != body.name && e.lower != body.name) continue;
    // The tolerance of model::BendingMode::shape_at, which would refuse the same element.
    if (std::abs(e.point.x() - centre) <= half * (1.0 + 2e-9)) continue;
    TableReader t = body_table.table("bending");
    t.fail("length", "element '" + e.name + "' acts on '" + body.name + "' at x = " + shortest_text(e.point.x()) +
                         " m, beyond the ends of the bending beam (x = " + shortest_text(centre - half, 6) + " m to " +
                         shortest_text(centre + half, 6) + " m): lengthen the beam or move its centre");
  }
}

namespace {

// `creep = { f11, f22, f23, f33 }`: Kalker's coefficients of one wheel, given directly.
CreepCoefficients read_creep(TableReader& parent) {
  TableReader t = parent.table("creep");
  CreepCoefficients c;
  c.f11 = t.positive("f11", Quantity::force);
  c.f22 = t.positive("f22", Quantity::force);
  // f23 and f33 may be zero: the spin terms are often left out of a hunting model (Wickens).
  // Left out, they are zero.
  c.f23 = t.optional_positive("f23", Quantity::moment, true).value_or(0.0);
  c.f33 = t.optional_positive("f33", Quantity::force_area, true).value_or(0.0);
  t.finish();
  return c;
}

// `hertz = { ... }`: what Hertz's theory needs to size the contact ellipse.
HertzContactInput read_hertz(TableReader& parent) {
  TableReader t = parent.table("hertz");
  HertzContactInput h;
  h.wheel_load = t.optional_positive("wheel_load", Quantity::force);
  if (t.has("wheel_transverse_radius")) {
    h.wheel_transverse_radius = t.quantity("wheel_transverse_radius", Quantity::length);
    if (*h.wheel_transverse_radius == 0.0)
      t.fail("wheel_transverse_radius",
             "must not be zero: positive for a convex tread, negative for a concave (hollow) one; leave the key "
             "out for a straight (conical) tread");
  }
  h.rail_head_radius = t.positive("rail_head_radius", Quantity::length);
  h.youngs_modulus = t.optional_positive("youngs_modulus", Quantity::modulus).value_or(h.youngs_modulus);
  h.poisson_ratio = t.optional_positive("poisson_ratio", Quantity::dimensionless, true).value_or(h.poisson_ratio);
  if (!(h.poisson_ratio < 0.5)) t.fail("poisson_ratio", "must be below 0.5 (steel: 0.28 to 0.3)");
  t.finish();
  return h;
}

}  // namespace

WheelRailContact read_contact(TableReader& t) {
  WheelRailContact c;
  c.rolling_radius = t.positive("rolling_radius", Quantity::length);
  c.contact_half_spacing = t.positive("contact_half_spacing", Quantity::length);
  c.conicity = t.positive("conicity", Quantity::dimensionless, true);
  // The rule contact_matrices and HuntingOptions apply: an equivalent conicity is a small slope.
  if (!(c.conicity < 1.0)) t.fail("conicity", "must be below 1 (0 ≤ conicity < 1; typical values 0.05 to 0.5)");
  c.contact_angle_parameter = t.optional_positive("contact_angle_parameter", Quantity::dimensionless, true);
  c.roll_parameter = t.optional_quantity("roll_parameter", Quantity::dimensionless);
  // W: without it, the wheelset's weight and the static loads of what stands on it.
  c.axle_load = t.optional_positive("axle_load", Quantity::force);
  if (!t.has("creep") && !t.has("hertz")) {
    t.refuse_misspelling("creep");
    t.refuse_misspelling("hertz");
  }
  if (t.has("creep") == t.has("hertz"))
    t.fail("creep", t.has("creep") ? "give creep or hertz, not both"
                                   : "missing: give the creep coefficients, creep = { f11 = \"…\", f22 = \"…\", "
                                     "f23 = \"…\", f33 = \"…\" }, or the contact they follow from, hertz = { "
                                     "rail_head_radius = \"0.3 m\" }");
  if (t.has("creep"))
    c.creep = read_creep(t);
  else
    c.hertz = read_hertz(t);
  return c;
}

double read_spin_inertia(TableReader& t) { return t.positive("spin_inertia", Quantity::inertia, true); }

}  // namespace railmodal::input
