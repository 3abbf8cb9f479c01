#include "dynamics/core/settling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace frictionlab::dynamics {
namespace settling_test {

SettleRule rule(double time, double speed) { return resolve_settling({time, speed}, BodyScales{}); }

TEST(DynSettling, SettlesAfterTheSettlingTimeInContactWithASlowNormalMotion) {
  ContactSettling s(rule(0.1, 0.05));
  s.update(0.0, true, 0.0);  // the window opens with the run
  EXPECT_FALSE(s.settled(0.0));
  s.update(0.05, true, 0.04);
  EXPECT_FALSE(s.settled(0.05));
  s.update(0.1, true, -0.04);
  EXPECT_TRUE(s.settled(0.1));
  EXPECT_EQ(s.since(), 0.0);
}

TEST(DynSettling, ALiftOffOrAFastNormalMotionRestartsTheWindow) {
  ContactSettling s(rule(0.1, 0.05));
  s.update(0.0, true, 0.0);
  s.update(0.2, false, 0.0);  // lift-off: the last step out of contact opens the window
  EXPECT_FALSE(s.settled(0.2));
  EXPECT_EQ(s.since(), 0.2);
  s.update(0.25, true, 0.0);
  s.update(0.29, true, 0.0);
  EXPECT_FALSE(s.settled(0.29));
  s.update(0.31, true, 0.0);
  EXPECT_TRUE(s.settled(0.31));
  s.update(0.4, true, -0.06);  // an impact: the contact point moves into the plane too fast
  EXPECT_FALSE(s.settled(0.4));
  EXPECT_EQ(s.since(), 0.4);
  s.update(0.45, true, 0.0);
  EXPECT_FALSE(s.settled(0.45));
  s.update(0.51, true, 0.0);
  EXPECT_TRUE(s.settled(0.51));
}

TEST(DynSettling, DefaultsComeFromTheLinearisedHertzVibration) {
  BodyScales b;
  b.gravity = 9.81;
  b.compression = 9.866e-5;
  b.hertz_frequency = std::sqrt(1.5 * 9.81 / b.compression);
  b.liftoff_speed = b.hertz_frequency * b.compression;
  const SettleRule r = resolve_settling({}, b);
  EXPECT_DOUBLE_EQ(r.time.value, kSettleTimePeriods * 2.0 * std::numbers::pi / b.hertz_frequency);
  EXPECT_DOUBLE_EQ(r.normal_speed.value, kSettleNormalSpeedFactor * b.liftoff_speed);
  EXPECT_EQ(r.time.key, "run.settle_time");
  EXPECT_EQ(r.normal_speed.key, "run.settle_normal_speed");
  EXPECT_EQ(r.time.source.rfind("default", 0), 0u);
  // The vibration of a body let go at eps = 0 (the largest that keeps the contact closed) peaks at
  // sqrt(1.2 g |eps_s|) (energy m g |eps_s| - (2/5) lambda |eps_s|^(5/2) = 0.6 m g |eps_s|): it
  // must count as settled.
  EXPECT_LT(std::sqrt(1.2 * 9.81 * b.compression), r.normal_speed.value);
  const SettleRule given = resolve_settling({0.0, 0.5}, b);
  EXPECT_EQ(given.time.value, 0.0);
  EXPECT_EQ(given.normal_speed.source, "given");
}

TEST(DynSettling, InvalidThresholdsNameTheirKey) {
  for (const auto& [given, key] : {std::pair{SettleThresholds{-1.0, {}}, "run.settle_time"},
                                   std::pair{SettleThresholds{{}, 0.0}, "run.settle_normal_speed"}}) {
    try {
      given.validate();
      ADD_FAILURE() << key << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
