// One task of an ensemble (dynamics/ensemble/task_execution.h): every run emitted once, the
// comparisons against the reference law and between replicas, and a resumed task giving the same
// rows as an uninterrupted one.

#include "dynamics/ensemble/task_execution.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <map>

#include "dynamics/body/scenario_run.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics::ensemble {
namespace task_execution_test {

const std::filesystem::path kStudies = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "studies";

// Case a of the printed egg for 0.5 s: the printed Padé law stops at its pole at 0.316 s.
// `shadow`: a line of the study (the shadow key), or none (the default: the compared laws).
EnsemblePlan plan(const std::string& shadow = "") {
  return EnsemblePlan::make(parse_study(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "pade-printed", "moller-ellipsoidal"]
set = ["run.t_end=0.5", "run.output_dt=0.01"]
)" + shadow + R"(
[replicas]
count = 2
size = 1e-9
)",
                                        "t.toml", kStudies));
}

std::map<long, RunRecord> run_task(const EnsemblePlan& p, const TaskOrder& order, bool* completed = nullptr,
                                   const std::atomic<bool>* cancel = nullptr) {
  std::map<long, RunRecord> out;
  ExecuteOptions o;
  o.cancel = cancel;
  const bool done = execute_task(p, order, o, [&](FinishedRun&& r) {
    EXPECT_FALSE(out.count(r.record.run)) << "emitted twice: " << r.record.run;
    out[r.record.run] = r.record;
  });
  if (completed) *completed = done;
  return out;
}

TaskOrder whole(const EnsemblePlan& p) {
  TaskOrder o;
  o.task = p.task(0);
  for (long i = 0; i < p.runs(); ++i) o.todo.push_back(i);
  return o;
}

TEST(EnsembleTaskExecution, EveryRunIsEmittedWithItsComparison) {
  const EnsemblePlan p = plan();
  ASSERT_EQ(p.tasks(), 1);
  bool completed = false;
  const auto rows = run_task(p, whole(p), &completed);
  EXPECT_TRUE(completed);
  ASSERT_EQ(rows.size(), 6u);
  // The reference on replica 0 is compared with nothing; on replica 1 with replica 0 (the floor).
  EXPECT_EQ(rows.at(0).diverge_ref, "");
  EXPECT_EQ(rows.at(3).diverge_ref, "replica:0");
  EXPECT_EQ(rows.at(3).diverge_horizon, 0.5);
  EXPECT_TRUE(std::isnan(rows.at(3).t_diverge)) << "a 1e-9 perturbation does not part in 0.5 s";
  // The other laws against the reference on their own replica, up to the end of the shorter run.
  for (const long run : {1L, 4L}) {
    EXPECT_EQ(rows.at(run).law, "pade-printed");
    EXPECT_EQ(rows.at(run).reason, "law-pole");
    EXPECT_EQ(rows.at(run).final_class, "stopped");
    EXPECT_EQ(rows.at(run).diverge_ref, "exact");
    EXPECT_EQ(rows.at(run).diverge_horizon, rows.at(run).t_final) << "it stopped first";
    EXPECT_FALSE(rows.at(run).message.empty());
  }
  for (const long run : {2L, 5L}) {
    EXPECT_EQ(rows.at(run).reason, "t_end");
    EXPECT_EQ(rows.at(run).diverge_horizon, 0.5);
    EXPECT_TRUE(rows.at(run).message.empty());
  }
  for (const auto& [run, r] : rows) {
    EXPECT_EQ(r.run, run);
    EXPECT_EQ(r.replica, run / 3);
    EXPECT_GT(r.steps, 0);
    EXPECT_GT(r.rhs_calls, 12 * r.steps) << "rk8pd: 12 or 13 calls a step, plus the samples'";
    if (r.reason == "t_end") {
      EXPECT_GT(r.liftoffs, 0) << "case a starts bouncing (docs/experiments.md)";
    }
    EXPECT_GE(r.work_slide, 0.0);
    EXPECT_GT(r.wall_time, 0.0);
    // Spun about its axis, the egg keeps its sense for 0.5 s: no reversal, a sense at the end.
    EXPECT_EQ(r.spin_reversals, 0);
    EXPECT_TRUE(std::isnan(r.t_first_reversal));
    EXPECT_NE(r.final_spin_sense, 0) << "the recorder keeps Omega";
  }
}

// The distance between the bodies' axes: exactly zero between two runs of the same law (exact and
// exact:pressure=hertz are one law), positive and growing between the reference's two replicas.
TEST(EnsembleTaskExecution, TheAxesOfTheSameLawsRunsAreExactlyTogetherAndTheFloorsPartMoreAndMore) {
  const EnsemblePlan p = EnsemblePlan::make(parse_study(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "exact:pressure=hertz"]
set = ["run.t_end=3.5", "run.output_dt=0.01"]
[replicas]
count = 2
size = 1e-6
)",
                                                        "t.toml", kStudies));
  const auto rows = run_task(p, whole(p));
  ASSERT_EQ(rows.size(), 4u);
  for (const long run : {1L, 3L}) {  // the same law against the reference on its replica
    ASSERT_EQ(rows.at(run).axis_angle_deg.size(), kAxisAngleTimes.size());
    EXPECT_TRUE(std::isnan(rows.at(run).t_part));
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(rows.at(run).axis_angle_deg[k], 0.0) << kAxisAngleTimes[k];
    for (std::size_t k = 4; k < kAxisAngleTimes.size(); ++k) EXPECT_TRUE(std::isnan(rows.at(run).axis_angle_deg[k]));
  }
  const RunRecord& floor = rows.at(2);  // the reference on replica 1 against replica 0
  EXPECT_EQ(floor.diverge_ref, "replica:0");
  ASSERT_EQ(floor.axis_angle_deg.size(), kAxisAngleTimes.size());
  for (std::size_t k = 0; k < 4; ++k) EXPECT_GT(floor.axis_angle_deg[k], 0.0) << kAxisAngleTimes[k];
  EXPECT_GT(floor.axis_angle_deg[3], 10.0 * floor.axis_angle_deg[0]) << "3 s against 0.1 s";
}

