// The runs of the paper job (dynamics/paper/experiment_runner.h): each is made from the scenario
// resolved when the job was planned, and that scenario, written beside the run, reproduces it.

#include "dynamics/paper/experiment_runner.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"

namespace frictionlab::dynamics::paper {
namespace experiment_runner_test {

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

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    out.push_back(text.substr(pos, end - pos));
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return out;
}

// A thinned trajectory.csv holds the rerun's rows 0, 10, 20, ... and its last, bit for bit: the
// output interval does not change the steps, and the rows kept are the samples at those times.
TEST(PaperExperimentRunner, AThinnedTrajectoryIsEveryTenthRowOfTheRerun) {
  const fs::path out = scratch("thinned");
  PlanOptions plan = tiny_plan(out, kScenarios);
  plan.laws = {"exact"};
  plan.baseline = false;
  RunnerOptions options;
  options.trajectory_every = 10;
  const auto results = run_experiments(plan_runs(plan), options);
  ASSERT_EQ(results.size(), 1u);
  ASSERT_TRUE(results[0].executed && results[0].error.empty()) << results[0].error;
  const auto thinned = lines(slurp(results[0].spec.out_dir / "trajectory.csv"));
  const ScenarioRun again = run_scenario(load_scenario(results[0].spec.out_dir / "scenario.toml"), out / "again");
  const auto full = lines(slurp(again.trajectory_csv));
  ASSERT_EQ(full.size(), 32u);  // the header and t = 0, 0.001, ..., 0.03
  ASSERT_EQ(thinned.size(), 5u);  // the header and t = 0, 0.01, 0.02, 0.03
  EXPECT_EQ(thinned[0], full[0]);
  for (std::size_t i = 1; i < thinned.size(); ++i) EXPECT_EQ(thinned[i], full[1 + 10 * (i - 1)]) << i;
  fs::remove_all(out);
}

TEST(PaperExperimentRunner, ThinningByLessThanOneIsRejected) {
  RunnerOptions options;
  options.trajectory_every = 0;
  EXPECT_THROW((void)run_experiments({}, options), std::invalid_argument);
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
