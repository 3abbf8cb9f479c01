// The example of docs/convex-bodies.md §7, compiled and run: a user's own shape, defined and
// registered in the user's code (no edit of dynamics/shapes/shape_registry.cpp), then made by kind
// like a built-in one. Keep this file and the page in step.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "dynamics/shapes/shape_registry.h"
#include "dynamics/shapes/tangent_plane.h"
#include "friction/support/errors.h"
#include "shape_test_support.h"

namespace user {

namespace sh = frictionlab::dynamics::shapes;

// --- docs/convex-bodies.md: example begins ---
// A ball of radius a centred at the shape origin: the point with outward normal -gamma is
// -a gamma, both principal radii are a (every point is an umbilic: the major direction is the
// reference tangent t1 by the rule of shape.h), and they never change.
class Ball final : public sh::Shape {
 public:
  Ball(double radius, std::string_view key) : a_(radius) {
    if (!(std::isfinite(radius) && radius > 0.0))
      throw frictionlab::support::invalid_value(key, radius, "it must be finite and > 0 m");
  }
  [[nodiscard]] std::string_view kind() const override { return "user-ball"; }
  [[nodiscard]] sh::SurfaceContact contact(const Eigen::Vector3d& gamma) const override {
    return {-a_ * gamma, a_, a_, sh::tangent_frame(gamma).t1};
  }
  [[nodiscard]] sh::RadiiGradient radii_gradient(const Eigen::Vector3d&, const sh::SurfaceContact&) const override {
    return {};  // zero: the radii do not depend on the orientation
  }
  [[nodiscard]] sh::SolidMassProperties homogeneous(double mass) const override {
    sh::validate_mass(mass);
    const double volume = 4.0 / 3.0 * std::numbers::pi * a_ * a_ * a_;
    return {mass, volume, Eigen::Vector3d::Zero(), 0.4 * mass * a_ * a_ * Eigen::Matrix3d::Identity()};
  }
  [[nodiscard]] double size() const override { return a_; }
  [[nodiscard]] double radius_about(const Eigen::Vector3d& p) const override { return a_ + p.norm(); }
  [[nodiscard]] bool contains(const Eigen::Vector3d& p) const override { return p.norm() < a_; }

 private:
  double a_;  // m
};

// Registered before main() runs: known to make_shape() and the listings from then on.
const sh::ShapeRegistrar ball_registrar{{
    .kind = "user-ball",
    .summary = "homogeneous ball (user example)",
    .parameters = {{"radius", 1, "m", "radius of the ball, > 0"}},
    .factory = [](const sh::ShapeArguments& args) {
      return std::make_shared<const Ball>(args.number("radius"), args.key("radius"));
    },
}};

// ... then, anywhere: sh::make_shape({"user-ball", {{"radius", {0.05}}}})
// --- docs/convex-bodies.md: example ends ---

}  // namespace user

namespace frictionlab::dynamics::shapes {
namespace user_shape_example_test {

TEST(DynShapesUserExample, IsMadeByKindAndKeepsTheContract) {
  const auto ball = make_shape({"user-ball", {{"radius", {0.05}}}});
  EXPECT_EQ(ball->kind(), "user-ball");
  for (const auto& g : testing::random_directions(50)) {
    const SurfaceContact c = ball->contact(g);
    EXPECT_EQ(c.R_major, 0.05);
    EXPECT_NEAR(c.major.dot(g), 0.0, 1e-15);
    // The contact map's differential is minus the radii matrix: here -a on the tangent plane.
    const auto [u, v] = testing::any_tangents(g);
    const Eigen::Vector3d dr = testing::sphere_derivative3(
        [&](const Eigen::Vector3d& x) { return ball->contact(x).r; }, g, u, 1e-3);
    EXPECT_EIGEN_NEAR(dr, Eigen::Vector3d(-0.05 * u), 1e-12);
  }
  const SolidMassProperties m = ball->homogeneous(2.0);
  EXPECT_NO_THROW(validate_inertia(m.inertia));
  EXPECT_NEAR(m.inertia(0, 0), 0.4 * 2.0 * 0.05 * 0.05, 1e-18);
  try {
    (void)make_shape({"user-ball", {{"radius", {-1.0}}}});
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "body.radius = -1 is invalid: it must be finite and > 0 m");
  }
  bool listed = false;
  for (const auto& k : shape_kinds()) listed = listed || k == "user-ball";
  EXPECT_TRUE(listed);
}

}  // namespace
}  // namespace frictionlab::dynamics::shapes
