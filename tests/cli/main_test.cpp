// What every subcommand of `frictionlab` shares (dynamics/cli/main.cpp): errors are one line
// `frictionlab: error: ...` with exit code 1, --help prints help with exit code 0, and output that
// cannot be written is an error.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace {

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

}  // namespace
}  // namespace frictionlab::testing
