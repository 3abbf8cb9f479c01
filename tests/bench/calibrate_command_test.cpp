// `frictionlab calibrate`, run as a user runs it: a tiny study writes its files; bad options give
// one error line and a non-zero exit.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace {

std::filesystem::path temp_out(const char* tag) {
  return std::filesystem::temp_directory_path() /
         (std::string("frictionlab_calibrate_cmd_") + tag + "_" + std::to_string(::getpid()));
}

TEST(CalibrateCommand, TinyStudyWritesTheFiles) {
  const auto out = temp_out("ok");
  const auto r = run_frictionlab("calibrate --out " + out.string() +
                                 " --laws decoupled --s-points 5 --mu-points 2 --psi-points 3 --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");  // progress goes to stderr
  for (const char* f : {"calibration.csv", "scan.csv", "curves.csv", "calibration_tables.md",
                        "plots/calibration_scan.gp", "plots/calibration_forces.gp"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  std::filesystem::remove_all(out);
}

TEST(CalibrateCommand, LegendsShowLawSpecsAsTheyAre) {
  // The forces figure names each engine law by its spec, decoupled:r_spin=...: escaped for
  // gnuplot's enhanced text, where '_' would make "spin=..." a subscript (support::gnuplot_text).
  const auto out = temp_out("legend");
  const auto r = run_frictionlab("calibrate --out " + out.string() +
                                 " --laws decoupled --s-points 5 --mu-points 2 --psi-points 3 --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out / "plots" / "calibration_forces.gp");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::filesystem::remove_all(out);
  EXPECT_NE(text.find("title 'decoupled:r\\_spin="), std::string::npos) << text;
  EXPECT_EQ(text.find("r_spin"), std::string::npos) << text;
  EXPECT_EQ(text.find("noenhanced"), std::string::npos) << text;
}

TEST(CalibrateCommand, BadOptionsGiveOneLineAndNonZeroExit) {
  const std::string out = " --out " + temp_out("bad").string();
  for (const auto& [args, fragment] :
       {std::pair<std::string, std::string>{"calibrate" + out + " --laws nope", "unknown engine law 'nope'"},
        {"calibrate" + out + " --pressures gaussian", "pressure model 'gaussian'"},
        {"calibrate" + out + " --s-points 1", "s points = 1 is invalid"}}) {
    const auto r = run_frictionlab(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace frictionlab::testing
