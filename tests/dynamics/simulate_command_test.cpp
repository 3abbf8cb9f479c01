// `frictionlab simulate`, run as a user runs it.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

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
  const std::string json = slurp(dir / "summary.json");
  EXPECT_NE(json.find("\"reason\": \"t_end\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"overrides\": [\"run.t_end=0.2\", \"run.output_dt=0.05\", \"contact.law=exact\"]"),
            std::string::npos)
      << json;
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

}  // namespace
}  // namespace frictionlab
