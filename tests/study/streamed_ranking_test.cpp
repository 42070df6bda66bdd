// compare_study: the ranking of a whole study written from its streamed rows (issue 19 item 2)
// is the ranking rank_variants and write_comparison write, byte for byte, whatever the thread
// count; with a top k, its first k variants.
#include <sstream>
#include <stdexcept>
#include <string>

#include "railmodal/railmodal.hpp"
#include "study/parallel_evaluation.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

std::string bundled_study(const std::string& name) { return std::string(RAILMODAL_DATA_DIR) + "/studies/" + name + ".toml"; }

std::string ranked(const Study& study, OutputFormat format) {
  EvaluationOptions options;
  options.threads = 1;
  std::ostringstream out;
  write_comparison(out, rank_variants(study, evaluate_study(study, options)), format);
  return out.str();
}

std::string streamed(const Study& study, OutputFormat format, int threads, int top = 0) {
  EvaluationOptions options;
  options.threads = threads;
  options.read_in_workers = true;
  std::ostringstream out;
  compare_study(out, study, options, format, top);
  return out.str();
}

// The lines of a text.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Feasible, infeasible (notes under the table, violations in CSV and JSON) and a deflection rule.
const char* const kStudies[] = {"two_axle_rail_length_and_springs", "resort_against_fette", "two_axle_joint_dip_deflection"};

TEST(CompareStudy, WritesTheBytesOfTheRankedComparisonWhateverTheThreadCount) {
  for (const char* name : kStudies) {
    const Study read = load_study(bundled_study(name));
    const Study unread = load_study(bundled_study(name), [](int) { return false; });
    for (OutputFormat format : {OutputFormat::table, OutputFormat::csv, OutputFormat::json}) {
      const std::string expected = ranked(read, format);
      for (int threads : {1, 2, 3})
        EXPECT_EQ(streamed(unread, format, threads), expected) << name << ", " << to_string(format) << ", " << threads;
    }
  }
}

TEST(CompareStudy, TopWritesTheFirstVariantsOfTheRankingWhateverTheThreadCount) {
  const Study study = load_study(bundled_study("two_axle_joint_dip_deflection"), [](int) { return false; });
  const std::vector<std::string> all_csv = lines(streamed(study, OutputFormat::csv, 1));
  ASSERT_GT(all_csv.size(), 5u);  // the heading and 7 variants
  for (int top : {1, 3, 100}) {
    const size_t shown = std::min<size_t>(static_cast<size_t>(top), all_csv.size() - 1);
    const std::vector<std::string> expected(all_csv.begin(), all_csv.begin() + 1 + static_cast<std::ptrdiff_t>(shown));
    for (int threads : {1, 2, 3}) {
      EXPECT_EQ(lines(streamed(study, OutputFormat::csv, threads, top)), expected) << top << " of them, " << threads;
      // The table's head counts every variant, its rows only the best.
      const std::vector<std::string> table = lines(streamed(study, OutputFormat::table, threads, top));
      EXPECT_EQ(table[1], lines(streamed(study, OutputFormat::table, 1))[1]);
      EXPECT_NE(streamed(study, OutputFormat::json, threads, top).find("\"rank\": " + std::to_string(shown) + ","),
                std::string::npos);
      EXPECT_EQ(streamed(study, OutputFormat::json, threads, top).find("\"rank\": " + std::to_string(shown + 1) + ","),
                std::string::npos);
    }
  }
}

TEST(CompareStudy, RefusesDocumentsShardsAndANegativeTop) {
  const Study study = load_study(bundled_study("resort_against_fette"), [](int) { return false; });
  EXPECT_THROW(streamed(study, OutputFormat::html, 1), std::invalid_argument);
  EXPECT_THROW(streamed(study, OutputFormat::csv, 1, -1), std::invalid_argument);
  EvaluationOptions shard;
  shard.shards = 2;
  std::ostringstream out;
  EXPECT_THROW(compare_study(out, study, shard, OutputFormat::csv), std::invalid_argument);
}

// A sink that fails (a full disk under a streamed ranking) stops every thread and its exception
// reaches the caller once they have joined, instead of ending the process from a worker.
TEST(EvaluateEach, ASinksFailureReachesTheCaller) {
  const Study study = open_study(bundled_study("resort_against_fette"));
  for (int threads : {1, 2}) {
    EvaluationOptions options;
    options.threads = threads;
    options.read_in_workers = true;
    EXPECT_THROW(study::evaluate_each(
                     study, options, [](size_t) {},
                     [](size_t, VariantResult&&) { throw std::runtime_error("the sink's disk is full"); }),
                 std::runtime_error)
        << threads << " threads";
  }
}

}  // namespace
}  // namespace railmodal::test
