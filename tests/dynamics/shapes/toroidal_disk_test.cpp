#include "dynamics/shapes/toroidal_disk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <gsl/gsl_integration.h>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "shape_test_support.h"

namespace frictionlab::dynamics::shapes {
namespace toroidal_disk_test {

using testing::any_tangents;
using testing::random_directions;

constexpr double kR = 0.05;     // disk radius to the rim tube's centre circle, m
constexpr double kRho = 0.004;  // rim radius, m
constexpr double kClosedFormRelTol = 1e-14;
// Finite differences of the implicit torus (Richardson, step 1e-4 of the size): see ellipsoid_test.
constexpr double kImplicitFdRelTol = 1e-6;
constexpr double kSphereFdRelTol = 1e-8;

// The torus (sqrt(x1^2 + x2^2) - R)^2 + x3^2 = rho^2 (its outer half bounds the disk).
double torus_f(const Eigen::Vector3d& x) {
  const double s = std::hypot(x.x(), x.y()) - kR;
  return s * s + x.z() * x.z() - kRho * kRho;
}

// Orientations away from the flat faces: |gamma_h| >= 0.05.
std::vector<Eigen::Vector3d> tilted_directions(int n) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& g : random_directions(2 * n, 13))
    if (std::hypot(g.x(), g.y()) >= 0.05 && static_cast<int>(out.size()) < n) out.push_back(g);
  return out;
}

TEST(DynShapesToroidalDisk, VerticalDiskTouchesAtTheRimsEquator) {
  const ToroidalDisk d(kR, kRho);
  for (const auto& g : random_directions(50)) {
    const Eigen::Vector3d h = Eigen::Vector3d(g.x(), g.y(), 0.0).normalized();  // axis horizontal
    const SurfaceContact c = d.contact(h);
    EXPECT_EIGEN_NEAR(c.r, Eigen::Vector3d(-(kR + kRho) * h), kClosedFormRelTol * kR);
    EXPECT_NEAR(c.R_major, kR + kRho, kClosedFormRelTol * kR);  // the parallel: the rim's equator
    EXPECT_NEAR(c.R_minor, kRho, kClosedFormRelTol * kRho);     // across the tube
    EXPECT_EIGEN_NEAR(c.major, Eigen::Vector3d(h.y(), -h.x(), 0.0), 1e-15);  // horizontal, along the rim
    const RadiiGradient grad = d.radii_gradient(h, c);
    EXPECT_EIGEN_NEAR(grad.major, Eigen::Vector3d::Zero(), 1e-17);  // R_major is extreme at gamma3 = 0
    EXPECT_EQ(grad.minor, Eigen::Vector3d::Zero());
  }
}

TEST(DynShapesToroidalDisk, TiltedDiskMatchesTheTorusClosedForms) {
  const ToroidalDisk d(kR, kRho);
  for (const auto& g : tilted_directions(100)) {
    const SurfaceContact c = d.contact(g);
    // On the torus, on its outer half, with outward normal grad f/|grad f| = -gamma.
    EXPECT_NEAR(torus_f(c.r), 0.0, 1e-17);
    const double s = std::hypot(c.r.x(), c.r.y());
    EXPECT_GE(s, kR);
    const Eigen::Vector3d grad_f(2 * (s - kR) * c.r.x() / s, 2 * (s - kR) * c.r.y() / s, 2 * c.r.z());
    EXPECT_EIGEN_NEAR(grad_f.normalized(), -g, 1e-12);
    // Meusnier: the parallel circle through r has radius s; the normal makes the angle with its
    // plane whose cosine is |gamma_h|; across the tube the radius is rho.
    const double sigma = std::hypot(g.x(), g.y());
    EXPECT_NEAR(c.R_major, s / sigma, 1e-13 * c.R_major);
    EXPECT_NEAR(c.R_minor, kRho, kClosedFormRelTol * kRho);
    EXPECT_NEAR(c.major.z(), 0.0, 1e-16);
    EXPECT_NEAR(c.major.dot(g), 0.0, 1e-16);
    EXPECT_NEAR(c.major.norm(), 1.0, 1e-15);
    // And against finite differences of the implicit surface.
    const auto [u, v] = any_tangents(g);
    const Eigen::Matrix2d K = testing::implicit_curvature(torus_f, c.r, g, u, v, 1e-4 * kR);
    const Eigen::Matrix2d R = testing::radii_matrix(c.R_major, c.R_minor, c.major, g, u, v);
    EXPECT_EIGEN_NEAR(K * R, Eigen::Matrix2d::Identity(), kImplicitFdRelTol * c.R_major / c.R_minor)
        << "gamma = " << g.transpose();
  }
}

