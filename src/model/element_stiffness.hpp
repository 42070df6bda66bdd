// Stiffness of one suspension element that depends on its static load: the swing hangers'
// pendulum (shared by assembly and the reports that describe the model).
#pragma once

#include "railmodal/vehicle.hpp"

namespace railmodal::model {

/// Lateral stiffness of swing hangers carrying `load` (N): load / (λ cos α),
/// bogie-wagons-natural digest §2.8.
double hanger_stiffness(const SwingHanger& hanger, double load);

/// Lateral stiffness of an element carrying `load`: the hanger pendulum in series with any
/// lateral spring stages of the same element; 0 with neither.
double lateral_stiffness(const Element& e, double load);

}  // namespace railmodal::model
