// load_study with its limit on the number of variants as a parameter, so that the fuzzer can
// keep each of its inputs small (tools/fuzz/fuzz_inputs.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "railmodal/study.hpp"

namespace railmodal {

/// railmodal::load_study, refusing a study of more than `max_variants` variants at the
/// [[variant]] or [[sweep]] that goes over.
Study load_study(const std::string& path, const std::function<bool(int index)>& read_only, size_t max_variants);

}  // namespace railmodal
