// Hertz's contact ellipse of a wheel on its rail and the creep coefficients it gives.
// PLACEHOLDER until issue 20's creep work lands: every function throws.
#include <stdexcept>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {

HertzContact hertz_contact(const HertzContactInput&, double) { throw std::logic_error("hertz_contact: not built yet"); }

CreepCoefficients creep_coefficients(const HertzContact&, double, double) {
  throw std::logic_error("creep_coefficients: not built yet");
}

}  // namespace railmodal
