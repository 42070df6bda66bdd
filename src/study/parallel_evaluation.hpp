// The shard's variants evaluated on several threads, each result handed to a sink as soon as it
// is made: evaluate_study keeps every result, a streamed ranking (study/streamed_ranking.hpp)
// only its keys.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "railmodal/study.hpp"

namespace railmodal::study {

/// Evaluates the variants of options' shard on its threads, as evaluate_study does (reading
/// unread ones in the workers with options.read_in_workers), and hands each result to `sink`
/// with its position among the shard's variants (0, 1, ... in index order). `prepare` is told
/// the number of the shard's variants before any is evaluated; `sink` is called from the
/// worker threads, concurrently, once per position. Returns the threads used. Throws
/// as evaluate_study: std::invalid_argument for invalid options or an unread variant, the
/// InputError of the lowest-index variant that could not be read.
int evaluate_each(const Study& study, const EvaluationOptions& options,
                  const std::function<void(size_t shard_size)>& prepare,
                  const std::function<void(size_t position, VariantResult&& result)>& sink);

/// evaluate_variant for a variant the caller gives up (a worker's, read for this evaluation):
/// its vehicle and scene are moved into the evaluation instead of copied, the result is the
/// same. `variant` keeps its name and parameters; its vehicle and scene are left valid but
/// unspecified.
VariantResult evaluate_owned_variant(StudyVariant&& variant, int index, const DeflectionRule& rule,
                                     const std::optional<HuntingOptions>& hunting, bool ride_rms_only);

}  // namespace railmodal::study
