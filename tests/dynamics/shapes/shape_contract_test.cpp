// What every shape promises (dynamics/shapes/shape.h), checked over each built-in kind by routes
// that do not use the shape's own formulas: the contact point is the lowest point; the differential
// of the contact map is minus the radii matrix (d r = -W d gamma on the tangent plane: the radii of
// curvature are how fast the contact point moves as the body turns); the gradients are those of
// the radii; no heap allocation per call; consistent mass properties and size.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "bench/allocation_counter.h"
#include "dynamics/shapes/shape_registry.h"
#include "shape_test_support.h"

namespace frictionlab::dynamics::shapes {
namespace shape_contract_test {

using testing::any_tangents;
using testing::random_directions;

// Central differences on the sphere (Richardson, step h), relative to the larger radius: truncation
// ~h^4 R^(5) (the slender ellipsoid's radii vary over ~0.1 rad: ~1e-11 R at h = 2e-4), rounding
// ~1e-16 R/h.
constexpr double kSphereFdStep = 2e-4;
constexpr double kSphereFdRelTol = 1e-8;

struct Case {
  std::string name;
  ShapeSpec spec;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
  return {
      {"triaxial_ellipsoid", {"ellipsoid", {{"semi_axes", {0.2, 0.03, 0.02}}}}},
      {"sphere_ellipsoid", {"ellipsoid", {{"semi_axes", {0.05, 0.05, 0.05}}}}},
      {"egg", {"revolution", {{"chi2", {0.06048, 0.3144, -2.704, 2.0}}}}},
      {"prolate_spheroid", {"revolution", {{"chi2", {0.0025, 0.0, -0.0625}}}}},  // 0.05^2 (1 - z^2/0.2^2)
      {"toroidal_disk", {"toroidal-disk", {{"radius", {0.05}}, {"rim_radius", {0.004}}}}},
  };
}

// Orientations away from the toroidal disk's flat faces (|gamma_h| >= 0.05), for every shape.
std::vector<Eigen::Vector3d> orientations(int n) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& g : random_directions(2 * n, 17))
    if (std::hypot(g.x(), g.y()) >= 0.05 && static_cast<int>(out.size()) < n) out.push_back(g);
  return out;
}

class DynShapesContract : public ::testing::TestWithParam<Case> {
 protected:
  std::shared_ptr<const Shape> shape_ = make_shape(GetParam().spec);
};

TEST_P(DynShapesContract, ContactIsTheLowestPointWithOrderedRadiiAndATangentMajorAxis) {
  const Shape& s = *shape_;
  const auto others = random_directions(300, 23);
  for (const auto& g : orientations(100)) {
    const SurfaceContact c = s.contact(g);
    EXPECT_GT(c.R_minor, 0.0);
    EXPECT_GE(c.R_major, c.R_minor);
    EXPECT_NEAR(c.major.norm(), 1.0, 1e-15);
    EXPECT_NEAR(c.major.dot(g), 0.0, 1e-15);
    for (const auto& o : others) {
      if (std::hypot(o.x(), o.y()) < 1e-3) continue;
      EXPECT_LE(c.r.dot(g), s.contact(o).r.dot(g) + 1e-16 * s.size());
    }
  }
}

TEST_P(DynShapesContract, TheContactMapsDifferentialIsMinusTheRadiiMatrix) {
  const Shape& s = *shape_;
  for (const auto& g : orientations(100)) {
    const SurfaceContact c = s.contact(g);
    const Eigen::Vector3d minor = g.cross(c.major);
    const auto [u, v] = any_tangents(g);
    for (const auto& tau : {u, v}) {
      const Eigen::Vector3d dr = testing::sphere_derivative3([&](const Eigen::Vector3d& x) { return s.contact(x).r; },
                                                             g, tau, kSphereFdStep);
      const Eigen::Vector3d W_tau = c.R_major * c.major.dot(tau) * c.major + c.R_minor * minor.dot(tau) * minor;
      EXPECT_EIGEN_NEAR(dr, -W_tau, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
    }
  }
}

TEST_P(DynShapesContract, RadiiGradientsAreTangentAndMatchCentralDifferences) {
  const Shape& s = *shape_;
  for (const auto& g : orientations(60)) {
    const SurfaceContact c = s.contact(g);
    const RadiiGradient grad = s.radii_gradient(g, c);
    EXPECT_NEAR(grad.major.dot(g), 0.0, 1e-15 * (grad.major.norm() + c.R_major));
    EXPECT_NEAR(grad.minor.dot(g), 0.0, 1e-15 * (grad.minor.norm() + c.R_major));
    const auto [u, v] = any_tangents(g);
    for (const auto& tau : {u, v}) {
      // The sum is defined everywhere (also at umbilics, e.g. on the sphere).
      const double dsum = testing::sphere_derivative(
          [&](const Eigen::Vector3d& x) {
            const SurfaceContact y = s.contact(x);
            return y.R_major + y.R_minor;
          },
          g, tau, kSphereFdStep);
      EXPECT_NEAR((grad.major + grad.minor).dot(tau), dsum, kSphereFdRelTol * c.R_major);
      if (c.R_major - c.R_minor > 1e-6 * c.R_major) {
        const double dmaj = testing::sphere_derivative(
            [&](const Eigen::Vector3d& x) { return s.contact(x).R_major; }, g, tau, kSphereFdStep);
        EXPECT_NEAR(grad.major.dot(tau), dmaj, kSphereFdRelTol * c.R_major) << "gamma = " << g.transpose();
      }
    }
  }
}

TEST_P(DynShapesContract, ContactAndGradientsAllocateNothing) {
  const Shape& s = *shape_;
  const auto dirs = orientations(200);
  (void)s.contact(dirs.front());
  const long long before = bench::g_allocations.load();
  double sink = 0.0;
  for (const auto& g : dirs) {
    const SurfaceContact c = s.contact(g);
    sink += c.R_major + s.radii_gradient(g, c).major.norm();
  }
  EXPECT_EQ(bench::g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST_P(DynShapesContract, MassPropertiesSizeAndInteriorAreConsistent) {
  const Shape& s = *shape_;
  const SolidMassProperties m = s.homogeneous(1.5);
  EXPECT_EQ(m.mass, 1.5);
  EXPECT_GT(m.volume, 0.0);
  EXPECT_NO_THROW(validate_inertia(m.inertia));
  EXPECT_TRUE(s.contains(m.centroid));
  EXPECT_EQ(s.size(), s.radius_about(Eigen::Vector3d::Zero()));
  double far = 0.0;
  for (const auto& g : random_directions(20000, 29)) {
    if (std::hypot(g.x(), g.y()) < 1e-3) continue;
    const SurfaceContact c = s.contact(g);
    far = std::max(far, c.r.norm());
    const double step = 1e-6 * s.size();
    EXPECT_TRUE(s.contains(c.r + step * g));   // gamma points into the body
    EXPECT_FALSE(s.contains(c.r - step * g));
  }
  EXPECT_GE(s.size(), far * (1 - 1e-15));
  EXPECT_LE(s.size(), far * (1 + 1e-3));
}

INSTANTIATE_TEST_SUITE_P(EveryBuiltInKind, DynShapesContract, ::testing::ValuesIn(cases()),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace frictionlab::dynamics::shapes
