#include "dynamics/io/run_folder.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "dynamics/body/equations_of_motion.h"  // the body's Sample and Observer
#include "friction/support/checked_output.h"

namespace frictionlab::dynamics {
namespace run_folder_test {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab-run-folder-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(DynRunFolder, StartCreatesTheFolderWithTheResolvedScenarioHeadedByItsSource) {
  const auto dir = fresh_dir("start") / "nested";
  start_run_folder(dir, "data/scenarios/x.toml\nwith --set run.t_end=1", "[run]\nt_end = 1");
  const std::string text = slurp(dir / "scenario.toml");
  // One header line (the source folded to one line), then the resolved TOML as given.
  EXPECT_EQ(text.find('\n'), text.find("\n[run]"));
  EXPECT_EQ(text.rfind("# data/scenarios/x.toml", 0), 0U) << text;
  EXPECT_NE(text.find("rerun: frictionlab simulate scenario.toml"), std::string::npos);
  EXPECT_NE(text.find("[run]\nt_end = 1\n"), std::string::npos);
  std::filesystem::remove_all(dir.parent_path());
}

TEST(DynRunFolder, StartRefusesAFolderUnderAFileNamingIt) {
  const auto dir = fresh_dir("blocked");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  try {
    start_run_folder(dir / "file" / "run", "s", "");
    FAIL() << "created a folder under a file";
  } catch (const support::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "file" / "run").string()), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(DynRunFolder, SummaryGetsTheOutputRecordErrorNullWhenNone) {
  const auto dir = fresh_dir("summary");
  std::filesystem::create_directories(dir);
  write_run_summary(dir / "a.json", support::Json{{"reason", "t_end"}}, {12, 5400, 100000000, ""});
  const auto a = support::Json::parse(slurp(dir / "a.json"));
  EXPECT_EQ(a["reason"], "t_end");
  EXPECT_EQ(a["output"]["trajectory_rows"], 12);
  EXPECT_EQ(a["output"]["trajectory_bytes"], 5400);
  EXPECT_EQ(a["output"]["max_output_bytes"], 100000000);
  EXPECT_TRUE(a["output"]["error"].is_null());
  write_run_summary(dir / "b.json", support::Json::object(), {3, 0, 1, "disk full"});
  EXPECT_EQ(support::Json::parse(slurp(dir / "b.json"))["output"]["error"], "disk full");
  std::filesystem::remove_all(dir);
}

struct Writer {
  bool fail = false;
  void close() const {
    if (fail) throw OutputFailure("close failed");
  }
};

TEST(DynRunFolder, AFailedCloseIsTheOutputErrorUnlessOneIsRecorded) {
  std::string error;
  Writer ok;
  close_trajectory(ok, error);
  EXPECT_EQ(error, "");
  Writer bad{true};
  close_trajectory(bad, error);
  EXPECT_EQ(error, "close failed");
  error = "the run's own";
  close_trajectory(bad, error);
  EXPECT_EQ(error, "the run's own");
}

struct Counter : Observer {
  int samples = 0, steps = 0, accepted_steps = 0;
  bool wants = false;
  void sample(const Sample&) override { ++samples; }
  void step(double) override { ++steps; }
  void accepted(const Sample&) override { ++accepted_steps; }
  [[nodiscard]] bool wants_accepted_steps() const override { return wants; }
};

TEST(DynRunFolder, TheTeeReportsToEveryObserverAndSkipsNull) {
  Counter a, b;
  const StateVector x = StateVector::Zero();
  const ContactState c{};
  const Sample s{0.0, x, c};
  TeeObserver<Observer, Sample> both({&a, &b});
  both.sample(s);
  both.step(0.1);
  TeeObserver<Observer, Sample> one({&a, nullptr});
  one.sample(s);
  EXPECT_EQ(a.samples, 2);
  EXPECT_EQ(a.steps, 1);
  EXPECT_EQ(b.samples, 1);
  EXPECT_EQ(b.steps, 1);
}

TEST(DynRunFolder, TheTeeHandsAcceptedStepsOnlyToTheObserversThatAskForThem) {
  Counter a, b;
  b.wants = true;
  const StateVector x = StateVector::Zero();
  const ContactState c{};
  const Sample s{0.0, x, c};
  TeeObserver<Observer, Sample> none({&a});
  EXPECT_FALSE(none.wants_accepted_steps());
  TeeObserver<Observer, Sample> both({&a, &b});
  EXPECT_TRUE(both.wants_accepted_steps());
  both.accepted(s);
  EXPECT_EQ(a.accepted_steps, 0);
  EXPECT_EQ(b.accepted_steps, 1);
}

}  // namespace
}  // namespace frictionlab::dynamics
