// `frictionlab paper`, run as a user runs it: option errors, and a tiny job writing every file.

#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "friction/support/folder_lock.h"
#include "tests/cli/cli_runner.h"

namespace frictionlab {
namespace paper_command_test {

using testing::run_frictionlab;
using testing::slurp;

std::filesystem::path fresh_dir(const std::string& name) { return testing::fresh_temp_dir("paper_" + name); }

// Case (c) of the homogeneous egg for 0.2 s with the exact and the printed law (which stops at its
// pole after 0.041 s) and the baseline: three runs, well under a second.
std::string tiny_job(const std::filesystem::path& dir, const std::string& extra = "") {
  return "paper --out " + dir.string() +
         " --eggs egg-homogeneous --cases c --laws exact,pade-printed --jobs 2 --no-figures --set run.t_end=0.2" +
         (extra.empty() ? "" : " " + extra);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

long json_integer(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": ([0-9]+)"))) return -1;
  return std::stol(m[1]);
}

// behaviour.csv by run label, without the wall-time column (the one number a rerun changes).
std::map<std::string, std::string> behaviour_rows(const std::filesystem::path& dir) {
  const auto lines = lines_of(slurp(dir / "behaviour.csv"));
  std::map<std::string, std::string> out;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<std::string> cells;
    std::stringstream row(lines[i]);
    for (std::string c; std::getline(row, c, ',');) cells.push_back(c);
    if (cells.size() < 12) continue;
    const std::string label = cells[3];
    cells.erase(cells.begin() + 11);  // wall_time_s
    std::string rest;
    for (const auto& c : cells) rest += c + ",";
    out[label] = rest;
  }
  return out;
}

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
  // The error along the motion: pade-printed shadowed along the exact run, the two figures, the table.
  EXPECT_TRUE(std::filesystem::exists(dir / "runs" / "egg-homogeneous-c" / "exact" / "shadow.csv"));
  for (const std::string f : {"shadow-egg-homogeneous-c", "divergence-egg-homogeneous-c"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "plots" / (f + ".gp"))) << f;
    if (have_gnuplot) {
      EXPECT_GT(std::filesystem::file_size(dir / "plots" / (f + ".png")), 0u) << f;
    }
  }
  const std::string report = slurp(dir / "experiments.md");
  EXPECT_NE(report.find("## The error along the motion"), std::string::npos);
  EXPECT_NE(report.find("| `pade-printed` |"), std::string::npos) << report;
  EXPECT_EQ(report.find("-0 "), std::string::npos);
  EXPECT_NE(report.find("## Trajectory error against `exact`"), std::string::npos);
  EXPECT_NE(report.find("egg-homogeneous-c/pade-printed: law-pole"), std::string::npos);
  EXPECT_NE(slurp(dir / "runs/egg-homogeneous-c/pade-printed/summary.json").find("\"reason\": \"law-pole\""),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

// The default output is small: trajectory.csv keeps every 50th sample (0.5 s) and the last one;
// --full-trajectories keeps every sample.
TEST(PaperCommand, TrajectoriesAreThinnedUnlessAskedForInFull) {
  for (const bool full : {false, true}) {
    const auto dir = fresh_dir(full ? "full" : "thin");
    const auto r = run_frictionlab(tiny_job(dir, std::string("--set run.t_end=0.7") + (full ? " --full-trajectories" : "")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto run = dir / "runs" / "egg-homogeneous-c" / "exact";
    const long samples = json_integer(slurp(run / "summary.json"), "trajectory_rows");
    ASSERT_EQ(samples, 71);  // t = 0, 0.01, ..., 0.7 (the final time is one of them)
    const auto rows = lines_of(slurp(run / "trajectory.csv"));
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows.front().rfind("t,gamma1", 0), 0u);
    EXPECT_EQ(static_cast<long>(rows.size()) - 1, full ? samples : 3) << (full ? "full" : "thinned");  // 0, 0.5, 0.7
    if (!full) {
      EXPECT_EQ(rows[2].rfind("0.5,", 0), 0u) << rows[2];
      EXPECT_EQ(rows[3].rfind("0.7", 0), 0u) << rows[3];
      // The printed law's run stops at 0.0413 s, between two kept samples: its last row is kept.
      const auto stopped = lines_of(slurp(dir / "runs" / "egg-homogeneous-c" / "pade-printed" / "trajectory.csv"));
      ASSERT_EQ(stopped.size(), 3u);
      EXPECT_EQ(stopped[2].rfind("0.0413", 0), 0u) << stopped[2];
    }
    EXPECT_NE(slurp(run / "features.json").find("\"every_nth_sample\": " + std::string(full ? "1" : "50")),
              std::string::npos);
    std::filesystem::remove_all(dir);
  }
}

// --resume keeps each run whose summary is complete and whose resolved scenario is what the plan
// would run, and redoes the others: an interrupted run, and every run of a changed scenario.
TEST(PaperCommand, ResumeKeepsCompleteRunsAndRedoesTheRest) {
  const auto dir = fresh_dir("resume");
  ASSERT_EQ(run_frictionlab(tiny_job(dir)).exit_code, 0);
  const auto first = behaviour_rows(dir);
  ASSERT_EQ(first.size(), 3u);
  const std::string first_comparison = slurp(dir / "comparison.csv");

  // Mark the baseline as interrupted, as a Ctrl-C during the run would have left it.
  const auto baseline_summary = dir / "runs" / "egg-homogeneous-c" / "exact-tol1e-10" / "summary.json";
  std::string json = slurp(baseline_summary);
  json = std::regex_replace(json, std::regex("\"reason\": \"[a-z_-]+\""), "\"reason\": \"interrupted\"");
  std::ofstream(baseline_summary) << json;
  const auto exact_csv = dir / "runs" / "egg-homogeneous-c" / "exact" / "trajectory.csv";
  const auto exact_written = std::filesystem::last_write_time(exact_csv);

  const auto r = run_frictionlab(tiny_job(dir, "--resume"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("kept  egg-homogeneous-c/exact:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("kept  egg-homogeneous-c/pade-printed: law-pole"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("redo  egg-homogeneous-c/exact-tol1e-10: it was interrupted"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("done  egg-homogeneous-c/exact-tol1e-10: t_end"), std::string::npos) << r.err;
  EXPECT_EQ(std::filesystem::last_write_time(exact_csv), exact_written) << "a kept run is not rewritten";
  // The kept runs give the report they gave: every number but the redone run's wall time.
  EXPECT_EQ(behaviour_rows(dir), first);
  const auto comparison = lines_of(slurp(dir / "comparison.csv"));
  const auto first_lines = lines_of(first_comparison);
  ASSERT_EQ(comparison.size(), first_lines.size());
  EXPECT_EQ(comparison[1], first_lines[1]);  // pade-printed against exact: both kept
  EXPECT_NE(slurp(dir / "experiments.md").find("kept from an earlier job"), std::string::npos);

  // Another end time: another scenario for every run, so nothing is kept.
  const auto again = run_frictionlab(tiny_job(dir, "--resume --set run.t_end=0.25"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.err.find("kept "), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("redo  egg-homogeneous-c/exact: its scenario changed"), std::string::npos) << again.err;
  std::filesystem::remove_all(dir);
}

// Ctrl-C stops the job; its report and its summary line say so at the top.
TEST(PaperCommand, AnInterruptedJobSaysSoInItsReportAndSummaryLine) {
  const auto dir = fresh_dir("interrupted");
  const auto started = dir / "runs" / "egg-homogeneous-c" / "exact" / "scenario.toml";
  const auto r = testing::run_frictionlab_signalled(
      "paper --out " + dir.string() + " --eggs egg-homogeneous --cases c --laws exact --jobs 1 --no-figures",
      SIGINT, [&] { return std::filesystem::exists(started); });
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(r.out.rfind("paper: INTERRUPTED: ", 0), 0u) << r.out;
  const std::string report = slurp(dir / "experiments.md");
  EXPECT_EQ(report.rfind("> **INTERRUPTED**", 0), 0u) << report.substr(0, 300);
  EXPECT_NE(report.find("--resume"), std::string::npos);
  EXPECT_NE(slurp(dir / "behaviour.csv").find(",interrupted,"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Two jobs on one folder (two --resume) both redid the same runs: a job holds its folder
// (support/folder_lock.h), and a second one is one line naming the folder and the holder.
TEST(PaperCommand, AFolderInUseByAnotherJobIsRefusedNamingTheHolder) {
  const auto dir = fresh_dir("in_use");
  const support::FolderLock held(dir);  // this process stands for the other job
  const auto r = run_frictionlab(tiny_job(dir, "--resume"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "frictionlab: error: --out " + dir.string() + " is in use by another frictionlab job (pid " +
                       std::to_string(::getpid()) + "; " + (dir / ".frictionlab.lock").string() +
                       "): wait for it to end, or choose another --out\n");
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "runs")) << "nothing ran";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab
