// The unit of a ride output's values, and whether a result has a grid error estimate: one answer
// for the reports, studies and the Python binding.
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

bool has_grid_error_estimate(const RideResult& result) {
  if (result.rms_only) return false;
  for (const RideAtSpeed& at : result.speeds)
    for (const RideOutputAtSpeed& o : at.outputs)
      if (!o.unbounded && o.rms > 0.0) return true;
  return false;
}

}  // namespace railmodal
