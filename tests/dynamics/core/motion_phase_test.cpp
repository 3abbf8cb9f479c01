#include "dynamics/core/motion_phase.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace frictionlab::dynamics {
namespace motion_phase_test {

MotionPhaseRule rule() {
  MotionPhaseRule r;
  r.rest_slip_speed = 1e-3;
  r.rest_spin = 1e-2;
  r.settle_normal_speed = 0.05;
  return r;
}

TEST(DynMotionPhase, OutOfContactIsAirborneWhateverTheMotion) {
  EXPECT_EQ(rule().classify(false, 3.0, 40.0, 1.0), MotionPhase::airborne);
  EXPECT_EQ(rule().classify(false, 0.0, 0.0, 0.0), MotionPhase::airborne);
}

TEST(DynMotionPhase, ANormalSpeedAtTheSettlingSpeedIsBouncingBeforeAnyOtherPhase) {
  EXPECT_EQ(rule().classify(true, 3.0, 40.0, 0.05), MotionPhase::bouncing);
  EXPECT_EQ(rule().classify(true, 0.0, 0.0, -0.06), MotionPhase::bouncing);  // either direction
  EXPECT_EQ(rule().classify(true, 3.0, 40.0, 0.049), MotionPhase::sliding);
}

TEST(DynMotionPhase, SlipAndSpinAgainstTheRestThresholds) {
  EXPECT_EQ(rule().classify(true, 1e-3, 0.0, 0.0), MotionPhase::sliding);  // at the threshold: slides
  EXPECT_EQ(rule().classify(true, 0.9e-3, 1e-2, 0.0), MotionPhase::rolling_spin);
  EXPECT_EQ(rule().classify(true, 0.9e-3, -1e-2, 0.0), MotionPhase::rolling_spin);
  EXPECT_EQ(rule().classify(true, 0.9e-3, 0.9e-2, 0.0), MotionPhase::near_rest);
}

TEST(DynMotionPhase, ARigidPlaneNeverBounces) {
  MotionPhaseRule r = rule();
  r.settle_normal_speed = MotionPhaseRule{}.settle_normal_speed;  // the default: infinite
  EXPECT_EQ(r.classify(true, 1.0, 0.0, 1e300), MotionPhase::sliding);
}

TEST(DynMotionPhase, EveryPhaseHasItsCodeAndADistinctName) {
  std::set<std::string> names;
  int code = 0;
  for (MotionPhase p : motion_phases()) {
    EXPECT_EQ(static_cast<int>(p), code++);
    names.insert(std::string(to_string(p)));
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kMotionPhases));
}

}  // namespace
}  // namespace frictionlab::dynamics
