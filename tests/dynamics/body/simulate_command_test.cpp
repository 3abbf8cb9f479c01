// `frictionlab simulate`, run as a user runs it.

#include <gtest/gtest.h>

#include <csignal>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace frictionlab {
namespace simulate_command_test {

using testing::run_frictionlab;
using testing::slurp;

const std::string kScenarios = std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/";

std::filesystem::path fresh_dir(const std::string& name) { return testing::fresh_temp_dir("simulate_" + name); }

TEST(DynSimulateCommand, AShortRunWritesCsvAndSummary) {
  const auto dir = fresh_dir("ok");
  const auto r = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --law exact --set run.t_end=0.2 "
                                 "--set run.output_dt=0.05 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("t_end at t = 0.2 s"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress bar when stderr is not a terminal
  EXPECT_NE(slurp(dir / "trajectory.csv").find("t,gamma1,gamma2,gamma3"), std::string::npos);
  const auto json = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(json["termination"]["reason"], "t_end");
  EXPECT_EQ(json["scenario"]["overrides"],
            nlohmann::json::array({"run.t_end=0.2", "run.output_dt=0.05", "contact.law=exact"}));
  std::filesystem::remove_all(dir);
}

TEST(DynSimulateCommand, APuckScenarioRunsThePuck) {
  const auto dir = fresh_dir("puck");
  const auto r = run_frictionlab("simulate " + kScenarios + "puck-ellipse.toml --law pade-reconstructed --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("puck-ellipse: rest at t = "), std::string::npos) << r.out;
  EXPECT_EQ(slurp(dir / "trajectory.csv").rfind("t,x,y,heading,vx,vy,omega,U,Omega,psi,F1,F2,M,ratio,energy,W_slide,W_spin,held\n", 0), 0u);
  const auto json = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(json["model"], "puck");
  EXPECT_EQ(json["law"], "pade-reconstructed");
  EXPECT_EQ(json["termination"]["reason"], "rest");
  EXPECT_TRUE(json["slip_stop_time"].is_number());
  EXPECT_TRUE(json["terminal_ratio"].is_number());
  EXPECT_NE(slurp(dir / "scenario.toml").find("model = 'puck'"), std::string::npos) << slurp(dir / "scenario.toml");
  // A bad puck value is one line naming its key.
  const auto bad = run_frictionlab("simulate " + kScenarios + "puck-ellipse.toml --set puck.b=1 --out " + dir.string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--set puck.b=1: puck.b = 1 is invalid"), std::string::npos) << bad.err;
  std::filesystem::remove_all(dir);
}

TEST(DynSimulateCommand, ALawSpecRunsAndIsEchoedVerbatim) {
  const auto dir = fresh_dir("spec");
  const auto r = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --law exact:pressure=hertz "
                                 "--set run.t_end=0.05 --set run.output_dt=0.05 --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(json["law"], "exact:pressure=hertz") << json.dump();
  EXPECT_NE(slurp(dir / "scenario.toml").find("law = 'exact:pressure=hertz'"), std::string::npos);
  const auto bad = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --law exact:pressure=flat --out " +
                                   dir.string() + "/bad");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--law exact:pressure=flat: "), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("one of hertz"), std::string::npos) << bad.err;
  std::filesystem::remove_all(dir);
}

TEST(DynSimulateCommand, BadInputGivesOneLineAndNonZeroExit) {
  const auto dir = fresh_dir("bad");
  for (const std::string& args :
       {std::string("simulate ") + kScenarios + "sphere-spinning.toml --set run.t_edn=1 --out " + dir.string(),
        std::string("simulate ") + kScenarios + "sphere-spinning.toml --law no-such-law --out " + dir.string(),
        std::string("simulate /no/such/file.toml --out ") + dir.string()}) {
    const auto r = run_frictionlab(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
}

// A file whose read fails (reading /proc/self/mem at offset 0 is EIO) was taken for an empty
// scenario ("section [body] is required"): the error names the file and the system's reason.
TEST(DynSimulateCommand, AFailedReadIsReportedAsSuchNotAsAnEmptyFile) {
  const auto dir = fresh_dir("eio");
  const auto r = run_frictionlab("simulate /proc/self/mem --out " + dir.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "frictionlab: error: reading scenario file '/proc/self/mem' failed: Input/output error\n");
  EXPECT_FALSE(std::filesystem::exists(dir));
}

// A table nested 40000 deep crashed the command (toml++ recursed out of the stack, SIGSEGV); it
// is one error line naming the rule (dynamics/io/toml_nesting.h), for a file and for a --set.
TEST(DynSimulateCommand, ADeeplyNestedScenarioIsOneErrorLineNotACrash) {
  const auto dir = fresh_dir("deep");
  std::filesystem::create_directories(dir);
  std::string dotted = "a";
  for (int i = 1; i < 40000; ++i) dotted += ".a";
  { std::ofstream(dir / "deep.toml") << "[" << dotted << "]\nx = 1\n"; }
  const auto r = run_frictionlab("simulate " + (dir / "deep.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("frictionlab: error: " + (dir / "deep.toml").string() + ":1: nested more than 64 levels deep", 0),
            0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const auto set = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --set " + dotted +
                                   "=1 --out " + (dir / "out").string());
  EXPECT_EQ(set.exit_code, 1) << set.err;
  EXPECT_NE(set.err.find("nested more than 64 levels deep"), std::string::npos) << set.err.substr(0, 200);
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  std::filesystem::remove_all(dir);
}

// The installed command finds the shipped scenarios by name from any folder (here the build's:
// the source tree's data/), with or without .toml; an existing path of that name wins.
TEST(DynSimulateCommand, AShippedScenarioIsFoundByNameFromAnyFolder) {
  const auto dir = fresh_dir("by_name");
  std::filesystem::create_directories(dir);
  for (const std::string name : {"sphere-sliding", "sphere-sliding.toml"}) {
    const auto r = run_frictionlab("simulate " + name + " --set run.t_end=0.01 --out out", dir);
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const auto json = nlohmann::json::parse(slurp(dir / "out" / "summary.json"));
    EXPECT_EQ(json["scenario"]["name"], "sphere-sliding");
    EXPECT_EQ(std::filesystem::weakly_canonical(json["scenario"]["source"].get<std::string>()),
              std::filesystem::weakly_canonical(kScenarios + "sphere-sliding.toml"));
  }
  // A file of that name in the working folder is what the user means.
  std::filesystem::copy_file(kScenarios + "sphere-spinning.toml", dir / "sphere-sliding.toml");
  const auto own = run_frictionlab("simulate sphere-sliding.toml --set run.t_end=0.01 --out own", dir);
  ASSERT_EQ(own.exit_code, 0) << own.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(dir / "own" / "summary.json"))["scenario"]["name"], "sphere-spinning");
  std::filesystem::remove_all(dir);
}

TEST(DynSimulateCommand, AnUnknownNameSaysWhereItLooked) {
  const auto dir = fresh_dir("unknown_name");
  std::filesystem::create_directories(dir);
  const auto r = run_frictionlab("simulate no-such-scenario --out out", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("frictionlab: error: scenario 'no-such-scenario' not found: no file 'no-such-scenario' here, "
                        "and no no-such-scenario or no-such-scenario.toml in data/scenarios, ",
                        0),
            0u)
      << r.err;
  EXPECT_NE(r.err.find(kScenarios.substr(0, kScenarios.size() - 1)), std::string::npos) << "the source tree's: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  std::filesystem::remove_all(dir);
}

// Whole rows only: every line of the CSV ends in a newline and has every column.
void expect_whole_rows(const std::string& csv) {
  ASSERT_FALSE(csv.empty());
  EXPECT_EQ(csv.back(), '\n') << "the CSV ends in half a row";
  std::istringstream lines(csv);
  int n = 0;
  for (std::string line; std::getline(lines, line); ++n)
    ASSERT_EQ(std::count(line.begin(), line.end(), ','), 32) << "row " << n << ": " << line;  // 33 columns
}

bool has_temporary_files(const std::filesystem::path& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

// A disk that fills up mid-run (here a file-size limit, as `ulimit -f` sets): the run stops at
// once, the command says so on one line and exits 1, and what was written stays valid.
TEST(DynSimulateCommand, AFileSizeLimitStopsTheRunWithOneErrorAndValidFiles) {
  const auto dir = fresh_dir("fsize");
  constexpr rlim_t kLimit = 20000;  // bytes: ~40 rows of the ~1000 the run would write
  const auto r = testing::run_frictionlab_with_file_limit(
      "simulate " + kScenarios + "sphere-spinning.toml --set run.t_end=1 --set run.output_dt=1e-3 --out " +
          dir.string(),
      kLimit);
  EXPECT_EQ(r.signal, 0) << "killed by a signal";
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("trajectory.csv"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
  const std::string csv = slurp(dir / "trajectory.csv");
  EXPECT_LE(csv.size(), kLimit);
  expect_whole_rows(csv);
  // The summary, where the simulation reports the stop, says why.
  ASSERT_TRUE(std::filesystem::exists(dir / "summary.json"));
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"), nullptr, false);
  ASSERT_FALSE(summary.is_discarded());
  EXPECT_EQ(summary["termination"]["reason"], "output-error");
  EXPECT_FALSE(has_temporary_files(dir));
  std::filesystem::remove_all(dir);
}

// run.max_output_bytes, enforced by the writer on the bytes it writes: the plan (1001 rows of at
// least 66 bytes) fits 100 kB, the rows (~550 bytes each) do not. The run stops with reason
// output-limit (exit 3, one line), its file whole and within one row of the limit, never past it.
TEST(DynSimulateCommand, AnOutputPastRunMaxOutputBytesStopsTheRunAtTheLimit) {
  const auto dir = fresh_dir("max_output_bytes");
  constexpr std::uintmax_t kLimit = 100000;
  constexpr std::uintmax_t kLongestRow = 32 * 25;  // 32 values of at most 24 characters, and separators
  const auto r = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --set run.t_end=1 "
                                 "--set run.output_dt=1e-3 --set run.max_output_bytes=100000 --out " + dir.string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("stopped early (output-limit)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("run.max_output_bytes"), std::string::npos) << r.err;
  const std::string csv = slurp(dir / "trajectory.csv");
  EXPECT_LE(csv.size(), kLimit);
  EXPECT_GT(csv.size() + kLongestRow, kLimit);
  expect_whole_rows(csv);
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(summary["termination"]["reason"], "output-limit");
  EXPECT_EQ(summary["output"]["trajectory_bytes"], csv.size());
  EXPECT_EQ(summary["output"]["max_output_bytes"], kLimit);
  EXPECT_LT(summary["final_time"].get<double>(), 1.0);
  std::filesystem::remove_all(dir);
}

// A shipped scenario run as it is writes what a laptop user accepts (README, docs/dynamics.md §6:
// at most 20 MB per run). egg-homogeneous-c is the largest (the longest run, to rest at 454 s):
// 213 MB at its old output_dt of 1e-3 s, 10.6 MB at 0.02 s. ~3 s of integration in Release.
TEST(DynSimulateCommand, TheLargestShippedScenarioWritesUnder20MB) {
  const auto dir = fresh_dir("largest");
  const auto r = run_frictionlab("simulate " + kScenarios + "egg-homogeneous-c.toml --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::uintmax_t bytes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) bytes += entry.file_size();
  EXPECT_LT(bytes, 20'000'000u);
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(summary["termination"]["reason"], "rest");  // it ran to its end: the size is the whole run's
  std::filesystem::remove_all(dir);
}

// The summary does not fit under the limit while the short trajectory does: no summary.json at
// all (never half of one), an error naming it, exit 1.
TEST(DynSimulateCommand, ASummaryThatCannotBeWrittenIsAnErrorAndLeavesNoPartialFile) {
  const auto dir = fresh_dir("fsize_summary");
  const auto r = testing::run_frictionlab_with_file_limit(
      "simulate " + kScenarios + "sphere-spinning.toml --set run.t_end=0.01 --set run.output_dt=0.01 --out " +
          dir.string(),
      1000);  // bytes: the CSV (~640) and scenario.toml (~490) fit, the summary (~3000) does not
  EXPECT_EQ(r.signal, 0) << "killed by a signal";
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("summary.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
  expect_whole_rows(slurp(dir / "trajectory.csv"));
  EXPECT_FALSE(has_temporary_files(dir));
  std::filesystem::remove_all(dir);
}

// A trajectory file that refuses every write (a link to /dev/full): an error naming it and why.
TEST(DynSimulateCommand, ATrajectoryThatCannotBeWrittenStopsTheRun) {
  const auto dir = fresh_dir("devfull");
  std::filesystem::create_directories(dir);
  std::filesystem::create_symlink("/dev/full", dir / "trajectory.csv");
  const auto r = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --set run.t_end=1 --out " +
                                 dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("trajectory.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  std::filesystem::remove_all(dir);
}

// The line on stdout that cannot be written is an error too.
TEST(DynSimulateCommand, StandardOutputThatCannotBeWrittenIsAnError) {
  const auto dir = fresh_dir("stdout_full");
  const auto r = run_frictionlab("simulate " + kScenarios + "sphere-spinning.toml --set run.t_end=0.01 --out " +
                                 dir.string() + " >/dev/full");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "frictionlab: error: writing to standard output failed: No space left on device\n");
  std::filesystem::remove_all(dir);
}

// A frictionless sphere slides for ever (k = 0: no rest, no rolling), so the run is still going
// when the signal comes: it must stop between steps, write its summary and exit 3.
class DynSimulateCommandSignal : public ::testing::TestWithParam<int> {};

TEST_P(DynSimulateCommandSignal, StopsTheRunWithItsSummaryWritten) {
  const auto dir = fresh_dir("signal");
  const auto r = testing::run_frictionlab_signalled(
      "simulate " + kScenarios + "sphere-sliding.toml --set contact.k=0 --set run.t_end=1e5 --set run.output_dt=0.1 "
      "--out " + dir.string(),
      GetParam(), [&] { return std::filesystem::exists(dir / "trajectory.csv"); });
  EXPECT_EQ(r.signal, 0) << "killed by the signal instead of stopping";
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"), nullptr, false);
  ASSERT_FALSE(summary.is_discarded()) << slurp(dir / "summary.json");
  EXPECT_EQ(summary["termination"]["reason"], "interrupted");
  EXPECT_LT(summary["final_time"].get<double>(), 1e5);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Signals, DynSimulateCommandSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& p) {
                           return p.param == SIGINT ? "SIGINT" : p.param == SIGTERM ? "SIGTERM" : "SIGHUP";
                         });

}  // namespace
}  // namespace frictionlab
