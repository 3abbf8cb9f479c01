#include "dynamics/rest_event.h"

#include <sstream>
#include <stdexcept>

namespace frictionlab::dynamics {
namespace {

void require_nonnegative(const char* key, const std::optional<double>& value, const char* unit) {
  if (value && !(std::isfinite(*value) && *value >= 0.0)) {
    std::ostringstream msg;
    msg.precision(12);
    msg << key << " = " << *value << " is invalid: it must be finite and >= 0 " << unit << " (0 disables rest)";
    throw std::invalid_argument(msg.str());
  }
}

std::string size_note(const BodyScales& s) {
  std::ostringstream n;
  n.precision(6);
  n << "R = " << s.size << " m (body size), g = " << s.gravity << " m/s^2";
  return n.str();
}

}  // namespace

void RestThresholds::validate() const {
  require_nonnegative("run.rest_slip_speed", slip_speed, "m/s");
  require_nonnegative("run.rest_spin", spin, "1/s");
  require_nonnegative("run.rest_kinetic_energy", kinetic_energy, "J");
}

RestRule resolve_rest(const RestThresholds& given, const BodyScales& s) {
  const std::string note = size_note(s);
  std::ostringstream mass;
  mass.precision(6);
  mass << "m = " << s.mass << " kg, " << note;
  return {resolve_threshold("run.rest_slip_speed", "m/s", given.slip_speed, kRestSlipSpeedFactor, s.speed,
                            "sqrt(g R)", note),
          resolve_threshold("run.rest_spin", "1/s", given.spin, kRestSpinFactor, s.rate, "sqrt(g/R)", note),
          resolve_threshold("run.rest_kinetic_energy", "J", given.kinetic_energy, kRestKineticEnergyFactor, s.energy,
                            "m g R", mass.str())};
}

}  // namespace frictionlab::dynamics
