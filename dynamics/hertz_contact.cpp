#include "dynamics/hertz_contact.h"

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

void PlaneContact::validate() const {
  if (!(std::isfinite(k) && k >= 0.0)) fail("contact.k", k, "the friction coefficient must be finite and >= 0");
  if (!(std::isfinite(lambda) && lambda > 0.0))
    fail("contact.lambda", lambda, "the Hertz stiffness must be finite and > 0 N/m^1.5");
  if (!(std::isfinite(g) && g >= 0.0)) fail("contact.g", g, "gravity must be finite and >= 0 m/s^2");
  if (patch == PatchModel::hertz && !(std::isfinite(E_star) && E_star > 0.0))
    fail("contact.E_star", E_star, "the effective modulus must be finite and > 0 Pa");
}

}  // namespace frictionlab::dynamics
