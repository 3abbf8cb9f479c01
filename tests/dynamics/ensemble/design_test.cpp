// Designs over the unit box (dynamics/ensemble/design.h).

#include "dynamics/ensemble/design.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace frictionlab::dynamics::ensemble {
namespace design_test {

TEST(EnsembleDesign, SobolStartsAsGslDocumentsIt) {
  // The GSL manual's example of gsl_qrng_sobol in 2 dimensions ("Quasi-Random Sequences",
  // Examples) prints 0.50000 0.50000, 0.75000 0.25000, 0.25000 0.75000, 0.37500 0.37500,
  // 0.87500 0.87500 as its first points.
  const auto p = sobol_points(2, 5);
  const double expected[5][2] = {{0.5, 0.5}, {0.75, 0.25}, {0.25, 0.75}, {0.375, 0.375}, {0.875, 0.875}};
  ASSERT_EQ(p.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t d = 0; d < 2; ++d) EXPECT_EQ(p[i][d], expected[i][d]) << "point " << i << ", axis " << d;
}

TEST(EnsembleDesign, SobolCoversEachDyadicIntervalOnce) {
  // The first 2^k - 1 points of a Sobol sequence (GSL omits the origin) fall one in each of the
  // 2^k intervals [j/2^k, (j+1)/2^k) of every axis but the one holding 0 (a (0, k)-net property).
  const int k = 6;
  const long n = (1L << k) - 1;
  const auto p = sobol_points(3, n);
  for (std::size_t d = 0; d < 3; ++d) {
    std::vector<int> hits(1u << k, 0);
    for (const auto& x : p) ++hits[static_cast<std::size_t>(std::floor(x[d] * (1 << k)))];
    EXPECT_EQ(hits[0], 0) << "axis " << d;
    for (std::size_t j = 1; j < hits.size(); ++j) EXPECT_EQ(hits[j], 1) << "axis " << d << ", interval " << j;
  }
}

TEST(EnsembleDesign, SobolRejectsDimensionsGslDoesNotHave) {
  EXPECT_THROW((void)sobol_points(0, 4), std::invalid_argument);
  EXPECT_THROW((void)sobol_points(kSobolMaxDimension + 1, 4), std::invalid_argument);
  EXPECT_NO_THROW((void)sobol_points(kSobolMaxDimension, 4));
}

TEST(EnsembleDesign, LatinHypercubePutsOnePointInEveryStratumOfEveryAxis) {
  for (const long n : {1L, 2L, 7L, 100L}) {
    const auto p = latin_hypercube(4, n, 11);
    ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
    for (std::size_t d = 0; d < 4; ++d) {
      std::vector<int> hits(static_cast<std::size_t>(n), 0);
      for (const auto& x : p) {
        ASSERT_GE(x[d], 0.0);
        ASSERT_LE(x[d], 1.0);
        ++hits[std::min(static_cast<std::size_t>(n - 1), static_cast<std::size_t>(std::floor(x[d] * static_cast<double>(n))))];
      }
      for (std::size_t j = 0; j < hits.size(); ++j) EXPECT_EQ(hits[j], 1) << "n " << n << ", axis " << d << ", stratum " << j;
    }
  }
}

TEST(EnsembleDesign, SeededDesignsRepeatAndDependOnTheSeed) {
  EXPECT_EQ(latin_hypercube(2, 20, 5), latin_hypercube(2, 20, 5));
  EXPECT_NE(latin_hypercube(2, 20, 5), latin_hypercube(2, 20, 6));
  EXPECT_EQ(random_points(3, 20, 5), random_points(3, 20, 5));
  EXPECT_NE(random_points(3, 20, 5), random_points(3, 20, 6));
  // The axes of a Latin hypercube are matched by independent permutations: not all on the diagonal.
  const auto p = latin_hypercube(2, 20, 5);
  int same = 0;
  for (const auto& x : p) same += std::floor(x[0] * 20) == std::floor(x[1] * 20);
  EXPECT_LT(same, 20);
}

TEST(EnsembleDesign, RandomPointsAreUniformInTheBox) {
  const auto p = random_points(2, 4000, 9);
  double mean[2] = {0, 0};
  for (const auto& x : p)
    for (std::size_t d = 0; d < 2; ++d) {
      ASSERT_GE(x[d], 0.0);
      ASSERT_LT(x[d], 1.0);
      mean[d] += x[d] / 4000.0;
    }
  for (const double m : mean) EXPECT_NEAR(m, 0.5, 5 * std::sqrt(1.0 / 12.0 / 4000.0));
}

TEST(EnsembleDesign, GridProductVariesTheFirstAxisSlowest) {
  const auto g = grid_product({{1.0, 2.0}, {10.0, 20.0, 30.0}});
  const std::vector<UnitPoint> expected{{1, 10}, {1, 20}, {1, 30}, {2, 10}, {2, 20}, {2, 30}};
  EXPECT_EQ(g, expected);
  EXPECT_EQ(grid_product({}), std::vector<UnitPoint>{UnitPoint{}}) << "no axes: one start";
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
