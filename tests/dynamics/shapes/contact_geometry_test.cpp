#include "dynamics/shapes/contact_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace contact_geometry_test {

// Newton is run to rounding; the contact point and radii come out within a few ulps of the body
// size (1e-13 relative leaves room for the 1/g' amplification of the rounding in gamma3).
constexpr double kGeomRelTol = 1e-13;

Eigen::Vector3d unit(double x, double y, double z) { return Eigen::Vector3d(x, y, z).normalized(); }

// Orientations: the poles exactly, 1e-8 from them, and away (deterministic random).
std::vector<Eigen::Vector3d> orientations() {
  std::vector<Eigen::Vector3d> g = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
  for (double t : {1e-8, 1e-8 * 3}) {
    g.emplace_back(std::sin(t), 0.0, std::cos(t));
    g.emplace_back(0.0, -std::sin(t), -std::cos(t));
    g.emplace_back(std::sin(t) * 0.6, std::sin(t) * 0.8, std::cos(t));
  }
  g.push_back(Eigen::Vector3d::UnitX());
  g.push_back(-Eigen::Vector3d::UnitY());
  std::mt19937 rng(42);
  std::normal_distribution<double> n;
  for (int i = 0; i < 20; ++i) g.push_back(unit(n(rng), n(rng), n(rng)));
  return g;
}

TEST(DynContactGeometry, SphereContactPointIsMinusRGamma) {
  const double R = 0.1;
  const ContactGeometry geo(Profile::sphere(R), 0.0);
  for (const auto& g : orientations()) {
    const ContactPoint c = geo.contact_point(g);
    EXPECT_EIGEN_NEAR(c.r, Eigen::Vector3d(-R * g), kGeomRelTol * R);
    EXPECT_NEAR(c.R_meridian, R, kGeomRelTol * R);
    EXPECT_NEAR(c.R_parallel, R, kGeomRelTol * R);
  }
}

TEST(DynContactGeometry, PolesAreExact) {
  const Profile egg = Profile::paper_egg();
  const ContactGeometry geo(egg, 0.0);
  const ContactPoint down = geo.contact_point(Eigen::Vector3d::UnitZ());  // axis up: touches at z_lo
  EXPECT_EQ(down.z, egg.z_lo());
  EXPECT_EQ(down.r, Eigen::Vector3d(0.0, 0.0, egg.z_lo()));
  const ContactPoint up = geo.contact_point(-Eigen::Vector3d::UnitZ());
  EXPECT_EQ(up.z, egg.z_hi());
  // Both radii are P'/2 at a pole.
  const double half_slope = 0.5 * egg.chi2().jet(egg.z_lo()).d1;
  EXPECT_NEAR(down.R_meridian, half_slope, kGeomRelTol * half_slope);
  EXPECT_NEAR(down.R_parallel, half_slope, kGeomRelTol * half_slope);
  EXPECT_EQ(geo.solve_contact_z(1.0), egg.z_lo());
  EXPECT_EQ(geo.solve_contact_z(-1.0), egg.z_hi());
}

TEST(DynContactGeometry, SpheroidMatchesClosedForm) {
  // x^2/a^2 + z^2/c^2 = 1: r = -(a^2 g1, a^2 g2, c^2 g3)/D, D = sqrt(a^2 rho^2 + c^2 g3^2),
  // R_parallel = a^2/D, R_meridian = a^2 c^2 / D^3 (rho^2 = g1^2 + g2^2).
  for (const auto& [a, c] : {std::pair{0.2, 0.05}, std::pair{0.05, 0.2}}) {
    const ContactGeometry geo(Profile::spheroid(a, c), 0.0);
    for (const auto& g : orientations()) {
      const double rho2 = g.x() * g.x() + g.y() * g.y();
      const double D = std::sqrt(a * a * rho2 + c * c * g.z() * g.z());
      const Eigen::Vector3d r = -Eigen::Vector3d(a * a * g.x(), a * a * g.y(), c * c * g.z()) / D;
      const ContactPoint p = geo.contact_point(g);
      const double L = std::max(a, c);
      EXPECT_EIGEN_NEAR(p.r, r, kGeomRelTol * L) << "a = " << a << ", c = " << c;
      EXPECT_NEAR(p.R_parallel, a * a / D, kGeomRelTol * a * a / D);
      EXPECT_NEAR(p.R_meridian, a * a * c * c / (D * D * D), kGeomRelTol * a * a * c * c / (D * D * D));
    }
  }
}

