// Error statistics on synthetic data with known max, RMS and quantiles, and the handling of
// non-finite values (counted and located, never folded into the max or the RMS).

#include "bench/accuracy/error_stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace frictionlab::accuracy {
namespace error_stats_test {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Sums of a handful of small integers: exact up to one rounding of the square root.
constexpr double kTol = 1e-15;

TEST(ErrorStats, KnownMaxRmsAndQuantiles) {
  const std::vector<double> ref = {1.0, 2.0, 3.0, 4.0};
  const std::vector<double> val = {4.0, -2.0, 3.0, 5.0};  // errors 3, -4, 0, 1
  const auto st = error_stats(val, ref);
  EXPECT_EQ(st.finite, 4u);
  EXPECT_EQ(st.nonfinite, 0u);
  EXPECT_EQ(st.first_nonfinite, kNoIndex);
  EXPECT_EQ(st.max_abs, 4.0);
  EXPECT_EQ(st.max_index, 1u);
  EXPECT_NEAR(st.rms, std::sqrt(26.0 / 4.0), kTol);
  // |errors| sorted: 0 1 3 4; nearest rank: ceil(0.5 * 4) = 2nd, ceil(0.95 * 4) = 4th.
  EXPECT_EQ(st.median_abs, 1.0);
  EXPECT_EQ(st.p95_abs, 4.0);
}

TEST(ErrorStats, NonFiniteValuesAreCountedApart) {
  const std::vector<double> ref = {0.0, 0.0, 0.0, 0.0, 0.0};
  const std::vector<double> val = {0.5, kNaN, -kInf, 0.25, kInf};
  const auto st = error_stats(val, ref);
  EXPECT_EQ(st.finite, 2u);
  EXPECT_EQ(st.nonfinite, 3u);
  EXPECT_EQ(st.first_nonfinite, 1u);
  EXPECT_EQ(st.max_abs, 0.5);
  EXPECT_EQ(st.max_index, 0u);
  EXPECT_NEAR(st.rms, std::sqrt((0.25 + 0.0625) / 2.0), kTol);
}

TEST(ErrorStats, NonFiniteReferenceIsCountedApart) {
  const std::vector<double> ref = {kNaN, 1.0};
  const std::vector<double> val = {1.0, 1.5};
  const auto st = error_stats(val, ref);
  EXPECT_EQ(st.reference_nonfinite, 1u);
  EXPECT_EQ(st.nonfinite, 0u);
  EXPECT_EQ(st.finite, 1u);
  EXPECT_EQ(st.max_abs, 0.5);
  EXPECT_EQ(st.max_index, 1u);
}

TEST(ErrorStats, NothingFiniteGivesNaNStatistics) {
  const std::vector<double> ref = {1.0, 1.0};
  const std::vector<double> val = {kNaN, kInf};
  const auto st = error_stats(val, ref);
  EXPECT_EQ(st.finite, 0u);
  EXPECT_EQ(st.nonfinite, 2u);
  EXPECT_TRUE(std::isnan(st.max_abs));
  EXPECT_TRUE(std::isnan(st.rms));
  EXPECT_EQ(st.max_index, kNoIndex);

  const auto empty = error_stats({}, {});
  EXPECT_EQ(empty.finite, 0u);
  EXPECT_TRUE(std::isnan(empty.rms));
}

TEST(ErrorStats, IdenticalValuesGiveExactZeros) {
  const std::vector<double> v = {0.1, -3.0, 1e-300, 7.0};
  const auto st = error_stats(v, v);
  EXPECT_EQ(st.max_abs, 0.0);
  EXPECT_EQ(st.rms, 0.0);
  EXPECT_EQ(st.max_index, 0u);  // ties: the first
}

TEST(ErrorStats, ConstantErrorHasEqualMaxRmsAndQuantiles) {
  std::vector<double> ref(1000), val(1000);
  for (std::size_t i = 0; i < ref.size(); ++i) {
    ref[i] = static_cast<double>(i);
    val[i] = ref[i] + (i % 2 == 0 ? 0.125 : -0.125);
  }
  const auto st = error_stats(val, ref);
  EXPECT_EQ(st.max_abs, 0.125);
  EXPECT_EQ(st.rms, 0.125);
  EXPECT_EQ(st.median_abs, 0.125);
  EXPECT_EQ(st.p95_abs, 0.125);
}

}  // namespace
}  // namespace frictionlab::accuracy
