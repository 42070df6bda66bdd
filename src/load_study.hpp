// load_study with its limit on the number of variants as a parameter, so that the fuzzer can
// keep each of its inputs small (tools/fuzz/fuzz_inputs.cpp); and read_variant into kept
// storage, for the study's workers (study/parallel_evaluation.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "railmodal/study.hpp"

namespace railmodal {

/// railmodal::load_study, refusing a study of more than `max_variants` variants at the
/// [[variant]] or [[sweep]] that goes over.
Study load_study(const std::string& path, const std::function<bool(int index)>& read_only, size_t max_variants,
                 std::vector<std::string>* warnings = nullptr);

/// What compare's outputs say once of a study's periods (table, JSON "notes", reports; the CSV
/// has no place for them): the notes `railmodal modes` prints of each of its vehicle files as
/// written, in the scene's DOF set, such as that a vehicle on wheelsets has its suspension modes,
/// without the wheel–rail contact terms. None for a study not read from a file.
std::vector<std::string> study_notes(const Study& study);

namespace detail {
/// read_variant written into *variant, whose vehicle's storage is reused where it has the
/// sizes: a study's workers read each variant into the vehicle of the one before. The same
/// variant; throws as read_variant, *variant then left valid but unspecified.
void read_variant_into(const Study& study, int index, StudyVariant* variant);
}  // namespace detail

}  // namespace railmodal