// dR/dgamma3 against the spheroid's closed form above: D^2 = a^2 + (c^2 - a^2) g3^2, so
// D' = (c^2 - a^2) g3/D, dR_parallel/dg3 = -a^2 D'/D^2, dR_meridian/dg3 = -3 a^2 c^2 D'/D^4.
TEST(DynContactGeometry, RadiiSlopesMatchTheSpheroidsClosedForm) {
  for (const auto& [a, c] : {std::pair{0.2, 0.05}, std::pair{0.05, 0.2}}) {
    const ContactGeometry geo(Profile::spheroid(a, c), 0.0);
    const double scale = 3.0 * std::pow(std::max(a, c) / std::min(a, c), 3) * std::max(a, c);  // bounds |R'|
    for (const auto& g : orientations()) {
      const double g3 = g.z();
      const double D = std::sqrt(a * a + (c * c - a * a) * g3 * g3);
      const double dD = (c * c - a * a) * g3 / D;
      const RadiiSlope s = geo.radii_slope(geo.contact_point(g));
      EXPECT_NEAR(s.parallel, -a * a * dD / (D * D), kGeomRelTol * scale) << "g3 = " << g3;
      EXPECT_NEAR(s.meridian, -3.0 * a * a * c * c * dD / (D * D * D * D), kGeomRelTol * scale) << "g3 = " << g3;
    }
  }
}

TEST(DynContactGeometry, ASpheresRadiiDoNotChangeWithTheOrientation) {
  const ContactGeometry geo(Profile::sphere(0.1), 0.0);
  for (const auto& g : orientations()) {
    const RadiiSlope s = geo.radii_slope(geo.contact_point(g));
    EXPECT_EQ(s.parallel, 0.0);
    EXPECT_EQ(s.meridian, 0.0);
  }
}

// On the egg (no closed form): central differences of the radii in gamma3, step 1e-6
// (truncation ~1e-12 of the third derivative; rounding ~1e-16 R / 1e-6 = 1e-10 R).
TEST(DynContactGeometry, RadiiSlopesMatchCentralDifferencesOnTheEgg) {
  const ContactGeometry geo(Profile::paper_egg(), 0.05);
  const auto at = [&](double g3) { return geo.contact_point({std::sqrt((1.0 - g3) * (1.0 + g3)), 0.0, g3}); };
  for (const double g3 : {-0.999, -0.9, -0.5, -0.1, 0.0, 0.2, 0.6, 0.97, 0.999}) {
    const double h = 1e-6;
    const ContactPoint lo = at(g3 - h), hi = at(g3 + h), c = at(g3);
    const RadiiSlope s = geo.radii_slope(c);
    const double tol = 1e-8 * std::max(c.R_meridian, c.R_parallel);
    EXPECT_NEAR(s.meridian, (hi.R_meridian - lo.R_meridian) / (2.0 * h), tol) << "g3 = " << g3;
    EXPECT_NEAR(s.parallel, (hi.R_parallel - lo.R_parallel) / (2.0 * h), tol) << "g3 = " << g3;
  }
}

TEST(DynContactGeometry, EggContactPointHasOutwardNormalMinusGamma) {
  const Profile egg = Profile::paper_egg();
  const double com = 0.07;
  const ContactGeometry geo(egg, com);
  for (const auto& g : orientations()) {
    const ContactPoint c = geo.contact_point(g);
    const PolynomialJet j = egg.chi2().jet(c.z);
    const double x = c.r.x(), y = c.r.y();
    // On the surface: x^2 + y^2 = P(z), z = xi3 + com.
    EXPECT_NEAR(x * x + y * y, j.value, kGeomRelTol * 0.1);
    EXPECT_NEAR(c.r.z() + com, c.z, 1e-16);
    // Outward normal (2x, 2y, -P') / |.| equals -gamma.
    const Eigen::Vector3d n = Eigen::Vector3d(2 * x, 2 * y, -j.d1).normalized();
    EXPECT_EIGEN_NEAR(n, Eigen::Vector3d(-g), 1e-12);
  }
}

