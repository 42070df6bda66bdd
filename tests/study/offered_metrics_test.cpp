// A ranking metric that no variant of the study can have is refused when the study is loaded,
// at the study file's line and key, as a misspelt mode name is once the variants are evaluated:
// a misspelt ride output (with the name it was probably meant to be), a ride metric on a scene
// without a ride, hunting_speed on vehicles without wheelsets. Before, every variant lacked the
// value and the study ranked in study order without a word (the user audit of 2026-11-27).
#include <string>

#include "railmodal/railmodal.hpp"
#include "study/study_files.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

const std::string kOfferedData = RAILMODAL_DATA_DIR;

// A study of the bundled `vehicle` (a file under data/vehicles) in the bundled `scene`, ranked
// by `ranking` (its [ranking] table's lines: the metric is on line 6).
std::string offered_study(const std::string& vehicle, const std::string& scene, const std::string& ranking,
                          const std::string& extra = "") {
  return write_temp("offered_study.toml", "[study]\nname = \"s\"\nvehicle = \"" + kOfferedData + "/vehicles/" + vehicle +
                                              "\"\nscene = \"" + kOfferedData + "/scenes/" + scene + "\"\n[ranking]\n" +
                                              ranking + "\n" + extra);
}

TEST(OfferedMetrics, AMisspeltRideOutputIsRefusedWithTheNameItMeant) {
  const std::string path =
      offered_study("two_axle_freight_wagon.toml", "two_axle_wagon_fra_class4.toml",
                    "objective = [{ metric = \"rms_acceleration:floor over the front axel, vertical\", goal = \"min\" }]");
  const InputError e = study_error_at(path, "misspelt output");
  EXPECT_EQ(e.file(), path);
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.message().find("key 'ranking.objective[0].metric'"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("no ride output named 'floor over the front axel, vertical'; did you mean "
                             "'floor over the front axle, vertical'?"),
            std::string::npos)
      << e.what();
  EXPECT_NE(e.message().find("'front left spring force'"), std::string::npos) << e.what();  // the names there are
  // Spelt right, it loads.
  EXPECT_NO_THROW(load_study(offered_study(
      "two_axle_freight_wagon.toml", "two_axle_wagon_fra_class4.toml",
      "objective = [{ metric = \"rms_acceleration:floor over the front axle, vertical\", goal = \"min\" }]")));
}

// Without [[ride.output]] the names are the default floor points of the study's vehicles.
TEST(OfferedMetrics, TheDefaultFloorPointsAreTheNamesWithoutRideOutputs) {
  const std::string scene = "manchester_coach_ore_low.toml";
  EXPECT_NO_THROW(load_study(offered_study("manchester_benchmark_coach.toml", scene,
                                           "\"max_rms_acceleration:floor over front bogie, vertical\" = \"1 m/s^2\"")));
  const InputError e = study_error_at(
      offered_study("manchester_benchmark_coach.toml", scene, "\"max_rms_acceleration:floor over bogie 1\" = \"1 m/s^2\""),
      "an output of another vehicle");
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.message().find("key 'ranking.max_rms_acceleration:floor over bogie 1'"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("'floor at mid-car, vertical'"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("default floor points"), std::string::npos) << e.what();
}

TEST(OfferedMetrics, ARideMetricNeedsARide) {
  const std::string path = write_study(example3_wagon(), "[ranking]\nobjective = [{ metric = \"max_wz\", goal = \"min\" }]\n");
  const InputError e = study_error_at(path, "max_wz without a ride");
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.message().find("metric 'max_wz' needs a ride"), std::string::npos) << e.what();
}

// A limit on a vibration's velocity (a peak or an RMS, shown in m/s) is a velocity: a bare number
// is m/s, as for a displacement's metre. A limit on a vehicle's speed (shown in km/h) needs its
// unit, as every speed does (review of 2026-11-27: both were refused with a km/h hint).
TEST(StudyLimits, AVibrationVelocityLimitMayBeBareAVehicleSpeedMayNot) {
  EXPECT_NO_THROW(load_study(write_study(example3_wagon(), "[ranking]\n\"max_peak:body.bounce:velocity\" = 0.05\n")));
  const InputError e =
      study_error_at(write_study(example3_wagon(), "[ranking]\nmin_lowest_critical_speed = 30\n"), "a bare speed");
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.message().find("give the speed its unit"), std::string::npos) << e.what();
}

