#include "dynamics/settling.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace frictionlab::dynamics {
namespace {

[[noreturn]] void fail(const char* key, double value, const char* rule) {
  std::ostringstream msg;
  msg.precision(12);
  msg << key << " = " << value << " is invalid: " << rule;
  throw std::invalid_argument(msg.str());
}

}  // namespace

void SettleThresholds::validate() const {
  if (time && !(std::isfinite(*time) && *time >= 0.0)) fail("run.settle_time", *time, "it must be finite and >= 0 s");
  if (normal_speed && !(std::isfinite(*normal_speed) && *normal_speed > 0.0))
    fail("run.settle_normal_speed", *normal_speed, "it must be finite and > 0 m/s");
}

SettleRule resolve_settling(const SettleThresholds& given, const BodyScales& s) {
  std::ostringstream note;
  note.precision(6);
  note << "omega_n = sqrt(1.5 g/|eps_s|) = " << s.hertz_frequency << " rad/s, |eps_s| = " << s.compression
       << " m (static Hertz compression), g = " << s.gravity << " m/s^2";
  const double period = 2.0 * std::numbers::pi / s.hertz_frequency;
  return {resolve_threshold("run.settle_time", "s", given.time, kSettleTimePeriods, period, "2 pi/omega_n", note.str()),
          resolve_threshold("run.settle_normal_speed", "m/s", given.normal_speed, kSettleNormalSpeedFactor,
                            s.liftoff_speed, "v_lift = omega_n |eps_s|", note.str())};
}

}  // namespace frictionlab::dynamics
