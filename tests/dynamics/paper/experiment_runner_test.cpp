// The runs of the paper job (dynamics/paper/experiment_runner.h): each is made from the scenario
// resolved when the job was planned, and that scenario, written beside the run, reproduces it.

#include "dynamics/paper/experiment_runner.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/scenario.h"
#include "dynamics/scenario_run.h"

namespace frictionlab::dynamics::paper {
namespace {

namespace fs = std::filesystem;

const fs::path kScenarios = fs::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_runner_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Case (c) of the homogeneous egg for 0.03 s: a few hundred steps per law.
PlanOptions tiny_plan(const fs::path& out, const fs::path& scenarios) {
  PlanOptions plan;
  plan.out_dir = out;
  plan.scenario_dir = scenarios;
  plan.eggs = {"egg-homogeneous"};
  plan.cases = {"c"};
  plan.laws = {"exact", "pade-reconstructed", "moller-ellipsoidal"};
  plan.baseline = true;
  plan.overrides = {"run.t_end=0.03", "run.output_dt=0.001"};
  return plan;
}

TEST(PaperExperimentRunner, EachRunsScenarioTomlNamesItsLawAndReproducesIt) {
  const fs::path out = scratch("reproduce");
  const auto results = run_experiments(plan_runs(tiny_plan(out, kScenarios)), RunnerOptions{});
  ASSERT_EQ(results.size(), 4u);  // three laws and the baseline
  for (const RunResult& r : results) {
    ASSERT_TRUE(r.executed) << r.name() << ": " << r.error;
    const Scenario written = load_scenario(r.spec.out_dir / "scenario.toml");
    EXPECT_EQ(written.law, r.spec.law) << r.name();
    const ScenarioRun again = run_scenario(written, out / "again" / r.spec.label);
    EXPECT_EQ(again.summary.steps, r.summary.steps) << r.name();
    EXPECT_TRUE(slurp(r.spec.out_dir / "trajectory.csv") == slurp(again.trajectory_csv))
        << r.name() << ": the rerun of its scenario.toml differs";
  }
  fs::remove_all(out);
}

// The job reads each scenario file once, when it plans: the runs need the files no more.
TEST(PaperExperimentRunner, RunsFromThePlannedScenariosWithoutRereadingFiles) {
  const fs::path out = scratch("once");
  const fs::path scenarios = scratch("once_scenarios");
  fs::create_directories(scenarios);
  fs::copy_file(kScenarios / "egg-homogeneous-c.toml", scenarios / "egg-homogeneous-c.toml");
  const std::vector<RunSpec> specs = plan_runs(tiny_plan(out, scenarios));
  fs::remove_all(scenarios);
  const auto results = run_experiments(specs, RunnerOptions{});
  for (const RunResult& r : results) EXPECT_TRUE(r.executed && r.error.empty()) << r.name() << ": " << r.error;
  fs::remove_all(out);
}

// The law of each run is the plan's: a --set of contact.law would contradict --laws.
TEST(PaperExperimentRunner, TheLawIsSetByThePlanNotByAnOverride) {
  PlanOptions plan = tiny_plan(scratch("law_override"), kScenarios);
  plan.overrides.push_back("contact.law=pade-printed");
  try {
    (void)plan_runs(plan);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--laws"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
