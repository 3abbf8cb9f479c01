#include "dynamics/core/rest_event.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace rest_event_test {

BodyScales scales_of(double mass, double size) {
  BodyScales s;
  s.size = size;
  s.mass = mass;
  s.gravity = 9.81;
  s.speed = std::sqrt(9.81 * size);
  s.rate = std::sqrt(9.81 / size);
  s.energy = mass * 9.81 * size;
  return s;
}

TEST(DynRestEvent, DefaultsAreFractionsOfTheBodysOwnScales) {
  const BodyScales s = scales_of(0.015, 0.024);
  const RestRule r = resolve_rest({}, s);
  EXPECT_DOUBLE_EQ(r.slip_speed.value, kRestSlipSpeedFactor * std::sqrt(9.81 * 0.024));
  EXPECT_DOUBLE_EQ(r.spin.value, kRestSpinFactor * std::sqrt(9.81 / 0.024));
  EXPECT_DOUBLE_EQ(r.kinetic_energy.value, kRestKineticEnergyFactor * 0.015 * 9.81 * 0.024);
  EXPECT_EQ(r.slip_speed.key, "run.rest_slip_speed");
  EXPECT_EQ(r.kinetic_energy.unit, "J");
  for (const auto* t : {&r.slip_speed, &r.spin, &r.kinetic_energy}) {
    EXPECT_EQ(t->source.rfind("default: ", 0), 0u) << t->source;
    EXPECT_NE(t->source.find("R = 0.024 m"), std::string::npos) << t->source;
  }
  EXPECT_NE(r.kinetic_energy.source.find("m g R"), std::string::npos);
  EXPECT_NE(r.kinetic_energy.source.find("m = 0.015 kg"), std::string::npos);
}

TEST(DynRestEvent, GivenValuesOverrideTheScaledDefaults) {
  RestThresholds given;
  given.spin = 0.5;
  given.kinetic_energy = 0.0;  // 0 disables
  const RestRule r = resolve_rest(given, scales_of(2.0, 0.27));
  EXPECT_EQ(r.spin.value, 0.5);
  EXPECT_EQ(r.spin.source, "given");
  EXPECT_EQ(r.kinetic_energy.value, 0.0);
  EXPECT_EQ(r.slip_speed.source.rfind("default", 0), 0u);
  EXPECT_FALSE(r.at_rest(true, 0.0, 0.0, 0.0));
}

TEST(DynRestEvent, ASmallTippeTopThatStillRollsIsNotAtRest) {
  // The state where the absolute thresholds (1e-3 m/s, 1e-2 1/s, 1e-3 J) stopped a 15 g top
  // (R = 2.4 cm) "at rest": no slip, little spin, kinetic energy 2.7e-4 J = 0.077 m g R with the
  // centre moving at 0.16 m/s.
  const RestRule r = resolve_rest({}, scales_of(0.015, 0.024));
  const double U = 4e-6, Omega = 0.0101, kinetic = 2.7e-4;
  EXPECT_TRUE(r.contact_stagnant(true, U, Omega));
  EXPECT_FALSE(r.at_rest(true, U, Omega, kinetic));
  const RestRule absolute = resolve_rest({1e-3, 1e-2, 1e-3}, scales_of(0.015, 0.024));
  EXPECT_FALSE(absolute.contact_stagnant(true, U, Omega)) << "with those, the spin 0.0101 just misses";
  EXPECT_TRUE(absolute.at_rest(true, U, 0.0099, kinetic)) << "and a moment later the top was 'at rest'";
}

TEST(DynRestEvent, OnlyInContact) {
  const RestRule r = resolve_rest({}, scales_of(1.0, 0.05));
  EXPECT_FALSE(r.contact_stagnant(false, 0.0, 0.0));
  EXPECT_FALSE(r.at_rest(false, 0.0, 0.0, 0.0));
  EXPECT_TRUE(r.at_rest(true, 0.0, 0.0, 0.0));
}

TEST(DynRestEvent, InvalidThresholdsNameTheirKey) {
  for (const auto& [given, key] : {std::pair{RestThresholds{-1.0, {}, {}}, "run.rest_slip_speed"},
                                   std::pair{RestThresholds{{}, std::nan(""), {}}, "run.rest_spin"},
                                   std::pair{RestThresholds{{}, {}, INFINITY}, "run.rest_kinetic_energy"}}) {
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
