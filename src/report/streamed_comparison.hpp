// The ranked comparison written from a streamed ranking (study/streamed_ranking.hpp): the same
// bytes write_comparison writes of the whole comparison, from each variant's row kept as text.
#pragma once

#include <ostream>

#include "railmodal/output_format.hpp"
#include "railmodal/study.hpp"
#include "study/streamed_ranking.hpp"

namespace railmodal::report {

/// What a streamed ranking keeps of a variant for `format` (table, csv or json): its row, or
/// its JSON object, without its rank; std::invalid_argument for another format.
study::StreamedRanking::Render streamed_row(const Ranking& ranking, const DeflectionRule& rule, OutputFormat format);

/// Writes `head` (the study's name, source, ranking and rule; no variants) with the variants
/// of `ranked` (rendered by streamed_row in `format`), as write_comparison writes a comparison
/// that holds them; with a ranking of the best k, those k, under a head that counts them all.
void write_streamed_comparison(std::ostream& out, const Comparison& head, const study::StreamedRanking& ranked,
                               OutputFormat format);

}  // namespace railmodal::report
