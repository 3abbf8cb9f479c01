// `frictionlab paper`, run as a user runs it: option errors, and a tiny job writing every file.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/cli/cli_runner.h"

namespace frictionlab {
namespace {

using testing::run_frictionlab;
using testing::slurp;

std::filesystem::path fresh_dir(const std::string& name) { return testing::fresh_temp_dir("paper_" + name); }

TEST(PaperCommand, BadOptionsGiveOneLineAndExitOne) {
  const auto dir = fresh_dir("bad");
  for (const std::string& args : {
           std::string("--laws exact,no-such-law"), std::string("--eggs egg-boiled"), std::string("--cases a,a"),
           std::string("--cases a,,b"), std::string("--set run.t_edn=1"), std::string("--jobs -2"),
           std::string("--scenarios /no/such/folder")}) {
    const auto r = run_frictionlab("paper --out " + dir.string() + " " + args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir)) << "nothing may be written on bad input";
}

TEST(PaperCommand, ATinyJobWritesRunsFiguresAndReport) {
  const auto dir = fresh_dir("tiny");
  const bool have_gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  // Case (c) of the homogeneous egg for 0.2 s: the printed Padé law stops at its pole at 0.041 s
  // while the others run on; a stop like that is a result (exit 0), not an error.
  const auto r = run_frictionlab("paper --out " + dir.string() +
                                 " --eggs egg-homogeneous --cases c --laws exact,pade-printed --jobs 2 "
                                 "--set run.t_end=0.2" + (have_gnuplot ? "" : " --no-figures"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("paper: 3 runs (1 stopped early, 0 not run)"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("done  egg-homogeneous-c/pade-printed: law-pole"), std::string::npos) << r.err;

  for (const std::string label : {"exact", "pade-printed", "exact-tol1e-10"}) {
    const auto run = dir / "runs" / "egg-homogeneous-c" / label;
    for (const std::string f : {"trajectory.csv", "summary.json", "scenario.toml", "features.json"})
      EXPECT_TRUE(std::filesystem::exists(run / f)) << (run / f);
    for (const std::string ext : {".full.dat", ".early.dat", ".end.dat"})
      EXPECT_TRUE(std::filesystem::exists(dir / "plots" / "data" / ("egg-homogeneous-c-" + label + ext))) << label << ext;
  }
  for (const std::string f : {"fig2-egg-homogeneous", "fig3-egg-homogeneous-c", "fig3-egg-homogeneous-c-early"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "plots" / (f + ".gp"))) << f;
    if (have_gnuplot) {
      EXPECT_GT(std::filesystem::file_size(dir / "plots" / (f + ".png")), 0u) << f;
    }
  }
  for (const std::string f : {"behaviour.csv", "comparison.csv", "narrative.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  const std::string report = slurp(dir / "experiments.md");
  EXPECT_NE(report.find("## Trajectory error against `exact`"), std::string::npos);
  EXPECT_NE(report.find("egg-homogeneous-c/pade-printed: law-pole"), std::string::npos);
  EXPECT_NE(slurp(dir / "runs/egg-homogeneous-c/pade-printed/summary.json").find("\"reason\": \"law-pole\""),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab
