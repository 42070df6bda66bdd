// The unit of each metric, which limits are read in and reports show.
#include <gtest/gtest.h>

#include "railmodal/study.hpp"

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

}  // namespace
}  // namespace railmodal
