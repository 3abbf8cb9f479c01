#include "dynamics/core/rest_event.h"

#include <cmath>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

using support::significant;

void require_nonnegative(const char* key, const std::optional<double>& value, const char* unit) {
  if (value && !(std::isfinite(*value) && *value >= 0.0))
    throw support::invalid_value(key, *value, "it must be finite and >= 0 " + std::string(unit) + " (0 disables rest)");
}

std::string size_note(const BodyScales& s) {
  return "R = " + significant(s.size, 6) + " m (body size), g = " + significant(s.gravity, 6) + " m/s^2";
}

}  // namespace

void RestThresholds::validate() const {
  require_nonnegative("run.rest_slip_speed", slip_speed, "m/s");
  require_nonnegative("run.rest_spin", spin, "1/s");
  require_nonnegative("run.rest_kinetic_energy", kinetic_energy, "J");
}

RestRule resolve_rest(const RestThresholds& given, const BodyScales& s) {
  const std::string note = size_note(s);
  const std::string mass = "m = " + significant(s.mass, 6) + " kg, " + note;
  return {resolve_threshold("run.rest_slip_speed", "m/s", given.slip_speed, kRestSlipSpeedFactor, s.speed,
                            "sqrt(g R)", note),
          resolve_threshold("run.rest_spin", "1/s", given.spin, kRestSpinFactor, s.rate, "sqrt(g/R)", note),
          resolve_threshold("run.rest_kinetic_energy", "J", given.kinetic_energy, kRestKineticEnergyFactor, s.energy,
                            "m g R", mass)};
}

}  // namespace frictionlab::dynamics
