// What every subcommand of `frictionlab` shares (dynamics/cli/main.cpp): errors are one line
// `frictionlab: error: ...` with exit code 1, --help prints help with exit code 0, and output that
// cannot be written is an error.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace main_test {

long count_lines(const std::string& s) { return std::count(s.begin(), s.end(), '\n'); }

TEST(CliMain, StandardOutputToAFullDeviceIsAnError) {
  const auto r = run_frictionlab("laws >/dev/full");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "frictionlab: error: writing to standard output failed: No space left on device\n");
}

TEST(CliMain, HelpStillPrintsHelpAndExitsZero) {
  for (const std::string args : {"--help", "simulate --help", "paper --help", "accuracy --help", "laws --help"}) {
    const auto r = run_frictionlab(args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << args << ": " << r.out;
    EXPECT_GT(count_lines(r.out), 2) << args;
  }
}

// Every command that writes files says in its --help how much it writes (docs/dynamics.md §6 has
// the measured sizes), so that nobody learns it from a full disk.
TEST(CliMain, EveryCommandThatWritesFilesStatesItsSizeInItsHelp) {
  for (const std::string command : {"simulate", "accuracy", "calibrate", "paper", "tippe-top", "puck-study", "ensemble"}) {
    const auto r = run_frictionlab(command + " --help");
    EXPECT_EQ(r.exit_code, 0) << command << ": " << r.err;
    EXPECT_NE(r.out.find(" MB"), std::string::npos) << command << " --help states no size:\n" << r.out;
  }
}

// Every command-line error, CLI11's own included, is one line `frictionlab: error: ...` and exit 1.
struct CliError {
  std::string args;
  std::string expected;  // a part of the message
};

TEST(CliMain, EveryCommandLineErrorIsOneLineAndExitOne) {
  const std::string never = fresh_temp_dir("cli_never").string();  // no command may create it
  const std::string scenario = std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/sphere-spinning.toml";
  const std::vector<CliError> cases = {
      {"frction", "unknown subcommand 'frction'"},
      {"", "a subcommand is required"},
      {"friction --U abc --Omega 0 --a 1 --b 1 --psi 0 --N 1 --k 0.1", "--U"},
      {"friction --bogus 1", "--bogus"},
      {"simulate " + scenario, "--out is required"},
      {"simulate " + scenario + " extra --out " + never, "extra"},
      {"paper --out " + never + " --jobs abc", "--jobs"},
      {"paper --out " + never + " --jobs -1", "--jobs = -1 is invalid"},
      {"accuracy --out " + never + " --s-points -3", "--s-points"},
      {"accuracy --out " + never + " --mu-points -1", "--mu-points"},
      {"accuracy --out " + never + " --psi-points x", "--psi-points"},
      {"accuracy --out " + never + " --threads -1", "--threads"},
      {"accuracy --out " + never + " --s-points 100000 --mu-points 100000", "grid points"},
      {"laws extra", "extra"},
  };
  for (const auto& c : cases) {
    const auto r = run_frictionlab(c.args);
    EXPECT_EQ(r.exit_code, 1) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << c.args << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args << ": " << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(never));
}

TEST(CliMain, AnUnknownSubcommandListsTheValidOnes) {
  const auto r = run_frictionlab("frction");
  for (const std::string name : {"laws", "friction", "simulate", "accuracy", "paper"})
    EXPECT_NE(r.err.find(name), std::string::npos) << name << " in " << r.err;
  EXPECT_NE(r.err.find("did you mean 'friction'"), std::string::npos) << r.err;
}

// A --set that is wrong is blamed on the --set, not on the file it overrides.
TEST(CliMain, ABadOverrideIsBlamedOnTheOverride) {
  const std::string never = fresh_temp_dir("cli_never_set").string();
  const std::string scenario = std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/sphere-spinning.toml";
  const auto r = run_frictionlab("simulate " + scenario + " --set run.t_end=abc --out " + never);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("frictionlab: error: --set run.t_end=abc: run.t_end must be a number", 0), 0u) << r.err;
  const auto law = run_frictionlab("simulate " + scenario + " --law fast --out " + never);
  EXPECT_EQ(law.exit_code, 1);
  EXPECT_EQ(law.err.rfind("frictionlab: error: --law fast: ", 0), 0u) << law.err;
  EXPECT_FALSE(std::filesystem::exists(never));
}

// Values CLI11 alone clamped (an integer beyond 64 bits became 9223372036854775807: tippe-top
// then ran for ever), read as 0 (1e-400) or ignored (an empty --law ran the scenario's own law)
// are one error line naming the option, the value and the rule, for every command
// (dynamics/cli/option_values.h).
TEST(CliMain, OutOfRangeNumbersAndEmptyValuesAreErrorsNotClampsOrDefaults) {
  const std::string never = fresh_temp_dir("cli_never_values").string();
  const std::string scenario = std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios/sphere-spinning.toml";
  const std::string huge = "99999999999999999999999";
  const std::vector<CliError> cases = {
      {"tippe-top --out " + never + " --max-steps " + huge,
       "--max-steps = '" + huge + "' is invalid: it must be an integer from -9223372036854775808"},
      {"accuracy --out " + never + " --threads " + huge, "--threads = '" + huge + "' is invalid"},
      {"calibrate --out " + never + " --threads " + huge, "--threads = '" + huge + "' is invalid"},
      {"accuracy --out " + never + " --s-points 0x10", "--s-points = '0x10' is invalid: it must be an integer in decimal"},
      {"ensemble " + never + ".toml --out " + never + " --threads 3000000000",
       "--threads = 3000000000 is invalid: it must be from -2147483648 to 2147483647"},
      {"paper --out " + never + " --jobs 3000000000", "--jobs = 3000000000 is invalid"},
      {"friction --U 1 --Omega 0 --a 1 --b 1 --psi 0 --N 1 --k 1e-400", "--k = '1e-400' is invalid: it underflows"},
      {"friction --U 1e400 --Omega 0 --a 1 --b 1 --psi 0 --N 1 --k 1", "--U = '1e400' is invalid: it overflows"},
      {"simulate " + scenario + " --law '' --out " + never, "--law = '' is invalid: it is empty"},
      {"simulate " + scenario + " --out ''", "--out = '' is invalid: it is empty"},
      {"tippe-top --out " + never + " --laws ''", "--laws = '' is invalid: it is empty"},
      {"friction ''", "INPUT = '' is invalid: it is empty"},
  };
  for (const auto& c : cases) {
    const auto r = run_frictionlab(c.args + " </dev/null");
    EXPECT_EQ(r.exit_code, 1) << c.args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << c.args << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args << ": " << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(never));
}

TEST(CliMain, VersionPrintsTheProjectVersion) {
  const auto r = run_frictionlab("--version");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "frictionlab " FRICTIONLAB_PROJECT_VERSION "\n");  // CMake's project(VERSION)
  EXPECT_TRUE(r.err.empty()) << r.err;
}

}  // namespace
}  // namespace frictionlab::testing
