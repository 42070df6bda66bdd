// The book's permissible dynamic deflections, element by element (springs digest §5).
#pragma once

#include <string>
#include <vector>

#include "railmodal/linear_system.hpp"
#include "railmodal/study.hpp"

namespace railmodal::study {

/// One limit the rule sets: on an element's whole stretch (stage = -1) or on one stage of it.
struct PermissibleDeflection {
  int element = 0;          ///< index into vehicle.elements
  int stage = -1;           ///< index into the element's vertical stages; -1: the element
  double permissible = 0.0;  ///< m, on the stage's (or element's) own deflection
  double share = 1.0;       ///< the stage's deflection per unit of element stretch
  std::string basis;        ///< "Lehner: coil springs 30 mm", "Korotkevich: …", "study: …"
  /// > 0 (N/m): a stage in series with a leaf-friction stage, which deflects by the force
  /// through the springs (friction included) over this stiffness rather than by its share.
  double force_stiffness = 0.0;
  /// m: for a leaf-friction stage in series with elastic stages, the element stretch those
  /// take alone while the leaf holds (response::leaf_hold_stretch); the stage deflects
  /// share × (stretch − hold), the series model of the simulation and of the criterion.
  double hold = 0.0;
};

/// Every limit of `rule` on the vehicle of `system` (its element loads give each stage's
/// static deflection f_st). Throws std::invalid_argument when an element limit names no
/// element with vertical springs (load_study checks this with the study's line first).
std::vector<PermissibleDeflection> permissible_deflections(const DeflectionRule& rule, const LinearSystem& system);

}  // namespace railmodal::study
