#include "dynamics/shapes/solid_mass_properties.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/eigen_near.h"

namespace frictionlab::dynamics::shapes {
namespace solid_mass_properties_test {

constexpr double kRoundingRelTol = 1e-14;

struct PointMass {
  double m;
  Eigen::Vector3d x;
};

// The inertia tensor of point masses about `p`, from its definition J = sum m (|x|^2 I - x x^T):
// off-diagonal J_ij = -sum m x_i x_j.
Eigen::Matrix3d point_inertia(const std::vector<PointMass>& pts, const Eigen::Vector3d& p) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (const auto& q : pts) {
    const Eigen::Vector3d d = q.x - p;
    J += q.m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  return J;
}

const std::vector<PointMass> kPoints = {{0.3, {0.1, 0.02, -0.05}}, {0.5, {-0.04, 0.07, 0.01}},
                                        {0.2, {0.03, -0.09, 0.08}}, {0.4, {0.0, 0.01, -0.02}}};

SolidMassProperties points_about_centroid() {
  SolidMassProperties s;
  for (const auto& q : kPoints) {
    s.mass += q.m;
    s.centroid += q.m * q.x;
  }
  s.centroid /= s.mass;
  s.inertia = point_inertia(kPoints, s.centroid);
  return s;
}

TEST(DynShapesSolidMassProperties, ParallelAxisShiftMatchesTheDefinition) {
  const SolidMassProperties s = points_about_centroid();
  for (const Eigen::Vector3d& p : std::vector<Eigen::Vector3d>{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.2, -0.1, 0.3), s.centroid}) {
    const Eigen::Matrix3d J = point_inertia(kPoints, p);
    EXPECT_EIGEN_NEAR(s.inertia_about(p), J, kRoundingRelTol * J.norm()) << "p = " << p.transpose();
  }
}

TEST(DynShapesSolidMassProperties, OffDiagonalElementsAreMinusTheProductsOfInertia) {
  // Two unit masses at (1, 1, 0) and (-1, -1, 0): the product of inertia ∫ x y dm = 2, J12 = -2.
  const std::vector<PointMass> pts = {{1.0, {1.0, 1.0, 0.0}}, {1.0, {-1.0, -1.0, 0.0}}};
  const Eigen::Matrix3d J = point_inertia(pts, Eigen::Vector3d::Zero());
  EXPECT_EQ(J(0, 1), -2.0);
  // Its principal axes are the diagonals, turned by 45 degrees about e3: the largest in-plane
  // moment (4, about (1, -1, 0)/sqrt 2) and the smallest (0, about (1, 1, 0)/sqrt 2).
  const Eigen::Matrix3d K = inertia_from_principal({0.0, 4.0, 4.0}, Eigen::Vector3d::UnitZ(), std::numbers::pi / 4);
  EXPECT_EIGEN_NEAR(K, J, kRoundingRelTol * 4);
}

TEST(DynShapesSolidMassProperties, InertiaFromPrincipalTurnsTheAxes) {
  // A rattleback: principal moments per unit mass (2, 16, 17) cm^2 about axes turned by delta about
  // the vertical: J11 = I1 c^2 + I2 s^2, J22 = I1 s^2 + I2 c^2, J12 = (I1 - I2) s c, J33 = I3.
  const double I1 = 2e-4, I2 = 16e-4, I3 = 17e-4, delta = 0.0873;
  const Eigen::Matrix3d J = inertia_from_principal({I1, I2, I3}, {0.0, 0.0, 2.0}, delta);
  const double c = std::cos(delta), s = std::sin(delta);
  Eigen::Matrix3d expected;
  expected << I1 * c * c + I2 * s * s, (I1 - I2) * s * c, 0.0, (I1 - I2) * s * c, I1 * s * s + I2 * c * c, 0.0, 0.0,
      0.0, I3;
  EXPECT_EIGEN_NEAR(J, expected, kRoundingRelTol * I3);
  const PrincipalInertia p = principal_inertia(J);
  EXPECT_EIGEN_NEAR(p.moments, Eigen::Vector3d(I1, I2, I3), kRoundingRelTol * I3);
  EXPECT_NEAR(std::abs(p.axes.col(0).dot(Eigen::Vector3d(c, s, 0.0))), 1.0, 1e-12);
  EXPECT_NEAR(p.axes.determinant(), 1.0, 1e-14);
  EXPECT_EIGEN_NEAR(p.axes * p.moments.asDiagonal() * p.axes.transpose(), J, kRoundingRelTol * I3);
  EXPECT_NO_THROW(validate_inertia(J));
  EXPECT_THROW((void)inertia_from_principal({I1, I2, I3}, Eigen::Vector3d::Zero(), 0.1), std::invalid_argument);
}

// Written out as a scenario's body.inertia, the tensor must read back symmetric to the bit.
TEST(DynShapesSolidMassProperties, InertiaFromPrincipalIsExactlySymmetric) {
  for (const double delta : {-0.7, -0.06, -0.0143, 0.005, 0.03, 0.7})
    for (const Eigen::Vector3d& axis : {Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(1.0, 2.0, 3.0)}) {
      const Eigen::Matrix3d J = inertia_from_principal({2e-4, 16e-4, 17e-4}, axis, delta);
      EXPECT_EQ(J, J.transpose()) << delta << " about " << axis.transpose();
    }
}

std::string error_of(const Eigen::Matrix3d& J) {
  try {
    validate_inertia(J, "body.inertia");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DynShapesSolidMassProperties, ValidationNamesTheKeyAndTheRule) {
  EXPECT_EQ(error_of(points_about_centroid().inertia), "");
  // A flat disc lies on the triangle inequality's edge (C = 2A): accepted.
  EXPECT_EQ(error_of(Eigen::Vector3d(0.25, 0.25, 0.5).asDiagonal()), "");
  Eigen::Matrix3d asym = Eigen::Vector3d(1.0, 2.0, 2.5).asDiagonal();
  asym(0, 1) = 0.1;
  const std::string e1 = error_of(asym);
  EXPECT_NE(e1.find("body.inertia = [1, 0.1, 0, 0, 2, 0, 0, 0, 2.5] is invalid"), std::string::npos) << e1;
  EXPECT_NE(e1.find("symmetric"), std::string::npos) << e1;
  const std::string e2 = error_of(Eigen::Vector3d(1.0, -2.0, 2.5).asDiagonal());
  EXPECT_NE(e2.find("positive definite"), std::string::npos) << e2;
  const std::string e3 = error_of(Eigen::Vector3d(1.0, 1.0, 2.1).asDiagonal());
  EXPECT_NE(e3.find("I3 <= I1 + I2"), std::string::npos) << e3;
  EXPECT_NE(e3.find("body.inertia"), std::string::npos) << e3;
  // The rule holds for the principal moments: this tensor's diagonal passes it, its moments do not.
  const Eigen::Matrix3d turned = inertia_from_principal({1.0, 1.0, 2.1}, {1.0, 1.0, 1.0}, 0.7);
  for (int i = 0; i < 3; ++i) EXPECT_LE(turned(i, i), turned.trace() - turned(i, i));
  EXPECT_NE(error_of(turned).find("I3 <= I1 + I2"), std::string::npos);
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(2, 2) = NAN;
  EXPECT_NE(error_of(nan).find("finite"), std::string::npos);
  EXPECT_THROW(validate_mass(0.0), std::invalid_argument);
  EXPECT_THROW(validate_mass(INFINITY), std::invalid_argument);
  EXPECT_NO_THROW(validate_mass(1e-3));
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
