#include "dynamics/body/tolerance_scales.h"

#include <gtest/gtest.h>

#include <limits>

#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace tolerance_scales_test {

TEST(DynToleranceScales, EachComponentIsScaledByItsOwnMagnitude) {
  BodyScales s;
  s.speed = 0.7;
  s.rate = 14.0;
  s.energy = 0.49;
  s.compression = 1e-4;
  const StateVector scale = absolute_tolerance_scales(s);
  StateVector expected;
  constexpr double inf = std::numeric_limits<double>::infinity();  // the pose: out of the error control
  expected << 0.7, 0.7, 0.7, 14.0, 14.0, 14.0, 1.0, 1.0, 1.0, 1e-4, 0.49, 0.49, inf, inf, inf, inf, inf, inf;
  for (int i = 0; i < StateLayout::kSize; ++i) EXPECT_EQ(scale[i], expected[i]) << "component " << i;
}

}  // namespace
}  // namespace frictionlab::dynamics
