#include "dynamics/puck/puck_trajectory_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "dynamics/puck/puck_state.h"
#include "friction/batch.h"

namespace frictionlab::dynamics::puck {
namespace puck_trajectory_csv_test {

namespace fs = std::filesystem;

// The `ratio` field of the row written for a contact with slip speed U and spin Omega (a = 0.05 m).
std::string ratio_written(double U, double Omega, Holds holds = {}) {
  const fs::path file = fs::path(::testing::TempDir()) / "puck_trajectory_csv_ratio.csv";
  {
    PuckTrajectoryCsv csv(file, 0.05);
    const PuckState x = make_puck_state({0.0, 0.0}, 0.0, {U, 0.0}, Omega);
    PuckContact c;
    c.e1 = {1.0, 0.0};
    c.U = U;
    c.Omega = Omega;
    c.force = {0.0, 0.0};
    csv.sample(PuckSample{0.0, x, c, 0.0, 0.0, holds});
    csv.close();
  }
  std::ifstream in(file);
  const std::string text(std::istreambuf_iterator<char>(in), {});
  fs::remove(file);
  const std::string header = text.substr(0, text.find('\n'));
  const std::string row = text.substr(header.size() + 1, text.size() - header.size() - 2);
  const auto names = friction::split_csv_line(header);
  const auto fields = friction::split_csv_line(row);
  EXPECT_EQ(names.size(), fields.size());
  for (std::size_t i = 0; i < names.size() && i < fields.size(); ++i)
    if (names[i] == "ratio") return std::string(fields[i]);
  ADD_FAILURE() << "no ratio column in " << header;
  return "";
}

TEST(DynPuckTrajectoryCsv, TheRatioIsTheSlipRatioWhereTheSpinGoesOn) {
  // ratio = U/(a |Omega|) (docs/puck.md §2), for either sign of the spin, 0 once the slip is held.
  EXPECT_EQ(ratio_written(0.5, 20.0), "0.5");
  EXPECT_EQ(ratio_written(0.5, -20.0), "0.5");
  EXPECT_EQ(ratio_written(0.0, 3.0, {true, false}), "0");
}

TEST(DynPuckTrajectoryCsv, TheRatioIsNanWhereThereIsNoSpin) {
  // Omega = 0 (the spin held, or a puck launched without spin; at rest both are 0): the ratio is
  // not defined there. nan, not inf: a gap in a plot, as docs/puck.md §2 says.
  EXPECT_EQ(ratio_written(0.5, 0.0, {false, true}), "nan");
  EXPECT_EQ(ratio_written(0.0, 0.0, {true, true}), "nan");
}

}  // namespace
}  // namespace frictionlab::dynamics::puck
