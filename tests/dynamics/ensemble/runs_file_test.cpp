// runs.csv across sessions (dynamics/ensemble/runs_file.h).

#include "dynamics/ensemble/runs_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>


namespace frictionlab::dynamics::ensemble {
namespace runs_file_test {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path fresh_dir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

RunRecord record(long run) {
  RunRecord r;
  r.run = run;
  r.law = "exact";
  r.values = {0.5};
  r.reason = "t_end";
  r.final_class = "tilted";
  r.t_final = 1.0;
  return r;
}

TEST(EnsembleRunsFile, ResumeKeepsWholeRowsAndCutsAPartialOne) {
  const fs::path dir = fresh_dir("runs_file");
  const fs::path file = dir / "runs.csv";
  const std::string header = runs_header({"k"});
  {
    RunsWriter w(file, header, false);
    w.write(record(4));
    w.write(record(1));
    w.close();
  }
  const std::string partial = to_csv_row(record(7)).substr(0, 10);
  { std::ofstream(file, std::ios::app | std::ios::binary) << partial; }
  const ExistingRuns e = read_existing_runs(file, header, 10);
  EXPECT_EQ(e.done, (std::set<long>{1, 4}));
  EXPECT_EQ(e.rows, 2);
  EXPECT_TRUE(e.cut_partial_row);
  EXPECT_EQ(slurp(file), header + to_csv_row(record(4)) + to_csv_row(record(1)));
  {
    RunsWriter w(file, header, true);  // resumed: appends after the kept rows, no second header
    w.write(record(0));
    w.close();
  }
  sort_runs_file(file);
  EXPECT_EQ(slurp(file), header + to_csv_row(record(0)) + to_csv_row(record(1)) + to_csv_row(record(4)));
  fs::remove_all(dir);
}

TEST(EnsembleRunsFile, AnotherStudysTableIsRefused) {
  const fs::path dir = fresh_dir("runs_file_other");
  const fs::path file = dir / "runs.csv";
  {
    RunsWriter w(file, runs_header({"k"}), false);
    w.write(record(3));
  }
  EXPECT_THROW((void)read_existing_runs(file, runs_header({"other"}), 10), std::invalid_argument) << "other columns";
  EXPECT_THROW((void)read_existing_runs(file, runs_header({"k"}), 3), std::invalid_argument) << "run 3 of 3 runs";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
