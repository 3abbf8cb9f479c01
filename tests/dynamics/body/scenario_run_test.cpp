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

// run.pose = false: the stepper integrates the state without the pose, which is never fed back
// (dynamics/core/run_loop.h). Everything else of the run is the same to the last bit: every row
// of trajectory.csv without the pose's six columns, the step and evaluation counts, every event.
// The runs go through bounces (the egg, the ellipsoid with the Hertz patch), slip holds (the
// rattleback's reversal), stick and rest (the braked rattleback), the tippe top and the disk.
struct PoseOffCase {
  std::string scenario;
  std::vector<std::string> overrides;
};

class DynScenarioRunWithoutPose : public ::testing::TestWithParam<PoseOffCase> {};

std::vector<std::string> csv_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

TEST_P(DynScenarioRunWithoutPose, TheRestOfTheRunIsTheSameToTheLastBit) {
  const PoseOffCase& param = GetParam();
  const std::string file = std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/" + param.scenario + ".toml";
  std::vector<std::string> off_overrides = param.overrides;
  off_overrides.push_back("run.pose=false");
  const Scenario on = load_scenario(file, param.overrides);
  const Scenario off = load_scenario(file, off_overrides);
  ASSERT_TRUE(on.run.pose);
  ASSERT_FALSE(off.run.pose);
  const auto dir_on = fresh_dir("pose_on_" + param.scenario);
  const auto dir_off = fresh_dir("pose_off_" + param.scenario);
  const ScenarioRun a = run_scenario(on, dir_on);
  const ScenarioRun b = run_scenario(off, dir_off);

  EXPECT_EQ(a.summary.reason, b.summary.reason);
  EXPECT_EQ(a.summary.steps, b.summary.steps);
  EXPECT_EQ(a.summary.rejected_steps, b.summary.rejected_steps);
  EXPECT_EQ(a.summary.rhs_calls, b.summary.rhs_calls);
  EXPECT_EQ(a.summary.t_final, b.summary.t_final);
  EXPECT_TRUE(a.summary.x_final.head<StateLayout::kPoseFreeSize>() ==
              b.summary.x_final.head<StateLayout::kPoseFreeSize>());
  EXPECT_GT(a.summary.steps, 100);

  const std::vector<std::string> rows_on = csv_lines(slurp(a.trajectory_csv));
  const std::vector<std::string> rows_off = csv_lines(slurp(b.trajectory_csv));
  ASSERT_EQ(rows_on.size(), rows_off.size());
  ASSERT_GT(rows_on.size(), 10u);
  for (std::size_t r = 0; r < rows_on.size(); ++r) {
    const std::vector<std::string> with_pose = csv_fields(rows_on[r]);
    ASSERT_EQ(with_pose.size(), kTrajectoryColumns.size()) << "row " << r;
    std::vector<std::string> expected;
    for (std::size_t i = 0; i < with_pose.size(); ++i) {
      if (i < kPoseColumnsBegin || i >= kPoseColumnsEnd) expected.push_back(with_pose[i]);
    }
    ASSERT_EQ(csv_fields(rows_off[r]), expected) << "row " << r << " of " << param.scenario;
  }

  const auto json_on = support::Json::parse(slurp(a.summary_json));
  const auto json_off = support::Json::parse(slurp(b.summary_json));
  EXPECT_TRUE(json_on["final_state"].contains("orientation"));
  EXPECT_FALSE(json_off["final_state"].contains("orientation"));
  EXPECT_FALSE(json_off["final_state"].contains("position"));
  for (const char* key : {"gamma", "omega", "v", "eps", "t"}) {
    EXPECT_EQ(json_on["final_state"][key], json_off["final_state"][key]) << key;
  }
  for (const char* key : {"stick", "slip_hold", "spin_hold", "termination", "energy_balance_error"}) {
    EXPECT_EQ(json_on[key], json_off[key]) << key;
  }
  std::filesystem::remove_all(dir_on);
  std::filesystem::remove_all(dir_off);
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, DynScenarioRunWithoutPose,
    ::testing::Values(PoseOffCase{"egg-printed-a", {"run.t_end=3", "contact.law=exact"}},
                      PoseOffCase{"ellipsoid-case-a", {"run.t_end=1", "contact.patch=hertz"}},
                      PoseOffCase{"rattleback-reversal", {"run.t_end=2.65"}},
                      PoseOffCase{"rattleback-braked", {"run.t_end=3"}},
                      PoseOffCase{"tippe-top", {"run.t_end=2"}},
                      PoseOffCase{"disk-spin-to-rest", {"run.t_end=1"}}),
    [](const auto& p) {
      std::string name = p.param.scenario;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

}  // namespace
}  // namespace frictionlab::dynamics
