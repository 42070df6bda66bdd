// What `railmodal compare` says once of a study (Study::notes): the periods of a vehicle on
// wheelsets are its suspension modes, without the wheel–rail contact, as `railmodal modes` notes
// it. The user audit of 2026-11-28 (F5) read a coach's body lower sway at 1.13 s in compare,
// 1.72 s on track, with no word of it.
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "railmodal/comparison_report.hpp"
#include "railmodal/railmodal.hpp"
#include "study/study_files.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kNotesData = RAILMODAL_DATA_DIR;

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(StudyNotes, AVehicleOnWheelsetsSaysItsPeriodsAreTheSuspensionsOnceInEveryFormat) {
  const std::string path = write_temp(
      "notes_study.toml", "[study]\nname = \"s\"\nvehicle = \"" + kNotesData +
                              "/vehicles/manchester_benchmark_coach_wheelsets.toml\"\n[ranking]\n"
                              "objective = [{ metric = \"static_deflection\", goal = \"min\" }]\n");
  const Study study = open_study(path);
  const std::vector<std::string> notes = study.notes;
  ASSERT_EQ(notes.size(), 1u);
  const std::string note = notes.front();
  EXPECT_NE(note.find("without the wheel–rail contact terms"), std::string::npos) << note;
  EvaluationOptions options;
  options.threads = 1;
  options.read_in_workers = true;  // an opened study's variants are read by the workers
  for (OutputFormat format : {OutputFormat::table, OutputFormat::markdown, OutputFormat::html}) {
    std::ostringstream out;
    compare_study(out, study, options, format);
    EXPECT_EQ(count_of(out.str(), format == OutputFormat::html ? "without the wheel–rail contact terms" : note), 1u)
        << to_string(format) << ":\n" << out.str();
  }
  std::ostringstream json;
  compare_study(json, study, options, OutputFormat::json);
  const nlohmann::json j = nlohmann::json::parse(json.str());
  ASSERT_TRUE(j.contains("notes")) << json.str();
  EXPECT_EQ(j.at("notes"), nlohmann::json::array({note}));
}

TEST(StudyNotes, AVehicleWithoutWheelsetsHasNone) {
  const Study study = open_study(write_study(example3_wagon(), "[ranking]\nmin_lowest_critical_speed = \"30 km/h\"\n"));
  EXPECT_TRUE(study.notes.empty());
  EvaluationOptions options;
  options.read_in_workers = true;
  std::ostringstream json;
  compare_study(json, study, options, OutputFormat::json);
  EXPECT_FALSE(nlohmann::json::parse(json.str()).contains("notes"));
}

}  // namespace
}  // namespace railmodal::test
