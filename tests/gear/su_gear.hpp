// The Су 1-3-1 driving gear of Zhdanov 1937 (digest shared/reference/unbalance-excitation.md,
// Table 4 and §5.1), in SI, for the tests of the driving gear and the balancing calculator.
// Masses in kg are the book's weights in kgf (numerically); J about the crosshead pin
// 71.665 kgf·m·s² = 703.0 kg·m².
#pragma once

#include <cmath>

#include "railmodal/driving_gear.hpp"

namespace railmodal::testing {

constexpr double kKgf = 9.81;  // N per kgf, the digest's g

inline GearCylinder su_cylinder(bool right) {
  GearCylinder c;
  c.name = right ? "right" : "left";
  c.lateral = right ? 1.14 : -1.14;           // rod plane 1140 mm from the centreline (§5.1)
  c.crank_offset = right ? 0.0 : -M_PI / 2;  // cranks at 90°, the left lags the right
  c.axle = 1;
  c.crank_radius = 0.35;
  c.rod_length = 2.35;
  c.rod_mass = 225.28;
  c.rod_centre_of_mass = 1.5575;
  c.rod_inertia = rod_inertia_about_centre(71.665 * kKgf, 225.28, 1.5575);
  c.reciprocating_mass = 365.75;
  return c;
}

/// The two cylinders and one driving axle with no rotating masses (the rod forces alone).
inline DrivingGear su_rods_only() {
  DrivingGear g;
  g.wheel_diameter = 1.85;
  g.wheel_plane_half_spacing = 0.795;  // 2S = 1590 mm
  g.cylinders = {su_cylinder(true), su_cylinder(false)};
  g.cylinders[0].axle = g.cylinders[1].axle = 0;
  g.axles.resize(1);
  g.axles[0].name = "driving";
  g.axles[0].crank_radius = 0.35;
  g.axles[0].right.static_load = g.axles[0].left.static_load = 9000 * kKgf;  // 18 t axle load
  g.axles[0].left.crank_offset = -M_PI / 2;
  return g;
}

/// The whole engine: coupled axle 1, driving axle 2, coupled axle 3 with the rotating masses of
/// §5.1 (crank webs, pin parts, coupling-rod shares; no counter-crank). The digest does not
/// give each mass's plane: pins and rod shares are put in the rod plane (a = 0.345 m), the webs
/// in the wheel plane (a = 0) — an assumption of this fixture, not a book value.
inline DrivingGear su_engine() {
  DrivingGear g = su_rods_only();
  g.cylinders[0].axle = g.cylinders[1].axle = 1;
  g.axles.resize(3);
  const char* names[] = {"coupled 1", "driving", "coupled 3"};
  const double webs[][2] = {{57.034, 0.3296}, {120.0, 0.3757}, {58.418, 0.330}};
  const double pins[] = {10.08, 65.79, 12.925};
  const double rods[] = {68.447, 181.5, 53.10};
  for (int a = 0; a < 3; ++a) {
    GearAxle& axle = g.axles[a];
    axle.name = names[a];
    axle.position = 0.0;
    axle.crank_radius = 0.35;
    axle.right.static_load = axle.left.static_load = 9000 * kKgf;
    axle.left.crank_offset = -M_PI / 2;
    for (GearWheel* w : {&axle.right, &axle.left}) {
      w->masses.push_back({"crank web", webs[a][0], webs[a][1], 0.0, 0.0, false});
      w->masses.push_back({"crank pin", pins[a], 0.35, 0.0, 0.345, false});
      w->masses.push_back({"coupling rod", rods[a], 0.35, 0.0, 0.345, false});
    }
  }
  return g;
}

}  // namespace railmodal::testing
