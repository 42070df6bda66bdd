// The root paths grouped into the branches of the root locus, with their names.
#pragma once

#include <string>
#include <vector>

#include "railmodal/hunting.hpp"
#include "stability/root_tracking.hpp"

namespace railmodal::stability {

struct Branches {
  std::vector<HuntingBranch> oscillatory;  ///< least damped first at the top speed
  /// [speed][root] → the name of the group that root belongs to: a branch's name, or for a
  /// root that is real at every speed its name with " (real root)".
  std::vector<std::vector<std::string>> name_of_root;
};

/// The two paths that hold the halves of one conjugate pair form a branch (paired at the
/// highest speed where they are complex, since a mode can be overdamped, two real roots, at
/// low speed where C_c/V is large). At each speed the branch's eigenvalue is the half with
/// Im λ > 0, or, while both are real, the larger (the one that decides stability); its
/// continuity is the smaller of the two paths' MACs. Paths complex at no speed, and pairs
/// overdamped (overdamped_root) at every speed, are real roots and are not branches. Each is named by root_name() at the lowest speed; the branches whose
/// frequency tends to Klingel's V/Λ get " (kinematic)" (see the .cpp for the test), and names
/// that repeat get " (2)", " (3)", … in order.
Branches group_branches(const LinearSystem& system, const std::vector<SpeedRoots>& speeds, const RootPaths& paths,
                        double klingel_wavelength, double continuity_threshold);

}  // namespace railmodal::stability
