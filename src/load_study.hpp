// load_study with its limit on the number of variants as a parameter, so that the fuzzer can
// keep each of its inputs small (tools/fuzz/fuzz_inputs.cpp); and, for the study's workers
// (study/parallel_evaluation.cpp), read_variant into kept storage and an evaluation's input error
// sent back to its variant's line.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "railmodal/errors.hpp"
#include "railmodal/study.hpp"

namespace railmodal {

/// railmodal::load_study, refusing a study of more than `max_variants` variants at the
/// [[variant]] or [[sweep]] that goes over.
Study load_study(const std::string& path, const std::function<bool(int index)>& read_only, size_t max_variants,
                 std::vector<std::string>* warnings = nullptr);

namespace detail {
/// read_variant written into *variant, whose vehicle's storage is reused where it has the
/// sizes: a study's workers read each variant into the vehicle of the one before. The same
/// variant; throws as read_variant, *variant then left valid but unspecified.
void read_variant_into(const Study& study, int index, StudyVariant* variant);

/// An InputError raised while variant `index` of a study read from a file was evaluated (a scene
/// output or source that does not fit its vehicle, a series damper an analysis refuses), as the
/// study's error: at the variant's assignment that writes the key it names, else at the variant's
/// line, naming the variant and the error's own file, line and key. `e` itself for a study
/// built in code.
InputError variant_input_error(const Study& study, int index, const InputError& e);
}  // namespace detail

}  // namespace railmodal
