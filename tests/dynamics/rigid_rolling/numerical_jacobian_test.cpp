#include "dynamics/rigid_rolling/numerical_jacobian.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "dynamics/rigid_rolling/ellipsoid_body.h"
#include "dynamics/rigid_rolling/rattleback_presets.h"
#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace numerical_jacobian_test {

TEST(DynRigidNumericalJacobian, GammaRowsAreTheCrossProductMatrix) {
  // gamma' = gamma x omega is bilinear: d gamma'/d omega = [gamma]x, d gamma'/d gamma = -[omega]x,
  // which central differences reproduce up to rounding.
  const RigidRollingModel model(rigid_body(kane_levinson_rattleback()));
  const RollingState x{Eigen::Vector3d(0.4, -1.2, 5.0), Eigen::Vector3d(0.05, -0.02, 1.0).normalized()};
  const RollingJacobian jac = numerical_jacobian(model, x);
  Eigen::Matrix3d gx, wx;
  gx << 0, -x.gamma.z(), x.gamma.y(), x.gamma.z(), 0, -x.gamma.x(), -x.gamma.y(), x.gamma.x(), 0;
  wx << 0, -x.omega.z(), x.omega.y(), x.omega.z(), 0, -x.omega.x(), -x.omega.y(), x.omega.x(), 0;
  EXPECT_EIGEN_NEAR((jac.block<3, 3>(3, 0)), gx, 1e-9);
  EXPECT_EIGEN_NEAR((jac.block<3, 3>(3, 3)), -wx, 1e-9);
}

TEST(DynRigidNumericalJacobian, RejectsABadStep) {
  const RigidRollingModel model(rigid_body(kane_levinson_rattleback()));
  EXPECT_THROW((void)numerical_jacobian(model, RollingState{}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
