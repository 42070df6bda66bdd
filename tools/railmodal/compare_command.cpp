// railmodal compare STUDY [--format table|csv|json|markdown|html] [-o OUT] [--threads N] [--shard K/N]
//                         [--merge SHARD.json ...] [--top K]
#include <iostream>
#include <memory>
#include <string_view>
#include <system_error>

#include "commands.hpp"
#include "output_file.hpp"
#include "railmodal/comparison_report.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/study.hpp"

namespace railmodal::cli {
namespace {

// The formats `compare` writes, its default first.
const std::vector<std::string> kCompareFormats{"table", "csv", "json", "markdown", "html"};

struct CompareOptions {
  std::string study;
  std::string format;  // "": report_format's rule
  std::string output = "-";
  int threads = 0;
  std::string shard;
  std::vector<std::string> merge;
  bool quiet = false;
  int top = 0;
};

// As many shards as a study may hold variants give each at most one.
constexpr int kMaxShards = static_cast<int>(kMaxStudyVariants);
static_assert(kMaxStudyVariants < 10000000, "parse_shard reads at most 7 digits");

// The value of 1 to 7 ASCII digits (7: kMaxShards, without overflow), or -1 for anything else.
int shard_number(std::string_view digits) {
  if (digits.empty() || digits.size() > 7) return -1;
  int value = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return -1;
    value = value * 10 + (c - '0');
  }
  return value;
}

// "K/N" into evaluation->shard and shards; false if it is not 1 <= K <= N <= kMaxShards. A plain
// scan rather than std::regex R"((\d{1,7})/(\d{1,7}))" (which made this file slow to compile),
// with the same matches.
bool parse_shard(const std::string& text, EvaluationOptions* evaluation) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return false;
  const int shard = shard_number(std::string_view(text).substr(0, slash));
  const int shards = shard_number(std::string_view(text).substr(slash + 1));
  if (shard < 0 || shards < 0) return false;
  evaluation->shard = shard;
  evaluation->shards = shards;
  return evaluation->shard >= 1 && evaluation->shard <= evaluation->shards && evaluation->shards <= kMaxShards;
}

// --shard read into `evaluation`: false (with the usage error on stderr) if it is malformed or
// given with --merge.
bool read_shard_option(const CompareOptions& o, EvaluationOptions* evaluation) {
  if (o.shard.empty()) return true;
  if (!parse_shard(o.shard, evaluation)) {
    std::cerr << "railmodal: error: --shard expects K/N with 1 <= K <= N <= " << kMaxShards
              << " (the most variants a study may hold), such as 2/4, not '" << o.shard << "'\n";
    return false;
  }
  if (!o.merge.empty()) {
    std::cerr << "railmodal: error: --shard and --merge exclude each other\n";
    return false;
  }
  return true;
}

int run(const CompareOptions& o) {
  OutputFormat format;
  try {
    // A shard is always JSON: neither --format nor -o's extension can ask for another.
    format = o.shard.empty() ? report_format(o.format, o.output, kCompareFormats)
                             : report_format(o.format, o.output, {"json"}, "a shard");
    if (!o.shard.empty() && format != OutputFormat::json)
      throw UsageError("--shard writes its results as JSON, not " + o.format);
  } catch (const UsageError& e) {
    return usage_error("compare", e.what());
  }
  EvaluationOptions evaluation;
  evaluation.threads = o.threads;
  if (!read_shard_option(o, &evaluation)) return kUsage;
  if (o.top > 0 && (!o.shard.empty() || format == OutputFormat::markdown || format == OutputFormat::html)) {
    std::cerr << "railmodal: error: --top applies to the ranking of a whole study (table, csv, json), not to "
              << (!o.shard.empty() ? "a shard" : std::string("the ") + to_string(format) + " report") << "\n";
    return kUsage;
  }
  try {
    OutputFiles outputs;
    std::ostream& out = outputs.open(o.output);
    outputs.refuse_inputs({o.study});
    outputs.refuse_inputs(o.merge);
    // open_study lists no variant and reads none: the threads that evaluate a variant make and
    // read it (read_in_workers), a shard its own only; a merge reads none but those its report
    // draws (read_variant). A bad override stops the run at the first such variant.
    const bool merging = !o.merge.empty();
    std::vector<std::string> warnings;
    const Study study = open_study(o.study, &warnings);
    print_input_warnings(warnings);  // the base vehicle's and the scene's, once: not a variant's
    evaluation.read_in_workers = true;
    outputs.refuse_inputs(study_files(study));
    if (!merging && !o.quiet) evaluation.progress = terminal_progress("compare");
    // Results streamed: only their keys held (and a report's best few). The page names the
    // study's files: merged shards are results of those same files, and give the page a single
    // run gives, byte for byte.
    const bool document = format == OutputFormat::markdown || format == OutputFormat::html;
    const Provenance files = document ? provenance_of(study_files(study)) : Provenance{};
    if (!o.shard.empty())
      compare_shard(out, study, evaluation, provenance_of(study_files(study)));
    else if (merging)
      compare_merged(out, study, o.merge, format, o.top, files);
    else
      compare_study(out, study, evaluation, format, o.top, files);
    outputs.commit();
    return kSuccess;
  } catch (const std::system_error& e) {  // the streamed ranking's (or shard's) temporary file
    throw OutputError(kOutput, std::string("railmodal: error: ") + e.what());
  } catch (...) {
    return exit_of_error("compare", o.study);
  }
}

}  // namespace

std::function<int()> add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Evaluate and rank the variants of a design study (docs/studies.md)");
  cmd->add_option("study", options->study, "Study file (TOML), e.g. data/studies/resort_against_fette.toml")->required();
  cmd->add_option("--format", options->format,
                  "Output format: the ranked table (table, csv, json) or the report (markdown, html); a shard is "
                  "always JSON; " + format_rule_help(kCompareFormats))
      ->check(CLI::IsMember(kCompareFormats));
  cmd->add_option("-o,--output", options->output, "Output file (written whole or not at all); - for stdout")
      ->capture_default_str();
  cmd->add_option("--threads", options->threads, "Threads evaluating variants; 0: all cores")
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  cmd->add_option("--shard", options->shard,
                  "Evaluate only share K of N (variants whose index mod N is K-1) and write its results as JSON");
  cmd->add_option("--merge", options->merge, "Rank the results of these shard files instead of evaluating")
      ->expected(1, -1);
  cmd->add_option("--top", options->top,
                  "Write only the best K variants of the ranking (table, csv, json); 0: every variant")
      ->check(CLI::Range(0, static_cast<int>(kMaxStudyVariants)))
      ->capture_default_str();
  add_quiet_flag(*cmd, &options->quiet);
  return [options] { return run(*options); };
}

}  // namespace railmodal::cli
