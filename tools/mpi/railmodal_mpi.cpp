// railmodal-mpi: railmodal compare across the ranks of an MPI job (docs/studies.md, "Across a
// cluster").
//
//   mpirun -np N railmodal-mpi compare STUDY.toml [--format table|csv|json|markdown|html] [-o OUT]
//                                                  [--threads T]
//
// Rank r evaluates shard r + 1 of N (the variants whose index mod N is r, as
// `railmodal compare --shard r+1/N`), rank 0 gathers the shards, ranks the variants and writes
// exactly what `railmodal compare STUDY.toml` writes. Exit codes as railmodal's: 0 success,
// 2 usage, 3 input, 5 output, 1 internal; every rank exits with the same code.
#include <mpi.h>
#ifdef __linux__
#include <sched.h>
#endif

#include <CLI/CLI.hpp>
#include <algorithm>
#include <climits>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/comparison_report.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/study.hpp"
#include "railmodal/version.hpp"

namespace {

using railmodal::cli::kInput;
using railmodal::cli::kInternal;
using railmodal::cli::kOutput;
using railmodal::cli::kSuccess;
using railmodal::cli::kUsage;
using railmodal::cli::OutputError;
using railmodal::cli::OutputFiles;

struct Options {
  std::string study;
  std::string format = "table";
  std::string output = "-";
  int threads = 0;
};

/// The default thread count of a rank: the cores it may run on (its binding), shared with the
/// other ranks of its node when they are not bound apart, at least 1.
int default_threads() {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks_on_node = 1;
  MPI_Comm_size(node, &ranks_on_node);
  MPI_Comm_free(&node);
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  int allowed = cores;
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) allowed = std::max(1, CPU_COUNT(&set));
#endif
  return std::max(1, std::min(allowed, cores / std::max(1, ranks_on_node)));
}

/// This rank's shard as JSON (write_shard), or a failure: its exit code and message.
struct ShardText {
  int code = kSuccess;
  std::string text;  ///< the shard, or the message when code != kSuccess
};

/// `step`'s text, or its failure with the exit code and message railmodal gives it.
template <class Step>
ShardText guarded(const Step& step) {
  try {
    return {kSuccess, step()};
  } catch (const railmodal::InputError& e) {
    return {kInput, e.what()};
  } catch (const OutputError& e) {
    return {e.code(), e.what()};
  } catch (const std::system_error& e) {  // a shard's temporary file (TMPDIR), as railmodal compare says it
    return {kOutput, std::string("railmodal: error: ") + e.what()};
  } catch (const std::exception& e) {
    return {kInternal, std::string("railmodal-mpi: internal error: ") + e.what()};
  }
}

/// The study opened, no variant listed or read: the threads that evaluate this rank's variants
/// make and read them from their index (EvaluationOptions::read_in_workers, as railmodal compare
/// does); rank 0's report reads the others it draws. A rank holds no list of the study's
/// variants (about 2.5 kB each).
railmodal::Study load_named_variants(const Options& o) { return railmodal::open_study(o.study); }

/// Rank 0, before any rank evaluates: its output opened, its study read, and the output refused
/// if it is one of the study's files (as railmodal compare does), so that these fail first.
ShardText prepare_output(const Options& o, OutputFiles& outputs, std::ostream** out,
                         std::optional<railmodal::Study>& study) {
  return guarded([&] {
    *out = &outputs.open(o.output);
    outputs.refuse_inputs({o.study});
    study = load_named_variants(o);
    outputs.refuse_inputs(railmodal::study_files(*study));
    return std::string();
  });
}

ShardText evaluate_shard(const Options& o, int rank, int size, int threads, std::optional<railmodal::Study>& study) {
  return guarded([&] {
    if (!study) study = load_named_variants(o);
    railmodal::EvaluationOptions evaluation;
    evaluation.shard = rank + 1;
    evaluation.shards = size;
    evaluation.threads = threads;
    evaluation.read_in_workers = true;
    std::ostringstream out;  // the results' text only: each result's waits in a temporary file (compare_shard)
    railmodal::compare_shard(out, *study, evaluation);
    return out.str();
  });
}

/// Collective: every rank learns whether any failed, so none waits for a shard that never
/// comes. The lowest failing rank prints its message and every rank returns that rank's code.
int first_failure(const ShardText& mine, int rank, int size) {
  int failing = mine.code != kSuccess ? rank : size;
  int first = size;
  MPI_Allreduce(&failing, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == size) return kSuccess;
  int code = mine.code;
  MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
  if (rank == first)
    std::cerr << (rank == 0 ? "" : "railmodal-mpi: rank " + std::to_string(rank) + ": ") << mine.text << "\n";
  return code;
}