TEST(DynContactGeometry, ContactCoordinateIsMonotoneAndContinuousThroughThePoles) {
  const ContactGeometry geo(Profile::paper_egg(), 0.0);
  double previous = geo.solve_contact_z(-1.0);
  for (int i = 1; i <= 2000; ++i) {
    const double g3 = -1.0 + 2.0 * i / 2000.0;
    const double z = geo.solve_contact_z(g3);
    EXPECT_LT(z, previous) << "gamma3 = " << g3;
    previous = z;
  }
  // Near the lower pole z - z_lo ~ (1 - gamma3) P'/2 (from g = 1 - 2P/P'^2 + ...).
  const Profile egg = Profile::paper_egg();
  const double slope = egg.chi2().jet(egg.z_lo()).d1;
  for (double d : {1e-8, 1e-10, 1e-12}) {
    const double z = geo.solve_contact_z(1.0 - d);
    EXPECT_NEAR((z - egg.z_lo()) / (d * slope / 2.0), 1.0, 1e-3) << "1 - gamma3 = " << d;
  }
}

TEST(DynContactGeometry, SpherePatchIsTheDupinCircle) {
  const double R = 0.1, depth = 1e-4;
  const ContactGeometry geo(Profile::sphere(R), 0.0);
  for (const auto& g : orientations()) {
    const PatchShape p = ContactGeometry::patch(geo.contact_point(g), g, depth);
    EXPECT_TRUE(p.circle);
    EXPECT_NEAR(p.a, std::sqrt(2 * depth * R), kGeomRelTol * p.a);
    EXPECT_EQ(p.a, p.b);
    EXPECT_NEAR(p.major.dot(g), 0.0, 1e-15);
    EXPECT_NEAR(p.major.norm(), 1.0, 1e-15);
  }
}

TEST(DynContactGeometry, SpheroidPatchAxesFollowThePrincipalDirections) {
  const double a = 0.2, c = 0.05, depth = 1e-4;
  const ContactGeometry geo(Profile::spheroid(a, c), 0.0);
  // On the equator of an oblate spheroid: R_parallel = a, R_meridian = c^2/a; the major axis is
  // the parallel (horizontal in the body: along body e2 for gamma = e1).
  const Eigen::Vector3d g = Eigen::Vector3d::UnitX();
  const PatchShape p = ContactGeometry::patch(geo.contact_point(g), g, depth);
  EXPECT_FALSE(p.circle);
  EXPECT_NEAR(p.a, std::sqrt(2 * depth * a), kGeomRelTol);
  EXPECT_NEAR(p.b, std::sqrt(2 * depth * c * c / a), kGeomRelTol);
  EXPECT_NEAR(std::abs(p.major.y()), 1.0, 1e-15);
  // Tilted: for a prolate spheroid near the equator the meridian is the major axis; the
  // meridian direction is the projection of e3 onto the contact plane.
  const ContactGeometry pro(Profile::spheroid(0.05, 0.2), 0.0);
  const Eigen::Vector3d gt = unit(1.0, 0.5, 0.3);
  const ContactPoint cp = pro.contact_point(gt);
  ASSERT_GT(cp.R_meridian, cp.R_parallel);
  const PatchShape pt = ContactGeometry::patch(cp, gt, depth);
  const Eigen::Vector3d meridian = (Eigen::Vector3d::UnitZ() - gt.z() * gt).normalized();
  EXPECT_EIGEN_NEAR(pt.major, meridian, 1e-15);
  EXPECT_NEAR(pt.a, std::sqrt(2 * depth * cp.R_meridian), kGeomRelTol);
}

TEST(DynContactGeometry, PatchAtAPoleIsACircleWithBodyE1AsMajorAxis) {
  const ContactGeometry geo(Profile::spheroid(0.2, 0.05), 0.0);
  const Eigen::Vector3d g = Eigen::Vector3d::UnitZ();
  const PatchShape p = ContactGeometry::patch(geo.contact_point(g), g, 1e-4);
  EXPECT_TRUE(p.circle);
  EXPECT_EQ(p.major, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(p.a, std::sqrt(2e-4 * 0.2 * 0.2 / 0.05), kGeomRelTol);
  // 1e-8 from the pole the radii differ by ~1e-16 relative: still a circle, b = a.
  const Eigen::Vector3d gn(1e-8, 0.0, std::sqrt(1.0 - 1e-16));
  const PatchShape pn = ContactGeometry::patch(geo.contact_point(gn), gn, 1e-4);
  EXPECT_TRUE(pn.circle);
  EXPECT_NEAR(pn.a, p.a, 1e-12 * p.a);
}

}  // namespace
}  // namespace frictionlab::dynamics
