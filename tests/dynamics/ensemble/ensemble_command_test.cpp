// `frictionlab ensemble`, run as a user runs it: the same table whatever the number of threads,
// --resume after a kill redoing nothing finished, a changed study refused, failing runs recorded,
// and one-line errors for bad studies and folders.

#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "friction/support/folder_lock.h"
#include "tests/cli/cli_runner.h"
#include "tests/dynamics/ensemble/runs_csv_reader.h"

namespace frictionlab {
namespace ensemble_command_test {

namespace fs = std::filesystem;
using testing::run_frictionlab;
using testing::runs_without_wall_time;
using testing::slurp;

const fs::path kStudies = fs::path(FRICTIONLAB_SOURCE_DIR) / "data" / "studies";
const std::string kSmoke = (kStudies / "smoke.toml").string();

fs::path fresh_dir(const std::string& name) { return testing::fresh_temp_dir("ensemble_" + name); }

long count(const std::string& s, char c) { return std::count(s.begin(), s.end(), c); }

// A study file of `text` in `dir` whose scenario paths point at the shipped scenarios.
fs::path write_study(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << "scenario = \"" << (kStudies / "../scenarios/egg-printed-a.toml").string() << "\"\n" << text;
  return p;
}

TEST(EnsembleCommand, SmokeStudyGivesTheSameRunsWithOneThreadAndWithAll) {
  const fs::path one = fresh_dir("one");
  const fs::path all = fresh_dir("all");
  const auto r1 = run_frictionlab("ensemble " + kSmoke + " --out " + one.string() + " --threads 1");
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  EXPECT_NE(r1.out.find("ensemble: 8 of 8 runs done"), std::string::npos) << r1.out;
  const auto r2 = run_frictionlab("ensemble " + kSmoke + " --out " + all.string() + " --threads 0 --no-figures");
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  const auto a = runs_without_wall_time(one / "runs.csv");
  ASSERT_EQ(a.size(), 9u) << "a header and 8 runs";
  EXPECT_EQ(runs_without_wall_time(all / "runs.csv"), a);
  EXPECT_TRUE(fs::exists(all / "figures" / "map-changes.gp"));
  EXPECT_FALSE(fs::exists(all / "figures" / "map-changes.png")) << "--no-figures: scripts, no gnuplot";
  // Sorted by run index once complete; every law ran on every replica of every start.
  for (std::size_t i = 1; i < a.size(); ++i) EXPECT_EQ(a[i].substr(0, a[i].find(',')), std::to_string(i - 1));
  EXPECT_TRUE(fs::exists(one / "ensemble.json"));
  // The report, and the maps of its two varied keys (drawn when gnuplot is there).
  const std::string report = slurp(one / "report.md");
  EXPECT_NE(report.find("## Does the law change the motion?"), std::string::npos) << report;
  EXPECT_NE(report.find("## Maps over"), std::string::npos) << report;
  EXPECT_TRUE(fs::exists(one / "figures" / "map-changes.gp"));
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    EXPECT_GT(fs::file_size(one / "figures" / "map-changes.png"), 0u) << r1.err;
  }
  fs::remove_all(one);
  fs::remove_all(all);
}

TEST(EnsembleCommand, ResumeAfterACutTableRedoesOnlyTheMissingRuns) {
  const fs::path full = fresh_dir("full");
  const fs::path cut = fresh_dir("cut");
  ASSERT_EQ(run_frictionlab("ensemble " + kSmoke + " --out " + full.string() + " --threads 1").exit_code, 0);
  fs::copy(full, cut, fs::copy_options::recursive);
  // A job killed mid-write: the header, three whole rows (in the order runs finished: here
  // 0, 1, 2 of the sorted table, i.e. start 0 with both replicas' exact and one pade-printed),
  // and half of the fourth.
  const std::string text = slurp(full / "runs.csv");
  std::size_t pos = 0;
  for (int line = 0; line < 4; ++line) pos = text.find('\n', pos) + 1;
  const std::size_t half = pos + (text.find('\n', pos) - pos) / 2;
  { std::ofstream(cut / "runs.csv", std::ios::binary | std::ios::trunc) << text.substr(0, half); }
  const auto kept = testing::rows_by_run(full / "runs.csv");

  const auto r = run_frictionlab("ensemble " + kSmoke + " --out " + cut.string() + " --threads 1 --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("8 of 8 runs done (5 this session"), std::string::npos) << r.out;
  EXPECT_EQ(runs_without_wall_time(cut / "runs.csv"), runs_without_wall_time(full / "runs.csv"));
  // The three finished rows were not redone: their wall times are the first job's, byte for byte.
  const auto after = testing::rows_by_run(cut / "runs.csv");
  for (long run = 0; run < 3; ++run) EXPECT_EQ(after.at(run), kept.at(run)) << run;

  // Resuming a complete folder runs nothing.
  const auto again = run_frictionlab("ensemble " + kSmoke + " --out " + cut.string() + " --resume");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("8 of 8 runs done (0 this session"), std::string::npos) << again.out;
  fs::remove_all(full);
  fs::remove_all(cut);
}

TEST(EnsembleCommand, ResumeAfterSigkillGivesTheUninterruptedTable) {
  // Runs of 6 s of motion (~0.1 s of wall time each): the job is killed once two rows are in.
  const fs::path dir = fresh_dir("kill");
  const fs::path study = write_study(dir, "study.toml", R"(laws = ["exact", "pade-reconstructed"]
set = ["run.t_end=6", "run.output_dt=0.01"]
[[vary]]
key = "initial.gamma3"
values = [0.97, 0.9, 0.8]
[replicas]
count = 2
size = 1e-6
)");
  const fs::path killed = dir / "killed";
  const auto rows = [&] {
    std::error_code ec;
    if (!fs::exists(killed / "runs.csv", ec)) return 0L;
    return count(slurp(killed / "runs.csv"), '\n') - 1;
  };
  const auto r = testing::run_frictionlab_signalled(
      "ensemble " + study.string() + " --out " + killed.string() + " --threads 1", SIGKILL, [&] { return rows() >= 2; });
  ASSERT_EQ(r.signal, SIGKILL) << "the job ended before it could be killed: " << r.err;
  const long before = rows();
  ASSERT_GE(before, 2);
  ASSERT_LT(before, 12) << "killed too late to test anything";
  const auto kept = testing::rows_by_run(killed / "runs.csv");

  const auto resumed = run_frictionlab("ensemble " + study.string() + " --out " + killed.string() + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("(" + std::to_string(12 - kept.size()) + " this session"), std::string::npos)
      << resumed.out << " after " << kept.size() << " rows";
  const fs::path clean = dir / "clean";
  ASSERT_EQ(run_frictionlab("ensemble " + study.string() + " --out " + clean.string()).exit_code, 0);
  EXPECT_EQ(runs_without_wall_time(killed / "runs.csv"), runs_without_wall_time(clean / "runs.csv"));
  const auto after = testing::rows_by_run(killed / "runs.csv");
  for (const auto& [run, row] : kept) EXPECT_EQ(after.at(run), row) << "run " << run << " was redone";
  fs::remove_all(dir);
}

TEST(EnsembleCommand, AChangedStudyOrAnExistingTableIsRefused) {
  const fs::path dir = fresh_dir("changed");
  ASSERT_EQ(run_frictionlab("ensemble " + kSmoke + " --out " + (dir / "out").string()).exit_code, 0);
  const auto before = slurp(dir / "out" / "runs.csv");
  const auto again = run_frictionlab("ensemble " + kSmoke + " --out " + (dir / "out").string());
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("runs.csv exists: add --resume"), std::string::npos) << again.err;
  // The same study with another seed (its replicas differ): resuming it would mix two ensembles.
  std::string text = slurp(kStudies / "smoke.toml");
  text.replace(text.find("seed = 1"), 8, "seed = 2");
  fs::create_directories(dir);
  const fs::path changed = kStudies.parent_path() / ("smoke-changed-" + std::to_string(::getpid()) + ".toml");
  // Written beside the shipped study so that its relative scenario path still resolves.
  const fs::path study = kStudies / changed.filename();
  { std::ofstream(study) << text; }
  const auto r = run_frictionlab("ensemble " + study.string() + " --out " + (dir / "out").string() + " --resume");
  fs::remove(study);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("holds the runs of another study"), std::string::npos) << r.err;
  EXPECT_EQ(count(r.err, '\n'), 1) << r.err;
  EXPECT_EQ(slurp(dir / "out" / "runs.csv"), before) << "the folder was left as it was";
  fs::remove_all(dir);
}

