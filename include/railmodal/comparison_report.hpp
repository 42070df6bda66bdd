// railmodal — the report of a design study: the ranked variants as a table, CSV or JSON, and
// documents to hand in (Markdown, a self-contained HTML page with inline SVG plots).
//
//   #include <railmodal/railmodal.hpp>
//   #include <fstream>
//   #include <iostream>
//
//   int main() {
//     railmodal::Study study = railmodal::load_study("data/studies/two_axle_rail_length_and_springs.toml");
//     railmodal::Comparison comparison = railmodal::rank_variants(study, railmodal::evaluate_study(study, {}));
//     railmodal::write_comparison(std::cout, comparison, railmodal::OutputFormat::table);
//     std::ofstream page("/dev/null");  // a file such as study.html
//     railmodal::ComparisonCurves curves = railmodal::comparison_curves(study, comparison, railmodal::kReportBest);
//     railmodal::write_comparison_report(page, study, comparison, curves, railmodal::OutputFormat::html);
//   }
#pragma once

#include <ostream>

#include "railmodal/output_format.hpp"
#include "railmodal/provenance.hpp"
#include "railmodal/study.hpp"

namespace railmodal {

/// Writes table, csv or json: from the ranked results alone. markdown and html need the study
/// (write_comparison_report); here they throw std::invalid_argument.
void write_comparison(std::ostream& out, const Comparison& comparison, OutputFormat format);

/// Evaluates the whole study (options.shards must be 1) and writes its ranking in table, csv or json: the bytes
/// write_comparison(out, rank_variants(study, evaluate_study(study, options)), format) writes, with the study's notes
/// (its vehicle files' modes' notes, as `railmodal modes` prints them) after the table's and as the JSON's "notes",
/// whatever the thread count, holding in memory per variant only its ranking keys (tens of bytes): each variant's
/// row waits in a temporary file until the ranking is known. With `top` > 0 only the best `top` variants are
/// written (the table's head still counts them all), and only their rows are held. markdown and html write the
/// bytes write_comparison_report writes of that comparison with comparison_curves(study, ..., kReportBest) and
/// `provenance`, holding the best kReportRows variants and the base whole and each other's sweep point (its
/// parameters, periods and ranked value) in the temporary file.
/// Throws as evaluate_study and rank_variants, std::system_error when the temporary file
/// cannot be made or written (TMPDIR), and std::invalid_argument for a negative `top` or a
/// `top` with markdown or html.
void compare_study(std::ostream& out, const Study& study, const EvaluationOptions& options, OutputFormat format,
                   int top = 0, const Provenance& provenance = {});

/// Ranks the results of `shard_files` (each written by compare_shard or write_shard; together
/// every variant of the study once) and writes them as compare_study does: the bytes
/// write_comparison_report writes of rank_variants(study, <the shards' results>) (the documents
/// with comparison_curves, which reads the variants it draws), holding one result at a time (each
/// file is read twice: checked, then ranked). Throws InputError naming the file for a shard of
/// another study or version, a variant in two shards or in none; otherwise as compare_study.
void compare_merged(std::ostream& out, const Study& study, const std::vector<std::string>& shard_files,
                    OutputFormat format, int top = 0, const Provenance& provenance = {});

/// The report of a study in any format; markdown and html are documents to hand in: why the
/// winner wins (its criteria against the base and the runner-up, what the others violate),
/// the ranked table (first kReportRows variants), each swept parameter against the periods
/// and the objective, and the amplitude-against-speed curves of the best kReportBest
/// feasible variants over the base's, from `curves` (comparison_curves(study, comparison,
/// kReportBest); table, csv and json do not draw them: pass {}). HTML is one self-contained
/// page with inline SVG plots. The documents end with the railmodal version and `provenance`'s
/// input files with their digests (provenance_of(study_files(study))). The writer reads no
/// file and runs no analysis.
inline constexpr int kReportRows = 40;
inline constexpr int kReportBest = 3;
void write_comparison_report(std::ostream& out, const Study& study, const Comparison& comparison,
                             const ComparisonCurves& curves, OutputFormat format, const Provenance& provenance = {});

/// The results of one shard of a study as JSON (railmodal compare --shard), for read_shard
/// (study.hpp) to merge: the study's name and size, the evaluation's shard, each result, and
/// `inputs`' files with their digests (provenance_of(study_files(study)), the study file first:
/// read_shard refuses a shard of another version of the study file; none: not checked).
void write_shard(std::ostream& out, const Study& study, const EvaluationOptions& options,
                 const std::vector<VariantResult>& results, const Provenance& inputs = {});

/// Evaluates options' shard and writes the bytes write_shard(out, study, options,
/// evaluate_study(study, options), inputs) writes, whatever the thread count, holding in
/// memory per variant only where its result's JSON lies in a temporary file (TMPDIR). Throws
/// as evaluate_study, and std::system_error when the temporary file cannot be made or written.
void compare_shard(std::ostream& out, const Study& study, const EvaluationOptions& options,
                   const Provenance& inputs = {});

}  // namespace railmodal
