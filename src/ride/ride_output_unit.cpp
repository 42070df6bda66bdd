// The unit of a ride output's values, one answer for reports and studies.
#include "railmodal/ride.hpp"

namespace railmodal {

std::string unit_of(const RideOutput& output) {
  switch (output.kind) {
    case RideOutput::Kind::point:
      return output.quantity == ResponseQuantity::displacement ? "m"
             : output.quantity == ResponseQuantity::velocity   ? "m/s"
                                                               : "m/s²";
    case RideOutput::Kind::element_deflection:
      return "m";
    case RideOutput::Kind::element_force:
    case RideOutput::Kind::wheel_rail_force:
      return "N";
  }
  return "";
}

}  // namespace railmodal
