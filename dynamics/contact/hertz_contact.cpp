#include "dynamics/contact/hertz_contact.h"

#include <cmath>

#include "friction/support/errors.h"

namespace frictionlab::dynamics {

void PlaneContact::validate() const {
  if (!(std::isfinite(k) && k >= 0.0))
    throw support::invalid_value("contact.k", k, "the friction coefficient must be finite and >= 0");
  if (!(std::isfinite(lambda) && lambda > 0.0))
    throw support::invalid_value("contact.lambda", lambda, "the Hertz stiffness must be finite and > 0 N/m^1.5");
  if (!(std::isfinite(g) && g >= 0.0))
    throw support::invalid_value("contact.g", g, "gravity must be finite and >= 0 m/s^2");
  if (patch == PatchModel::hertz && !(std::isfinite(E_star) && E_star > 0.0))
    throw support::invalid_value("contact.E_star", E_star, "the effective modulus must be finite and > 0 Pa");
}

}  // namespace frictionlab::dynamics
