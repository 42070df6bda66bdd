// The ranked comparison written from a streamed ranking (study/streamed_ranking.hpp): the same
// bytes write_comparison writes of the whole comparison, from each variant's row kept as text;
// and a shard's file (write_shard) from each result's JSON kept as text.
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/study.hpp"
#include "study/streamed_ranking.hpp"

namespace railmodal::report {

/// What a streamed ranking keeps of a variant for `format` (table, csv or json): its row, or
/// its JSON object, without its rank; std::invalid_argument for another format.
study::StreamedRanking::Render streamed_row(const Ranking& ranking, const DeflectionRule& rule, OutputFormat format);

/// Writes `head` (the study's name, source, ranking and rule; no variants) with the variants
/// of `ranked` (rendered by streamed_row in `format`), as write_comparison writes a comparison
/// that holds them; with a ranking of the best k, those k, under a head that counts them all.
/// `notes` (Study::notes) follow the table's notes, and are the JSON's "notes" (the CSV has none).
void write_streamed_comparison(std::ostream& out, const Comparison& head, const study::StreamedRanking& ranked,
                               OutputFormat format, const std::vector<std::string>& notes = {});

/// A result's JSON object laid out as it stands in a shard's "results" array (write_shard),
/// without the line break and indentation before it, for write_streamed_shard to insert.
std::string shard_result_json(const VariantResult& r);

/// Writes the bytes write_shard writes of the shard's `count` results in one pass, each
/// inserted where write_shard would write it from the text shard_result_json made of it
/// (result_at(0), result_at(1), ... in index order).
void write_streamed_shard(std::ostream& out, const Study& study, const EvaluationOptions& options, size_t count,
                          const std::function<std::string(size_t)>& result_at, const Provenance& inputs);

}  // namespace railmodal::report
