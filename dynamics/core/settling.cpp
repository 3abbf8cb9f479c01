#include "dynamics/core/settling.h"

#include <cmath>
#include <numbers>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

void SettleThresholds::validate() const {
  if (time && !(std::isfinite(*time) && *time >= 0.0))
    throw support::invalid_value("run.settle_time", *time, "it must be finite and >= 0 s");
  if (normal_speed && !(std::isfinite(*normal_speed) && *normal_speed > 0.0))
    throw support::invalid_value("run.settle_normal_speed", *normal_speed, "it must be finite and > 0 m/s");
}

SettleRule resolve_settling(const SettleThresholds& given, const BodyScales& s) {
  const std::string note = "omega_n = sqrt(1.5 g/|eps_s|) = " + support::significant(s.hertz_frequency, 6) +
                           " rad/s, |eps_s| = " + support::significant(s.compression, 6) +
                           " m (static Hertz compression), g = " + support::significant(s.gravity, 6) + " m/s^2";
  const double period = 2.0 * std::numbers::pi / s.hertz_frequency;
  return {resolve_threshold("run.settle_time", "s", given.time, kSettleTimePeriods, period, "2 pi/omega_n", note),
          resolve_threshold("run.settle_normal_speed", "m/s", given.normal_speed, kSettleNormalSpeedFactor,
                            s.liftoff_speed, "v_lift = omega_n |eps_s|", note)};
}

}  // namespace frictionlab::dynamics
