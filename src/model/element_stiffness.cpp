// Load-dependent element stiffness: swing hangers (bogie-wagons-natural digest §2.8).
#include "model/element_stiffness.hpp"

#include <cmath>

namespace railmodal::model {

double hanger_stiffness(const SwingHanger& hanger, double load) {
  // Pendulum: N = load / (λ cos α).
  return load / (hanger.length * std::cos(hanger.inclination));
}

double lateral_stiffness(const Element& e, double load) {
  const double spring = series_stiffness(e.lateral_stages);
  if (!e.hanger) return spring;
  const double pendulum = hanger_stiffness(*e.hanger, load);
  return spring > 0.0 ? 1.0 / (1.0 / pendulum + 1.0 / spring) : pendulum;
}

}  // namespace railmodal::model