/// Rank 0: the gathered shards ranked and written as railmodal compare writes them.
int merge_and_write(const Options& o, const railmodal::Study& study, const std::vector<std::string>& shards,
                    OutputFiles& outputs, std::ostream& out) {
  const ShardText written = guarded([&] {
    std::vector<railmodal::VariantResult> results;
    std::set<int> seen;
    for (size_t r = 0; r < shards.size(); ++r) {
      const std::string origin = "railmodal-mpi rank " + std::to_string(r);
      std::istringstream in(shards[r]);
      for (railmodal::VariantResult& result : railmodal::read_shard(in, origin, study)) {
        if (!seen.insert(result.index).second)
          throw railmodal::InputError(origin, 0, 0, "variant '" + result.name + "' is also in an earlier shard");
        results.push_back(std::move(result));
      }
    }
    for (int i = 0; i < railmodal::variant_count(study); ++i)
      if (!seen.count(i))
        throw railmodal::InputError(o.study, 0, 0, "no rank returned variant " + std::to_string(i + 1) + " ('" +
                                                       railmodal::variant_name(study, i) + "')");
    const railmodal::Comparison comparison = railmodal::rank_variants(study, std::move(results));
    const railmodal::OutputFormat format = *railmodal::output_format_from_string(o.format);
    // The documents draw the best designs' curves: studied here, read first (the shards did not).
    const bool document = format == railmodal::OutputFormat::markdown || format == railmodal::OutputFormat::html;
    railmodal::write_comparison_report(out, study, comparison,
                                       document
                                           ? railmodal::comparison_curves(study, comparison, railmodal::kReportBest)
                                           : railmodal::ComparisonCurves{},
                                       format,
                                       document ? railmodal::provenance_of(railmodal::study_files(study))
                                                : railmodal::Provenance{});
    outputs.commit();
    return std::string();
  });
  if (written.code != kSuccess) std::cerr << written.text << "\n";
  return written.code;
}

int run(const Options& o, int rank, int size) {
  const int threads = o.threads > 0 ? o.threads : default_threads();  // collective: before anything can fail
  std::optional<railmodal::Study> study;
  OutputFiles outputs;  // rank 0's
  std::ostream* out = nullptr;
  // Rank 0's output and study are checked before any rank evaluates: a bad output fails alone.
  int code = first_failure(rank == 0 ? prepare_output(o, outputs, &out, study) : ShardText{}, rank, size);
  if (code != kSuccess) return code;
  ShardText shard = evaluate_shard(o, rank, size, threads, study);
  code = first_failure(shard, rank, size);
  if (code != kSuccess) return code;

  // The shards' lengths, then their bytes, to rank 0 (one Gatherv holds at most INT_MAX bytes).
  const long long own_length = static_cast<long long>(shard.text.size());
  int length = own_length > INT_MAX ? -1 : static_cast<int>(own_length);
  std::vector<int> lengths(rank == 0 ? size : 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(lengths.size(), 0);
  int fits = 1;
  if (rank == 0) {
    long long total = 0;
    for (int r = 0; r < size; ++r) {
      if (lengths[r] < 0) fits = 0;
      offsets[r] = static_cast<int>(std::min<long long>(total, INT_MAX));
      total += std::max(lengths[r], 0);
    }
    if (total > INT_MAX) fits = 0;
  }
  MPI_Bcast(&fits, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!fits) {
    if (rank == 0) std::cerr << "railmodal-mpi: error: the shards' results exceed 2 GiB; use --shard and --merge\n";
    return kInternal;
  }
  std::vector<char> bytes;
  if (rank == 0) bytes.resize(static_cast<size_t>(offsets.back()) + static_cast<size_t>(lengths.back()));
  MPI_Gatherv(shard.text.data(), length, MPI_CHAR, bytes.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  shard.text.clear();
  shard.text.shrink_to_fit();

  if (rank == 0) {
    std::vector<std::string> shards;
    for (int r = 0; r < size; ++r) shards.emplace_back(bytes.data() + offsets[r], static_cast<size_t>(lengths[r]));
    bytes.clear();
    code = merge_and_write(o, *study, shards, outputs, *out);
  }
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);  // only the main thread calls MPI
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);

  Options o;
  CLI::App app{"railmodal-mpi: railmodal compare across MPI ranks (mpirun -np N railmodal-mpi compare STUDY.toml)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "railmodal-mpi " + std::string(railmodal::version()));
  CLI::App* cmd = app.add_subcommand(
      "compare", "Evaluate and rank the variants of a design study, rank r evaluating shard r+1 of N (docs/studies.md)");
  cmd->add_option("study", o.study, "Study file (TOML), e.g. data/studies/resort_against_fette.toml")->required();
  cmd->add_option("--format", o.format, "Output format: the ranked table (table, csv, json) or the report (markdown, html)")
      ->check(CLI::IsMember({"table", "csv", "json", "markdown", "html"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", o.output, "Output file, written by rank 0 whole or not at all; - for stdout")
      ->capture_default_str();
  cmd->add_option("--threads", o.threads,
                  "Threads per rank; 0: the cores the rank may run on, shared among the ranks of its node")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();

  int code = kSuccess;
  bool parsed = false;
  // Every rank parses the same arguments and reaches the same verdict; rank 0 speaks.
  try {
    app.parse(argc, argv);
    parsed = true;
  } catch (const CLI::CallForHelp&) {
    if (rank == 0) std::cout << app.help();
  } catch (const CLI::CallForAllHelp&) {
    if (rank == 0) std::cout << app.help("", CLI::AppFormatMode::All);
  } catch (const CLI::CallForVersion& e) {
    if (rank == 0) std::cout << e.what() << "\n";
  } catch (const CLI::ParseError& e) {
    if (rank == 0) std::cerr << "railmodal-mpi: error: " << e.what() << "\nRun 'railmodal-mpi --help' for usage.\n";
    code = kUsage;
  }
  if (parsed) code = run(o, rank, size);
  MPI_Finalize();
  return code;
}
