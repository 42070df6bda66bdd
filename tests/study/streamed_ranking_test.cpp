// compare_study: the ranking of a whole study written from its streamed rows (issue 19 item 2)
// is the ranking rank_variants and write_comparison write, byte for byte, whatever the thread
// count; with a top k, its first k variants. The documents (Markdown, HTML), a shard's file
// (compare_shard) and a merge of shard files (compare_merged) are the bytes their in-memory
// writers write too.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>

#include "railmodal/railmodal.hpp"
#include "report/comparison_document.hpp"
#include "study/parallel_evaluation.hpp"
#include "study/spilled_texts.hpp"
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

TEST(CompareStudy, RefusesATopForDocumentsShardsAndANegativeTop) {
  const Study study = load_study(bundled_study("resort_against_fette"), [](int) { return false; });
  EXPECT_THROW(streamed(study, OutputFormat::html, 1, 2), std::invalid_argument);
  EXPECT_THROW(streamed(study, OutputFormat::markdown, 1, 2), std::invalid_argument);
  EXPECT_THROW(streamed(study, OutputFormat::csv, 1, -1), std::invalid_argument);
  EvaluationOptions shard;
  shard.shards = 2;
  std::ostringstream out;
  EXPECT_THROW(compare_study(out, study, shard, OutputFormat::csv), std::invalid_argument);
}

// SpilledTexts::each_of hands on the texts at the positions asked for, in their order, the same
// as at() reads one by one, however it reads them: in one pass, in several (small gathering
// rooms: 0 bytes hold one text a pass, 40 bytes a few short ones), or one read a text (where
// passes would read the file too often: a room of 1 byte, or 1 MiB in a file holding a text of
// 1.5 MiB; in one pass the long text straddles the 1 MiB chunks the file is read by). An empty
// text among them.
TEST(SpilledTexts, EachOfGivesTheTextsInTheOrderAskedHoweverGathered) {
  const size_t count = 60;
  for (bool long_text : {false, true}) {
    const auto text_of = [&](size_t k) {
      if (k == 5) return std::string();
      if (k == 17 && long_text) return std::string((size_t{3} << 19) + 11, 'x');  // 1.5 MiB
      return "text " + std::to_string(k) + std::string(k % 7, '+');
    };
    study::SpilledTexts spilled("a test keeps its texts", "");
    spilled.resize(count);
    for (size_t k = 0; k < count; ++k) spilled.put((k * 37) % count, text_of((k * 37) % count));  // out of order
    spilled.finish();
    std::vector<size_t> asked;  // a rank order: every position once
    for (size_t k = 0; k < count; ++k) asked.push_back((k * 13 + 7) % count);
    const std::vector<size_t> some(asked.begin(), asked.begin() + 20);
    for (const std::vector<size_t>* positions : std::initializer_list<const std::vector<size_t>*>{&asked, &some})
      for (size_t room : {size_t{0}, size_t{1}, size_t{40}, size_t{1} << 20, study::SpilledTexts::kGatherBytes}) {
        std::vector<std::string> got;
        spilled.each_of(*positions, [&](std::string_view text) { got.emplace_back(text); }, room);
        ASSERT_EQ(got.size(), positions->size()) << room;
        for (size_t i = 0; i < got.size(); ++i) {
          EXPECT_EQ(got[i], text_of((*positions)[i])) << "rank " << i << ", room " << room << ", " << long_text;
          EXPECT_EQ(got[i], spilled.at((*positions)[i]));
        }
      }
    // A bad request visits nothing, however many passes it would take (room 0: one text a pass,
    // so the repeat lies in a later pass than the first texts).
    for (size_t room : {size_t{0}, study::SpilledTexts::kGatherBytes}) {
      size_t visited = 0;
      const auto count_visits = [&](std::string_view) { ++visited; };
      EXPECT_THROW(spilled.each_of({3, 4, 3}, count_visits, room), std::invalid_argument);
      EXPECT_THROW(spilled.each_of({3, 4, count}, count_visits, room), std::out_of_range);
      EXPECT_EQ(visited, 0u) << room;
    }
  }
}

// The document of the whole comparison, as railmodal compare wrote it before it streamed.
std::string document(const Study& study, const Comparison& comparison, OutputFormat format) {
  std::ostringstream out;
  write_comparison_report(out, study, comparison, comparison_curves(study, comparison, kReportBest), format,
                          provenance_of(study_files(study)));
  return out.str();
}

std::string streamed_document(const Study& study, OutputFormat format, int threads) {
  EvaluationOptions options;
  options.threads = threads;
  options.read_in_workers = true;
  std::ostringstream out;
  compare_study(out, study, options, format, 0, provenance_of(study_files(study)));
  return out.str();
}

