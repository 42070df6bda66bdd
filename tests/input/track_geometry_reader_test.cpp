// load_track_geometry: units, comments, the step from the record, and errors that name the
// file, line, column and the column's header; the bad-input corpus of geometry files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "railmodal/errors.hpp"
#include "railmodal/ride_simulation.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

TEST(TrackGeometryReader, ReadsColumnsInMillimetresAndMetres) {
  const std::string path = write_temp("track.csv",
                                      "# measured on line 7, km 12.000 to 12.001\n"
                                      "distance [m], vertical level [mm], cross-level [m]\n"
                                      "100.00, 1.5, 0.001\n"
                                      "100.25, -2.0, 0.002\n"
                                      "\n"
                                      "100.50, +0.5, -0.003\n");
  const TrackGeometry g = load_track_geometry(path);
  EXPECT_DOUBLE_EQ(g.step, 0.25);
  EXPECT_FALSE(g.periodic);
  EXPECT_EQ(g.source, path);
  ASSERT_EQ(g.vertical_level.size(), 3);
  EXPECT_DOUBLE_EQ(g.vertical_level(0), 1.5e-3);
  EXPECT_DOUBLE_EQ(g.vertical_level(1), -2.0e-3);
  EXPECT_DOUBLE_EQ(g.vertical_level(2), 0.5e-3);
  EXPECT_DOUBLE_EQ(g.cross_level(2), -0.003);
  EXPECT_EQ(g.alignment.size(), 0);
  EXPECT_DOUBLE_EQ(g.length(), 0.75);
}

// The columns named as the scene names the components (vertical_level, cross_level) read as the
// spellings before 2026-11-27 do ("vertical level", "cross-level", above).
TEST(TrackGeometryReader, ColumnsNamedAsTheScenesComponents) {
  const TrackGeometry g = load_track_geometry(write_temp(
      "track_underscored.csv", "distance [m], vertical_level [mm], cross_level [m]\n0, 1.5, 0.001\n0.25, -2.0, 0.002\n"));
  ASSERT_EQ(g.vertical_level.size(), 2);
  EXPECT_DOUBLE_EQ(g.vertical_level(1), -2.0e-3);
  EXPECT_DOUBLE_EQ(g.cross_level(1), 0.002);
}

TEST(TrackGeometryReader, ToleratesDistancesRoundedWithinAThousandthOfAStep) {
  // 1/3 m written to 4 decimals: off its place by up to 3e-5 m, 1e-4 of the step
  const TrackGeometry g = load_track_geometry(write_temp(
      "third.csv", "distance [m],alignment [mm]\n0,1\n0.3333,2\n0.6667,3\n1.0000,4\n"));
  EXPECT_NEAR(g.step, 1.0 / 3.0, 1e-12);
  EXPECT_EQ(g.alignment.size(), 4);
}

TEST(TrackGeometryReader, ErrorsNameFileLineAndColumn) {
  const std::string path = write_temp("bad.csv", "distance [m], vertical level [mm]\n0, 1\n0.5,  x2\n");
  try {
    load_track_geometry(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 7);  // where 'x2' starts
    EXPECT_NE(e.message().find("column 'vertical level [mm]'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_track_geometry(write_temp("missing_dir.csv", "") + ".nothing"), InputError);
  EXPECT_THROW(load_track_geometry(write_temp("empty.csv", "# nothing\n")), InputError);
  EXPECT_THROW(load_track_geometry(write_temp("one_row.csv", "distance [m], alignment [m]\n0, 1\n")), InputError);
}

// Every file of tests/corpus/bad_track_geometry/ names, in its first line "# expect: REGEX",
// the message it must get, as an InputError naming the file.
TEST(TrackGeometryReader, BadInputCorpus) {
  const std::filesystem::path corpus =
      std::filesystem::path(RAILMODAL_DATA_DIR) / ".." / "tests" / "corpus" / "bad_track_geometry";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    std::ifstream in(entry.path());
    std::string first;
    std::getline(in, first);
    ASSERT_EQ(first.rfind("# expect: ", 0), 0u) << entry.path() << ": no '# expect: ' line";
    const std::regex expect(first.substr(10));
    ++files;
    try {
      load_track_geometry(entry.path().string());
      ADD_FAILURE() << entry.path() << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), entry.path().string());
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_TRUE(std::regex_search(e.message(), expect)) << entry.path() << ": " << e.what();
    }
  }
  EXPECT_GE(files, 10);
}

}  // namespace
}  // namespace railmodal::test
