// Regression pins: numbers observed in runs of this code, not derived. Reduced versions of the
// paper's cases (section 2; docs/model.md §6): the first seconds of each run with the exact law,
// under two integration tolerances, asserting only early features seen to hold under both (the
// later motion is chaotic in its bouncing phases: docs/experiments.md), and where the printed Padé
// law stops. They catch unintended changes; a deliberate change of the model, the integrator or
// the features may move them (update them with the run that produced the new value, and say why
// in the commit). The paper's claims the exact law does not reproduce are documented in
// docs/experiments.md, not forced here.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/paper/experiment_runner.h"

namespace frictionlab::dynamics::paper {
namespace paper_cases_regression_pin_test {

// s: long enough for case (a) to reach the vertical (seen at 3.0 s and 4.7 s for the two eggs),
// short enough for a test (~0.1 s of integration in Release for all six runs).
constexpr double kShortRun = 6.0;
// The mean of gamma3 over the last second (5-6 s), as seen with tolerances 1e-9 and 1e-10
// (observed 2026-11-21 and again 2026-11-22 after the steps were freed of the output grid; 2-core
// AMD EPYC KVM, Debian 12, g++ 12.2):
//   a: 0.996 (printed), 0.988-0.998 (homogeneous: the tolerance already matters here);
//   b: -0.998, -0.995; c: -0.454 (printed), 0.102 (homogeneous).
// The bounds leave a margin of about half the distance from the start value (0.97, -0.97, -0.02).
constexpr double kCaseAAbove = 0.975;   // a: the axis has risen toward the vertical (from 0.97)
constexpr double kCaseBBelow = -0.975;  // b: toward the inverted vertical (from -0.97)
constexpr double kCaseCPrintedBelow = -0.1;     // c, egg-printed: the axis turns toward gamma3 = -1
constexpr double kCaseCHomogeneousAbove = 0.05;  // c, egg-homogeneous: toward gamma3 = +1

std::string tolerance(double tol) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", tol);
  return buf;
}

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("frictionlab_paper_cases_" + name + "_" + std::to_string(::getpid()));
}

class PaperCasesEarlyRegressionPin : public ::testing::TestWithParam<double> {};

TEST_P(PaperCasesEarlyRegressionPin, FirstSecondsWithTheExactLaw) {
  const double tol = GetParam();
  PlanOptions plan;
  plan.out_dir = scratch(tolerance(tol));
  plan.scenario_dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";
  plan.laws = {"exact"};
  plan.baseline = false;
  plan.overrides = {"run.t_end=" + tolerance(kShortRun), "run.abs_tol=" + tolerance(tol),
                    "run.rel_tol=" + tolerance(tol)};
  RunnerOptions ro;
  ro.jobs = 2;
  const auto results = run_experiments(plan_runs(plan), ro);
  std::filesystem::remove_all(plan.out_dir);
  ASSERT_EQ(results.size(), 6u);

  std::map<std::string, const RunResult*> by;
  for (const auto& r : results) {
    ASSERT_TRUE(r.executed) << r.name() << ": " << r.error;
    EXPECT_EQ(r.summary.reason, Termination::t_end) << r.name() << ": " << r.summary.message;
    by[r.spec.group()] = &r;
  }
  for (const std::string egg : {"egg-printed", "egg-homogeneous"}) {
    const RunFeatures& a = by.at(egg + "-a")->features;
    EXPECT_EQ(a.first_move, 1) << egg;
    EXPECT_GT(a.gamma3_final_mean, kCaseAAbove) << egg;
    ASSERT_TRUE(a.vertical.reached) << egg;  // "the axis quickly becomes vertical"
    EXPECT_EQ(a.vertical.pole, 1) << egg;

    const RunFeatures& b = by.at(egg + "-b")->features;
    EXPECT_EQ(b.first_move, -1) << egg;
    EXPECT_LT(b.gamma3_final_mean, kCaseBBelow) << egg;
  }
  EXPECT_LT(by.at("egg-printed-c")->features.gamma3_final_mean, kCaseCPrintedBelow);
  EXPECT_GT(by.at("egg-homogeneous-c")->features.gamma3_final_mean, kCaseCHomogeneousAbove);
}

INSTANTIATE_TEST_SUITE_P(Tolerances, PaperCasesEarlyRegressionPin, ::testing::Values(1e-9, 1e-10));

// The printed Padé law's F2 has a real pole (docs/model.md §4): its run of case (c) stops within
// 0.05 s (at 0.041 s for tolerances 1e-8 to 1e-10) instead of running on, and says why.
TEST(PaperCasesRegressionPin, PrintedPadeStopsEarlyInCaseCAndSaysWhy) {
  for (const double tol : {1e-9, 1e-10}) {
    PlanOptions plan;
    plan.out_dir = scratch("printed");
    plan.scenario_dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";
    plan.laws = {"pade-printed"};
    plan.eggs = {"egg-homogeneous"};
    plan.cases = {"c"};
    plan.overrides = {"run.t_end=1", "run.abs_tol=" + tolerance(tol), "run.rel_tol=" + tolerance(tol)};
    const auto results = run_experiments(plan_runs(plan), RunnerOptions{});
    std::filesystem::remove_all(plan.out_dir);
    ASSERT_EQ(results.size(), 1u);
    const RunResult& r = results[0];
    ASSERT_TRUE(r.executed) << r.error;
    EXPECT_FALSE(r.ended_normally()) << to_string(r.summary.reason);
    EXPECT_LT(r.summary.t_final, 0.05);
    EXPECT_NE(r.summary.message.find("F2"), std::string::npos) << r.summary.message;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
