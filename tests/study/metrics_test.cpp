// The unit of each metric, which limits are read in and reports show.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>

#include "railmodal/study.hpp"
#include "study/metrics.hpp"

namespace railmodal {
namespace {

TEST(Metrics, EachMetricHasItsSIUnit) {
  EXPECT_STREQ(metric_unit("critical_speed"), "m/s");
  EXPECT_STREQ(metric_unit("critical_speed:body bounce"), "m/s");
  EXPECT_STREQ(metric_unit("bounce_period"), "s");
  EXPECT_STREQ(metric_unit("static_deflection:bogie"), "m");
  EXPECT_STREQ(metric_unit("metacentric_height"), "m");
  EXPECT_STREQ(metric_unit("dynamic_deflection_ratio:spring"), "");
  EXPECT_STREQ(metric_unit("peak:body.z:displacement"), "m");
  EXPECT_STREQ(metric_unit("peak:body.z:velocity"), "m/s");
  EXPECT_STREQ(metric_unit("peak:body.z:acceleration"), "m/s^2");
  EXPECT_STREQ(metric_unit("peak:body.pitch:displacement"), "rad");
  EXPECT_STREQ(metric_unit("peak:body.pitch:velocity"), "rad/s");
  EXPECT_STREQ(metric_unit("peak:body.pitch:acceleration"), "rad/s^2");
}

// Two kinds of metric are "m/s": the vehicle's own speed, which reports show in km/h and whose
// limits need their unit, and a vibration's velocity, shown and read in m/s (study_reader.cpp's
// limit_quantity and study::display_unit both go by metric_is_vehicle_speed).
TEST(Metrics, VehicleSpeedsAreToldFromVibrationVelocities) {
  for (const char* speed : {"lowest_critical_speed", "critical_speed", "critical_speed:body bounce",
                            "bounce_critical_speed", "hunting_speed"}) {
    EXPECT_TRUE(metric_is_vehicle_speed(speed)) << speed;
    EXPECT_STREQ(metric_unit(speed), "m/s") << speed;
  }
  for (const char* velocity : {"peak:body.z:velocity", "rms_velocity:floor over bogie 1"}) {
    EXPECT_FALSE(metric_is_vehicle_speed(velocity)) << velocity;
    EXPECT_STREQ(metric_unit(velocity), "m/s") << velocity;
  }
  for (const char* other : {"bounce_period", "static_deflection", "peak:body.pitch:velocity", "max_wz",
                            "rms_acceleration:floor", "dynamic_deflection_ratio"})
    EXPECT_FALSE(metric_is_vehicle_speed(other)) << other;
}

// The notes under a comparison's table and its document's sentences show a value as the table's
// column does (user audit 2026-11-27c: the notes had 4 significant digits where the table has
// the metric's decimals): km/h to 0.1, periods to 1 ms, N_MV to 0.01; more decimals only where
// two values that differ would read the same, and the limit as the study gives it.
TEST(Metrics, NotesShowAValueAsItsTableColumnDoes) {
  const std::string speed = "critical_speed:body bounce";
  EXPECT_EQ(study::table_decimals(speed), 1);
  EXPECT_EQ(study::shown_as_tabled(speed, 79.3089 / 3.6), "79.3 km/h");
  EXPECT_EQ(study::shown_as_tabled("period:body bounce", 0.56740134), "0.567 s");
  EXPECT_EQ(study::shown_as_tabled("max_nmv", 1.11), "1.11");
  EXPECT_EQ(study::shown_as_tabled("max_nmv", 1.1), "1.10");  // the trailing zero kept (F13)
  EXPECT_EQ(study::shown_as_tabled(speed, std::numeric_limits<double>::infinity()), "none");
  // Two values apart: 89.97 against 90 reads "89.97", not "90.0"; 79.31 against 90 needs no more.
  const auto apart = study::shown_apart(speed, 89.97 / 3.6, 90 / 3.6);
  EXPECT_EQ(apart.first, "89.97 km/h");
  EXPECT_EQ(apart.second, "90.00 km/h");
  EXPECT_EQ(study::shown_apart(speed, 79.31 / 3.6, 90 / 3.6).first, "79.3 km/h");
  EXPECT_EQ(study::shown_apart(speed, 25.0, 25.0).first, "90.0 km/h");  // equal values stay at the table's
  // The table's figure: fixed decimals, two significant digits for a figure too small for them,
  // never a negative zero.
  EXPECT_EQ(study::table_figure(0.004, 3), "0.004");  // %.2g: no trailing zero
  EXPECT_EQ(study::table_figure(-0.0001, 1), "-0.0001");
  EXPECT_EQ(study::table_figure(-0.0, 2), "0.00");
  EXPECT_EQ(study::table_figure(-0.004, 2), "-0.004");
  // A violation for people: the value as the table shows it, the limit as given; for programs
  // both to 6 significant digits, as before.
  Ranking ranking;
  ranking.constraints.push_back({speed, 90 / 3.6, std::nullopt, {}});
  VariantResult r;
  r.critical_speeds_evaluated = true;
  r.critical_speeds.push_back({79.3089 / 3.6, 0, "rail_joints", 1, "body bounce", false});
  ASSERT_EQ(study::violations(r, ranking, true).size(), 1u);
  EXPECT_EQ(study::violations(r, ranking, true)[0], "critical speed of body bounce 79.3 km/h < 90 km/h");
  EXPECT_EQ(study::violations(r, ranking, false)[0], "critical_speed:body bounce 79.3089 km/h < 90 km/h");
  r.critical_speeds[0].speed = 89.97 / 3.6;
  EXPECT_EQ(study::violations(r, ranking, true)[0], "critical speed of body bounce 89.97 km/h < 90 km/h");
}

}  // namespace
}  // namespace railmodal
