// What an N_MV estimate covers, in one place for the ride's reports and a study's max_nmv.
#pragma once

#include <algorithm>
#include <string>

#include "railmodal/ride.hpp"

namespace railmodal::ride {

/// "vertical only" (or "lateral only", "longitudinal and vertical only") when a lateral or
/// vertical axis of the floor point has no output (taken as 0: the vertical-only coach reads 0.76
/// where all its axes give 0.99); "" when both are there: the longitudinal axis, which no bundled
/// scene outputs, is only named.
inline std::string nmv_scope(const RideComfortAtPoint& c) {
  const auto missing = [&c](RideAxis a) {
    return std::find(c.missing_axes.begin(), c.missing_axes.end(), a) != c.missing_axes.end();
  };
  if (!missing(RideAxis::lateral) && !missing(RideAxis::vertical)) return "";
  std::string present;
  for (RideAxis a : {RideAxis::longitudinal, RideAxis::lateral, RideAxis::vertical})
    if (!missing(a)) present += (present.empty() ? "" : " and ") + std::string(to_string(a));
  return present + " only";
}

}  // namespace railmodal::ride
