// Shen, Hedrick and Elkins' creep-force saturation: Z. Y. Shen, J. K. Hedrick and J. A. Elkins,
// "A comparison of alternative creep force models for rail vehicle dynamic analysis", Proc. 8th
// IAVSD Symposium (1983), pp. 591–605; the cubic is Johnson and Vermeulen's, "Contact of
// nonspherical elastic bodies transmitting tangential forces", J. Appl. Mech. 31 (1964) 338–340.
// Also Garg and Dukkipati, Dynamics of Railway Vehicle Systems (1984), ch. 5. docs/stability.md
// derives it.
#include "stability/creep_saturation.hpp"

#include <cmath>

namespace railmodal::stability {

model::WheelContactForces saturated_creep_forces(const CreepCoefficients& creep, const model::WheelCreepage& creepage,
                                                 double friction_limit) {
  model::WheelContactForces f = model::linear_creep_forces(creep, creepage);
  const double resultant = std::hypot(f.longitudinal, f.lateral);
  // At zero creepage the law is the linear one (the cubic's slope at 0 is 1): nothing to scale,
  // and no 0/0.
  if (resultant == 0.0) return f;
  const double u = resultant / friction_limit;
  // u − u²/3 + u³/27 rises from 0 with slope 1 to 1 at u = 3 with slope 0: full sliding beyond.
  const double saturated = u < 3.0 ? friction_limit * u * (1.0 - u / 3.0 + u * u / 27.0) : friction_limit;
  const double scale = saturated / resultant;
  f.longitudinal *= scale;
  f.lateral *= scale;
  f.spin_moment *= scale;
  return f;
}

}  // namespace railmodal::stability
