#include "dynamics/core/all_finite.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <limits>

namespace frictionlab::dynamics {
namespace all_finite_test {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The lengths of the states the core integrates (the puck's 8, the body's 18), one the reduction
// splits unevenly (3), and a dynamic one.
template <class V>
void check_every_position(V x) {
  const Eigen::Index n = x.size();
  for (Eigen::Index i = 0; i < n; ++i) x[i] = 1.0 + static_cast<double>(i);
  ASSERT_TRUE(all_finite(x));
  for (Eigen::Index i = 0; i < n; ++i) {
    for (const double bad : {kInf, -kInf, kNaN, -kNaN}) {
      V y = x;
      y[i] = bad;
      EXPECT_FALSE(all_finite(y)) << "n = " << n << ", component " << i << " = " << bad;
    }
  }
}

TEST(DynAllFinite, AnInfiniteOrNaNComponentAnywhereIsFound) {
  check_every_position(Eigen::Matrix<double, 3, 1>());
  check_every_position(Eigen::Matrix<double, 8, 1>());
  check_every_position(Eigen::Matrix<double, 18, 1>());
  check_every_position(Eigen::VectorXd(11));
}

TEST(DynAllFinite, ExtremeFiniteValuesAreFinite) {
  Eigen::Matrix<double, 18, 1> x;
  x.setConstant(std::numeric_limits<double>::max());
  x[1] = -std::numeric_limits<double>::max();
  x[2] = std::numeric_limits<double>::denorm_min();
  x[3] = -0.0;
  EXPECT_TRUE(all_finite(x)) << "a sum of the largest doubles would overflow; the check must not";
  EXPECT_TRUE(all_finite(Eigen::VectorXd()));
}

TEST(DynAllFinite, AgreesWithEigensAllFiniteOnSegments) {
  Eigen::Matrix<double, 18, 1> x = Eigen::Matrix<double, 18, 1>::LinSpaced(-9.0, 8.0);
  x[14] = kNaN;
  EXPECT_EQ(all_finite(x.head<12>()), x.head<12>().allFinite());
  EXPECT_EQ(all_finite(x.tail<6>()), x.tail<6>().allFinite());
  EXPECT_FALSE(all_finite(x.tail<6>()));
}

}  // namespace
}  // namespace frictionlab::dynamics
