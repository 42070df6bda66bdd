// The variants a study plan defines, in study order: its variants as written, then each
// sweep's points (the full grid, or the seeded sample).
#pragma once

#include <vector>

#include "study/study_plan.hpp"

namespace railmodal::study {

std::vector<VariantSpec> planned_variants(const StudyPlan& plan);

}  // namespace railmodal::study
