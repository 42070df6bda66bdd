// Kalker's linear-theory creep coefficients C11, C22, C23, C33.
// PLACEHOLDER until issue 20's creep work lands.
#include <stdexcept>

#include "railmodal/wheel_rail.hpp"

namespace railmodal {

KalkerCoefficients kalker_coefficients(double, double) { throw std::logic_error("kalker_coefficients: not built yet"); }

}  // namespace railmodal
