// The input files a report names in its footer, with the hash of their content.
#include <gtest/gtest.h>

#include <sstream>

#include "railmodal/railmodal.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// The published FNV-1a 64 test vectors (Fowler, Noll and Vo's reference test suite).
TEST(Provenance, DigestIsFnv1a64) {
  EXPECT_EQ(content_digest(""), "cbf29ce484222325");
  EXPECT_EQ(content_digest("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(content_digest("foobar"), "85944171f73967e8");
}

TEST(Provenance, ListsEachFileOnceAsGivenWithTheDigestOfItsBytes) {
  const std::string a = write_temp("a.toml", "x = 1\n"), b = write_temp("b.toml", "y = 2\n");
  const Provenance p = provenance_of({a, "", b, a});
  ASSERT_EQ(p.files.size(), 2u);
  EXPECT_EQ(p.files[0].path, a);
  EXPECT_EQ(p.files[0].digest, content_digest("x = 1\n"));
  EXPECT_EQ(p.files[1].path, b);
  EXPECT_EQ(p.files[1].digest, content_digest("y = 2\n"));
}

TEST(Provenance, RefusesAFileThatCannotBeRead) {
  try {
    provenance_of({"no/such/file.toml"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "no/such/file.toml");
    EXPECT_NE(std::string(e.what()).find("cannot be read"), std::string::npos);
  }
}

// A pipe (`railmodal critical-speed <(cat scene.toml)`) is empty once the run has read it: its
// hash would be that of no bytes. A file that is not a regular one is listed, not hashed, and
// the footer says so. /dev/null stands for the drained pipe (a device, nothing left to read).
TEST(Provenance, ListsAFileThatIsNotRegularUnhashed) {
  const Provenance p = provenance_of({"/dev/null"});
  ASSERT_EQ(p.files.size(), 1u);
  EXPECT_EQ(p.files[0].path, "/dev/null");
  EXPECT_EQ(p.files[0].digest, "");
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/resort_car_10m_rails.toml");
  std::ostringstream page;
  write_critical_speed_report(page, study_critical_speeds(scene, load_vehicle(scene.vehicle_file)),
                              OutputFormat::markdown, p);
  EXPECT_NE(page.str().find(", from /dev/null (not a regular file: not hashed)."), std::string::npos) << page.str();
}

// Every page says which railmodal and which files made it; without files it says so.
TEST(Provenance, ReportFootersNameTheVersionAndTheInputs) {
  const Scene scene = load_scene(std::string(RAILMODAL_DATA_DIR) + "/scenes/resort_car_10m_rails.toml");
  const CriticalSpeedStudy study = study_critical_speeds(scene, load_vehicle(scene.vehicle_file));
  const Provenance inputs = provenance_of({scene.source, scene.vehicle_file});
  const std::string version = "railmodal " + std::string(railmodal::version()) + " critical-speed";
  for (OutputFormat format : {OutputFormat::html, OutputFormat::markdown}) {
    std::ostringstream page, unrecorded;
    write_critical_speed_report(page, study, format, inputs);
    EXPECT_NE(page.str().find(version + ", from " + scene.source + " (FNV-1a 64 " + inputs.files[0].digest + "), " +
                              scene.vehicle_file + " (FNV-1a 64 " + inputs.files[1].digest + ")."),
              std::string::npos);
    write_critical_speed_report(unrecorded, study, format);
    EXPECT_NE(unrecorded.str().find(version + "; input files not recorded."), std::string::npos);
  }
}

}  // namespace
}  // namespace railmodal::test
