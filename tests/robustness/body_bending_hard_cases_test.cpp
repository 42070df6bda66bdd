// Hard numerical cases of a body's bending mode (Body::bending): an element at the very end of
// the beam, a mode far stiffer than the suspension, massless rotations condensed beside it, no
// modal damping. Each must give a finite, named answer, never NaN or an exception.
#include <cmath>

#include "model/body_bending.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// A 24 m, 32 t body on four springs at x = ±support, with a bending mode of `frequency`.
Vehicle flexible_body(double support, double frequency, double damping_ratio = 0.02) {
  Vehicle v;
  Body body;
  body.name = "body";
  body.mass = 32000.0;
  body.inertia = {5.68e4, 1.97e6, 1.97e6};
  body.centre_of_gravity = {0.0, 0.0, 1.8};
  body.reference_point = {0.0, 0.0, 0.8};
  body.held = {Motion::lateral, Motion::yaw};
  BodyBending b;
  b.length = 24.0;
  b.mode = BodyBending::Mode{frequency, 8000.0};
  b.damping_ratio = damping_ratio;
  body.bending = b;
  v.bodies.push_back(body);
  for (double x : {support, -support})
    for (double y : {1.0, -1.0}) {
      Element e;
      e.name = "spring";
      e.upper = "body";
      e.point = {x, y, 0.8};
      e.vertical_stages = {{"air", 4.3e5, 1}};
      e.vertical_damping = 2e4;
      v.elements.push_back(e);
    }
  return v;
}

TEST(BodyBendingHardCases, ElementsAtTheBeamsVeryEndsAreOnIt) {
  // 12 m written so that it sits a few ulps beyond the end: accepted, with φ = 1 to round-off.
  const double end = 12.0 * (1.0 + 4e-16);
  const LinearSystem s = assemble(flexible_body(end, 9.0), DofSet::vertical);
  const int q = s.index_of("body.bending");
  EXPECT_NEAR(s.element_vertical_map(0, q), 1.0, 1e-12);
  EXPECT_NEAR(s.element_vertical_map(2, q), 1.0, 1e-12);
}

TEST(BodyBendingHardCases, AModeFarStifferThanTheSuspension) {
  // 1 kHz against 1 Hz rigid modes: ω² spans 6 decades. The mode must stay at 1 kHz, raised only
  // by the springs' k·Σφ²/(2 m_b ω²) ≈ 1e-4 (first order), and the rigid modes be unmoved.
  const ModalResult r = solve_modes(assemble(flexible_body(9.5, 1000.0), DofSet::vertical));
  const Mode& bending = mode_named(r, "body first vertical bending");
  EXPECT_TRUE(std::isfinite(bending.frequency_hz));
  EXPECT_NEAR(bending.frequency_hz, 1000.0, 1e-3 * 1000.0);
  EXPECT_GT(bending.frequency_hz, 1000.0);
  const double rigid_bounce = mode_named(solve_modes(assemble(flexible_body(9.5, 1e5), DofSet::vertical)),
                                         "body bounce").frequency_hz;
  EXPECT_NEAR(mode_named(r, "body bounce").frequency_hz, rigid_bounce, 1e-3 * rigid_bounce);
}

TEST(BodyBendingHardCases, MasslessRotationsBesideTheMode) {
  // No roll or pitch inertia: those rotations are condensed statically, the bending DOF is not.
  Vehicle v = flexible_body(9.5, 9.0);
  v.bodies[0].inertia = {0.0, 0.0, 0.0};
  v.bodies[0].centre_of_gravity = v.bodies[0].reference_point;  // no m·d² either
  const ModalResult r = solve_modes(assemble(v, DofSet::all));
  const Mode& bending = mode_named(r, "body first vertical bending");
  EXPECT_TRUE(std::isfinite(bending.frequency_hz));
  EXPECT_GT(bending.frequency_hz, 9.0);
}

TEST(BodyBendingHardCases, NoModalDampingLeavesTheSuspensionsDamping) {
  // ζ = 0: only the secondary dampers damp the mode (through φ at the bogie centres); the damped
  // modes are finite and stable.
  const DampedModalResult r = solve_damped_modes(assemble(flexible_body(9.5, 9.0, 0.0), DofSet::vertical));
  EXPECT_TRUE(r.stable);
  bool found = false;
  for (const DampedMode& m : r.modes) {
    if (m.name != "body first vertical bending") continue;
    found = true;
    ASSERT_TRUE(m.damping_ratio.has_value());
    EXPECT_GT(*m.damping_ratio, 0.0);
    EXPECT_LT(*m.damping_ratio, 0.2);
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace railmodal::test