TEST(EnsembleCommand, ARunThatFailsIsRecordedAndTheOthersGoOn) {
  // run.max_step = 1e-3 s with run.max_steps = 1000 reaches only 1 s: the start with t_end = 2 s
  // is an invalid scenario (each key alone is valid at its extremes, so the plan accepts it).
  const fs::path dir = fresh_dir("fail");
  const fs::path study = write_study(dir, "study.toml", R"(laws = ["exact"]
set = ["run.max_steps=1000", "run.output_dt=0.01"]
[[vary]]
key = "run.max_step"
values = [0, 1e-3]
[[vary]]
key = "run.t_end"
values = [0.05, 2]
)");
  const auto r = run_frictionlab("ensemble " + study.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("4 of 4 runs done (4 this session: 1 failed"), std::string::npos) << r.out;
  const std::string runs = slurp(dir / "out" / "runs.csv");
  EXPECT_NE(runs.find("3,3,0,exact,0.001,2,failed,failed,"), std::string::npos) << runs;
  EXPECT_NE(runs.find("run.max_step"), std::string::npos) << "the reason is recorded: " << runs;
  fs::remove_all(dir);
}

TEST(EnsembleCommand, Hdf5TrajectoriesAreWrittenWhenAskedAndOnlyThen) {
  const fs::path dir = fresh_dir("hdf5");
  const auto r = run_frictionlab("ensemble " + kSmoke + " --out " + dir.string() + " --hdf5 --no-figures");
#ifdef FRICTIONLAB_ENSEMBLE_HDF5
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(fs::file_size(dir / "trajectories.h5"), 8u * 1000u) << "8 runs of about 11 rows each";
#else
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--hdf5 is not available"), std::string::npos) << r.err;
#endif
  const fs::path without = fresh_dir("no_hdf5");
  ASSERT_EQ(run_frictionlab("ensemble " + kSmoke + " --out " + without.string() + " --no-figures").exit_code, 0);
  EXPECT_FALSE(fs::exists(without / "trajectories.h5"));
  fs::remove_all(dir);
  fs::remove_all(without);
}

