#include "dynamics/puck/puck.h"

#include "friction/support/errors.h"

namespace frictionlab::dynamics::puck {

void Puck::validate() const {
  if (!(std::isfinite(mass) && mass > 0.0)) throw support::invalid_value("puck.mass", mass, "it must be finite and > 0 kg");
  if (!(std::isfinite(a) && a > 0.0)) throw support::invalid_value("puck.a", a, "it must be finite and > 0 m");
  if (!(std::isfinite(b) && b > 0.0 && b <= a))
    throw support::invalid_value("puck.b", b, "it must be finite, > 0 m and <= puck.a (the major axis is body x)");
  if (!(std::isfinite(inertia) && inertia > 0.0))
    throw support::invalid_value("puck.inertia", inertia, "it must be finite and > 0 kg m^2");
}

}  // namespace frictionlab::dynamics::puck
