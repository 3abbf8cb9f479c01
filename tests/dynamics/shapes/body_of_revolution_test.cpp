#include "dynamics/shapes/body_of_revolution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dynamics/body/body_scales.h"
#include "dynamics/shapes/contact_geometry.h"
#include "dynamics/shapes/mass_properties.h"
#include "dynamics/shapes/ellipsoid.h"
#include "shape_test_support.h"

namespace frictionlab::dynamics::shapes {
namespace body_of_revolution_test {

using testing::any_tangents;
using testing::random_directions;

// Central differences on the sphere (Richardson, h = 1e-3), relative to the larger radius.
constexpr double kSphereFdRelTol = 1e-8;
// Two independent geometry codes (Newton on the profile, closed form of the ellipsoid): a few ulps
// of the size after Newton's rounding amplified by 1/g' (docs/dynamics.md §2).
constexpr double kTwoCodesRelTol = 1e-12;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

::testing::AssertionResult same_bits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  for (int i = 0; i < 3; ++i)
    if (bits(a(i)) != bits(b(i)))
      return ::testing::AssertionFailure() << "component " << i << ": " << a(i) << " vs " << b(i);
  return ::testing::AssertionSuccess();
}

// Poles, 1e-8 and 3e-8 from them, the equator, and 20000 random orientations.
std::vector<Eigen::Vector3d> many_orientations() {
  std::vector<Eigen::Vector3d> g = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                    -Eigen::Vector3d::UnitY()};
  for (double t : {1e-8, 3e-8, 1e-6}) {
    g.emplace_back(std::sin(t), 0.0, std::cos(t));
    g.emplace_back(0.0, -std::sin(t), -std::cos(t));
    g.emplace_back(std::sin(t) * 0.6, std::sin(t) * 0.8, std::cos(t));
  }
  for (const auto& d : random_directions(20000, 11)) g.push_back(d);
  return g;
}

// The lead's wiring: the shape's r minus the centre of mass (0, 0, com) must be today's body-frame
// contact point, bit for bit, and the radii and the major axis those of ContactGeometry::patch().
TEST(DynShapesBodyOfRevolution, ContactPointMinusComIsContactGeometrysBitForBit) {
  const Profile egg = Profile::paper_egg();
  const BodyOfRevolution shape(egg);
  for (const double com : {0.0, homogeneous_mass_properties(egg, 2.0).centroid, -0.03}) {
    const ContactGeometry today(egg, com);
    const Eigen::Vector3d c0(0.0, 0.0, com);
    for (const auto& g : many_orientations()) {
      const SurfaceContact s = shape.contact(g);
      const ContactPoint t = today.contact_point(g);
      ASSERT_TRUE(same_bits(s.r - c0, t.r)) << "com = " << com << ", gamma = " << g.transpose();
      ASSERT_EQ(bits(s.R_major), bits(std::max(t.R_meridian, t.R_parallel)));
      ASSERT_EQ(bits(s.R_minor), bits(std::min(t.R_meridian, t.R_parallel)));
      ASSERT_TRUE(same_bits(s.major, ContactGeometry::patch(t, g, 1e-5).major));
    }
  }
}

