#include "dynamics/scenario_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "dynamics/trajectory_csv.h"
#include "friction/registry.h"
#include "test_support.h"

namespace frictionlab::dynamics {
namespace {

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
  const auto law = friction::make_law("exact");
  const auto dir = fresh_dir("run");
  const ScenarioRun run = run_scenario(s, *law, dir);
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

  const std::string json = slurp(run.summary_json);
  for (const char* key : {"\"reason\": \"t_end\"", "\"final_time\": 0.1", "\"steps\":", "\"rhs_calls\":",
                          "\"wall_time_s\":", "\"liftoffs\": 0", "\"min_N_over_mg\":", "\"initial_energy\":",
                          "\"final_energy\":", "\"final_state\":", "\"law\": \"exact\"", "\"name\": \"sphere\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << " in\n" << json;
  EXPECT_TRUE(std::filesystem::exists(dir / "scenario.toml"));
  std::filesystem::remove_all(dir);
}

TEST(DynScenarioRun, ARunThatFailsMidwayStillLeavesItsCsvAndSummary) {
  const Scenario s = parse_scenario(kSphere, "sphere.toml");
  const testing::PoleTestLaw law(1.8);  // non-finite once U < 1.8 m/s: after ~0.03 s
  const auto dir = fresh_dir("fail");
  const ScenarioRun run = run_scenario(s, law, dir);
  EXPECT_EQ(run.summary.reason, Termination::non_finite);
  const std::string csv = slurp(run.trajectory_csv);
  EXPECT_GE(std::count(csv.begin(), csv.end(), '\n'), 4);  // header, t = 0, 0.01, 0.02, final
  const std::string json = slurp(run.summary_json);
  EXPECT_NE(json.find("\"reason\": \"non-finite\""), std::string::npos) << json;
  EXPECT_NE(json.find("F2 = inf"), std::string::npos) << json;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::dynamics
