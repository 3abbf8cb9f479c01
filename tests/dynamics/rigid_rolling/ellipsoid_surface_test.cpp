#include "dynamics/rigid_rolling/ellipsoid_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <stdexcept>

#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace ellipsoid_surface_test {

// Closed forms evaluated in double: a few ulps of the 0.2 m semi-axis.
constexpr double kExact = 1e-15;  // m
// Central differences with step 1e-6: O(h^2) truncation ~1e-12, O(eps/h) rounding ~1e-10 (m/s).
constexpr double kDifference = 1e-9;

const EllipsoidSurface kSurface(Eigen::Vector3d(0.2, 0.03, 0.02), Eigen::Vector3d(0.001, -0.002, 0.01));

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

TEST(DynRigidEllipsoidSurface, ContactPointIsOnTheSurfaceWithOutwardNormalMinusGamma) {
  std::mt19937 rng(7);
  const Eigen::Vector3d inv_sq = kSurface.semi_axes().cwiseProduct(kSurface.semi_axes()).cwiseInverse();
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector3d gamma = random_unit(rng);
    const Eigen::Vector3d p = kSurface.contact_point(gamma) - kSurface.centre();
    EXPECT_NEAR(p.dot(inv_sq.cwiseProduct(p)), 1.0, 1e-13) << "on the implicit surface";
    const Eigen::Vector3d normal = inv_sq.cwiseProduct(p).normalized();  // gradient of the implicit function
    EXPECT_EIGEN_NEAR(normal, -gamma, 1e-13);
  }
}

TEST(DynRigidEllipsoidSurface, VerticesAreTheClosedForms) {
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    EXPECT_EIGEN_NEAR(kSurface.contact_point(e), kSurface.centre() - kSurface.semi_axes()(i) * e, kExact);
    EXPECT_EIGEN_NEAR(kSurface.contact_point(-e), kSurface.centre() + kSurface.semi_axes()(i) * e, kExact);
  }
}

TEST(DynRigidEllipsoidSurface, DependsOnTheDirectionOfGammaOnly) {
  const Eigen::Vector3d gamma = Eigen::Vector3d(0.3, -0.2, 0.9).normalized();
  EXPECT_EIGEN_NEAR(kSurface.contact_point(2.5 * gamma), kSurface.contact_point(gamma), kExact);
}

TEST(DynRigidEllipsoidSurface, RateMatchesCentralDifferences) {
  std::mt19937 rng(11);
  constexpr double h = 1e-6;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d gamma = random_unit(rng);
    const Eigen::Vector3d omega = 3.0 * random_unit(rng);
    const Eigen::Vector3d rate = gamma.cross(omega);  // gamma' of a rigid motion
    const Eigen::Vector3d fd = (kSurface.contact_point(gamma + h * rate) - kSurface.contact_point(gamma - h * rate)) / (2.0 * h);
    EXPECT_EIGEN_NEAR(kSurface.contact_point_rate(gamma, rate), fd, kDifference);
  }
}

TEST(DynRigidEllipsoidSurface, RadiiOfCurvatureAtTheBottomVertex) {
  // The contact point moves by -R1 dg1 along x when gamma tilts by dg1 there (docs §1): R1 = a1^2/a3.
  const Eigen::Vector3d rate_x = kSurface.contact_point_rate(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX());
  const Eigen::Vector3d rate_y = kSurface.contact_point_rate(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  EXPECT_EIGEN_NEAR(rate_x, Eigen::Vector3d(-0.2 * 0.2 / 0.02, 0.0, 0.0), 1e-14);
  EXPECT_EIGEN_NEAR(rate_y, Eigen::Vector3d(0.0, -0.03 * 0.03 / 0.02, 0.0), 1e-14);
}

TEST(DynRigidEllipsoidSurface, InvalidInputThrows) {
  EXPECT_THROW(EllipsoidSurface(Eigen::Vector3d(0.2, 0.0, 0.02), Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(EllipsoidSurface(Eigen::Vector3d(0.2, -0.03, 0.02), Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(EllipsoidSurface(Eigen::Vector3d(0.2, 0.03, 0.02), Eigen::Vector3d(0.0, 0.0, NAN)), std::invalid_argument);
  try {
    EllipsoidSurface(Eigen::Vector3d(0.2, 0.0, 0.02), Eigen::Vector3d::Zero());
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ellipsoid.semi_axes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace frictionlab::dynamics::rigid_rolling