TEST(DynShapesBodyOfRevolution, RadiiGradientsMatchCentralDifferencesOnTheSphere) {
  const BodyOfRevolution shape(Profile::paper_egg());
  for (const auto& g : random_directions(200)) {
    const SurfaceContact c = shape.contact(g);
    const RadiiGradient grad = shape.radii_gradient(g, c);
    const auto [u, v] = any_tangents(g);
    for (const auto& tau : {u, v}) {
      const double dmaj = testing::sphere_derivative(
          [&](const Eigen::Vector3d& x) { return shape.contact(x).R_major; }, g, tau, 1e-3);
      const double dmin = testing::sphere_derivative(
          [&](const Eigen::Vector3d& x) { return shape.contact(x).R_minor; }, g, tau, 1e-3);
      EXPECT_NEAR(grad.major.dot(tau), dmaj, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
      EXPECT_NEAR(grad.minor.dot(tau), dmin, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
    }
  }
}

TEST(DynShapesBodyOfRevolution, RadiiGradientsVanishAtThePoles) {
  const BodyOfRevolution shape(Profile::paper_egg());
  for (const Eigen::Vector3d& g : std::vector<Eigen::Vector3d>{Eigen::Vector3d::UnitZ(), Eigen::Vector3d(-Eigen::Vector3d::UnitZ())}) {
    const RadiiGradient grad = shape.radii_gradient(g, shape.contact(g));
    EXPECT_EQ(grad.major, Eigen::Vector3d::Zero());
    EXPECT_EQ(grad.minor, Eigen::Vector3d::Zero());
  }
}

// Two independent geometry codes: the spheroid as a profile (Newton on the contact equation,
// radii from P) and as an ellipsoid (closed form).
TEST(DynShapesBodyOfRevolution, SpheroidAgreesWithTheEllipsoid) {
  for (const auto& [a, c] : {std::pair{0.2, 0.05}, std::pair{0.05, 0.2}}) {
    const BodyOfRevolution rev(Profile::spheroid(a, c));
    const Ellipsoid ell({a, a, c});
    const double L = std::max(a, c);
    for (const auto& g : random_directions(2000, 5)) {
      const SurfaceContact p = rev.contact(g);
      const SurfaceContact q = ell.contact(g);
      EXPECT_EIGEN_NEAR(p.r, q.r, kTwoCodesRelTol * L);
      EXPECT_NEAR(p.R_major, q.R_major, kTwoCodesRelTol * p.R_major);
      EXPECT_NEAR(p.R_minor, q.R_minor, kTwoCodesRelTol * p.R_major);
      EXPECT_NEAR(std::abs(p.major.dot(q.major)), 1.0, kTwoCodesRelTol);
      const RadiiGradient gp = rev.radii_gradient(g, p);
      const RadiiGradient gq = ell.radii_gradient(g, q);
      EXPECT_EIGEN_NEAR(gp.major, gq.major, kTwoCodesRelTol * p.R_major) << "gamma = " << g.transpose();
      EXPECT_EIGEN_NEAR(gp.minor, gq.minor, kTwoCodesRelTol * p.R_major) << "gamma = " << g.transpose();
    }
  }
}

TEST(DynShapesBodyOfRevolution, HomogeneousMassPropertiesAreTheProfiles) {
  const Profile egg = Profile::paper_egg();
  const MassProperties h = homogeneous_mass_properties(egg, 2.0);
  const SolidMassProperties p = BodyOfRevolution(egg).homogeneous(2.0);
  EXPECT_EQ(p.mass, 2.0);
  EXPECT_EQ(p.volume, h.volume);
  EXPECT_EQ(p.centroid, Eigen::Vector3d(0.0, 0.0, h.centroid));
  EXPECT_EQ(p.inertia, Eigen::Vector3d(h.A, h.A, h.C).asDiagonal().toDenseMatrix());
  // A spheroid's against the ellipsoid's closed form (an independent computation).
  const SolidMassProperties s = BodyOfRevolution(Profile::spheroid(0.2, 0.05)).homogeneous(3.0);
  const SolidMassProperties e = Ellipsoid({0.2, 0.2, 0.05}).homogeneous(3.0);
  EXPECT_NEAR(s.volume, e.volume, 1e-14 * e.volume);
  EXPECT_EIGEN_NEAR(s.centroid, e.centroid, 1e-15);
  EXPECT_EIGEN_NEAR(s.inertia, e.inertia, 1e-14 * e.inertia.norm());
}

TEST(DynShapesBodyOfRevolution, RadiusAboutAPointIsTheFarthestSurfacePoint) {
  const Profile egg = Profile::paper_egg();
  const BodyOfRevolution shape(egg);
  // On the axis: body_size's own bits.
  for (const double z : {0.0, 0.07, -0.05}) EXPECT_EQ(shape.radius_about({0.0, 0.0, z}), body_size(egg, z));
  EXPECT_EQ(shape.size(), body_size(egg, 0.0));
  // A sphere about an off-axis point: R + |p|.
  const BodyOfRevolution sphere(Profile::sphere(0.1));
  EXPECT_NEAR(sphere.radius_about({0.03, -0.04, 0.02}), 0.1 + std::sqrt(0.0029), 1e-15);
  // Off the axis, against a fine sampling of the contact map.
  const auto dirs = random_directions(40000, 3);
  for (const Eigen::Vector3d& p : std::vector<Eigen::Vector3d>{Eigen::Vector3d(0.05, 0.0, 0.07), Eigen::Vector3d(-0.1, 0.2, -0.05)}) {
    double best = 0.0;
    for (const auto& g : dirs) best = std::max(best, (shape.contact(g).r - p).norm());
    const double R = shape.radius_about(p);
    EXPECT_GE(R, best * (1 - 1e-14)) << p.transpose();
    EXPECT_LE(R, best * (1 + 1e-3)) << p.transpose();
  }
}

TEST(DynShapesBodyOfRevolution, ContainsItsInteriorOnly) {
  const BodyOfRevolution shape(Profile::paper_egg());
  EXPECT_TRUE(shape.contains({0.0, 0.0, 0.07}));
  EXPECT_FALSE(shape.contains({0.0, 0.0, 0.26}));
  EXPECT_FALSE(shape.contains({0.0, 0.0, -0.1}));
  EXPECT_FALSE(shape.contains({0.3, 0.0, 0.07}));
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
