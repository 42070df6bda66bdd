// railmodal-mpi: railmodal compare across the ranks of an MPI job (docs/studies.md, "Across a
// cluster").
//
//   mpirun -np N railmodal-mpi compare STUDY.toml [--format table|csv|json|markdown|html] [-o OUT]
//                                                  [--threads T]
//
// Rank r evaluates shard r + 1 of N (the variants whose index mod N is r, as
// `railmodal compare --shard r+1/N`) into a temporary file on its node, rank 0 receives the
// other ranks' shards in chunks into temporary files on its own node, merges them as
// `railmodal compare --merge` does (one result in memory at a time) and writes exactly what
// `railmodal compare STUDY.toml` writes. Exit codes as railmodal's: 0 success, 2 usage,
// 3 input, 5 output, 1 internal; every rank exits with the same code.
#include <mpi.h>
#ifdef __linux__
#include <sched.h>
#endif

#include <stdlib.h>  // mkstemp
#include <unistd.h>  // close

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
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
  std::string format;  // "": report_format's rule, as railmodal compare's
  railmodal::OutputFormat chosen = railmodal::OutputFormat::table;  // by that rule
  std::string output = "-";
  int threads = 0;
};

// The formats compare writes, its default first (railmodal compare's).
const std::vector<std::string> kFormats{"table", "csv", "json", "markdown", "html"};

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

/// A step's outcome on this rank: success, or its exit code and message.
struct Outcome {
  int code = kSuccess;
  std::string message;  ///< when code != kSuccess
};

