// The progress line (dynamics/ensemble/progress_meter.h).

#include "dynamics/ensemble/progress_meter.h"

#include <gtest/gtest.h>

namespace frictionlab::dynamics::ensemble {
namespace progress_meter_test {

TEST(EnsembleProgressMeter, LineSaysRunsRateAndTimeLeft) {
  // 100 of 1000 done before, 200 now in 100 s: 2 runs/s, 700 left: 350 s = 6 min.
  EXPECT_EQ(ProgressMeter::line(1000, 100, 200, 100.0), "300/1000 runs (30.0 %), 2 runs/s, 6 min left");
  EXPECT_EQ(ProgressMeter::line(10, 0, 0, 0.0), "0/10 runs (0.0 %)");
  EXPECT_EQ(ProgressMeter::line(10, 2, 8, 4.0), "10/10 runs (100.0 %), 2 runs/s");
}

TEST(EnsembleProgressMeter, DurationsReadNaturally) {
  EXPECT_EQ(ProgressMeter::duration(42.0), "42 s");
  EXPECT_EQ(ProgressMeter::duration(720.0), "12 min");
  EXPECT_EQ(ProgressMeter::duration(3.2 * 3600), "3.2 h");
  EXPECT_EQ(ProgressMeter::duration(2.1 * 86400), "2.1 d");
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
