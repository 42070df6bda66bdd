// The shard files of railmodal compare --shard read one result at a time, for a merge that
// holds no more than its ranking keys (issue 19, item 2).
#pragma once

#include <functional>
#include <string>

#include "railmodal/study.hpp"

namespace railmodal::input {

/// Reads shard `file` of `study` as read_shard does, but hands each result to `sink` in file
/// order instead of returning them all: the file is parsed twice, first to check it whole
/// (read_shard's errors, in its order: nothing reaches the sink from a bad file), then to hand
/// on its results, so that only one result is in memory at once.
void read_shard_each(const std::string& file, const Study& study, const std::function<void(VariantResult&&)>& sink);

}  // namespace railmodal::input
