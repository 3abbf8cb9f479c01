#include "dynamics/core/run_stops.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <atomic>
#include <string>
#include <vector>

#include "dynamics/core/run_summary.h"

namespace frictionlab::dynamics {
namespace run_stops_test {

struct Stops {
  std::vector<std::pair<Termination, std::string>> seen;
  auto recorder() {
    return [this](Termination why, std::string message) { seen.emplace_back(why, std::move(message)); };
  }
};

TEST(DynRunStops, MaxStepsStopsAtTheLimitWithItsRuleAndThreshold) {
  RunSummaryOf<Eigen::Vector3d> s;  // any model's summary
  Stops stops;
  EXPECT_FALSE(stop_at_step_limits(99, 100, nullptr, s, stops.recorder()));
  EXPECT_TRUE(stops.seen.empty());
  EXPECT_TRUE(stop_at_step_limits(100, 100, nullptr, s, stops.recorder()));
  ASSERT_EQ(stops.seen.size(), 1U);
  EXPECT_EQ(stops.seen[0].first, Termination::max_steps);
  EXPECT_NE(stops.seen[0].second.find("run.max_steps = 100"), std::string::npos) << stops.seen[0].second;
  EXPECT_EQ(s.rule, "accepted steps = run.max_steps");
  ASSERT_EQ(s.thresholds.size(), 1U);
  EXPECT_EQ(s.thresholds[0].key, "run.max_steps");
  EXPECT_EQ(s.thresholds[0].value, 100.0);
  EXPECT_EQ(s.thresholds[0].source, "given");
}

TEST(DynRunStops, TEndStopsOnceReached) {
  RunSummaryOf<Eigen::Vector3d> s;  // any model's summary
  Stops stops;
  EXPECT_FALSE(stop_at_t_end(0.999, 1.0, s, stops.recorder()));
  EXPECT_TRUE(stop_at_t_end(1.0, 1.0, s, stops.recorder()));
  ASSERT_EQ(stops.seen.size(), 1U);
  EXPECT_EQ(stops.seen[0].first, Termination::t_end);
  EXPECT_EQ(s.rule, "t = run.t_end");
  ASSERT_EQ(s.thresholds.size(), 1U);
  EXPECT_EQ(s.thresholds[0].key, "run.t_end");
  EXPECT_EQ(s.thresholds[0].value, 1.0);
}

TEST(DynRunStops, ACancelledJobIsInterrupted) {
  RunSummaryOf<Eigen::Vector3d> s;  // any model's summary
  Stops stops;
  std::atomic<bool> cancel{false};
  EXPECT_FALSE(stop_at_step_limits(1, 100, &cancel, s, stops.recorder()));
  cancel = true;
  EXPECT_TRUE(stop_at_step_limits(1, 100, &cancel, s, stops.recorder()));
  ASSERT_EQ(stops.seen.size(), 1U);
  EXPECT_EQ(stops.seen[0].first, Termination::interrupted);
  EXPECT_TRUE(s.rule.empty());  // an interruption is no rule of the motion
}

TEST(DynRunStops, MessagesNameTheOutputTheLawTheTimesAndTheState) {
  const std::string pole = law_pole_message("F2", "pade-printed", 1e-3, 0.316, "U = 1 m/s");
  for (const char* part : {"F2", "'pade-printed'", "0.001 s", "t = 0.316 s", "U = 1 m/s"})
    EXPECT_NE(pole.find(part), std::string::npos) << part << " in " << pole;
  EXPECT_NE(non_finite_step_message(4.25).find("t = 4.25 s"), std::string::npos);
  EXPECT_EQ(non_finite_message("gamma is NaN").rfind("gamma is NaN", 0), 0U);
  const std::string gsl = integrator_failure_message("step size too small", 2.5, "Omega = 3 1/s");
  for (const char* part : {"GSL: step size too small", "t = 2.5 s", "Omega = 3 1/s"})
    EXPECT_NE(gsl.find(part), std::string::npos) << part << " in " << gsl;
}

}  // namespace
}  // namespace frictionlab::dynamics