TEST(DynShapesToroidalDisk, RadiiGradientsMatchCentralDifferencesOnTheSphere) {
  const ToroidalDisk d(kR, kRho);
  for (const auto& g : tilted_directions(100)) {
    const SurfaceContact c = d.contact(g);
    const RadiiGradient grad = d.radii_gradient(g, c);
    EXPECT_NEAR(grad.major.dot(g), 0.0, 1e-15 * c.R_major);
    const auto [u, v] = any_tangents(g);
    for (const auto& tau : {u, v}) {
      const double dmaj = testing::sphere_derivative(
          [&](const Eigen::Vector3d& x) { return d.contact(x).R_major; }, g, tau, 1e-4);
      EXPECT_NEAR(grad.major.dot(tau), dmaj, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
    }
  }
}

TEST(DynShapesToroidalDisk, ContactIsTheLowestPoint) {
  const ToroidalDisk d(kR, kRho);
  // Surface points: the torus's outer half and the two faces (points of the disk plus rho e3).
  std::vector<Eigen::Vector3d> surface;
  for (int i = 0; i < 64; ++i) {
    const double az = 2 * std::numbers::pi * i / 64;
    const Eigen::Vector3d e(std::cos(az), std::sin(az), 0.0);
    for (int j = 0; j <= 32; ++j) {
      const double phi = -std::numbers::pi / 2 + std::numbers::pi * j / 32;
      surface.push_back((kR + kRho * std::cos(phi)) * e + kRho * std::sin(phi) * Eigen::Vector3d::UnitZ());
    }
    for (double f : {0.0, 0.5, 1.0}) {
      surface.push_back(f * kR * e + kRho * Eigen::Vector3d::UnitZ());
      surface.push_back(f * kR * e - kRho * Eigen::Vector3d::UnitZ());
    }
  }
  for (const auto& g : tilted_directions(100)) {
    const double low = d.contact(g).r.dot(g);
    for (const auto& x : surface) EXPECT_LE(low, x.dot(g) + 1e-17);
  }
}

TEST(DynShapesToroidalDisk, FaceClearanceIsTheHeightOfTheFacesLowestEdgePoint) {
  const ToroidalDisk d(kR, kRho);
  for (const auto& g : tilted_directions(50)) {
    const double low = d.contact(g).r.dot(g);
    // The faces' edges: circles of radius R at x3 = ±rho. Their lowest point by a coarse search
    // over the azimuth, refined by golden sections (the height is smooth and unimodal there).
    double edge = INFINITY;
    for (double z : {kRho, -kRho}) {
      const auto height = [&](double az) { return Eigen::Vector3d(kR * std::cos(az), kR * std::sin(az), z).dot(g); };
      constexpr int n = 720;
      const double step = 2 * std::numbers::pi / n;
      int best = 0;
      for (int i = 1; i < n; ++i)
        if (height(i * step) < height(best * step)) best = i;
      double lo = (best - 1) * step, hi = (best + 1) * step;
      const double k = (std::sqrt(5.0) - 1) / 2;
      while (hi - lo > 1e-12) {
        const double a = hi - k * (hi - lo), b = lo + k * (hi - lo);
        if (height(a) < height(b)) hi = b;
        else lo = a;
      }
      edge = std::min(edge, height(0.5 * (lo + hi)));
    }
    EXPECT_NEAR(d.face_clearance(g), edge - low, 1e-16) << "gamma = " << g.transpose();
    EXPECT_NEAR(d.face_clearance(g), kRho * (1.0 - std::abs(g.z())), 1e-17);
  }
}

TEST(DynShapesToroidalDisk, FlatFaceIsOutsideTheDomain) {
  const ToroidalDisk d(kR, kRho);
  for (const Eigen::Vector3d& g : std::vector<Eigen::Vector3d>{Eigen::Vector3d::UnitZ(), Eigen::Vector3d(-Eigen::Vector3d::UnitZ()),
                                  Eigen::Vector3d(1e-7, 0.0, 1.0).normalized(),
                                  Eigen::Vector3d(0.0, -0.9e-6, -1.0).normalized()}) {
    try {
      (void)d.contact(g);
      ADD_FAILURE() << "no FlatFaceContact at gamma = " << g.transpose();
    } catch (const FlatFaceContact& e) {
      const std::domain_error& base = e;  // a domain error, not an input error
      const std::string what = base.what();
      EXPECT_NE(what.find("rad from the vertical"), std::string::npos) << what;
      EXPECT_NE(what.find("flat face"), std::string::npos) << what;
      EXPECT_EQ(e.sigma(), std::hypot(g.x(), g.y()));
      EXPECT_LT(e.sigma(), ToroidalDisk::kMinTilt);
    }
  }
  // Just inside the domain: a finite contact with the closed-form radii.
  const Eigen::Vector3d g = Eigen::Vector3d(1.01e-6, 0.0, 1.0).normalized();
  const SurfaceContact c = d.contact(g);
  EXPECT_NEAR(c.R_major, kR / g.x() + kRho, 1e-15 * c.R_major);
}

// ∫ over the solid of revolution with the weight 2 pi s (s the distance from the axis): the
// cylinder s <= R, |z| <= rho, and the half tube s = R + rho sin a, z = rho cos a sin b
// (a in [0, pi/2], b in [-pi/2, pi/2], dA = rho^2 cos^2 a cos b da db). Gauss-Legendre throughout.
template <class F>
double disk_quadrature(F&& f) {
  constexpr std::size_t n = 30;
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)> t(
      gsl_integration_glfixed_table_alloc(n), &gsl_integration_glfixed_table_free);
  const auto node = [&](double lo, double hi, std::size_t i) {
    double x = 0, w = 0;
    gsl_integration_glfixed_point(lo, hi, i, &x, &w, t.get());
    return std::pair{x, w};
  };
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const auto [s, ws] = node(0.0, kR, i);
      const auto [z, wz] = node(-kRho, kRho, j);
      sum += ws * wz * 2 * std::numbers::pi * s * f(s, z);
      const auto [a, wa] = node(0.0, std::numbers::pi / 2, i);
      const auto [b, wb] = node(-std::numbers::pi / 2, std::numbers::pi / 2, j);
      const double st = kR + kRho * std::sin(a), zt = kRho * std::cos(a) * std::sin(b);
      sum += wa * wb * kRho * kRho * std::cos(a) * std::cos(a) * std::cos(b) * 2 * std::numbers::pi * st * f(st, zt);
    }
  }
  return sum;
}

