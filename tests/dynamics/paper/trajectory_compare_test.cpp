// Trajectory comparison (dynamics/paper/trajectory_compare.h) on functions with known answers.

#include "dynamics/paper/trajectory_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace frictionlab::dynamics::paper {
namespace trajectory_compare_test {

// Linear interpolation of linear functions is exact up to rounding.
constexpr double kRounding = 1e-13;

std::vector<double> grid(double dt, double t_end) {
  std::vector<double> t;
  for (long i = 0; static_cast<double>(i) * dt <= t_end + 1e-12; ++i) t.push_back(static_cast<double>(i) * dt);
  return t;
}

std::vector<double> apply(const std::vector<double>& t, double a, double b) {
  std::vector<double> y;
  for (const double x : t) y.push_back(a + b * x);
  return y;
}

TEST(PaperTrajectoryCompare, InterpolationIsExactForLinesAndNaNOutside) {
  const auto t = grid(0.013, 2.0);
  const auto y = apply(t, 0.2, -0.7);
  for (const double x : {0.0, 0.0065, 0.5, 1.2345, t.back()}) EXPECT_NEAR(interpolate(t, y, x), 0.2 - 0.7 * x, kRounding) << x;
  EXPECT_TRUE(std::isnan(interpolate(t, y, -1e-9)));
  EXPECT_TRUE(std::isnan(interpolate(t, y, t.back() + 1e-9)));
  EXPECT_TRUE(std::isnan(interpolate({}, {}, 0.0)));
}

TEST(PaperTrajectoryCompare, FirstDivergenceOfTwoLinesOnDifferentGrids) {
  // |ya - yb| = 0.011 t exceeds 0.05 after t = 4.5454... s; on a 0.01 s grid first at 4.55 s.
  const auto ta = grid(0.01, 10.0);
  const auto tb = grid(0.013, 8.0);
  const Divergence d = first_divergence(ta, apply(ta, 0.5, 0.0), tb, apply(tb, 0.5, 0.011), 0.05, 0.01);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.t, 4.55, 1e-9);
  EXPECT_NEAR(d.horizon, tb.back(), 1e-15);
}

TEST(PaperTrajectoryCompare, IdenticalRunsNeverDiverge) {
  const auto t = grid(0.01, 3.0);
  const auto y = apply(t, -0.3, 0.1);
  const Divergence d = first_divergence(t, y, t, y, 0.0, 0.01);
  EXPECT_FALSE(d.found);
  EXPECT_NEAR(d.horizon, 3.0, 1e-12);
  // The end of the shorter run is compared too: a jump in its last sample is found there.
  auto y2 = y;
  y2.back() += 0.1;
  const Divergence e = first_divergence(t, y, t, y2, 0.05, 0.007);
  ASSERT_TRUE(e.found);
  EXPECT_GT(e.t, 3.0 - 0.01);
}

TEST(PaperTrajectoryCompare, InvalidGridOrThresholdIsRejected) {
  const auto t = grid(0.01, 1.0);
  const auto y = apply(t, 0.0, 1.0);
  EXPECT_THROW((void)first_divergence(t, y, t, y, 0.05, 0.0), std::invalid_argument);
  EXPECT_THROW((void)first_divergence(t, y, t, y, -0.1, 0.01), std::invalid_argument);
  EXPECT_THROW((void)first_divergence(t, y, t, y, 0.05, std::nan("")), std::invalid_argument);
}

TEST(PaperTrajectoryCompare, TiltDifference) {
  EXPECT_NEAR(tilt_difference_deg(1.0, 0.0), 90.0, 1e-12);
  EXPECT_NEAR(tilt_difference_deg(0.5, -0.5), 60.0, 1e-12);
  EXPECT_NEAR(tilt_difference_deg(-1.0, -1.0), 0.0, 1e-12);
  EXPECT_NEAR(tilt_difference_deg(1.0 + 1e-15, 1.0), 0.0, 1e-6);  // clamped, no NaN
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