TEST(EnsembleCommand, BadStudiesAndOptionsAreOneLineAndWriteNothing) {
  const fs::path dir = fresh_dir("bad");
  const fs::path bad_key = write_study(dir, "bad_key.toml", "laws = [\"exact\"]\n[[vary]]\nkey = \"contact.kk\"\nvalues = [1]\n");
  const fs::path bad_law = write_study(dir, "bad_law.toml", "laws = [\"exact\", \"pade\"]\n");
  const fs::path bad_toml = write_study(dir, "bad_toml.toml", "laws = [\"exact\"\n");
  const fs::path out = dir / "out";
  for (const std::string& args : {bad_key.string(), bad_law.string(), bad_toml.string(), (dir / "missing.toml").string(),
                                  dir.string(), kSmoke + " --threads -1"}) {
    const auto r = run_frictionlab("ensemble " + args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(count(r.err, '\n'), 1) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(out)) << args << ": nothing may be written on bad input";
  }
  fs::remove_all(dir);
}

// A read that fails (EIO) was taken for an empty study; the error says the read failed.
TEST(EnsembleCommand, AFailedReadOfTheStudyIsReportedAsSuch) {
  const fs::path dir = fresh_dir("eio");
  const auto r = run_frictionlab("ensemble /proc/self/mem --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "frictionlab: error: reading study file '/proc/self/mem' failed: Input/output error\n");
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The shipped studies are found by name from any folder (dynamics/io/shipped_data.h).
TEST(EnsembleCommand, AShippedStudyIsFoundByName) {
  const fs::path dir = fresh_dir("by_name");
  fs::create_directories(dir);
  const auto r = run_frictionlab("ensemble smoke --out out --no-figures", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("8 of 8 runs done"), std::string::npos) << r.out;
  EXPECT_NE(slurp(dir / "out" / "ensemble.json").find("\"study\": \"smoke\""), std::string::npos);
  const auto missing = run_frictionlab("ensemble no-such-study --out out2", dir);
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err.rfind("frictionlab: error: study 'no-such-study' not found: no file 'no-such-study' here, and "
                              "no no-such-study or no-such-study.toml in data/studies, ",
                              0),
            0u)
      << missing.err;
  fs::remove_all(dir);
}

// Two --resume jobs on one folder both redid the runs it lacked: the folder is held by its job
// (support/folder_lock.h), and a second job is one line naming the folder and the holder's pid.
TEST(EnsembleCommand, AFolderInUseByAnotherJobIsRefusedNamingTheHolder) {
  const fs::path dir = fresh_dir("in_use");
  const support::FolderLock held(dir / "out");  // this process stands for the other job
  const auto r = run_frictionlab("ensemble " + kSmoke + " --out " + (dir / "out").string() + " --resume");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "frictionlab: error: --out " + (dir / "out").string() +
                       " is in use by another frictionlab job (pid " + std::to_string(::getpid()) + "; " +
                       (dir / "out" / ".frictionlab.lock").string() + "): wait for it to end, or choose another --out\n");
  EXPECT_FALSE(fs::exists(dir / "out" / "runs.csv"));
  fs::remove_all(dir);
}

