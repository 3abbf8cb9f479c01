#include "friction/law.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

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

std::string number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
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
  // Scales every law multiplies by or divides by: overflow would turn finite input into inf or
  // NaN output, and a zero axis ratio is no ellipse.
  constexpr double kMinNormal = std::numeric_limits<double>::min();
  const double mu = in.b / in.a;
  if (mu < kMinNormal) {
    fail("b", in.b, ("the axis ratio b/a = " + number(mu) + " (a = " + number(in.a) +
                     " m) is below the smallest normal double, " + number(kMinNormal) +
                     ": a thinner patch is a line")
                        .c_str());
  }
  const double kN = in.k * in.N;
  if (!std::isfinite(kN)) {
    fail("N", in.N, ("with k = " + number(in.k) + ", k N = " + number(kN) +
                     " overflows: the largest friction force must be a finite double (N)")
                        .c_str());
  }
  if (!std::isfinite(kN * in.a)) {
    fail("a", in.a, ("with k N = " + number(kN) + " N, k N a = " + number(kN * in.a) +
                     " overflows: the largest friction moment must be a finite double (N m)")
                        .c_str());
  }
}

double slip_ratio(double U, double length, double Omega) {
  const double d = length * std::abs(Omega);
  if (d >= std::numeric_limits<double>::min() && d <= std::numeric_limits<double>::max()) {
    return U / d;  // the common case: one rounding in d, one in the quotient
  }
  if (U == 0.0) return 0.0;
  // length |Omega| is outside the normal range: divide the significands and add the exponents.
  int eu = 0;
  int el = 0;
  int eo = 0;
  const double mu = std::frexp(U, &eu);
  const double ml = std::frexp(length, &el);
  const double mo = std::frexp(std::abs(Omega), &eo);
  return std::ldexp(mu / (ml * mo), eu - el - eo);
}

}  // namespace frictionlab::friction
