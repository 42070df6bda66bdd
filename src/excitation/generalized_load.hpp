// The generalised load into storage the caller keeps.
#pragma once

#include <Eigen/Core>

#include "railmodal/excitation.hpp"

namespace railmodal::excitation {

/// generalized_load(system, load) into `Q`, reusing the storage it holds (the same bits): the
/// critical speeds build a load at every resonance of every variant of a study.
void generalized_load_into(const LinearSystem& system, const HarmonicLoad& load, Eigen::VectorXcd* Q);

}  // namespace railmodal::excitation
