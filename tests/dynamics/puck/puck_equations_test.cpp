#include "dynamics/puck/puck_equations.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics::puck {
namespace puck_equations_test {

constexpr double kPi = std::numbers::pi;

Puck ellipse() { return {0.17, uniform_plate_inertia(0.17, 0.04, 0.02), 0.04, 0.02}; }

TEST(DynPuckEquations, EnergyFallsByTheFrictionPower) {
  // E' = m v.v' + I omega omega' = -(F1 U + M Omega): F2 is normal to the slip and does no work.
  const auto exact = friction::make_law("exact");
  const testing::SmoothTestLaw smooth;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  for (const friction::FrictionLaw* law : {static_cast<const friction::FrictionLaw*>(exact.get()),
                                           static_cast<const friction::FrictionLaw*>(&smooth)}) {
    const PuckOnPlane sys(ellipse(), 0.3, 9.81, *law);
    for (int i = 0; i < 50; ++i) {
      const PuckState x = make_puck_state({uni(rng), uni(rng)}, 3.0 * uni(rng), {uni(rng), uni(rng)}, 40.0 * uni(rng));
      const PuckContact c = sys.contact(x);
      PuckState d;
      sys.derivatives(x, c, {}, d);
      const double power = sys.puck().mass * velocity(x).dot(velocity(d)) + sys.puck().inertia * spin(x) * spin(d);
      EXPECT_NEAR(power, -(c.friction.F1 * c.U + c.friction.M * c.Omega), 1e-12) << law->name();
      EXPECT_NEAR(slide_work(d) + spin_work(d), -power, 1e-12);
      EXPECT_GE(slide_work(d) + spin_work(d), -1e-15) << law->name();  // dissipative laws
      EXPECT_EIGEN_NEAR(Eigen::Vector2d(position(d)), Eigen::Vector2d(velocity(x)), 0.0);
      EXPECT_EQ(heading(d), spin(x));
    }
  }
}

TEST(DynPuckEquations, TheSlipFrameAndTheAngleToTheMajorAxis) {
  const auto exact = friction::make_law("exact");
  const PuckOnPlane sys(ellipse(), 0.3, 9.81, *exact);
  // Heading 0 (major axis along x): slip along x gives psi = 0, along y psi = pi/2, along (1, 1)
  // psi = -pi/4 = 3 pi/4 (mod pi), for either sense of the slip.
  for (const auto& [v, psi] : {std::pair{Eigen::Vector2d(1, 0), 0.0}, std::pair{Eigen::Vector2d(0, 2), kPi / 2.0},
                               std::pair{Eigen::Vector2d(-1, -1), 3.0 * kPi / 4.0}, std::pair{Eigen::Vector2d(1, 1), 3.0 * kPi / 4.0}}) {
    const PuckContact c = sys.contact(make_puck_state({0, 0}, 0.0, v, 5.0));
    EXPECT_NEAR(c.psi, psi, 1e-15) << v.transpose();
    EXPECT_EIGEN_NEAR(c.e1, v.normalized(), 1e-15);
    EXPECT_DOUBLE_EQ(c.U, v.norm());
    // The friction opposes the slip: F . e1 = -F1 < 0; F2 acts along e2 = z x e1.
    EXPECT_NEAR(c.force.dot(c.e1), -c.friction.F1, 1e-15);
    EXPECT_NEAR(c.force.dot(Eigen::Vector2d(-c.e1.y(), c.e1.x())), -c.friction.F2, 1e-15);
  }
  // The patch turns with the body: heading pi/3 with slip along x gives psi = pi/3.
  EXPECT_NEAR(sys.contact(make_puck_state({0, 0}, kPi / 3.0, {2, 0}, 1.0)).psi, kPi / 3.0, 1e-15);
  // N = m g.
  EXPECT_DOUBLE_EQ(sys.contact(make_puck_state({0, 0}, 0.0, {1, 0}, 0.0)).N, 0.17 * 9.81);
}

TEST(DynPuckEquations, HeldComponentsStayAtZero) {
  const auto exact = friction::make_law("exact");
  const PuckOnPlane sys(ellipse(), 0.3, 9.81, *exact);
  const PuckState x = make_puck_state({0.1, 0.2}, 0.5, {0.0, 0.0}, 12.0);
  PuckState d;
  sys(x, {.slip = true, .spin = false}, d);
  EXPECT_EQ(velocity(d).norm(), 0.0);
  EXPECT_EQ(position(d).norm(), 0.0);
  // The held slip gives the law U = 0: the pure-spin moment (3/8) k N a E(e) (docs/model.md §2).
  const double e = std::sqrt(1.0 - 0.25);
  EXPECT_NEAR(-spin(d) * sys.puck().inertia, 3.0 / 8.0 * 0.3 * 0.17 * 9.81 * 0.04 * std::comp_ellint_2(e), 1e-12);
  sys(make_puck_state({0, 0}, 0.5, {1.0, 0.5}, 0.0), {.slip = false, .spin = true}, d);
  EXPECT_EQ(spin(d), 0.0);
  EXPECT_EQ(heading(d), 0.0);
  EXPECT_NEAR(velocity(d).norm(), 0.3 * 9.81, 1e-12);  // pure sliding: F1 = kN, F2 = 0
}

TEST(DynPuckEquations, RejectsAnInvalidPuck) {
  const auto exact = friction::make_law("exact");
  Puck p = ellipse();
  p.b = 0.05;  // b > a
  EXPECT_THROW(PuckOnPlane(p, 0.3, 9.81, *exact), std::invalid_argument);
  EXPECT_THROW(PuckOnPlane(ellipse(), -0.1, 9.81, *exact), std::invalid_argument);
  p = ellipse();
  p.inertia = 0.0;
  EXPECT_THROW(PuckOnPlane(p, 0.3, 9.81, *exact), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::puck
