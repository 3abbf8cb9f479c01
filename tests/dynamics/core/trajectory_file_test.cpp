// The trajectory file every model's writer fills (dynamics/core/trajectory_file.h): the header
// and rows as given, and what the record file's failures become for the run loop: the size limit
// an OutputLimitReached with its hint (the rows before it kept), a failed write or close an
// OutputFailure.

#include "dynamics/core/trajectory_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace frictionlab::dynamics {
namespace trajectory_file_test {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path temporary(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("frictionlab_trajectory_file_" + name + "_" + std::to_string(::getpid()) + ".csv");
}

// What the run's error message adds to the record file's own: which keys to change.
constexpr std::string_view kLimitHint = " (run.max_output_bytes: raise it, or run.output_dt)";

TEST(DynTrajectoryFile, TheHeaderJoinsTheColumnsWithCommasAndEndsTheLine) {
  constexpr std::array<std::string_view, 3> columns = {"t", "x", "held"};
  EXPECT_EQ(trajectory_file_header(columns), "t,x,held\n");
  constexpr std::array<std::string_view, 1> one = {"t"};
  EXPECT_EQ(trajectory_file_header(one), "t\n");
}

TEST(DynTrajectoryFile, WritesTheHeaderThenEachRowAsGiven) {
  const auto file = temporary("rows");
  {
    TrajectoryFile out(file, "t,x\n");
    out.append("0,1.5\n");
    out.append("0.1,-2\n");
    EXPECT_EQ(out.size(), 4u + 6u + 7u);
    out.close();
  }
  EXPECT_EQ(slurp(file), "t,x\n0,1.5\n0.1,-2\n");
  std::filesystem::remove(file);
}

TEST(DynTrajectoryFile, ARowPastTheSizeLimitIsOutputLimitReachedWithTheHintAndTheRowsBeforeItStay) {
  const auto file = temporary("limit");
  // Header 4 bytes + two rows of 4: exactly 12, the limit. The third row would pass it.
  TrajectoryFile out(file, "t,x\n", 12);
  out.append("0,1\n");
  out.append("1,2\n");
  try {
    out.append("2,3\n");
    ADD_FAILURE() << "a row past the limit of 12 bytes was taken";
  } catch (const OutputLimitReached& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("past its limit of 12 bytes"), std::string::npos) << what;
    ASSERT_GE(what.size(), kLimitHint.size());
    EXPECT_EQ(what.substr(what.size() - kLimitHint.size()), kLimitHint) << what;
  }
  EXPECT_EQ(out.size(), 12u);
  EXPECT_NO_THROW(out.close());  // the limit is not a failure: the file closes cleanly
  EXPECT_EQ(slurp(file), "t,x\n0,1\n1,2\n");
  std::filesystem::remove(file);
}

TEST(DynTrajectoryFile, AHeaderPastTheSizeLimitIsRefusedNamingTheKey) {
  const auto file = temporary("header");
  try {
    TrajectoryFile out(file, "t,x\n", 3);
    ADD_FAILURE() << "a header of 4 bytes was taken under a limit of 3";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("run.max_output_bytes"), std::string::npos) << what;
    EXPECT_NE(what.find("header of trajectory.csv (4 bytes)"), std::string::npos) << what;
  }
  std::filesystem::remove(file);
}

TEST(DynTrajectoryFile, AFailedWriteIsAnOutputFailureAndTheFileStaysFailed) {
  TrajectoryFile out("/dev/full", "t,x\n");
  // Rows of 1 KiB fill the record file's buffer (64 KiB) within 100 rows; the write then fails.
  const std::string row = std::string(1023, '1') + "\n";
  bool failed = false;
  for (int i = 0; i < 1000 && !failed; ++i) {
    try {
      out.append(row);
    } catch (const OutputFailure& e) {
      failed = true;
      EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(failed) << "1000 rows of 1 KiB written to /dev/full without an error";
  EXPECT_THROW(out.append("0,1\n"), OutputFailure);
  EXPECT_THROW(out.close(), OutputFailure);
}

TEST(DynTrajectoryFile, ACloseThatFailsIsAnOutputFailure) {
  TrajectoryFile out("/dev/full", "t,x\n");
  out.append("0,1\n");  // buffered: the failure shows when the file is closed
  EXPECT_THROW(out.close(), OutputFailure);
}

}  // namespace
}  // namespace frictionlab::dynamics
