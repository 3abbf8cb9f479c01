// The study grid: sizes, exact end points, log and even spacing, the nodes the study relies on
// (mu = 1, psi = 0, pi/2, pi), the numbering of points, and the errors bad sizes give.

#include "bench/accuracy/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace frictionlab::accuracy {
namespace grid_test {

constexpr double pi = std::numbers::pi;
// Nodes are computed by pow and by one multiply-add: a few ulps of 1 relative.
constexpr double kSpacingTol = 1e-12;

TEST(Grid, DefaultSizesAreTheStudys) {
  const Grid grid{GridSpec{}};
  EXPECT_EQ(grid.s().size(), 200u);
  EXPECT_EQ(grid.mu().size(), 20u);
  EXPECT_EQ(grid.psi().size(), 25u);
  EXPECT_EQ(grid.slice_size(), 25u * 2u * 200u);
  EXPECT_EQ(grid.size(), 200u * 20u * 25u * 2u);
}

TEST(Grid, SlipRatiosAreLogSpacedWithExactEnds) {
  const Grid grid{GridSpec{}};
  const auto& s = grid.s();
  EXPECT_EQ(s.front(), 1e-3);
  EXPECT_EQ(s.back(), 1e3);
  const double ratio = std::pow(10.0, 6.0 / 199.0);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_NEAR(s[i] / s[i - 1], ratio, kSpacingTol) << "i = " << i;
  }
}

TEST(Grid, AxisRatiosAreEvenFrom005ToTheCircle) {
  const Grid grid{GridSpec{}};
  const auto& mu = grid.mu();
  EXPECT_EQ(mu.front(), 0.05);
  EXPECT_EQ(mu.back(), 1.0);
  for (std::size_t i = 1; i < mu.size(); ++i) EXPECT_NEAR(mu[i] - mu[i - 1], 0.05, kSpacingTol);
  EXPECT_NEAR(mu[grid.nearest_mu(0.5)], 0.5, kSpacingTol);
}

TEST(Grid, OrientationsHoldZeroHalfPiAndPiExactly) {
  const Grid grid{GridSpec{}};
  const auto& psi = grid.psi();
  EXPECT_EQ(psi.front(), 0.0);
  EXPECT_EQ(psi[12], pi / 2.0);
  EXPECT_EQ(psi.back(), pi);
  for (std::size_t i = 1; i < psi.size(); ++i) EXPECT_NEAR(psi[i] - psi[i - 1], pi / 24.0, kSpacingTol);
  EXPECT_EQ(grid.nearest_psi(pi / 4.0), 6u);
  EXPECT_EQ(grid.nearest_psi(pi / 3.0), 8u);
}

TEST(Grid, PointsAreNumberedSFastestThenSignThenPsiThenMu) {
  GridSpec spec;
  spec.s_points = 4;
  spec.mu_points = 3;
  spec.psi_points = 5;
  const Grid grid{spec};
  std::size_t i = 0;
  for (std::size_t imu = 0; imu < 3; ++imu) {
    for (std::size_t ipsi = 0; ipsi < 5; ++ipsi) {
      for (std::size_t isign = 0; isign < 2; ++isign) {
        for (std::size_t is = 0; is < 4; ++is, ++i) {
          ASSERT_EQ(grid.index(imu, ipsi, isign, is), i);
          const GridPoint p = grid.point(i);
          EXPECT_EQ(p.s, grid.s()[is]);
          EXPECT_EQ(p.mu, grid.mu()[imu]);
          EXPECT_EQ(p.psi, grid.psi()[ipsi]);
          EXPECT_EQ(p.sign, Grid::kSigns[isign]);
          EXPECT_EQ(grid.mu_index(i), imu);
        }
      }
    }
  }
  EXPECT_EQ(i, grid.size());
}

TEST(Grid, ContactIsTheDimensionlessOne) {
  const auto in = to_contact({0.25, 0.4, 1.0, -1});
  EXPECT_EQ(in.U, 0.25);
  EXPECT_EQ(in.Omega, -1.0);
  EXPECT_EQ(in.a, 1.0);
  EXPECT_EQ(in.b, 0.4);
  EXPECT_EQ(in.psi.radians(), 1.0);
  EXPECT_EQ(in.N, 1.0);
  EXPECT_EQ(in.k, 1.0);
}

void expect_invalid(const GridSpec& spec, const std::string& fragment) {
  std::string error;
  EXPECT_FALSE(spec.is_valid(&error));
  EXPECT_NE(error.find(fragment), std::string::npos) << error;
  try {
    (void)Grid{spec};
    ADD_FAILURE() << "no exception for " << fragment;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), error);
  }
}

TEST(Grid, BadSpecsNameTheValueAndTheRule) {
  GridSpec spec;
  EXPECT_TRUE(spec.is_valid(nullptr));
  spec.s_points = 1;
  expect_invalid(spec, "s points = 1 is invalid");
  spec = {};
  spec.mu_points = 1;
  expect_invalid(spec, "mu points = 1 is invalid");
  spec = {};
  spec.psi_points = 24;
  expect_invalid(spec, "psi points = 24 is invalid: the orientation grid needs an odd number");
  spec.psi_points = 1;
  expect_invalid(spec, "psi points = 1 is invalid");
  spec = {};
  spec.s_min = 0.0;
  expect_invalid(spec, "s_min = 0 is invalid");
  spec = {};
  spec.s_max = 1e-4;
  expect_invalid(spec, "s_max = 0.0001 is invalid");
  spec = {};
  spec.mu_min = 1.0;
  expect_invalid(spec, "mu_min = 1 is invalid");
}

TEST(Grid, SmallestValidGrid) {
  GridSpec spec;
  spec.s_points = 2;
  spec.mu_points = 2;
  spec.psi_points = 3;
  const Grid grid{spec};
  EXPECT_EQ(grid.size(), 2u * 2u * 3u * 2u);
  EXPECT_EQ(grid.psi()[1], pi / 2.0);
}

}  // namespace
}  // namespace frictionlab::accuracy
