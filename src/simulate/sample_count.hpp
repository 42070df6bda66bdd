// How many samples a run of a duration at a time step records: one rule for the simulations
// and for the estimates made before them, so the two cannot disagree.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace railmodal::simulate {

/// The samples of a run from t = 0 to `duration` every `step`: the nearest whole number of
/// steps, and the sample at t = 0.
inline Eigen::Index sample_count(double duration, double step) {
  return static_cast<Eigen::Index>(std::llround(duration / step)) + 1;
}

}  // namespace railmodal::simulate