// The reference's runs carry the compared laws as shadow laws (dynamics/core/shadow_laws.h): the
// columns are filled on them only, and the runs are the same bit for bit as without.
TEST(EnsembleTaskExecution, TheReferencesRunsShadowTheComparedLawsWithoutChangingAnything) {
  const EnsemblePlan with = plan();
  const EnsemblePlan without = plan("shadow = false");
  ASSERT_EQ(with.shadow_laws(), (std::vector<std::string>{"pade-printed", "moller-ellipsoidal"}));
  ASSERT_TRUE(without.shadow_laws().empty());
  const auto a = run_task(with, whole(with));
  const auto b = run_task(without, whole(without));
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [run, r] : a) {
    ASSERT_EQ(r.shadow.size(), 2u) << run;
    RunRecord plain = r;
    RunRecord other = b.at(run);
    plain.shadow.clear();
    plain.wall_time = other.wall_time = 0.0;
    EXPECT_EQ(to_csv_row(plain), to_csv_row(other)) << "the shadow laws changed run " << run;
    for (const ShadowColumns& c : r.shadow) EXPECT_EQ(c.evaluated(), r.law == "exact") << run;
  }
  for (const long run : {0L, 3L}) {  // the reference's runs
    const ShadowColumns& moller = a.at(run).shadow[1];
    EXPECT_EQ(moller.failures, 0);
    EXPECT_GT(moller.F_median, 0.0);
    EXPECT_LE(moller.F_median, moller.F_p95);
    EXPECT_LE(moller.F_p95, moller.F_max * 1.023) << "quantiles within 2.3 %";
    EXPECT_LE(moller.F_max, 2.0) << "two laws within the friction bound differ by at most 2 kN";
    EXPECT_GT(moller.M_max, 0.0);
    EXPECT_TRUE(std::isfinite(moller.dE));
    EXPECT_GE(a.at(run).shadow[0].failures, 0) << "pade-printed counts its poles";
  }
  // A row with the shadow columns reads back as it was written.
  const std::string row = to_csv_row(a.at(0));
  const RunRecord back = parse_run_row(std::string_view(row).substr(0, row.size() - 1), 0, RunModel::body, 2);
  EXPECT_EQ(to_csv_row(back), row);
}

// Shadowing the reference law with itself gives zero everywhere, and a law's columns are the
// statistics that `frictionlab simulate --shadow` writes for the same start (another path through
// the same statistics: summary.json).
TEST(EnsembleTaskExecution, TheShadowColumnsAreZeroForTheOwnLawAndTheSimulateShadowStatistics) {
  const EnsemblePlan p = plan(R"(shadow = ["exact", "moller-ellipsoidal"])");
  TaskOrder first;
  first.task = p.task(0);
  first.todo = {0};
  const auto rows = run_task(p, first);
  ASSERT_EQ(rows.size(), 1u);
  const ShadowColumns& self = rows.at(0).shadow.at(0);
  EXPECT_EQ(self.F_max, 0.0);
  EXPECT_EQ(self.M_max, 0.0);
  EXPECT_EQ(self.dE, 0.0);
  EXPECT_EQ(self.failures, 0);

  Scenario s = p.scenario({0, 0, 0});
  s.run.shadow = {"moller-ellipsoidal"};
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab_ens_shadow_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const ScenarioRun run = run_scenario(s, dir);
  std::ifstream in(run.summary_json);
  const auto summary = support::Json::parse(in);
  const auto& law = summary["shadow"]["laws"][0];
  const auto& F = law["errors"]["contact"]["F"];
  const ShadowColumns& m = rows.at(0).shadow.at(1);
  EXPECT_EQ(F["median"].get<double>(), m.F_median);
  EXPECT_EQ(F["p95"].get<double>(), m.F_p95);
  EXPECT_EQ(F["max"].get<double>(), m.F_max);
  EXPECT_EQ(law["errors"]["contact"]["M"]["max"].get<double>(), m.M_max);
  EXPECT_EQ(law["difference_J"].get<double>(), m.dE);
  std::filesystem::remove_all(dir);
}

TEST(EnsembleTaskExecution, AResumedTaskRecomputesItsReferenceAndGivesTheSameRows) {
  const EnsemblePlan p = plan();
  auto all = run_task(p, whole(p));
  // Only the Möller run of replica 1 and the reference of replica 1 (which needs replica 0's) are left.
  TaskOrder rest;
  rest.task = p.task(0);
  rest.todo = {3, 5};
  const auto again = run_task(p, rest);
  ASSERT_EQ(again.size(), 2u);
  for (const long run : {3L, 5L}) {
    RunRecord a = all.at(run);
    RunRecord b = again.at(run);
    a.wall_time = b.wall_time = 0.0;
    EXPECT_EQ(to_csv_row(b), to_csv_row(a)) << run;
  }
}

TEST(EnsembleTaskExecution, AnInterruptedTaskEmitsNothingUnfinished) {
  const EnsemblePlan p = plan();
  std::atomic<bool> cancel{true};
  bool completed = true;
  const auto rows = run_task(p, whole(p), &completed, &cancel);
  EXPECT_FALSE(completed);
  EXPECT_TRUE(rows.empty());
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