TEST(OfferedMetrics, HuntingSpeedNeedsAVehicleWithWheelsets) {
  const InputError e =
      study_error_at(write_study(example3_wagon(), "[ranking]\nmin_hunting_speed = \"150 km/h\"\n"), "no wheelsets");
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.message().find("key 'ranking.min_hunting_speed': metric 'hunting_speed' needs wheelsets"),
            std::string::npos)
      << e.what();
  EXPECT_NE(e.message().find("'wagon'"), std::string::npos) << e.what();  // the vehicles it looked at
  EXPECT_NO_THROW(load_study(offered_study("manchester_benchmark_coach_wheelsets.toml",
                                           "manchester_coach_wheelsets_ore_alignment.toml",
                                           "objective = [{ metric = \"hunting_speed\", goal = \"max\" }]")));
}

// rms_acceleration: on a spring force (N) read the force's RMS as an acceleration in m/s² (the
// audit's 1.5e4 "m/s^2"): refused, naming the output's quantity and the metric that fits it,
// whose unit is the output's own.
TEST(OfferedMetrics, AnRmsMetricOfAnotherQuantityIsRefusedWithTheOneThatFits) {
  const std::string scene = "two_axle_wagon_fra_class4.toml";
  const InputError e = study_error_at(
      offered_study("two_axle_freight_wagon.toml", scene,
                    "objective = [{ metric = \"rms_acceleration:front left spring force\", goal = \"min\" }]"),
      "a force as an acceleration");
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(e.message().find("ride output 'front left spring force' is an element's force (N), not an acceleration: "
                             "use 'rms_force:front left spring force', its RMS in N"),
            std::string::npos)
      << e.what();
  const InputError v = study_error_at(
      offered_study("two_axle_freight_wagon.toml", scene,
                    "objective = [{ metric = \"rms_force:floor at mid-wagon, vertical\", goal = \"min\" }]"),
      "an acceleration as a force");
  EXPECT_NE(v.message().find("is an acceleration (m/s²), not a force: use 'rms_acceleration:floor at mid-wagon, "
                             "vertical'"),
            std::string::npos)
      << v.what();
  // The force's own metric loads, and its limit is read as a force.
  const Study s = load_study(offered_study("two_axle_freight_wagon.toml", scene,
                                           "\"max_rms_force:front left spring force\" = \"2 tf\""));
  ASSERT_EQ(s.ranking.constraints.size(), 1u);
  EXPECT_DOUBLE_EQ(*s.ranking.constraints[0].max, 2000 * 9.80665);
  const InputError unit = study_error_at(
      offered_study("two_axle_freight_wagon.toml", scene, "\"max_rms_force:front left spring force\" = \"2 m\""),
      "a length as a force limit");
  EXPECT_NE(unit.message().find("expected a force"), std::string::npos) << unit.what();
}

// A variant that changes the scene's ride may name outputs the base scene does not: the name is
// then left to the evaluated variants.
TEST(OfferedMetrics, AStudyThatChangesTheRideIsNotCheckedAgainstTheBaseScene) {
  EXPECT_NO_THROW(load_study(offered_study(
      "two_axle_freight_wagon.toml", "two_axle_wagon_fra_class4.toml",
      "objective = [{ metric = \"rms_acceleration:floor over the rear axle, vertical\", goal = \"min\" }]",
      "[[variant]]\nname = \"rear\"\nscene_overrides = { \"ride.output[1].name\" = "
      "\"floor over the rear axle, vertical\" }\n")));
}

