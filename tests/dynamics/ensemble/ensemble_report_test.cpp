// The report of a finished study (dynamics/ensemble/ensemble_report.h), on the smoke study's plan
// with synthetic rows whose answers are known.

#include "dynamics/ensemble/ensemble_report.h"

#include <gtest/gtest.h>

namespace frictionlab::dynamics::ensemble {
namespace ensemble_report_test {

const std::filesystem::path kStudies = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "studies";

TEST(EnsembleReport, SaysWhatRanHowItEndedAndWhatChanged) {
  const EnsemblePlan plan = EnsemblePlan::make(read_study(kStudies / "smoke.toml"));
  std::vector<RunRecord> rows;
  for (long i = 0; i < plan.runs(); ++i) {
    const RunId id = plan.run_id(i);
    RunRecord r;
    r.run = i;
    r.start = id.start;
    r.replica = id.replica;
    r.law = plan.study().laws[static_cast<std::size_t>(id.law)];
    r.values = plan.start_values(id.start);
    r.reason = id.law == 0 ? "rest" : "law-pole";
    r.final_class = id.law == 0 ? "pole+" : "stopped";
    r.wall_time = 0.5;
    r.rhs_calls = 1000;
    rows.push_back(r);
  }
  const std::string md = report_markdown(plan, rows, "frictionlab ensemble smoke.toml --out x", "a machine", {"figures/map-changes.png"});
  for (const std::string part : {"# Ensemble `smoke`", "**8 runs**", "## How the runs ended", "| exact | 4 | 0 | 4 |",
                                 "## Where the runs end: outcome classes", "| pade-printed | 0 | 4 | 1 |",
                                 "## Does the law change the motion?", "p < 0.01 and W1 > 2 × floor W1",
                                 "### Verdicts at a glance", "| outcome class | **changes** |",
                                 "## Divergence times against the floor", "## Maps over `initial.gamma3` × `initial.omega3`",
                                 "| pade-printed | 0 | 0 | **2** | 0 | 2 |", "![map-changes](figures/map-changes.png)",
                                 "## Cost", "**Predicted wall time on P cores**", "| cores | 1 | 2 | 64 | 1024 |", "| exact | 4 | 0.5 | 0.5 | 0.5 | 2.0 | 1e+03 | 500000 |", "a machine"})
    EXPECT_NE(md.find(part), std::string::npos) << "missing: " << part << "\n" << md;
}

// The shadow table: per law, medians over the reference's runs of each run's values, the largest
// of the largest, dE over the run's friction work, failures summed (and the runs that had any).
TEST(EnsembleReport, TheShadowTableSummarisesTheReferencesRuns) {
  const EnsemblePlan plan = EnsemblePlan::make(read_study(kStudies / "smoke.toml"));
  ASSERT_EQ(plan.shadow_laws(), std::vector<std::string>{"pade-printed"});
  std::vector<RunRecord> rows;
  const double median[] = {0.1, 0.2, 0.2, 0.3};
  const long failures[] = {0, 2, 0, 1};
  long k = 0;
  for (long i = 0; i < plan.runs(); ++i) {
    const RunId id = plan.run_id(i);
    RunRecord r;
    r.run = i;
    r.law = plan.study().laws[static_cast<std::size_t>(id.law)];
    r.values = plan.start_values(id.start);
    r.reason = "rest";
    r.final_class = "pole+";
    r.shadow.resize(1);
    if (id.law == 0) {
      ShadowColumns& c = r.shadow[0];
      c.F_median = median[k];
      c.F_p95 = 2 * median[k];
      c.F_max = static_cast<double>(k + 1);
      c.M_median = 0.01;
      c.M_max = 0.5;
      c.dE = -1.0;
      c.failures = failures[k];
      r.work_slide = 6.0;
      r.work_spin = 4.0;
      ++k;
    }
    rows.push_back(r);
  }
  ASSERT_EQ(k, 4);
  const std::string md = report_markdown(plan, rows, "c", "m", {"figures/shadow_errors.png"});
  for (const std::string part : {"## Each law's friction along the reference's motion",
                                 "| pade-printed | 4 | 0.2 | 0.4 | 4 | 0.01 | 0.5 | -10 % | -10 % to -10 % | 3 (2) |",
                                 "![the force errors along the motion](figures/shadow_errors.png)"})
    EXPECT_NE(md.find(part), std::string::npos) << "missing: " << part << "\n" << md;
}

TEST(EnsembleReport, MachineDescriptionNamesTheCores) {
  EXPECT_NE(machine_description().find("cores)"), std::string::npos) << machine_description();
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
