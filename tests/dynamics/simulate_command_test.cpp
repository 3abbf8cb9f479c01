// `frictionlab simulate`, run as a user runs it.

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace frictionlab {
namespace {

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