/// `step` run, or its failure with the exit code and message railmodal gives it.
template <class Step>
Outcome guarded(const Step& step) {
  try {
    step();
    return {};
  } catch (const railmodal::InputError& e) {
    return {kInput, e.what()};
  } catch (const OutputError& e) {
    return {e.code(), e.what()};
  } catch (const std::system_error& e) {  // a temporary file (TMPDIR), as railmodal compare says it
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
Outcome prepare_output(const Options& o, OutputFiles& outputs, std::ostream** out,
                       std::optional<railmodal::Study>& study) {
  return guarded([&] {
    *out = &outputs.open(o.output);
    outputs.refuse_inputs({o.study});
    study = load_named_variants(o);
    outputs.refuse_inputs(railmodal::study_files(*study));
  });
}

/// A shard's file in TMPDIR (or /tmp) on this rank's node, removed when this goes: a rank's own
/// shard until it is sent (or, on rank 0, merged), and on rank 0 each other rank's as received.
/// A node's temporary directory, not a shared one: the ranks need no directory they can all
/// write, and rank 0 reads every shard from its own disk. Its name says whose shard it is, for
/// the merge's messages.
class ShardFile {
 public:
  explicit ShardFile(int rank) {
    const char* tmpdir = std::getenv("TMPDIR");
    const std::string dir = tmpdir && *tmpdir ? tmpdir : "/tmp";
    path_ = dir + "/railmodal-mpi-rank-" + std::to_string(rank) + "-shard-XXXXXX";
    const int fd = ::mkstemp(path_.data());
    if (fd < 0)
      throw std::system_error(errno, std::generic_category(),
                              "cannot make a shard's temporary file in " + dir + " (set TMPDIR to a writable directory)");
    ::close(fd);
  }
  ShardFile(const ShardFile&) = delete;
  ShardFile& operator=(const ShardFile&) = delete;
  ~ShardFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

  /// Throws std::system_error naming the file if `file` (writing it) has failed.
  void check_written(const std::ofstream& file) const {
    if (!file)
      throw std::system_error(errno ? errno : EIO, std::generic_category(),
                              "cannot write a shard's temporary file " + path_ + " (free space there, set TMPDIR)");
  }

 private:
  std::string path_;
};

/// Evaluates this rank's shard into `file`.
Outcome evaluate_shard(const Options& o, int rank, int size, int threads, std::optional<railmodal::Study>& study,
                       std::unique_ptr<ShardFile>& file) {
  return guarded([&] {
    if (!study) study = load_named_variants(o);
    railmodal::EvaluationOptions evaluation;
    evaluation.shard = rank + 1;
    evaluation.shards = size;
    evaluation.threads = threads;
    evaluation.read_in_workers = true;
    file = std::make_unique<ShardFile>(rank);
    std::ofstream out(file->path(), std::ios::binary);
    railmodal::compare_shard(out, *study, evaluation);  // each result's text waits in a temporary file meanwhile
    out.close();
    file->check_written(out);
  });
}

/// Collective: every rank learns whether any failed, so none waits for a shard that never
/// comes. The lowest failing rank prints its message and every rank returns that rank's code.
int first_failure(const Outcome& mine, int rank, int size) {
  int failing = mine.code != kSuccess ? rank : size;
  int first = size;
  MPI_Allreduce(&failing, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == size) return kSuccess;
  int code = mine.code;
  MPI_Bcast(&code, 1, MPI_INT, first, MPI_COMM_WORLD);
  if (rank == first)
    std::cerr << (rank == 0 ? "" : "railmodal-mpi: rank " + std::to_string(rank) + ": ") << mine.message << "\n";
  return code;
}

// A shard travels to rank 0 in messages of at most kChunk bytes, then an empty one: rank 0
// holds one chunk at a time, whatever the shard's size (about 3.4 kB a variant).
constexpr int kChunk = 1 << 20;
constexpr int kShardTag = 1;

/// A rank other than 0: its shard's file sent to rank 0, chunk by chunk, and the empty message
/// that ends it, sent even when the file cannot be read (the failure is this rank's to report).
Outcome send_shard(const ShardFile& file) {
  std::ifstream in(file.path(), std::ios::binary);
  std::vector<char> chunk(kChunk);
  while (in) {
    in.read(chunk.data(), kChunk);
    const int n = static_cast<int>(in.gcount());
    if (n > 0) MPI_Send(chunk.data(), n, MPI_CHAR, 0, kShardTag, MPI_COMM_WORLD);
  }
  MPI_Send(chunk.data(), 0, MPI_CHAR, 0, kShardTag, MPI_COMM_WORLD);
  return guarded([&] {
    if (in.bad() || !in.eof())
      throw std::system_error(errno ? errno : EIO, std::generic_category(),
                              "cannot read back the shard's temporary file " + file.path());
  });
}

/// Rank 0: each other rank's shard received into a file of its own, in rank order. A file that
/// cannot be written is reported after every message has been received, so no rank waits.
Outcome receive_shards(int size, std::vector<std::unique_ptr<ShardFile>>& files) {
  std::vector<char> chunk(kChunk);
  Outcome outcome;
  for (int r = 1; r < size; ++r) {
    std::ofstream out;
    if (outcome.code == kSuccess) outcome = guarded([&] {
        files.push_back(std::make_unique<ShardFile>(r));
        out.open(files.back()->path(), std::ios::binary);
      });
    for (;;) {
      MPI_Status status;
      MPI_Recv(chunk.data(), kChunk, MPI_CHAR, r, kShardTag, MPI_COMM_WORLD, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_CHAR, &n);
      if (n == 0) break;
      if (outcome.code == kSuccess) out.write(chunk.data(), n);
    }
    if (outcome.code == kSuccess) outcome = guarded([&] {
        out.close();
        files.back()->check_written(out);
      });
  }
  return outcome;
}

/// Rank 0: the shards' files merged, ranked and written as railmodal compare writes the study
/// (compare_merged: one result in memory at a time; each variant exactly once).
int merge_and_write(const Options& o, const railmodal::Study& study,
                    const std::vector<std::unique_ptr<ShardFile>>& files, OutputFiles& outputs, std::ostream& out) {
  const Outcome written = guarded([&] {
    std::vector<std::string> paths;
    for (const auto& f : files) paths.push_back(f->path());
    const railmodal::OutputFormat format = o.chosen;
    // The documents end with the input files (railmodal compare's provenance); the others ignore it.
    railmodal::compare_merged(out, study, paths, format, 0, railmodal::provenance_of(railmodal::study_files(study)));
    outputs.commit();
  });
  if (written.code != kSuccess) std::cerr << written.message << "\n";
  return written.code;
}

int run(const Options& o, int rank, int size) {
  const int threads = o.threads > 0 ? o.threads : default_threads();  // collective: before anything can fail
  std::optional<railmodal::Study> study;
  OutputFiles outputs;  // rank 0's
  std::ostream* out = nullptr;
  // Rank 0's output and study are checked before any rank evaluates: a bad output fails alone.
  int code = first_failure(rank == 0 ? prepare_output(o, outputs, &out, study) : Outcome{}, rank, size);
  if (code != kSuccess) return code;
  // Rank 0's shard first, then the others' as received, in rank order.
  std::vector<std::unique_ptr<ShardFile>> shards(1);
  code = first_failure(evaluate_shard(o, rank, size, threads, study, shards.front()), rank, size);
  if (code != kSuccess) return code;

  code = first_failure(rank == 0 ? receive_shards(size, shards) : send_shard(*shards.front()), rank, size);
  if (rank != 0) shards.clear();  // sent: its file goes
  if (code != kSuccess) return code;
  if (rank == 0) code = merge_and_write(o, *study, shards, outputs, *out);
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
  cmd->add_option("--format", o.format,
                  "Output format: the ranked table (table, csv, json) or the report (markdown, html); " +
                      railmodal::cli::format_rule_help(kFormats))
      ->check(CLI::IsMember(kFormats));
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
    o.chosen = railmodal::cli::report_format(o.format, o.output, kFormats);
    parsed = true;
  } catch (const railmodal::cli::UsageError& e) {
    if (rank == 0) std::cerr << "railmodal-mpi: error: " << e.what() << "\nRun 'railmodal-mpi --help' for usage.\n";
    code = kUsage;
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
