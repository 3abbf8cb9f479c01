#include "dynamics/rigid_rolling/rounded_disk_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace rounded_disk_surface_test {

constexpr double kExact = 1e-15;       // m: closed forms in double
constexpr double kDifference = 1e-9;   // m/s: central differences, step 1e-6 (see the ellipsoid test)

Eigen::Vector3d random_tilted_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Vector3d g(n(rng), n(rng), n(rng));
  return g.normalized();
}

TEST(DynRigidRoundedDiskSurface, ContactPointIsWhereTheTorusSupportsThePlane) {
  // Independent of the formula: the torus is the rim circle (radius Rc in the plane z = 0) swollen
  // by rho, so its lowest point below direction gamma lies at depth Rc |gamma_plane| + rho, and is
  // at distance rho from the rim circle.
  const RoundedDiskSurface disk(0.05, 0.004);
  std::mt19937 rng(3);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d gamma = random_tilted_unit(rng);
    const Eigen::Vector3d r = disk.contact_point(gamma);
    const double plane = std::hypot(gamma.x(), gamma.y());
    EXPECT_NEAR(-r.dot(gamma), disk.rim_centre_radius() * plane + 0.004, 1e-15);
    const double from_rim = std::hypot(std::hypot(r.x(), r.y()) - disk.rim_centre_radius(), r.z());
    EXPECT_NEAR(from_rim, 0.004, 1e-15);
  }
}

TEST(DynRigidRoundedDiskSurface, KnifeEdgeDiskTouchesAtTheRim) {
  const RoundedDiskSurface disk(0.05, 0.0);
  const double beta = 0.3;  // tilt from vertical: gamma = (cos beta, 0, sin beta)
  EXPECT_EIGEN_NEAR(disk.contact_point(Eigen::Vector3d(std::cos(beta), 0.0, std::sin(beta))), Eigen::Vector3d(-0.05, 0.0, 0.0), kExact);
}

TEST(DynRigidRoundedDiskSurface, UprightDiskStandsOnItsRim) {
  const RoundedDiskSurface disk(0.05, 0.005);
  EXPECT_EIGEN_NEAR(disk.contact_point(Eigen::Vector3d(0.0, 1.0, 0.0)), Eigen::Vector3d(0.0, -0.05, 0.0), kExact);
}

TEST(DynRigidRoundedDiskSurface, RateMatchesCentralDifferences) {
  const RoundedDiskSurface disk(0.05, 0.005, Eigen::Vector3d(0.0, 0.0, 0.001));
  std::mt19937 rng(5);
  constexpr double h = 1e-6;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d gamma = random_tilted_unit(rng);
    const Eigen::Vector3d rate = gamma.cross(4.0 * random_tilted_unit(rng));
    const Eigen::Vector3d fd = (disk.contact_point(gamma + h * rate) - disk.contact_point(gamma - h * rate)) / (2.0 * h);
    EXPECT_EIGEN_NEAR(disk.contact_point_rate(gamma, rate), fd, kDifference);
  }
}

TEST(DynRigidRoundedDiskSurface, FlatDiskHasNoContactPoint) {
  const RoundedDiskSurface disk(0.05, 0.005);
  EXPECT_THROW((void)disk.contact_point(Eigen::Vector3d::UnitZ()), std::domain_error);
  EXPECT_THROW((void)disk.contact_point_rate(-Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()), std::domain_error);
  EXPECT_NO_THROW((void)disk.contact_point(Eigen::Vector3d(1e-8, 0.0, 1.0)));  // nearly flat is still defined
}

TEST(DynRigidRoundedDiskSurface, InvalidInputThrows) {
  EXPECT_THROW(RoundedDiskSurface(0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(RoundedDiskSurface(0.05, 0.05), std::invalid_argument);
  EXPECT_THROW(RoundedDiskSurface(0.05, -0.001), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
