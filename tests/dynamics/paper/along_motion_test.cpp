// The error along the motion in the paper job (dynamics/paper/along_motion.h): the binned shadow
// errors of figure (a) from a shadow.csv whose medians are known.

#include "dynamics/paper/along_motion.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace frictionlab::dynamics::paper {
namespace along_motion_test {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_along_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::vector<std::string>> rows_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    rows.emplace_back();
    for (std::string w; words >> w;) rows.back().push_back(w);
  }
  return rows;
}

TEST(PaperAlongMotion, TheShadowDataHoldsEachBinsMedianAndHighQuantileOfTheContactStates) {
  const fs::path dir = scratch("bins");
  // kShadowBins bins over t in [0, 400]: one bin per second; samples every 0.25 s. In each bin the
  // law "L,x=1" (quoted: a comma) has |dF1| = 1, 2, 3, 4 (in contact) and the bin's last sample in
  // the air (phase 0, left out); its dM is -dF1 (the median of |dM| is the same).
  std::ofstream csv(dir / "shadow.csv");
  csv << "t,phase,s,b_over_a,a,psi,N,\"dF1[L,x=1]\",\"dF2[L,x=1]\",\"dM[L,x=1]\",\"dP[L,x=1]\"\n";
  for (int i = 0; i <= 4 * kShadowBins; ++i) {
    const double t = 0.25 * i;
    const int k = i % 4;  // 0..3 within a second
    const bool air = k == 3;
    csv << t << "," << (air ? 0 : 2) << ",1,1,0.01,0,10," << (air ? 99 : k + 1) << ",nan," << -(air ? 99 : k + 1)
        << ",0\n";
  }
  csv.close();
  write_shadow_figure_data(dir / "shadow.csv", dir, "g-exact");
  const auto rows = rows_of(dir / "g-exact.shadow.dat");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kShadowBins) + 1);
  EXPECT_EQ(rows[0][3], "dF1[L,x=1]:med");
  const auto& first = rows[1];  // t in [0, 1): |dF1| = 1, 2, 3 in contact
  EXPECT_EQ(std::stod(first[0]), 0.5);  // the bin's centre
  EXPECT_EQ(first[1], "2");             // sliding dominates
  EXPECT_EQ(std::stod(first[2]), 2.0);  // the median of 1, 2, 3
  EXPECT_NEAR(std::stod(first[3]), 2.9, 1e-12);  // the 95 % quantile, linear between order statistics
  EXPECT_EQ(first[4], "NaN");           // dF2 failed everywhere
  EXPECT_EQ(std::stod(first[6]), 2.0);  // |dM|
  EXPECT_EQ(std::stod(first[8]), 0.0);  // dP
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
