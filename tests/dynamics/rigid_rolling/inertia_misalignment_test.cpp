#include "dynamics/rigid_rolling/inertia_misalignment.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

namespace frictionlab::dynamics::rigid_rolling {
namespace inertia_misalignment_test {

TEST(DynRigidInertiaMisalignment, AngleRoundTrips) {
  for (double delta : {-0.7, -0.05, 0.0, 0.01, 0.3, 1.2}) {
    const Eigen::Matrix3d j = inertia_rotated_about_vertical(2.0, 16.0, 17.0, delta);
    EXPECT_NEAR(misalignment_angle(j), delta, 1e-14) << delta;
  }
}

TEST(DynRigidInertiaMisalignment, SmallerMomentLiesAlongTheRotatedAxis) {
  const double delta = 0.2;
  const Eigen::Matrix3d j = inertia_rotated_about_vertical(2.0, 16.0, 17.0, delta);
  const Eigen::Vector3d axis(std::cos(delta), std::sin(delta), 0.0);
  EXPECT_NEAR(axis.dot(j * axis), 2.0, 1e-13);
  EXPECT_NEAR((j * axis - 2.0 * axis).norm(), 0.0, 1e-13);
  // The tensor element has the sign of -delta when A0 < B0 (the integral of x y dm: of +delta).
  EXPECT_LT(j(0, 1), 0.0);
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
