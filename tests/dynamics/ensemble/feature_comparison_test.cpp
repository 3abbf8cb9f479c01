// Laws against the reference and the chaos floor (dynamics/ensemble/feature_comparison.h,
// dynamics/ensemble/chaos_floor_rule.h), on synthetic studies with known answers.

#include "dynamics/ensemble/feature_comparison.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/ensemble/random_stream.h"

namespace frictionlab::dynamics::ensemble {
namespace feature_comparison_test {

// 200 replicas per law: t_rest ~ uniform(100, 200) s, drawn anew for "same", exact's own value
// plus a shift for "shifted"; final class pole+ unless the law turns it.
std::vector<RunRecord> study(double shift_b, const std::string& class_b) {
  std::vector<RunRecord> rows;
  RandomStream rng(3);
  for (long replica = 0; replica < 200; ++replica) {
    const double exact_t_rest = 100.0 + 100.0 * rng.uniform();
    for (const std::string law : {"exact", "same", "shifted"}) {
      RunRecord r;
      r.replica = replica;
      r.law = law;
      r.reason = "rest";
      r.t_rest = law == "exact" ? exact_t_rest : law == "same" ? 100.0 + 100.0 * rng.uniform() : exact_t_rest + shift_b;
      r.t_final = r.t_rest;
      r.final_class = law == "shifted" && replica % 4 != 0 ? class_b : "pole+";
      r.diverge_horizon = r.t_final;
      if (law == "exact" && replica % 2 == 1) {
        r.diverge_ref = "replica:" + std::to_string(replica - 1);
        r.t_diverge = 20.0 + 10.0 * rng.uniform();
      } else if (law != "exact") {
        r.diverge_ref = "exact";
        r.t_diverge = law == "same" ? 20.0 + 10.0 * rng.uniform() : 2.0 + rng.uniform();
      }
      rows.push_back(r);
    }
  }
  return rows;
}

const FeatureComparison& find(const std::vector<FeatureComparison>& v, const std::string& feature, const std::string& law) {
  for (const auto& c : v)
    if (c.feature == feature && c.law == law) return c;
  throw std::runtime_error("no " + feature + " for " + law);
}

TEST(EnsembleChaosFloorRule, TheRuleNeedsSignificanceAndTheFloorFactor) {
  EXPECT_EQ(judge(0.001, 3.0, 1.0), Verdict::changes);
  EXPECT_EQ(judge(0.5, 1.5, 1.0), Verdict::within_chaos);
  EXPECT_EQ(judge(0.001, 1.5, 1.0), Verdict::unclear) << "significant but within twice the floor";
  EXPECT_EQ(judge(0.5, 3.0, 1.0), Verdict::unclear) << "above the floor but not significant";
  EXPECT_EQ(judge(0.01, 3.0, 1.0), Verdict::unclear) << "p must be below 1 %";
  EXPECT_EQ(judge(std::nan(""), 3.0, 1.0), Verdict::not_available);
  EXPECT_EQ(judge(1e-9, 3e-8, 1e-11, 1e-3), Verdict::negligible) << "detectable, but below the feature's resolution";
  EXPECT_EQ(judge(1e-9, 3.0, 1.0, 3.0), Verdict::negligible) << "at the resolution";
  EXPECT_EQ(judge(1e-9, 3.0, 1.0, 2.9), Verdict::changes);
  EXPECT_EQ(to_string(Verdict::within_chaos), "within chaos");
}

TEST(EnsembleFeatureComparison, AShiftedLawChangesTheMotionAndAnEqualOneStaysWithinChaos) {
  const auto c = compare_features(study(60.0, "pole-"), {"exact", "same", "shifted"});
  ASSERT_EQ(c.size(), compared_features().size() * 3);
  const auto& ref = find(c, "t_rest", "exact");
  EXPECT_EQ(ref.summary.runs, 200);
  EXPECT_EQ(ref.summary.finite, 200);
  EXPECT_EQ(ref.distances.verdict, Verdict::not_available) << "the reference is not judged";
  EXPECT_GT(ref.distances.floor_w1, 0.0);
  EXPECT_LT(ref.distances.floor_w1, 15.0) << "two halves of one uniform(100, 200): W1 ~ 5 s";
  EXPECT_NEAR(ref.summary.quantiles[2], 150.0, 10.0);
  const auto& same = find(c, "t_rest", "same");
  EXPECT_EQ(same.distances.verdict, Verdict::within_chaos);
  const auto& shifted = find(c, "t_rest", "shifted");
  EXPECT_NEAR(shifted.distances.w1, 60.0, 1e-9) << "W1 is the shift";
  EXPECT_LT(shifted.distances.p, 1e-10);
  EXPECT_EQ(shifted.distances.verdict, Verdict::changes);
  // A systematic shift below the feature's resolution (0.1 s for t_rest) is negligible.
  const auto tiny = compare_features(study(0.05, "pole+"), {"exact", "same", "shifted"});
  EXPECT_EQ(find(tiny, "t_rest", "shifted").distances.verdict, Verdict::negligible);
  // A feature no run has: n/a, not a verdict.
  EXPECT_EQ(find(c, "t_vertical", "shifted").distances.verdict, Verdict::not_available);
  EXPECT_EQ(find(c, "t_vertical", "shifted").summary.finite, 0);
}

TEST(EnsembleFeatureComparison, RunsThatStoppedEarlyLeaveTheNumericFeatures) {
  auto rows = study(0.0, "pole+");
  for (auto& r : rows)
    if (r.law == "shifted") {
      r.reason = "law-pole";
      r.final_class = "stopped";
    }
  const auto c = compare_features(rows, {"exact", "same", "shifted"});
  EXPECT_EQ(find(c, "t_rest", "shifted").summary.normal, 0);
  EXPECT_EQ(find(c, "t_rest", "shifted").distances.verdict, Verdict::not_available);
  const auto k = compare_classes(rows, {"exact", "same", "shifted"});
  ASSERT_EQ(k.size(), 3u);
  EXPECT_EQ(k[2].counts.at("stopped"), 200);
  EXPECT_EQ(k[2].tv, 1.0);
  EXPECT_EQ(k[2].verdict, Verdict::changes) << "every run stopped: its outcome class is another";
}

TEST(EnsembleFeatureComparison, OutcomeClassesAgainstTheFloor) {
  const auto k = compare_classes(study(0.0, "pole-"), {"exact", "same", "shifted"});
  EXPECT_EQ(k[0].counts.at("pole+"), 200);
  EXPECT_EQ(k[0].floor_tv, 0.0) << "exact's halves agree";
  EXPECT_EQ(k[1].verdict, Verdict::within_chaos);
  EXPECT_NEAR(k[2].tv, 0.75, 1e-12) << "three in four replicas turned";
  EXPECT_EQ(k[2].verdict, Verdict::changes);
}

TEST(EnsembleFeatureComparison, DivergenceTimesAgainstTheFloors) {
  const auto d = compare_divergence(study(0.0, "pole+"), {"exact", "same", "shifted"});
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[2].law, "floor");
  EXPECT_EQ(d[2].compared, 100) << "one per replica pair";
  EXPECT_EQ(d[0].compared, 200);
  EXPECT_EQ(d[0].parted, 200);
  EXPECT_GT(d[0].p, kSignificance) << "parts like the floor";
  EXPECT_LT(d[1].p, 1e-10) << "parts at 2-3 s, the floor at 20-30 s";
  EXPECT_NEAR(d[1].quantiles[2], 2.5, 0.2);
}

TEST(EnsembleFeatureComparison, RunsComparedOverLessTimeThanTheFloorTakesAreNotTested) {
  auto rows = study(0.0, "pole+");
  for (auto& r : rows)
    if (r.law == "shifted") {  // stopped at 0.3 s, never parted before
      r.diverge_horizon = 0.3;
      r.t_diverge = std::nan("");
    }
  const auto d = compare_divergence(rows, {"exact", "same", "shifted"});
  EXPECT_EQ(d[1].parted, 0);
  EXPECT_TRUE(std::isnan(d[1].p)) << "0.3 s of comparison cannot tell whether it parts at 20-30 s";
  // A floor that never parts (a motion without chaos): the law is tested over the floor's horizon.
  for (auto& r : rows)
    if (r.law == "exact") r.t_diverge = std::nan("");
  const auto calm = compare_divergence(rows, {"exact", "same", "shifted"});
  EXPECT_EQ(calm[2].parted, 0);
  EXPECT_TRUE(std::isnan(calm[1].p)) << "stopped at 0.3 s: still no test against a floor compared over 100-200 s";
  EXPECT_LT(calm[0].p, 1e-10) << "parts at 20-30 s where the floor never does";
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
