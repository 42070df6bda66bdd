// The walk over every spring stage of an element or a vehicle, whatever its direction: for what
// looks at each stage alike (whether its coefficients are valid, the largest leaf friction,
// whether any stage has friction or a load-deflection curve), so that a direction is not left
// out of one of them.
#pragma once

#include <initializer_list>
#include <vector>

#include "railmodal/vehicle.hpp"

namespace railmodal::model {

/// Calls visit(stage) for each spring stage of `element`: its vertical, lateral and longitudinal
/// stages, in that order.
template <typename Visit>
void each_spring_stage(const Element& element, Visit&& visit) {
  for (const std::vector<SpringStage>* stages :
       {&element.vertical_stages, &element.lateral_stages, &element.longitudinal_stages})
    for (const SpringStage& stage : *stages) visit(stage);
}

/// The same for every element of `vehicle`, in the order of its elements.
template <typename Visit>
void each_spring_stage(const Vehicle& vehicle, Visit&& visit) {
  for (const Element& element : vehicle.elements) each_spring_stage(element, visit);
}

}  // namespace railmodal::model
