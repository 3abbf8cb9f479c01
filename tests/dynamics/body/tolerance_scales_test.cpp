#include "dynamics/body/tolerance_scales.h"

#include <gtest/gtest.h>

#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace {

TEST(DynToleranceScales, EachComponentIsScaledByItsOwnMagnitude) {
  BodyScales s;
  s.speed = 0.7;
  s.rate = 14.0;
  s.energy = 0.49;
  s.compression = 1e-4;
  const StateVector scale = absolute_tolerance_scales(s);
  StateVector expected;
  expected << 0.7, 0.7, 0.7, 14.0, 14.0, 14.0, 1.0, 1.0, 1.0, 1e-4, 0.49, 0.49;
  EXPECT_EIGEN_NEAR(scale, expected, 0.0);
}

}  // namespace
}  // namespace frictionlab::dynamics
