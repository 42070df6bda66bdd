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

}  // namespace
}  // namespace railmodal