// 120 sampled spring sets of the resort car and its base: more variants than the documents'
// table shows, the base ranked among them (near the middle: the samples lie on both sides of
// it), below the table's rows, and sweeps binned in the Markdown tables (more than 12 values).
std::string sampled_study() {
  const std::string data = RAILMODAL_DATA_DIR;
  return write_temp("sampled.toml", R"([study]
name = "Resort car: 120 sampled spring sets and the base"
vehicle = ")" + data + R"(/vehicles/resort_car.toml"
scene = ")" + data + R"(/scenes/resort_car_10m_rails.toml"

[[sweep]]
name = "springs"
sample = { count = 120, seed = 11 }
parameters = [
  { key = "secondary.spring.stiffness", from = "455 kgf/cm", to = "845 kgf/cm", label = "c3" },
  { key = "primary.spring[0].stiffness", from = "490 kgf/cm", to = "910 kgf/cm", label = "c1" },
]

[ranking]
min_critical_speed = "30 km/h"
objective = [{ metric = "bounce_period", goal = "max" }]
)");
}

TEST(CompareStudy, WritesTheBytesOfTheDocumentsWhateverTheThreadCount) {
  std::vector<std::string> studies;
  for (const char* name : kStudies) studies.push_back(bundled_study(name));
  studies.push_back(bundled_study("two_axle_wagon_ride_springs"));
  studies.push_back(sampled_study());
  for (const std::string& file : studies) {
    const Study read = load_study(file);
    const Study opened = open_study(file);
    EvaluationOptions options;
    options.threads = 1;
    const Comparison comparison = rank_variants(read, evaluate_study(read, options));
    for (OutputFormat format : {OutputFormat::markdown, OutputFormat::html}) {
      const std::string expected = document(read, comparison, format);
      for (int threads : {1, 2, 3})
        EXPECT_EQ(streamed_document(opened, format, threads), expected) << file << ", " << to_string(format) << ", " << threads;
    }
  }
}

// The sampled study does what its comment says: the base below the table's rows, and binned
// sweeps, so that the test above covers both.
TEST(CompareStudy, TheSampledStudyRanksItsBaseBelowTheTable) {
  const Study study = load_study(sampled_study());
  const Comparison comparison = rank_variants(study, evaluate_study(study, {}));
  ASSERT_NE(comparison_base(comparison), nullptr);
  EXPECT_GT(comparison_base(comparison)->rank, kReportRows);
  const std::string markdown = document(study, comparison, OutputFormat::markdown);
  EXPECT_NE(markdown.find("The first 40 of 121 variants"), std::string::npos);
  EXPECT_NE(markdown.find("Against the base:"), std::string::npos);
}

std::string shard_of(const Study& study, int shard, int shards, int threads, bool streamed_shard) {
  EvaluationOptions options;
  options.shard = shard;
  options.shards = shards;
  options.threads = threads;
  options.read_in_workers = true;
  std::ostringstream out;
  if (streamed_shard)
    compare_shard(out, study, options, provenance_of(study_files(study)));
  else
    write_shard(out, study, options, evaluate_study(study, options), provenance_of(study_files(study)));
  return out.str();
}

TEST(CompareShard, WritesTheBytesOfWriteShardWhateverTheThreadCount) {
  for (const char* name : kStudies) {
    const Study study = open_study(bundled_study(name));
    for (int shard : {1, 2, 3}) {
      const std::string expected = shard_of(study, shard, 3, 1, false);
      for (int threads : {1, 2}) EXPECT_EQ(shard_of(study, shard, 3, threads, true), expected) << name << " " << shard;
    }
    // A shard with no variant (more shards than variants) still names the study.
    EXPECT_EQ(shard_of(study, 100, 100, 2, true), shard_of(study, 100, 100, 1, false)) << name;
  }
}

TEST(CompareMerged, WritesWhatTheWholeStudyWritesInEveryFormat) {
  for (const char* name : kStudies) {
    const Study study = open_study(bundled_study(name));
    std::vector<std::string> files;
    for (int shard : {2, 1, 3})
      files.push_back(write_temp(std::string(name) + "_" + std::to_string(shard) + ".json", shard_of(study, shard, 3, 2, true)));
    for (OutputFormat format : {OutputFormat::table, OutputFormat::csv, OutputFormat::json, OutputFormat::markdown,
                                OutputFormat::html}) {
      const Provenance inputs = provenance_of(study_files(study));
      std::ostringstream merged;
      compare_merged(merged, study, files, format, 0, inputs);
      EXPECT_EQ(merged.str(), streamed_document(study, format, 2)) << name << ", " << to_string(format);
    }
    // The best two of merged shards are the best two of the study.
    std::ostringstream best, whole;
    compare_merged(best, study, files, OutputFormat::csv, 2);
    EvaluationOptions options;
    options.read_in_workers = true;
    compare_study(whole, study, options, OutputFormat::csv, 2);
    EXPECT_EQ(best.str(), whole.str()) << name;
    EXPECT_EQ(lines(best.str()).size(), 3u) << name;  // the heading and two variants
    // A shard left out, or given twice: named errors, nothing written.
    std::ostringstream out;
    EXPECT_THROW(compare_merged(out, study, {files[0], files[1]}, OutputFormat::csv), InputError);
    EXPECT_THROW(compare_merged(out, study, {files[0], files[1], files[2], files[0]}, OutputFormat::csv), InputError);
    EXPECT_EQ(out.str(), "");
  }
}

