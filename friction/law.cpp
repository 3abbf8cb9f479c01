#include "friction/law.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace frictionlab::friction {
namespace {

[[noreturn]] void fail(const char* name, double value, const char* rule) {
  std::ostringstream msg;
  msg.precision(17);
  msg << "friction input " << name << " = " << value << " is invalid: " << rule;
  throw std::invalid_argument(msg.str());
}

void require_finite(const char* name, double value) {
  if (!std::isfinite(value)) fail(name, value, "it must be a finite number");
}

}  // namespace

PoleDenominators FrictionLaw::pole_denominators(const ContactInput& /*in*/) const {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  return {nan, nan, nan};
}

void validate(const ContactInput& in) {
  require_finite("U", in.U);
  require_finite("Omega", in.Omega);
  require_finite("a", in.a);
  require_finite("b", in.b);
  require_finite("psi", in.psi);
  require_finite("N", in.N);
  require_finite("k", in.k);
  if (in.U < 0.0) fail("U", in.U, "the slip speed must be >= 0 m/s (e1 points along the slip)");
  if (in.a <= 0.0) fail("a", in.a, "the major semi-axis must be > 0 m");
  if (in.b <= 0.0) fail("b", in.b, "the minor semi-axis must be > 0 m");
  if (in.b > in.a) {
    std::ostringstream rule;
    rule.precision(17);
    rule << "the minor semi-axis must not exceed the major semi-axis a = " << in.a << " m";
    fail("b", in.b, rule.str().c_str());
  }
  if (in.N < 0.0) fail("N", in.N, "the normal force must be >= 0 N");
  if (in.k < 0.0) fail("k", in.k, "the friction coefficient must be >= 0");
}

}  // namespace frictionlab::friction
