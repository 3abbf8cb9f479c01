// The paper's narrative as checks (dynamics/paper/narrative_checks.h), judged on hand-made
// features: each rule can say yes, partly, no and n/a.

#include "dynamics/paper/narrative_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace frictionlab::dynamics::paper {
namespace narrative_checks_test {

constexpr double kWeight = 2.0 * 9.81;  // N, the paper's egg

// A case-(a)-like run that ends at rest: vertical at 4 s for 3 s, plateau at -0.5 from 20 s to
// 80 s, rest on the other pole at 150 s, no lift-off.
RunResult case_a_run() {
  RunResult r;
  r.spec.egg = "egg-printed";
  r.spec.case_id = "a";
  r.spec.law = r.spec.label = "exact";
  r.executed = true;
  r.weight = kWeight;
  r.low_pole = 1;
  r.summary.reason = Termination::rest;
  r.summary.t_final = 150.0;
  r.summary.liftoffs = 0;
  r.summary.min_normal_force = 0.5 * kWeight;
  RunFeatures& f = r.features;
  f.t_final = 150.0;
  f.gamma3_initial = 0.97;
  f.gamma3_final = f.gamma3_final_mean = -1.0;
  f.kinetic_final = 1e-4;
  f.vertical = {true, 4.0, 1, true, 7.0};
  f.near_vertical = {true, 3.0, 1, true, 7.0};
  f.plateau.found = true;
  f.plateau.t_from = 7.0;
  f.plateau.t_start = 20.0;
  f.plateau.gamma3 = -0.5;
  f.plateau.t_end = 80.0;
  f.descent_oscillation = 0.01;
  return r;
}

const ClaimCheck& find(const std::vector<ClaimCheck>& checks, const std::string& id) {
  const auto it = std::find_if(checks.begin(), checks.end(), [&](const ClaimCheck& c) { return c.id == id; });
  if (it == checks.end()) throw std::runtime_error("no such claim: " + std::string(id));
  return *it;
}

TEST(PaperNarrativeChecks, CaseAAsThePaperTellsIt) {
  const RunResult a = case_a_run();
  const auto checks = check_narrative({&a, nullptr, nullptr});
  ASSERT_EQ(checks.size(), 6u);
  for (const auto& id : {"a1", "a2", "a3", "a4", "a5", "a6"}) EXPECT_EQ(find(checks, id).verdict, Verdict::holds) << id << ": " << find(checks, id).evidence;
  EXPECT_NE(find(checks, "a1").evidence.find("t = 4 s"), std::string::npos) << find(checks, "a1").evidence;
}

TEST(PaperNarrativeChecks, EachCaseARuleCanFail) {
  RunResult a = case_a_run();
  a.summary.liftoffs = 12;
  a.summary.min_normal_force = 0.0;
  a.features.vertical.t_reached = 40.0;  // 27 % of the run: not "quickly"
  a.features.plateau.t_start = 70.0;     // tilt 63 s, plateau held 10 s: not "fast, then slowly"
  a.summary.reason = Termination::rolling;
  a.features.gamma3_final_mean = -0.97;  // rolling near the pole
  const auto checks = check_narrative({&a, nullptr, nullptr});
  EXPECT_EQ(find(checks, "a1").verdict, Verdict::fails);
  EXPECT_EQ(find(checks, "a3").verdict, Verdict::fails);
  EXPECT_EQ(find(checks, "a4").verdict, Verdict::partly);
  EXPECT_EQ(find(checks, "a5").verdict, Verdict::partly);
  EXPECT_EQ(find(checks, "a6").verdict, Verdict::fails);
  EXPECT_NE(find(checks, "a6").evidence.find("12 lift-offs"), std::string::npos) << find(checks, "a6").evidence;
}

TEST(PaperNarrativeChecks, ARunStoppedAtAPoleIsNotJudgedOnWhatItDidNotReach) {
  RunResult a = case_a_run();
  a.summary.reason = Termination::integrator_failure;
  a.summary.t_final = a.features.t_final = 0.45;
  a.features.vertical = {};
  a.features.near_vertical = {};
  a.features.plateau = {};
  a.features.max_abs_gamma3 = 0.975;
  const auto checks = check_narrative({&a, nullptr, nullptr});
  for (const auto& id : {"a1", "a2", "a3", "a4", "a5", "a6"})
    EXPECT_EQ(find(checks, id).verdict, Verdict::not_measurable) << id << ": " << find(checks, id).evidence;
  EXPECT_NE(find(checks, "a1").evidence.find("integrator-failure"), std::string::npos);
}

TEST(PaperNarrativeChecks, CaseBSpinsLongerAndCaseCSettlesAtCaseAsAngle) {
  const RunResult a = case_a_run();
  RunResult b = case_a_run();
  b.spec.case_id = "b";
  b.features.gamma3_initial = -0.97;
  b.features.vertical = {true, 4.0, -1, true, 12.0};  // 8 s vs 3 s in case a
  b.features.near_vertical = {true, 3.0, -1, true, 12.0};
  b.features.descent_oscillation = 0.05;  // 5x case a
  RunResult c = case_a_run();
  c.spec.case_id = "c";
  c.features.gamma3_initial = -0.02;
  c.features.vertical = {};
  c.features.near_vertical = {};
  c.features.plateau.t_from = 0.0;
  c.features.plateau.gamma3 = -0.48;  // 118.7 deg vs 120 deg
  c.features.rise_extreme = 0.52;
  c.features.sampled_liftoffs_before_plateau = 7;
  auto checks = check_narrative({&a, &b, &c});
  EXPECT_EQ(checks.size(), 16u);
  EXPECT_EQ(find(checks, "b2").verdict, Verdict::holds) << find(checks, "b2").evidence;
  EXPECT_EQ(find(checks, "b4").verdict, Verdict::holds) << find(checks, "b4").evidence;
  EXPECT_EQ(find(checks, "c1").verdict, Verdict::fails) << find(checks, "c1").evidence;  // toward -1, not +1
  EXPECT_EQ(find(checks, "c2").verdict, Verdict::holds);
  EXPECT_EQ(find(checks, "c3").verdict, Verdict::holds) << find(checks, "c3").evidence;
  EXPECT_EQ(find(checks, "c4").verdict, Verdict::holds);
  EXPECT_EQ(find(checks, "c5").verdict, Verdict::holds);

  b.features.vertical.t_left = 8.0;  // 4 s vs 3 s: not "much longer" at 0.999 ...
  checks = check_narrative({&a, &b, &c});
  EXPECT_EQ(find(checks, "b2").verdict, Verdict::partly);  // ... but 9 s vs 4 s at 0.99
  b.features.near_vertical.t_left = 8.0;
  c.features.plateau.gamma3 = -0.3;  // 107.5 deg
  checks = check_narrative({&a, &b, &c});
  EXPECT_EQ(find(checks, "b2").verdict, Verdict::fails);
  EXPECT_EQ(find(checks, "c3").verdict, Verdict::fails);
}

TEST(PaperNarrativeChecks, VerdictNames) {
  EXPECT_EQ(to_string(Verdict::holds), "yes");
  EXPECT_EQ(to_string(Verdict::partly), "partly");
  EXPECT_EQ(to_string(Verdict::fails), "no");
  EXPECT_EQ(to_string(Verdict::not_measurable), "n/a");
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
