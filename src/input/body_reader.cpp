#include "input/body_reader.hpp"

#include "railmodal/vehicle.hpp"

namespace railmodal::input {

double read_mass(TableReader& t, double gravity) {
  if (t.has("mass") == t.has("weight"))
    t.fail("mass", t.has("mass") ? "give mass or weight, not both" : "missing: give mass (\"34 t\") or weight (\"34000 kgf\")");
  if (t.has("mass")) return t.positive("mass", Quantity::mass);
  const double mass = t.positive("weight", Quantity::force) / gravity;  // the book's m = P/g
  if (!within_magnitudes(mass)) t.fail("weight", "divided by the gravity gives a mass: " + magnitude_complaint(mass));
  return mass;
}

Eigen::Vector3d read_inertia(TableReader& t, double mass) {
  if (t.has("inertia") && t.has("radius_of_gyration"))
    t.fail("inertia", "give inertia or radius_of_gyration, not both");
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();
  const bool radii = t.has("radius_of_gyration");
  if (!radii && !t.has("inertia"))
    t.fail("radius_of_gyration", "missing: give radius_of_gyration = {roll, pitch, yaw} or inertia = {roll, pitch, yaw}");
  TableReader sub = t.table(radii ? "radius_of_gyration" : "inertia");
  const char* names[] = {"roll", "pitch", "yaw"};
  for (int k = 0; k < 3; ++k) {
    if (radii) {
      const auto r = sub.optional_positive(names[k], Quantity::length, true);
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
      t.fail("free", motion_from_string(word)
                         ? "'" + word + "' is free unless held; only longitudinal motion is held unless freed"
                         : "unknown motion '" + word + "' (only \"longitudinal\" is held unless freed)");
  return true;
}

}  // namespace railmodal::input