TEST(DynShapesToroidalDisk, HomogeneousMassPropertiesMatchQuadrature) {
  const double m = 0.3048;
  const SolidMassProperties p = ToroidalDisk(kR, kRho).homogeneous(m);
  const double V = disk_quadrature([](double, double) { return 1.0; });
  EXPECT_NEAR(p.volume, V, 1e-13 * V);
  const double rho = m / V;
  const double C = rho * disk_quadrature([](double s, double) { return s * s; });
  const double A = rho * disk_quadrature([](double s, double z) { return 0.5 * s * s + z * z; });
  EXPECT_NEAR(p.inertia(2, 2), C, 1e-13 * C);
  EXPECT_NEAR(p.inertia(0, 0), A, 1e-13 * A);
  EXPECT_NEAR(p.inertia(1, 1), A, 1e-13 * A);
  EXPECT_EQ(p.inertia(0, 1), 0.0);
  EXPECT_EQ(p.centroid, Eigen::Vector3d::Zero());
  // A thin disk tends to the flat disk's m R^2/2 and m R^2/4.
  const SolidMassProperties thin = ToroidalDisk(kR, 1e-7).homogeneous(m);
  EXPECT_NEAR(thin.inertia(2, 2), m * kR * kR / 2, 1e-5 * m * kR * kR);
  EXPECT_NEAR(thin.inertia(0, 0), m * kR * kR / 4, 1e-5 * m * kR * kR);
}

TEST(DynShapesToroidalDisk, RadiiMustBePositiveAndFinite) {
  EXPECT_THROW((void)ToroidalDisk(0.0, 0.01), std::invalid_argument);
  EXPECT_THROW((void)ToroidalDisk(0.05, -0.01), std::invalid_argument);
  try {
    (void)ToroidalDisk(0.05, NAN, "body.radius", "body.rim_radius");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("body.rim_radius = "), std::string::npos) << e.what();
  }
}

TEST(DynShapesToroidalDisk, SizeRadiusAboutAndContains) {
  const ToroidalDisk d(kR, kRho);
  EXPECT_DOUBLE_EQ(d.size(), kR + kRho);
  EXPECT_DOUBLE_EQ(d.radius_about(Eigen::Vector3d::Zero()), kR + kRho);
  // Against a fine sampling of the surface (torus outer half and the faces' edges suffice: the
  // farthest point of a disk plus a ball lies on the torus).
  for (const Eigen::Vector3d& p : std::vector<Eigen::Vector3d>{Eigen::Vector3d(0.01, -0.02, 0.003), Eigen::Vector3d(0.0, 0.0, -0.1)}) {
    double best = 0.0;
    for (int i = 0; i < 720; ++i) {
      const double az = 2 * std::numbers::pi * i / 720;
      const Eigen::Vector3d e(std::cos(az), std::sin(az), 0.0);
      for (int j = 0; j <= 360; ++j) {
        const double phi = -std::numbers::pi / 2 + std::numbers::pi * j / 360;
        const Eigen::Vector3d x = (kR + kRho * std::cos(phi)) * e + kRho * std::sin(phi) * Eigen::Vector3d::UnitZ();
        best = std::max(best, (x - p).norm());
      }
    }
    EXPECT_GE(d.radius_about(p), best * (1 - 1e-14));
    EXPECT_LE(d.radius_about(p), best * (1 + 1e-4));
  }
  EXPECT_TRUE(d.contains(Eigen::Vector3d::Zero()));
  EXPECT_TRUE(d.contains({kR + 0.99 * kRho, 0.0, 0.0}));
  EXPECT_FALSE(d.contains({kR + 1.01 * kRho, 0.0, 0.0}));
  EXPECT_FALSE(d.contains({0.0, 0.0, 1.01 * kRho}));
  EXPECT_FALSE(d.contains({kR + 0.8 * kRho, 0.0, 0.8 * kRho}));  // outside the rounded corner
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
