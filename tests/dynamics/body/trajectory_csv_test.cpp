// The trajectory writer (dynamics/body/trajectory_csv.h): the documented columns, whole rows, and a
// failed write reported to the simulation as OutputFailure.

#include "dynamics/body/trajectory_csv.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace frictionlab::dynamics {
namespace trajectory_csv_test {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct SampleData {
  StateVector x = make_state(Eigen::Vector3d(1.5, 0, 0), Eigen::Vector3d(0, 0, 20), Eigen::Vector3d::UnitZ(), -1e-4);
  ContactState c{};
  Sample at(double t) const { return Sample{t, x, c, 2.0, 1.0}; }
};

TEST(DynTrajectoryCsv, AZeroIsWrittenWithoutItsSign) {
  // Pure spin: the exact law's F1 comes out as -0.0 (arithmetic residue), and gamma2, v2 may too.
  // The file writes "0" (no "-0" in a table), and trajectory_row, which the Python module's
  // columns take, holds what the file reads back: +0.0.
  const auto file = std::filesystem::temp_directory_path() / ("frictionlab_csv_zero_" + std::to_string(::getpid()) + ".csv");
  SampleData d;
  d.x = make_state(Eigen::Vector3d(0, -0.0, 0), Eigen::Vector3d(0, 0, 20), Eigen::Vector3d(0, -0.0, 1), -1e-4);
  d.c.gamma = Eigen::Vector3d(0, -0.0, 1);
  d.c.N = 9.81;
  d.c.Omega = 20;
  d.c.friction = {-0.0, -0.0, 0.003};
  d.c.in_contact = true;
  {
    TrajectoryCsv csv(file);
    csv.sample(d.at(-0.0));
    csv.close();
  }
  const std::string text = slurp(file);
  const std::string row = text.substr(text.find('\n') + 1);
  EXPECT_EQ(("," + row).find(",-0,"), std::string::npos) << row;
  EXPECT_EQ(row.rfind("0,0,0,1,", 0), 0u) << row;  // t, gamma1, gamma2, gamma3
  for (const double x : trajectory_row(d.at(-0.0))) EXPECT_FALSE(x == 0.0 && std::signbit(x)) << row;
  std::filesystem::remove(file);
}

TEST(DynTrajectoryCsv, WritesTheHeaderAndOneWholeRowPerSample) {
  const auto file = std::filesystem::temp_directory_path() / ("frictionlab_csv_" + std::to_string(::getpid()) + ".csv");
  SampleData d;
  d.c.gamma = Eigen::Vector3d::UnitZ();
  d.c.N = 9.81;
  d.c.in_contact = true;
  {
    TrajectoryCsv csv(file);
    csv.sample(d.at(0.0));
    csv.sample(d.at(0.1));
    csv.close();
    EXPECT_EQ(csv.rows(), 2);
  }
  const std::string text = slurp(file);
  std::string header;
  for (const auto c : kTrajectoryColumns) header += (header.empty() ? "" : ",") + std::string(c);
  ASSERT_EQ(text.substr(0, header.size() + 1), header + "\n");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
  // The last row, read back field by field: t, gamma, omega, v, eps, N, ..., energy, kinetic, ...
  const std::string last = text.substr(text.rfind('\n', text.size() - 2) + 1);
  std::vector<double> fields;
  std::istringstream row(last);
  for (std::string f; std::getline(row, f, ',');) fields.push_back(std::strtod(f.c_str(), nullptr));
  ASSERT_EQ(fields.size(), kTrajectoryColumns.size()) << last;
  const std::vector<double> expected_head = {0.1, 0, 0, 1, 0, 0, 20, 1.5, 0, 0, -1e-4, 9.81};
  for (std::size_t i = 0; i < expected_head.size(); ++i) EXPECT_EQ(fields[i], expected_head[i]) << kTrajectoryColumns[i];
  EXPECT_EQ(fields[20], 2.0);  // energy
  EXPECT_EQ(fields[21], 1.0);  // kinetic
  EXPECT_EQ(fields[24], 1.0);  // in_contact
  std::filesystem::remove(file);
}

// run.pose = false: the six columns of the pose (x, y, qw, qx, qy, qz) are left out of the header
// and of every row; the other columns keep their order and values.
TEST(DynTrajectoryCsv, WithoutThePoseItsSixColumnsAreLeftOut) {
  const auto file = std::filesystem::temp_directory_path() / ("frictionlab_csv_nopose_" + std::to_string(::getpid()) + ".csv");
  SampleData d;
  d.c.gamma = Eigen::Vector3d::UnitZ();
  d.c.N = 9.81;
  d.c.in_contact = true;
  position(d.x) << 0.25, -0.5;
  {
    TrajectoryCsv csv(file, 0, false);
    csv.sample(d.at(0.1));
    csv.close();
  }
  const std::string text = slurp(file);
  const std::string header = text.substr(0, text.find('\n'));
  EXPECT_EQ(header,
            "t,gamma1,gamma2,gamma3,omega1,omega2,omega3,v1,v2,v3,eps,N,U,Omega,F1,F2,M,a,b,psi,energy,kinetic,"
            "W_slide,W_spin,in_contact,stick,slip_held");
  EXPECT_EQ(header + "\n", trajectory_header(false));
  std::vector<std::string> fields;
  std::istringstream row(text.substr(header.size() + 1));
  for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
  ASSERT_EQ(fields.size(), kTrajectoryColumns.size() - 6);
  EXPECT_EQ(fields[0], "0.1");
  EXPECT_EQ(fields[11], "9.81");     // N
  EXPECT_EQ(fields[24], "1");        // in_contact
  EXPECT_EQ(fields[26], "0\n");      // slip_held, the last
  EXPECT_EQ(text.find("0.25"), std::string::npos);  // no x
  std::filesystem::remove(file);
}

TEST(DynTrajectoryCsv, AFailedWriteIsAnOutputFailure) {
  SampleData d;
  TrajectoryCsv csv("/dev/full");
  bool failed = false;
  for (int i = 0; i < 100000 && !failed; ++i) {
    try {
      csv.sample(d.at(i * 1e-3));
    } catch (const OutputFailure& e) {
      failed = true;
      EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(failed) << "100000 rows written to /dev/full without an error";
  EXPECT_THROW(csv.sample(d.at(1.0)), OutputFailure);  // it stays failed
  EXPECT_THROW(csv.close(), OutputFailure);
}

TEST(DynTrajectoryCsv, ACloseThatFailsIsAnOutputFailure) {
  SampleData d;
  TrajectoryCsv csv("/dev/full");
  csv.sample(d.at(0.0));  // buffered: the failure shows when the file is closed
  EXPECT_THROW(csv.close(), OutputFailure);
}

TEST(DynTrajectoryCsv, AFileThatCannotBeOpenedIsAnError) {
  EXPECT_THROW(TrajectoryCsv("/no/such/folder/trajectory.csv"), std::runtime_error);
}

}  // namespace
}  // namespace frictionlab::dynamics
