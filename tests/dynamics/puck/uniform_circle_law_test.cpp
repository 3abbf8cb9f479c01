// The test law's own checks against closed forms derived independently of it (docs/puck.md §3):
// uniform pressure over a circle of radius a, per kN and kNa.
#include "uniform_circle_law.h"

#include <gtest/gtest.h>

namespace frictionlab::testing {
namespace uniform_circle_law_test {

friction::FrictionForces at(double u) {
  const UniformCircleTestLaw law;
  return law.evaluate({u, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0});
}

TEST(DynPuckUniformCircleTestLaw, PureSpinGivesTwoThirdsKNa) {
  // M0 = ∫ k p rho dA = k N/(pi a^2) 2 pi a^3/3 = (2/3) k N a.
  EXPECT_NEAR(at(0.0).M, 2.0 / 3.0, 1e-13);
  EXPECT_NEAR(at(0.0).F1, 0.0, 1e-13);
}

TEST(DynPuckUniformCircleTestLaw, SlowSlipHasSlopeOne) {
  // F1 = k p (U/|Omega|) ∫_0^a ∫ sin^2 dphi drho = kN U/(a|Omega|) to first order; M - M0 = O(u^2).
  for (const double u : {1e-3, 1e-4}) {
    EXPECT_NEAR(at(u).F1 / u, 1.0, 5.0 * u) << u;
    EXPECT_NEAR(at(u).M, 2.0 / 3.0, 5.0 * u * u) << u;
  }
}

TEST(DynPuckUniformCircleTestLaw, FastSlipFollowsTheSecondMoment) {
  // F1 = kN (1 - <y^2>/(2 a^2 u^2) + ...), M = kNa <y^2>/(a^2 u), <y^2> = a^2/4 for uniform pressure.
  for (const double u : {50.0, 200.0}) {
    EXPECT_NEAR(at(u).M * u, 0.25, 2.0 / (u * u)) << u;
    EXPECT_NEAR((1.0 - at(u).F1) * 2.0 * u * u, 0.25, 5.0 / (u * u)) << u;
  }
}

TEST(DynPuckUniformCircleTestLaw, IsDissipativeSymmetricAndContinuousAcrossTheEdge) {
  for (const double u : {0.2, 0.653, 0.999, 1.001, 3.0}) {
    const friction::FrictionForces f = at(u);
    EXPECT_NEAR(f.F2, 0.0, 1e-12) << u;  // a circle: F2 = 0
    EXPECT_GT(f.F1, 0.0);
    EXPECT_GT(f.M, 0.0);
    EXPECT_LE(f.F1, 1.0);
  }
  // The ICR crossing the rim: both sides meet.
  EXPECT_NEAR(at(1.0 - 1e-7).F1, at(1.0 + 1e-7).F1, 1e-5);
  EXPECT_NEAR(at(1.0 - 1e-7).M, at(1.0 + 1e-7).M, 1e-5);
}

}  // namespace
}  // namespace frictionlab::testing
