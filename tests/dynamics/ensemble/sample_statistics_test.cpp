// Sample summaries (dynamics/ensemble/sample_statistics.h) against hand computations.

#include "dynamics/ensemble/sample_statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frictionlab::dynamics::ensemble {
namespace sample_statistics_test {

TEST(EnsembleSampleStatistics, QuantilesInterpolateOrderStatistics) {
  // Type 7 on {1, 2, 3, 4}: h = 3 p; p = 0.25 -> 1.75, 0.5 -> 2.5, 0.9 -> 3.7 (R: quantile(1:4, ...)).
  const std::vector<double> x{4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(quantile(x, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(quantile(x, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile(x, 0.9), 3.7);
  EXPECT_EQ(quantile(x, 0.0), 1.0);
  EXPECT_EQ(quantile(x, 1.0), 4.0);
  EXPECT_EQ(quantile({std::nan(""), 5.0}, 0.5), 5.0) << "missing values are skipped";
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

TEST(EnsembleSampleStatistics, TotalVariationOfCategories) {
  EXPECT_EQ(total_variation({{"a", 2}, {"b", 2}}, {{"a", 10}, {"b", 10}}), 0.0);
  EXPECT_EQ(total_variation({{"a", 4}}, {{"b", 3}}), 1.0);
  // (3/4, 1/4) vs (1/4, 3/4): (1/2)(1/2 + 1/2) = 1/2.
  EXPECT_DOUBLE_EQ(total_variation({{"a", 3}, {"b", 1}}, {{"a", 1}, {"b", 3}}), 0.5);
}

TEST(EnsembleSampleStatistics, ChiSquareHomogeneityByHand) {
  // 2 x 2 table [[30, 10], [10, 30]]: expected 20 everywhere, X^2 = 4 * 100/20 = 20, 1 degree of
  // freedom: p = erfc(sqrt(20/2)) = 7.74e-6.
  EXPECT_NEAR(chi_square_homogeneity_p({{"a", 30}, {"b", 10}}, {{"a", 10}, {"b", 30}}), std::erfc(std::sqrt(10.0)), 1e-15);
  EXPECT_DOUBLE_EQ(chi_square_homogeneity_p({{"a", 5}, {"b", 5}}, {{"a", 50}, {"b", 50}}), 1.0) << "X^2 = 0";
  EXPECT_EQ(chi_square_homogeneity_p({{"a", 5}}, {{"a", 7}}), 1.0) << "one category";
  EXPECT_TRUE(std::isnan(chi_square_homogeneity_p({}, {{"a", 7}})));
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
