// Dissipation and sign checks on synthetic data.

#include "bench/accuracy/consistency.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace frictionlab::accuracy {
namespace consistency_test {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Dissipation, IsF1TimesSPlusMTimesSign) {
  EXPECT_EQ(dissipation(0.5, 0.25, 2.0, +1), 1.25);
  EXPECT_EQ(dissipation(0.5, 0.25, 2.0, -1), 0.75);
  EXPECT_EQ(dissipation(0.0, -0.25, 2.0, -1), 0.25);  // M odd in Omega: still dissipative
  EXPECT_EQ(dissipation(0.1, -0.5, 1.0, +1), 0.1 - 0.5);
}

TEST(Dissipation, CountsNegativePowerAndFindsTheWorst) {
  const std::vector<double> power = {0.0, 1.0, -0.5, kNaN, -2.0, -1e-300, kInf};
  const auto st = dissipation_stats(power);
  EXPECT_EQ(st.checked, 5u);
  EXPECT_EQ(st.nonfinite, 2u);
  EXPECT_EQ(st.violations, 3u);  // zero power is allowed (no slip), any negative is not
  EXPECT_EQ(st.worst, -2.0);
  EXPECT_EQ(st.worst_index, 4u);
}

TEST(Dissipation, NoViolationReportsZeroAndNoIndex) {
  const std::vector<double> power = {0.0, 3.0};
  const auto st = dissipation_stats(power);
  EXPECT_EQ(st.violations, 0u);
  EXPECT_EQ(st.worst, 0.0);
  EXPECT_EQ(st.worst_index, kNoIndex);
}

TEST(SignCheck, CountsOppositeAndZeroWhereTheReferenceIsClear) {
  const std::vector<double> ref = {1.0, -1.0, 1.0, 1e-10, -1e-10, 0.5, 0.5, -0.5};
  const std::vector<double> val = {2.0, 3.0, 0.0, -1.0, 1.0, kNaN, -0.1, -1e-300};
  // considered: indices 0, 1, 2, 6, 7 (3, 4: reference below threshold; 5: value not finite)
  const auto st = sign_stats(val, ref);
  EXPECT_EQ(st.considered, 5u);
  EXPECT_EQ(st.opposite, 2u);  // 1 and 6
  EXPECT_EQ(st.zero, 1u);      // 2
  EXPECT_DOUBLE_EQ(st.opposite_fraction(), 0.4);
  EXPECT_DOUBLE_EQ(st.zero_fraction(), 0.2);
  EXPECT_DOUBLE_EQ(st.mismatch_fraction(), 0.6);
}

TEST(SignCheck, ThresholdIsStrictAndEmptyGivesZeroFractions) {
  const std::vector<double> ref = {kSignThreshold, -kSignThreshold};
  const std::vector<double> val = {-1.0, 1.0};
  const auto st = sign_stats(val, ref);
  EXPECT_EQ(st.considered, 0u);
  EXPECT_EQ(st.mismatch_fraction(), 0.0);
  const auto loose = sign_stats(val, ref, 0.0);
  EXPECT_EQ(loose.considered, 2u);
  EXPECT_EQ(loose.opposite, 2u);
}

}  // namespace
}  // namespace frictionlab::accuracy
