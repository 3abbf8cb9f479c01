#include "dynamics/body/scenario_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dynamics/body/trajectory_csv.h"
#include "friction/support/json.h"
#include "friction/registry.h"

namespace frictionlab::dynamics {
namespace scenario_run_test {

const char* kSphere = R"(
[body]
profile = "sphere"
radius = 0.05
mass = 1
[contact]
k = 0.2
lambda = 1e7
[initial]
gamma = [0, 0, 1]
v = [2, 0, 0]
eps = "static"
[run]
t_end = 0.1
output_dt = 0.01
)";

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab_dyn_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(DynScenarioRun, WritesTrajectorySummaryAndResolvedScenario) {
  const Scenario s = parse_scenario(kSphere, "sphere.toml");
  const auto dir = fresh_dir("run");
  const ScenarioRun run = run_scenario(s, dir);
  EXPECT_EQ(run.summary.reason, Termination::t_end);

  const std::string csv = slurp(run.trajectory_csv);
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  std::string expected;
  for (auto c : kTrajectoryColumns) {
    if (!expected.empty()) expected += ',';
    expected += c;
  }
  EXPECT_EQ(header, expected);
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), static_cast<long>(kTrajectoryColumns.size()) - 1);
  }
  EXPECT_EQ(rows, 11);  // t = 0, 0.01, ..., 0.1

  const auto summary = support::Json::parse(slurp(run.summary_json));
  EXPECT_EQ(summary["output"]["trajectory_rows"], rows);
  EXPECT_TRUE(summary["output"]["error"].is_null());
  const std::string json = slurp(run.summary_json);
  for (const char* key : {"\"reason\": \"t_end\"", "\"final_time\": 0.1", "\"steps\":", "\"rhs_calls\":",
                          "\"wall_time_s\":", "\"liftoffs\": 0", "\"min_N_over_mg\":", "\"initial_energy\":",
                          "\"final_energy\":", "\"final_state\":", "\"law\": \"exact\"", "\"name\": \"sphere\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << " in\n" << json;
  EXPECT_TRUE(std::filesystem::exists(dir / "scenario.toml"));
  std::filesystem::remove_all(dir);
}

TEST(DynScenarioRun, ARunThatStopsEarlyStillLeavesItsCsvAndSummary) {
  const Scenario s = parse_scenario(kSphere, "sphere.toml", {"run.max_steps=5"});
  const auto dir = fresh_dir("early");
  const ScenarioRun run = run_scenario(s, dir);
  EXPECT_EQ(run.summary.reason, Termination::max_steps);
  const std::string csv = slurp(run.trajectory_csv);
  EXPECT_GE(std::count(csv.begin(), csv.end(), '\n'), 3);  // header, t = 0, final
  const std::string json = slurp(run.summary_json);
  EXPECT_NE(json.find("\"reason\": \"max-steps\""), std::string::npos) << json;
  EXPECT_NE(json.find("run.max_steps = 5"), std::string::npos) << json;
  std::filesystem::remove_all(dir);
}

// The scenario is the one source of truth of a run: rerunning the scenario.toml written beside it
// reproduces its trajectory to the last bit, whatever the law (set by an override here, as the
// command line and the paper job set it).
class DynScenarioRunReproduces : public ::testing::TestWithParam<std::string> {};

TEST_P(DynScenarioRunReproduces, RerunningItsScenarioTomlGivesTheSameTrajectory) {
  // Sliding and spinning at once (every output of the law matters), on a slightly tilted sphere,
  // with values that need all 17 digits to read back.
  const Scenario s = parse_scenario(kSphere, "sphere.toml",
                                    {"contact.law=" + GetParam(), "initial.omega=[0.30000000000000004, 0, 15]",
                                     "initial.gamma=[0.1, 0, 0.99498743710662]", "run.t_end=0.02",
                                     "run.output_dt=0.002"});
  const auto first = fresh_dir("first_" + GetParam());
  const auto second = fresh_dir("second_" + GetParam());
  const ScenarioRun a = run_scenario(s, first);
  const Scenario again = load_scenario(first / "scenario.toml");
  EXPECT_EQ(again.law, GetParam());
  EXPECT_EQ(again.name, s.name);
  EXPECT_EQ(support::Json::parse(slurp(a.summary_json))["law"], GetParam());
  const ScenarioRun b = run_scenario(again, second);
  EXPECT_EQ(a.summary.reason, b.summary.reason);
  EXPECT_GT(a.summary.steps, 10);
  const std::string csv = slurp(a.trajectory_csv);
  EXPECT_GT(std::count(csv.begin(), csv.end(), '\n'), 10);
  EXPECT_TRUE(csv == slurp(b.trajectory_csv)) << "the trajectories differ";
  std::filesystem::remove_all(first);
  std::filesystem::remove_all(second);
}

// Every registered law but the reference quadrature exact-reference, which costs ~10-30 ms per
// call (bench/accuracy/study.h): too slow for a test run of a few thousand calls.
std::vector<std::string> laws_to_rerun() {
  std::vector<std::string> out;
  for (const auto& info : friction::list_laws())
    if (info.name != "exact-reference") out.push_back(info.name);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Laws, DynScenarioRunReproduces, ::testing::ValuesIn(laws_to_rerun()),
                         [](const auto& p) {
                           std::string name = p.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace frictionlab::dynamics
