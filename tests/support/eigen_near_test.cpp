#include "tests/support/eigen_near.h"

#include <gtest/gtest-spi.h>

#include <limits>

namespace frictionlab::testing {
namespace eigen_near_test {

TEST(SupportEigenNear, PassesWithinTheToleranceForVectorsMatricesAndExpressions) {
  const Eigen::Vector3d a(1.0, 2.0, 3.0);
  EXPECT_EIGEN_NEAR(a, Eigen::Vector3d(1.0, 2.0, 3.0 + 1e-13), 1e-12);
  EXPECT_EIGEN_NEAR(Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Identity() * (1.0 + 1e-14), 1e-12);
  EXPECT_EIGEN_NEAR(a.head<2>(), Eigen::Vector2d(1.0, 2.0), 0.0);
  Eigen::Matrix<double, 12, 1> x = Eigen::Matrix<double, 12, 1>::LinSpaced(0.0, 1.0);
  EXPECT_EIGEN_NEAR(x, x, 0.0);
}

TEST(SupportEigenNear, FailsAndPrintsBothSides) {
  // The Euclidean norm of (0, 0, 3e-12) is 3e-12 > 1e-12.
  EXPECT_NONFATAL_FAILURE(EXPECT_EIGEN_NEAR(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3 + 3e-12), 1e-12),
                          "difference");
  EXPECT_NONFATAL_FAILURE(EXPECT_EIGEN_NEAR(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 4), 0.5),
                          "Eigen::Vector3d(1, 2, 4) =");
  // The norm is Euclidean, not the largest component: each component is within 1, the norm is sqrt(3).
  EXPECT_NONFATAL_FAILURE(EXPECT_EIGEN_NEAR(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.9, 0.9, 0.9), 1.0), "> 1");
}

TEST(SupportEigenNear, FailsOnShapeMismatchAndOnNaN) {
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(2), b = Eigen::VectorXd::Zero(3);
  EXPECT_NONFATAL_FAILURE(EXPECT_EIGEN_NEAR(a, b, 1.0), "is 2x1 but");
  EXPECT_NONFATAL_FAILURE(
      EXPECT_EIGEN_NEAR(Eigen::Vector2d(0.0, std::numeric_limits<double>::quiet_NaN()), Eigen::Vector2d::Zero(), 1.0),
      "nan");
}

}  // namespace
}  // namespace frictionlab::testing