// A scene without a periodic source (random track alone) has no critical speeds, peaks or dynamic
// deflections: a metric that reads them is refused at its key. A critical speed asked for there
// is most likely the hunting speed (user audit 2026-11-28, F3: min_critical_speed = "300 km/h"
// passed every variant, one of them hunting at 259 km/h), which the message names.
TEST(OfferedMetrics, ACriticalSpeedNeedsAPeriodicSourceAndTheMessageNamesTheHuntingSpeed) {
  const std::string scene = "manchester_coach_wheelsets_ore_alignment.toml";  // irregularity only
  const InputError shorthand = study_error_at(
      offered_study("manchester_benchmark_coach_wheelsets.toml", scene, "min_critical_speed = \"300 km/h\""),
      "a critical speed without a periodic source");
  EXPECT_EQ(shorthand.line(), 6);
  EXPECT_NE(shorthand.message().find("key 'ranking.min_critical_speed': metric 'lowest_critical_speed' needs a "
                                     "periodic source"),
            std::string::npos)
      << shorthand.what();
  EXPECT_NE(shorthand.message().find("the scene " + scene + " has none"), std::string::npos) << shorthand.what();
  EXPECT_NE(shorthand.message().find("use 'min_hunting_speed'"), std::string::npos) << shorthand.what();
  const InputError objective = study_error_at(
      offered_study("manchester_benchmark_coach_wheelsets.toml", scene,
                    "objective = [{ metric = \"critical_speed:body lower sway\", goal = \"max\" }]"),
      "a mode's critical speed without a periodic source");
  EXPECT_EQ(objective.line(), 6);
  EXPECT_NE(objective.message().find("key 'ranking.objective[0].metric'"), std::string::npos) << objective.what();
  EXPECT_NE(objective.message().find("use metric 'hunting_speed'"), std::string::npos) << objective.what();
  // The hunting speed itself loads.
  EXPECT_NO_THROW(load_study(
      offered_study("manchester_benchmark_coach_wheelsets.toml", scene, "min_hunting_speed = \"300 km/h\"")));
}

// Peaks and dynamic deflections are responses to the periodic sources too; the deflection rule
// checks them. Neither names the hunting speed.
TEST(OfferedMetrics, PeaksAndDeflectionsNeedAPeriodicSource) {
  const std::string scene = "manchester_coach_ore_low.toml";
  const InputError peak = study_error_at(
      offered_study("manchester_benchmark_coach.toml", scene,
                    "objective = [{ metric = \"peak:body.bounce:acceleration\", goal = \"min\" }]"),
      "a peak without a periodic source");
  EXPECT_EQ(peak.line(), 6);
  EXPECT_NE(peak.message().find("so no variant has its peaks or dynamic deflections"), std::string::npos)
      << peak.what();
  EXPECT_EQ(peak.message().find("hunting"), std::string::npos) << peak.what();
  const InputError rule = study_error_at(
      offered_study("manchester_benchmark_coach.toml", scene,
                    "objective = [{ metric = \"max_wz\", goal = \"min\" }]", "[permissible_dynamic_deflection]\nrule = \"lehner\"\n"),
      "a deflection rule without a periodic source");
  EXPECT_EQ(rule.line(), 7);  // the table's header, the first line after the ranking's
  EXPECT_NE(rule.message().find("key 'permissible_dynamic_deflection': the dynamic deflections are those under the "
                                "scene's periodic sources"),
            std::string::npos)
      << rule.what();
  // On a scene with rail joints the same peak loads.
  EXPECT_NO_THROW(load_study(write_study(example3_wagon(), "[ranking]\n\"max_peak:body.bounce:acceleration\" = 5\n")));
}

// A variant may add a periodic source through the scene's `source` keys: the study is then left
// to its variants.
TEST(OfferedMetrics, AStudyThatChangesTheSourcesIsNotCheckedForThem) {
  EXPECT_NO_THROW(load_study(offered_study(
      "two_axle_freight_wagon.toml", "two_axle_wagon_fra_class4.toml", "min_critical_speed = \"30 km/h\"",
      "[[variant]]\nname = \"class 5\"\nscene_overrides = { \"source[0].vertical_level.class\" = 5 }\n")));
}

}  // namespace
}  // namespace railmodal::test
