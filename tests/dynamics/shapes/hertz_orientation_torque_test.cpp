#include "dynamics/shapes/hertz_orientation_torque.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <vector>

#include "dynamics/contact/hertz_patch.h"
#include "dynamics/shapes/body_of_revolution.h"
#include "dynamics/shapes/ellipsoid.h"
#include "dynamics/shapes/toroidal_disk.h"
#include "shape_test_support.h"

namespace frictionlab::dynamics::shapes {
namespace hertz_orientation_torque_test {

using testing::random_directions;

constexpr double kEStar = 1e9;     // Pa
constexpr double kDelta = 2e-5;    // m
// Central differences of V along the rotation (Richardson, h = 1e-3): ~1e-10 relative; the
// elasticities are exact to rounding (dynamics/contact/hertz_ellipse.h).
constexpr double kFdRelTol = 1e-7;

double stiffness(const Shape& s, const Eigen::Vector3d& g) {
  const SurfaceContact c = s.contact(g);
  return kEStar * hertz_ellipse(c.R_major, c.R_minor).stiffness_per_modulus;
}

Eigen::Vector3d torque(const Shape& s, const Eigen::Vector3d& g) {
  const SurfaceContact c = s.contact(g);
  const HertzEllipse e = hertz_ellipse(c.R_major, c.R_minor);
  const double lambda = kEStar * e.stiffness_per_modulus;
  return hertz_orientation_torque(g, kDelta, lambda, log_stiffness_gradient(c, s.radii_gradient(g, c), e));
}

// The torque does the work that turning the body at fixed delta stores in the contact:
// -omega . T = dV/dt with V = (2/5) lambda(gamma) delta^(5/2) and gamma' = gamma x omega.
void expect_conservative(const Shape& s, const std::vector<Eigen::Vector3d>& orientations) {
  const auto omegas = random_directions(3, 21);
  for (const auto& g : orientations) {
    const Eigen::Vector3d T = torque(s, g);
    EXPECT_NEAR(T.dot(g), 0.0, 1e-15 * T.norm());
    for (const auto& w : omegas) {
      const Eigen::Vector3d gdot = g.cross(w);
      const double rate = gdot.norm();
      const double dVdt = rate * testing::sphere_derivative(
                                     [&](const Eigen::Vector3d& x) {
                                       return 0.4 * stiffness(s, x) * kDelta * kDelta * std::sqrt(kDelta);
                                     },
                                     g, gdot / rate, 1e-3);
      EXPECT_NEAR(-w.dot(T), dVdt, kFdRelTol * T.norm() + 1e-25) << s.kind() << ", gamma = " << g.transpose();
    }
  }
}

TEST(DynShapesHertzOrientationTorque, IsConservativeOnATriaxialEllipsoid) {
  expect_conservative(Ellipsoid({0.2, 0.03, 0.02}), random_directions(60));
}

TEST(DynShapesHertzOrientationTorque, IsConservativeOnAToroidalDisk) {
  std::vector<Eigen::Vector3d> tilted;
  for (const auto& g : random_directions(80))
    if (std::hypot(g.x(), g.y()) > 0.1) tilted.push_back(g);
  expect_conservative(ToroidalDisk(0.05, 0.003), tilted);
}

TEST(DynShapesHertzOrientationTorque, IsConservativeOnTheEgg) {
  expect_conservative(BodyOfRevolution(Profile::paper_egg()), random_directions(60));
}

// For a body of revolution the general form reduces to docs/contact-models.md §3's
// (2/5) delta^(5/2) lambda'(gamma3) gamma x e3, which dynamics/contact/hertz_patch.h computes.
TEST(DynShapesHertzOrientationTorque, ReducesToTheBodyOfRevolutionsTorque) {
  const Profile egg = Profile::paper_egg();
  const BodyOfRevolution shape(egg);
  const ContactGeometry geometry(egg, 0.0);
  const HertzNormalContact today(kEStar);
  for (const auto& g : random_directions(500)) {
    const Eigen::Vector3d expected = today.evaluate(geometry, geometry.contact_point(g), g, -kDelta).torque;
    EXPECT_EIGEN_NEAR(torque(shape, g), expected, 1e-12 * expected.norm()) << "gamma = " << g.transpose();
  }
}

// The sphere: lambda is constant, no torque.
TEST(DynShapesHertzOrientationTorque, VanishesOnASphere) {
  const Ellipsoid sphere({0.1, 0.1, 0.1});
  for (const auto& g : random_directions(20)) EXPECT_EIGEN_NEAR(torque(sphere, g), Eigen::Vector3d::Zero(), 1e-16);  // V ~ 3e-4 J
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