// A sweep point waits in the ranking's file as bytes: read back, it is the same point, numbers
// bit for bit (a value ranked first or none, −0, the smallest subnormal, text with a NUL).
TEST(SweepPoint, ReadsBackAsWritten) {
  report::SweepPoint point;
  point.feasible = true;
  point.ranked = -0.0;
  point.parameters = {{"secondary.spring.stiffness", "455 kgf/cm"}, {"a", std::string("x\0y", 3)}};
  point.periods = {{"body bounce", 0.9447}, {"pitch", 4.9406564584124654e-324}};
  for (const bool ranked : {true, false}) {
    if (!ranked) point.ranked.reset(), point.feasible = false;
    const report::SweepPoint back = report::sweep_point_from_bytes(report::to_bytes(point));
    EXPECT_EQ(back.feasible, point.feasible);
    ASSERT_EQ(back.ranked.has_value(), ranked);
    if (ranked) {
      EXPECT_TRUE(std::signbit(*back.ranked));
    }
    EXPECT_EQ(back.parameters, point.parameters);
    EXPECT_EQ(back.periods, point.periods);
  }
  EXPECT_THROW(report::sweep_point_from_bytes(report::to_bytes(point).substr(0, 20)), std::invalid_argument);
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

// Every result of `study` by evaluate_each, in study order; with `names_written` false a
// variant names only the modes its ranking reads (study::ModeNamesRead).
std::vector<VariantResult> evaluated_each(const Study& study, bool names_written) {
  EvaluationOptions options;
  options.threads = 2;
  options.read_in_workers = true;
  std::vector<VariantResult> results;
  study::evaluate_each(
      study, options, [&](size_t count) { results.resize(count); },
      [&](size_t k, VariantResult&& r) { results[k] = std::move(r); }, names_written);
  return results;
}

void expect_names_read(Study study);

// A CSV or table of a ranking writes one mode name, the lowest critical speed's, so its variants
// name only that and the modes the ranking reads: every metric has the value it has with every name, every name given is the
// one every-name evaluation gives, and the names not read are left out. A metric naming a mode
// the variant lacks has every name given (a study whose variants all lack it is refused with
// their names listed, study::check_mode_names).
TEST(EvaluateEach, NamesOnlyTheModesTheRankingReadsWhenNoNameIsWritten) {
  for (const char* name : {"two_axle_rail_length_and_springs", "resort_against_fette"})
    expect_names_read(open_study(bundled_study(name)));
}

void expect_names_read(Study study) {
  const std::vector<VariantResult> all = evaluated_each(study, true);
  // Every mode-named metric a result could be ranked by: a period and a critical speed of
  // every mode (a resonance's eigenspace) a variant has, and one no variant has.
  std::vector<std::string> metrics{"period:no such mode", "critical_speed:no such mode"};
  for (const VariantResult& r : all) {
    for (const auto& m : r.modes) metrics.push_back("period:" + m.name);
    for (const auto& c : r.critical_speeds) metrics.push_back("critical_speed:" + c.mode_name);
  }
  std::sort(metrics.begin(), metrics.end());
  metrics.erase(std::unique(metrics.begin(), metrics.end()), metrics.end());
  ASSERT_GT(metrics.size(), 5u);  // two modes of each kind at least, and the missing two
  size_t left_out = 0, read = 0;
  for (const std::string& metric : metrics) {
    study.ranking.objective.assign(1, RankingCriterion{metric, true, 1.0, {}});
    study.ranking.constraints.clear();
    const std::vector<VariantResult> named = evaluated_each(study, false);
    ASSERT_EQ(named.size(), all.size());
    const bool missing = metric.find("no such mode") != std::string::npos;
    for (size_t k = 0; k < all.size(); ++k) {
      ASSERT_TRUE(all[k].ok()) << all[k].failure;
      EXPECT_EQ(metric_value(named[k], metric), metric_value(all[k], metric)) << metric << ", " << all[k].name;
      ASSERT_EQ(named[k].modes.size(), all[k].modes.size());
      for (size_t m = 0; m < all[k].modes.size(); ++m) {
        const std::string& name = named[k].modes[m].name;
        (name.empty() ? left_out : read) += 1;
        EXPECT_TRUE(name.empty() ? !missing : name == all[k].modes[m].name) << metric << ", mode " << m + 1;
        EXPECT_EQ(named[k].modes[m].period_s, all[k].modes[m].period_s);
      }
      ASSERT_EQ(named[k].critical_speeds.size(), all[k].critical_speeds.size());
      if (!all[k].critical_speeds.empty()) {  // the tables' lowest critical speed names its mode
        EXPECT_EQ(named[k].critical_speeds.front().mode_name, all[k].critical_speeds.front().mode_name) << metric;
      }
      for (size_t c = 0; c < all[k].critical_speeds.size(); ++c) {
        const std::string& name = named[k].critical_speeds[c].mode_name;
        EXPECT_TRUE(name.empty() ? !missing : name == all[k].critical_speeds[c].mode_name) << metric << ", " << c;
      }
    }
  }
  EXPECT_GT(left_out, 0u) << study.name;  // names were left out
  EXPECT_GT(read, 0u) << study.name;
}

}  // namespace
}  // namespace railmodal::test
