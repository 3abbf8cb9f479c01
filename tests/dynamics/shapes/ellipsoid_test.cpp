#include "dynamics/shapes/ellipsoid.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <gsl/gsl_integration.h>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/shapes/tangent_plane.h"
#include "shape_test_support.h"

namespace frictionlab::dynamics::shapes {
namespace ellipsoid_test {

using testing::any_tangents;
using testing::random_directions;

// The closed forms are evaluated to rounding: a few ulps of the body's size (or of a radius).
constexpr double kClosedFormRelTol = 1e-13;
// Finite differences of the implicit surface (Richardson, step 1e-3 of the size): truncation
// ~1e-12, rounding ~1e-10 of a curvature; the FD tests use this (relative).
constexpr double kImplicitFdRelTol = 1e-7;
// Central differences on the sphere (Richardson, h = kSphereFdStep): truncation ~h^4 R^(5), where
// the radii of this slender ellipsoid (a1/a3 ~ 7) vary over ~a3/a1 rad, ~1e-11 R; rounding
// ~1e-16 R/h ~ 1e-12 R.
constexpr double kSphereFdStep = 2e-4;
constexpr double kSphereFdRelTol = 1e-8;

const Eigen::Vector3d kAxes(0.2, 0.07, 0.03);  // triaxial, a1 > a2 > a3, m

double implicit_f(const Eigen::Vector3d& a, const Eigen::Vector3d& x) {
  return x.cwiseQuotient(a).squaredNorm() - 1.0;
}

TEST(DynShapesEllipsoid, ContactPointIsOnTheSurfaceWithOutwardNormalMinusGamma) {
  const Ellipsoid e(kAxes);
  for (const auto& g : random_directions(200)) {
    const SurfaceContact c = e.contact(g);
    EXPECT_NEAR(implicit_f(kAxes, c.r), 0.0, 1e-15);
    // The outward normal is grad f / |grad f|, grad f = 2 D^-2 r.
    const Eigen::Vector3d n = c.r.cwiseQuotient(kAxes.cwiseProduct(kAxes)).normalized();
    EXPECT_EIGEN_NEAR(n, -g, 1e-14);
    // r is the lowest point: no surface point lies lower along gamma (support function).
    for (const auto& other : random_directions(20, 99)) EXPECT_LE(c.r.dot(g), e.contact(other).r.dot(g) + 1e-16);
  }
}

TEST(DynShapesEllipsoid, VerticesHaveClosedFormRadii) {
  const Ellipsoid e(kAxes);
  for (int i = 0; i < 3; ++i) {
    for (double sign : {1.0, -1.0}) {
      // gamma = -sign e_i touches at the vertex sign a_i e_i: radii a_j^2/a_i, a_k^2/a_i.
      const Eigen::Vector3d g = -sign * Eigen::Vector3d::Unit(i);
      const SurfaceContact c = e.contact(g);
      EXPECT_EIGEN_NEAR(c.r, sign * kAxes(i) * Eigen::Vector3d::Unit(i), kClosedFormRelTol * kAxes(0));
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const int big = kAxes(j) > kAxes(k) ? j : k, small = big == j ? k : j;
      const double R_big = kAxes(big) * kAxes(big) / kAxes(i), R_small = kAxes(small) * kAxes(small) / kAxes(i);
      EXPECT_NEAR(c.R_major, R_big, kClosedFormRelTol * R_big) << "vertex " << i;
      EXPECT_NEAR(c.R_minor, R_small, kClosedFormRelTol * R_small) << "vertex " << i;
      EXPECT_NEAR(std::abs(c.major.dot(Eigen::Vector3d::Unit(big))), 1.0, 1e-15) << "vertex " << i;
    }
  }
}

// The route of the Hessian of f: the shape operator on the tangent plane is P (grad^2 f) P/|grad f|;
// its inverse restricted to the plane is the radii matrix.
TEST(DynShapesEllipsoid, RadiiAreTheInverseOfTheShapeOperatorFromTheHessian) {
  const Ellipsoid e(kAxes);
  const Eigen::Matrix3d H = 2.0 * kAxes.cwiseProduct(kAxes).cwiseInverse().asDiagonal().toDenseMatrix();
  for (const auto& g : random_directions(200)) {
    const SurfaceContact c = e.contact(g);
    const Eigen::Vector3d grad = H * c.r;
    const auto [u, v] = any_tangents(g);
    Eigen::Matrix2d S;
    S << u.dot(H * u), u.dot(H * v), v.dot(H * u), v.dot(H * v);
    S /= grad.norm();
    const Eigen::Matrix2d R = S.inverse();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(R);
    EXPECT_NEAR(c.R_major, eig.eigenvalues()(1), 1e-12 * c.R_major);
    EXPECT_NEAR(c.R_minor, eig.eigenvalues()(0), 1e-12 * c.R_major);
    const Eigen::Vector3d major = eig.eigenvectors()(0, 1) * u + eig.eigenvectors()(1, 1) * v;
    EXPECT_NEAR(std::abs(c.major.dot(major)), 1.0, 1e-9) << "gamma = " << g.transpose();
    EXPECT_NEAR(c.major.norm(), 1.0, 1e-15);
    EXPECT_NEAR(c.major.dot(g), 0.0, 1e-15);
  }
}

TEST(DynShapesEllipsoid, CurvaturesMatchFiniteDifferencesOfTheImplicitSurface) {
  const Ellipsoid e(kAxes);
  const auto f = [](const Eigen::Vector3d& x) { return implicit_f(kAxes, x); };
  for (const auto& g : random_directions(40)) {
    const SurfaceContact c = e.contact(g);
    const auto [u, v] = any_tangents(g);
    // gamma points into the body from its lowest point.
    const Eigen::Matrix2d K = testing::implicit_curvature(f, c.r, g, u, v, 1e-3 * kAxes(0));
    const Eigen::Matrix2d R = testing::radii_matrix(c.R_major, c.R_minor, c.major, g, u, v);
    EXPECT_EIGEN_NEAR(K * R, Eigen::Matrix2d::Identity(), kImplicitFdRelTol * c.R_major / c.R_minor)
        << "gamma = " << g.transpose();
  }
}

TEST(DynShapesEllipsoid, RadiiGradientsMatchCentralDifferencesOnTheSphere) {
  const Ellipsoid e(kAxes);
  for (const auto& g : random_directions(100)) {
    const SurfaceContact c = e.contact(g);
    const RadiiGradient grad = e.radii_gradient(g, c);
    // Tangent to rounding of the unprojected gradient (whose normal part is -R).
    EXPECT_NEAR(grad.major.dot(g), 0.0, 1e-15 * (grad.major.norm() + c.R_major));
    EXPECT_NEAR(grad.minor.dot(g), 0.0, 1e-15 * (grad.minor.norm() + c.R_major));
    const auto [u, v] = any_tangents(g);
    for (const auto& tau : {u, v}) {
      const double dmaj = testing::sphere_derivative([&](const Eigen::Vector3d& x) { return e.contact(x).R_major; },
                                                     g, tau, kSphereFdStep);
      const double dmin = testing::sphere_derivative([&](const Eigen::Vector3d& x) { return e.contact(x).R_minor; },
                                                     g, tau, kSphereFdStep);
      EXPECT_NEAR(grad.major.dot(tau), dmaj, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
      EXPECT_NEAR(grad.minor.dot(tau), dmin, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
    }
  }
}

TEST(DynShapesEllipsoid, SphereHasRadiusAEverywhere) {
  const double a = 0.05;
  const Ellipsoid e({a, a, a});
  auto dirs = random_directions(100);
  dirs.push_back(Eigen::Vector3d::UnitZ());
  dirs.push_back(-Eigen::Vector3d::UnitZ());
  for (const auto& g : dirs) {
    const SurfaceContact c = e.contact(g);
    EXPECT_EIGEN_NEAR(c.r, Eigen::Vector3d(-a * g), kClosedFormRelTol * a);
    EXPECT_NEAR(c.R_major, a, kClosedFormRelTol * a);
    EXPECT_NEAR(c.R_minor, a, kClosedFormRelTol * a);
    // Every point is an umbilic: the major direction is the rule's t1, bit for bit.
    EXPECT_EQ(c.major, tangent_frame(g).t1);
    const RadiiGradient grad = e.radii_gradient(g, c);
    EXPECT_EIGEN_NEAR(grad.major, Eigen::Vector3d::Zero(), kClosedFormRelTol * a);
    EXPECT_EIGEN_NEAR(grad.minor, Eigen::Vector3d::Zero(), kClosedFormRelTol * a);
  }
}

// The four umbilics of a triaxial ellipsoid lie in the e1-e3 plane at
// x1^2 = a1^2 (a1^2 - a2^2)/(a1^2 - a3^2), x3^2 = a3^2 (a2^2 - a3^2)/(a1^2 - a3^2), with both radii
// a2^3/(a1 a3) (the curvature a1 a3/a2^3 of the classical result).
TEST(DynShapesEllipsoid, UmbilicsHaveEqualRadiiAndTheRulesDirection) {
  const Ellipsoid e(kAxes);
  const double a1 = kAxes(0), a2 = kAxes(1), a3 = kAxes(2);
  const double x1 = a1 * std::sqrt((a1 * a1 - a2 * a2) / (a1 * a1 - a3 * a3));
  const double x3 = a3 * std::sqrt((a2 * a2 - a3 * a3) / (a1 * a1 - a3 * a3));
  const double R = a2 * a2 * a2 / (a1 * a3);
  for (double s1 : {1.0, -1.0}) {
    for (double s3 : {1.0, -1.0}) {
      const Eigen::Vector3d point(s1 * x1, 0.0, s3 * x3);
      const Eigen::Vector3d g = -point.cwiseQuotient(kAxes.cwiseProduct(kAxes)).normalized();
      const SurfaceContact c = e.contact(g);
      EXPECT_EIGEN_NEAR(c.r, point, kClosedFormRelTol * a1);
      EXPECT_NEAR(c.R_major, R, 1e-12 * R);
      EXPECT_NEAR(c.R_minor, R, 1e-12 * R);
      EXPECT_EQ(c.major, tangent_frame(g).t1);  // deterministic: the rule, not rounding
      // Both gradients are that of the mean radius, which is smooth through the umbilic.
      const RadiiGradient grad = e.radii_gradient(g, c);
      EXPECT_EQ(grad.major, grad.minor);
      const auto [u, v] = any_tangents(g);
      for (const auto& tau : {u, v}) {
        const double dmean = testing::sphere_derivative(
            [&](const Eigen::Vector3d& x) {
              const SurfaceContact y = e.contact(x);
              return 0.5 * (y.R_major + y.R_minor);
            },
            g, tau, kSphereFdStep);
        EXPECT_NEAR(grad.major.dot(tau), dmean, kSphereFdRelTol * R);
      }
    }
  }
}

TEST(DynShapesEllipsoid, AtThePolesTheFrameIsBodyE1) {
  const Ellipsoid e({0.1, 0.1, 0.04});  // oblate spheroid: the poles are umbilics
  for (const Eigen::Vector3d& g : std::vector<Eigen::Vector3d>{Eigen::Vector3d::UnitZ(), Eigen::Vector3d(-Eigen::Vector3d::UnitZ())}) {
    const SurfaceContact c = e.contact(g);
    EXPECT_EQ(c.major, Eigen::Vector3d::UnitX());
    EXPECT_NEAR(c.R_major, 0.1 * 0.1 / 0.04, kClosedFormRelTol * 0.25);
  }
}

// ∫ over the solid by the map xi = (a1 sin A, a2 cos A sin B, a3 cos A cos B sin C), A, B, C in
// [-pi/2, pi/2], Jacobian a1 a2 a3 cos^3 A cos^2 B cos C: smooth integrands, Gauss-Legendre.
template <class F>
double ellipsoid_quadrature(const Eigen::Vector3d& a, F&& f) {
  constexpr std::size_t n = 40;
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> t(
      gsl_integration_glfixed_table_alloc(n), &gsl_integration_glfixed_table_free);
  const double h = std::numbers::pi / 2;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double A = 0, wa = 0;
    gsl_integration_glfixed_point(-h, h, i, &A, &wa, t.get());
    for (std::size_t j = 0; j < n; ++j) {
      double B = 0, wb = 0;
      gsl_integration_glfixed_point(-h, h, j, &B, &wb, t.get());
      for (std::size_t k = 0; k < n; ++k) {
        double C = 0, wc = 0;
        gsl_integration_glfixed_point(-h, h, k, &C, &wc, t.get());
        const Eigen::Vector3d x(a(0) * std::sin(A), a(1) * std::cos(A) * std::sin(B),
                                a(2) * std::cos(A) * std::cos(B) * std::sin(C));
        const double jac = a.prod() * std::pow(std::cos(A), 3) * std::pow(std::cos(B), 2) * std::cos(C);
        sum += wa * wb * wc * jac * f(x);
      }
    }
  }
  return sum;
}

TEST(DynShapesEllipsoid, HomogeneousMassPropertiesMatchQuadrature) {
  const double m = 0.7;
  const SolidMassProperties p = Ellipsoid(kAxes).homogeneous(m);
  const double V = ellipsoid_quadrature(kAxes, [](const Eigen::Vector3d&) { return 1.0; });
  EXPECT_NEAR(p.volume, V, 1e-12 * V);
  EXPECT_NEAR(p.volume, 4.0 / 3.0 * std::numbers::pi * kAxes.prod(), 1e-15 * V);
  EXPECT_EQ(p.mass, m);
  EXPECT_EQ(p.centroid, Eigen::Vector3d::Zero());
  const double rho = m / V;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double J = rho * ellipsoid_quadrature(kAxes, [&](const Eigen::Vector3d& x) {
        return (i == j ? x.squaredNorm() : 0.0) - x(i) * x(j);
      });
      EXPECT_NEAR(p.inertia(i, j), J, 1e-12 * p.inertia.trace()) << "J" << i + 1 << j + 1;
    }
  }
  EXPECT_THROW((void)Ellipsoid(kAxes).homogeneous(0.0), std::invalid_argument);
}

TEST(DynShapesEllipsoid, SemiAxesMustBePositiveAndFinite) {
  for (const Eigen::Vector3d& a : std::vector<Eigen::Vector3d>{Eigen::Vector3d(0.1, -0.1, 0.1), Eigen::Vector3d(0.1, 0.1, 0.0),
                                  Eigen::Vector3d(0.1, NAN, 0.1), Eigen::Vector3d(INFINITY, 0.1, 0.1)}) {
    try {
      (void)Ellipsoid(a, "body.semi_axes");
      ADD_FAILURE() << "accepted " << a.transpose();
    } catch (const std::invalid_argument& err) {
      EXPECT_NE(std::string(err.what()).find("body.semi_axes = ["), std::string::npos) << err.what();
      EXPECT_NE(std::string(err.what()).find("must be finite and > 0 m"), std::string::npos) << err.what();
    }
  }
}

TEST(DynShapesEllipsoid, RadiusAboutAPointIsTheFarthestSurfacePoint) {
  const Eigen::Vector3d a(0.3, 0.2, 0.1);
  const Ellipsoid e(a);
  // Closed forms: the centre; a point on the longest axis; the degenerate ("hard") case of a point
  // on a shorter axis near the centre: mu = a1^2, xi2 = a2^2 p2/(a1^2 - a2^2) ... (the header's
  // formula), distance^2 = (a2 y - p2)^2 + a1^2 (1 - y^2), y = -a2 p2/(a1^2 - a2^2).
  EXPECT_NEAR(e.radius_about(Eigen::Vector3d::Zero()), 0.3, 1e-15);
  EXPECT_NEAR(e.radius_about({0.05, 0.0, 0.0}), 0.35, 1e-15);
  EXPECT_NEAR(e.radius_about({-0.05, 0.0, 0.0}), 0.35, 1e-15);
  const double p2 = 0.01, y = -0.2 * p2 / (0.09 - 0.04);
  EXPECT_NEAR(e.radius_about({0.0, p2, 0.0}), std::sqrt(std::pow(0.2 * y - p2, 2) + 0.09 * (1 - y * y)), 1e-15);
  EXPECT_DOUBLE_EQ(e.size(), 0.3);
  // Against the largest distance over a fine sampling of the surface: never exceeded, and reached
  // to the sampling's resolution (samples of the contact map, 40000 directions).
  const auto dirs = random_directions(40000, 3);
  for (const Eigen::Vector3d& p : std::vector<Eigen::Vector3d>{Eigen::Vector3d(0.02, -0.05, 0.03), Eigen::Vector3d(0.0, 0.15, 0.05),
                                  Eigen::Vector3d(0.0, 0.0, -0.09), Eigen::Vector3d(1.0, 2.0, -3.0)}) {
    double best = 0.0;
    for (const auto& g : dirs) best = std::max(best, (e.contact(g).r - p).norm());
    const double R = e.radius_about(p);
    EXPECT_GE(R, best * (1 - 1e-14)) << p.transpose();
    EXPECT_LE(R, best * (1 + 1e-4)) << p.transpose();
  }
}

TEST(DynShapesEllipsoid, ContainsItsInteriorOnly) {
  const Ellipsoid e(kAxes);
  EXPECT_TRUE(e.contains(Eigen::Vector3d::Zero()));
  EXPECT_TRUE(e.contains({0.199, 0.0, 0.0}));
  EXPECT_FALSE(e.contains({0.2, 0.0, 0.0}));
  EXPECT_FALSE(e.contains({0.0, 0.0, 0.031}));
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
