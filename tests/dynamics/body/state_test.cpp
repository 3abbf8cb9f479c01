#include "dynamics/body/state.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace frictionlab::dynamics {
namespace state_test {

// R(q) gamma for the orientation made from gamma: the body's upward vertical turned into the world.
Eigen::Vector3d world_vertical(const Eigen::Vector3d& gamma, double heading) {
  const Eigen::Vector4d o = orientation_from(gamma, heading);
  const Eigen::Quaterniond q(o[0], o[1], o[2], o[3]);
  return q.toRotationMatrix() * gamma.normalized();
}

TEST(DynState, TheOrientationTurnsTheBodysVerticalIntoTheWorldsForEveryTilt) {
  for (const Eigen::Vector3d& gamma :
       {Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(0.2431, 0.0, 0.97), Eigen::Vector3d(0.3, -0.4, 0.1),
        Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, -1.0), Eigen::Vector3d(1e-7, 0.0, -1.0),
        Eigen::Vector3d(0.0, -3e-9, -1.0), Eigen::Vector3d(-0.6, 0.8, -1e-3)}) {
    for (const double heading : {0.0, 1.2, -std::numbers::pi}) {
      const Eigen::Vector4d o = orientation_from(gamma, heading);
      EXPECT_NEAR(o.norm(), 1.0, 1e-15) << gamma.transpose() << ", heading " << heading;
      EXPECT_LT((world_vertical(gamma, heading) - Eigen::Vector3d::UnitZ()).norm(), 1e-15)
          << gamma.transpose() << ", heading " << heading;
    }
  }
}

// The same bits as Eigen's Quaternion::FromTwoVectors away from the opposite direction, whose
// arithmetic orientation_from follows.
TEST(DynState, TheTiltIsEigensShortestRotationBitForBit) {
  for (const Eigen::Vector3d& gamma :
       {Eigen::Vector3d(0.2431, 0.0, 0.97), Eigen::Vector3d(0.3, -0.4, 0.1), Eigen::Vector3d(-0.6, 0.8, -0.5)}) {
    const Eigen::Quaterniond eigen = Eigen::Quaterniond::FromTwoVectors(gamma, Eigen::Vector3d::UnitZ());
    const Eigen::Vector4d o = orientation_from(gamma, 0.0);
    const Eigen::Quaterniond ours(o[0], o[1], o[2], o[3]);
    const Eigen::Quaterniond heading0 = Eigen::Quaterniond(Eigen::AngleAxisd(0.0, Eigen::Vector3d::UnitZ())) * eigen;
    EXPECT_EQ(ours.coeffs(), heading0.coeffs()) << gamma.transpose();
  }
}

TEST(DynState, TheHeadingTurnsAboutTheWorldsVertical) {
  const Eigen::Vector3d gamma(0.3, -0.4, 0.8);
  const Eigen::Vector4d a = orientation_from(gamma, 0.0), b = orientation_from(gamma, 0.7);
  const Eigen::Matrix3d ra = Eigen::Quaterniond(a[0], a[1], a[2], a[3]).toRotationMatrix();
  const Eigen::Matrix3d rb = Eigen::Quaterniond(b[0], b[1], b[2], b[3]).toRotationMatrix();
  const Eigen::Matrix3d turn = rb * ra.transpose();
  EXPECT_TRUE(turn.isApprox(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-14));
}

}  // namespace state_test
}  // namespace frictionlab::dynamics
