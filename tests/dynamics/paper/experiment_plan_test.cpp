// The grid of the paper's runs (dynamics/paper/experiment_plan.h): names, folders, overrides.

#include "dynamics/paper/experiment_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace frictionlab::dynamics::paper {
namespace experiment_plan_test {

PlanOptions options() {
  PlanOptions o;
  o.out_dir = "/tmp/frictionlab-plan-test";  // nothing is written by plan_runs
  o.scenario_dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";
  return o;
}

TEST(PaperExperimentPlan, DefaultGridHasEveryEggCaseLawAndABaseline) {
  const auto runs = plan_runs(options());
  ASSERT_EQ(runs.size(), 2u * 3u * (default_laws().size() + 1));
  const RunSpec& first = runs.front();
  EXPECT_EQ(first.egg, "egg-printed");
  EXPECT_EQ(first.case_id, "a");
  EXPECT_EQ(first.law, "exact");
  EXPECT_EQ(first.out_dir, std::filesystem::path("/tmp/frictionlab-plan-test/runs/egg-printed-a/exact"));
  EXPECT_EQ(first.scenario_file.filename(), "egg-printed-a.toml");
  EXPECT_EQ(first.overrides.front(), "run.output_dt=0.01");

  const RunSpec& baseline = runs[default_laws().size()];
  EXPECT_TRUE(baseline.baseline);
  EXPECT_EQ(baseline.law, "exact");
  EXPECT_EQ(baseline.label, "exact-tol1e-10");  // the scenarios' 1e-9 x 0.1, printed cleanly
  EXPECT_EQ(baseline.overrides.back(), "run.rel_tol=1e-10");
}

TEST(PaperExperimentPlan, UserOverridesComeAfterThePaperDefaults) {
  PlanOptions o = options();
  o.eggs = {"egg-homogeneous"};
  o.cases = {"c"};
  o.laws = {"pade-reconstructed"};
  o.overrides = {"run.t_end=2", "run.output_dt=0.05"};
  const auto runs = plan_runs(o);
  ASSERT_EQ(runs.size(), 1u);  // no reference law: no baseline
  EXPECT_EQ(runs[0].group(), "egg-homogeneous-c");
  EXPECT_EQ(runs[0].overrides, (std::vector<std::string>{"run.output_dt=0.01", "run.t_end=2", "run.output_dt=0.05"}));
}

TEST(PaperExperimentPlan, BadNamesAndOverridesAreRejectedBeforeAnythingRuns) {
  const auto rejects = [](auto change, const std::string& needle) {
    PlanOptions o = options();
    change(o);
    try {
      (void)plan_runs(o);
      ADD_FAILURE() << "accepted; expected an error containing '" << needle << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  rejects([](PlanOptions& o) { o.laws = {"exact", "no-such-law"}; }, "unknown friction law 'no-such-law'");
  rejects([](PlanOptions& o) { o.eggs = {"egg-boiled"}; }, "--eggs");
  rejects([](PlanOptions& o) { o.cases = {"a", "a"}; }, "given twice");
  rejects([](PlanOptions& o) { o.cases = {}; }, "--cases is empty");
  rejects([](PlanOptions& o) { o.out_dir.clear(); }, "--out");
  rejects([](PlanOptions& o) { o.overrides = {"run.t_edn=1"}; }, "t_edn");
  rejects([](PlanOptions& o) { o.scenario_dir = "/no/such/folder"; }, "does not exist");
  rejects([](PlanOptions& o) { o.overrides = {"run.shadow=[\"exact\"]"}; }, "--no-shadow");
}

TEST(PaperExperimentPlan, TheReferenceRunShadowsEveryOtherLawUnlessAskedNotTo) {
  PlanOptions o = options();
  o.eggs = {"egg-printed"};
  o.cases = {"a"};
  o.laws = {"pade-reconstructed", "exact", "exact:pressure=uniform"};
  const auto runs = plan_runs(o);
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[1].law, "exact");
  EXPECT_EQ(runs[1].scenario->run.shadow, (std::vector<std::string>{"pade-reconstructed", "exact:pressure=uniform"}));
  for (const std::size_t other : {0u, 2u, 3u}) EXPECT_TRUE(runs[other].scenario->run.shadow.empty()) << other;
  o.shadow = false;
  for (const RunSpec& r : plan_runs(o)) EXPECT_TRUE(r.scenario->run.shadow.empty()) << r.label;
  o.shadow = true;
  o.laws = {"exact"};  // nothing to compare: no shadow laws
  for (const RunSpec& r : plan_runs(o)) EXPECT_TRUE(r.scenario->run.shadow.empty()) << r.label;
}

TEST(PaperExperimentPlan, LawsMayBeSpecs) {
  PlanOptions o = options();
  o.eggs = {"egg-printed"};
  o.cases = {"a"};
  o.laws = friction::split_law_list("exact:pressure=hertz,pade-printed");
  o.baseline = false;
  const auto runs = plan_runs(o);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].law, "exact:pressure=hertz");
  EXPECT_EQ(runs[0].scenario->law, "exact:pressure=hertz");
  EXPECT_EQ(runs[1].law, "pade-printed");
  o.laws = {"exact", "exact:pressure=hertz"};  // the same law twice
  EXPECT_THROW((void)plan_runs(o), std::invalid_argument);
  o.laws = {"exact:pressure=flat"};
  try {
    (void)plan_runs(o);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--laws: "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("one of hertz"), std::string::npos) << e.what();
  }
}

TEST(PaperExperimentPlan, SplitList) {
  EXPECT_EQ(split_list("a, b ,c", "--cases"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(split_list("exact", "--laws"), (std::vector<std::string>{"exact"}));
  EXPECT_THROW((void)split_list("a,,b", "--cases"), std::invalid_argument);
  EXPECT_THROW((void)split_list("", "--cases"), std::invalid_argument);
  EXPECT_THROW((void)split_list("a,", "--cases"), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
