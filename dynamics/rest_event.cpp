#include "dynamics/rest_event.h"

#include <sstream>
#include <stdexcept>

namespace frictionlab::dynamics {
namespace {

void require_nonnegative(const char* key, double value, const char* unit) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    std::ostringstream msg;
    msg.precision(12);
    msg << key << " = " << value << " is invalid: it must be finite and >= 0 " << unit << " (0 disables rest)";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

void RestThresholds::validate() const {
  require_nonnegative("run.rest_slip_speed", slip_speed, "m/s");
  require_nonnegative("run.rest_spin", spin, "1/s");
  require_nonnegative("run.rest_kinetic_energy", kinetic_energy, "J");
}

}  // namespace frictionlab::dynamics