// SIGTERM (kill, a batch system's end of allocation) stops the job like Ctrl-C, with one line
// saying so, what is kept and how to go on; while it runs, a second job on its folder is refused
// naming it; --resume then finishes the study without redoing a kept run, and no lock file stays.
TEST(EnsembleCommand, SigtermSaysWhatIsKeptAndResumeFinishes) {
  const fs::path dir = fresh_dir("sigterm");
  const fs::path study = write_study(dir, "study.toml", R"(laws = ["exact", "pade-reconstructed"]
set = ["run.t_end=6", "run.output_dt=0.01"]
[[vary]]
key = "initial.gamma3"
values = [0.97, 0.9, 0.8]
[replicas]
count = 4
size = 1e-6
)");
  const fs::path out = dir / "out";
  const auto rows = [&] {
    std::error_code ec;
    if (!fs::exists(out / "runs.csv", ec)) return 0L;
    return count(slurp(out / "runs.csv"), '\n') - 1;
  };
  testing::CommandResult second;
  std::string holder;
  const auto r = testing::run_frictionlab_signalled(
      "ensemble " + study.string() + " --out " + out.string() + " --threads 1", SIGTERM, [&] {
        if (rows() < 1) return false;
        holder = slurp(out / ".frictionlab.lock");
        second = run_frictionlab("ensemble " + study.string() + " --out " + out.string() + " --resume");
        return true;
      });
  EXPECT_EQ(second.exit_code, 1) << second.err;
  ASSERT_FALSE(holder.empty());
  EXPECT_NE(second.err.find("is in use by another frictionlab job (pid " + holder.substr(0, holder.size() - 1) + ";"),
            std::string::npos)
      << second.err;
  ASSERT_EQ(r.exit_code, 3) << "the job ended before the signal, or died of it: " << r.err;
  const long kept = rows();
  ASSERT_LT(kept, 24) << "stopped too late to test anything";
  const std::string line = "frictionlab: ensemble: stopped by SIGTERM; " + std::to_string(kept) + " runs are kept in " +
                           (out / "runs.csv").string() + ", " + std::to_string(24 - kept) +
                           " remain: add --resume to continue\n";
  EXPECT_EQ(r.err.substr(r.err.size() - std::min(r.err.size(), line.size())), line) << r.err;
  EXPECT_EQ(r.err.find("frictionlab:"), r.err.rfind("frictionlab:")) << "one line of frictionlab's own: " << r.err;
  EXPECT_FALSE(fs::exists(out / ".frictionlab.lock"));

  const auto before = testing::rows_by_run(out / "runs.csv");
  const auto resumed = run_frictionlab("ensemble " + study.string() + " --out " + out.string() + " --resume --no-figures");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("24 of 24 runs done (" + std::to_string(24 - kept) + " this session"), std::string::npos)
      << resumed.out;
  const auto after = testing::rows_by_run(out / "runs.csv");
  for (const auto& [run, row] : before) EXPECT_EQ(after.at(run), row) << "run " << run << " was redone";
  EXPECT_FALSE(fs::exists(out / ".frictionlab.lock"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab
