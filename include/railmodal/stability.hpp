// railmodal — static lateral stability of a body on its springs (bogie-wagons-natural
// digest §2.6–2.7): the metacentric height and Nolltein's measure.
//
//   #include <railmodal/railmodal.hpp>
//   #include <iostream>
//
//   int main() {
//     auto vehicle = railmodal::load_vehicle("data/vehicles/resort_car.toml");
//     auto s = railmodal::lateral_stability(vehicle, "body");
//     std::cout << "h = " << s.metacentric_height << " m, h - d0 = " << s.margin << " m\n";
//   }
#pragma once

#include <string>

#include "railmodal/summary.hpp"
#include "railmodal/vehicle.hpp"

namespace railmodal {

struct LateralStability {
  std::string body;
  /// Static roll stiffness of the springs about the body's reference point, every other
  /// motion (bogie roll, ...) free to settle and the body's lateral motion held: N·m/rad.
  double roll_stiffness = 0.0;
  /// h = roll_stiffness / W: height of the metacentre above the reference point, eq. (235b).
  double metacentric_height = 0.0;
  /// d0: height of the CG above the reference point.
  double cg_height = 0.0;
  /// h − d0: the body returns when positive, overturns when negative (§2.6).
  double margin = 0.0;
  /// Nolltein's measure h / (b2 d0), eq. (242c), 1/m, for a given half spacing b2 of the
  /// springs nearest the track; ≥ 4 1/m (0.04 1/cm) for three-axle and ≥ 6 1/m
  /// (0.06 1/cm) for bogie cars.
  double nolltein_measure(double b2) const { return metacentric_height / (b2 * cg_height); }
  /// The method, the check h − d0 ≥ 0 (as d0 − h ≤ 0) and the stages ("assemble", "condense").
  AnalysisSummary summary;
};

/// Computes the static roll stiffness from the elastic springs of the assembled vehicle
/// (gravity excluded, since h is compared with d0) by static condensation. Throws
/// std::invalid_argument when the body has no free roll motion.
LateralStability lateral_stability(const Vehicle& vehicle, const std::string& body);

}  // namespace railmodal
