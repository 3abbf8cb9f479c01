#include "friction/law.h"

#include <cmath>
#include <limits>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

using support::shortest;

// Friction inputs print round-trip (support::shortest): the message shows the very double that
// failed (b a hair above a, say), which the 10 digits of a message number may not.
support::InvalidValue invalid_input(const char* name, double value, std::string_view rule) {
  return {std::string("friction input ") + name, shortest(value), rule};
}

void require_finite(const char* name, double value) {
  if (!std::isfinite(value)) throw invalid_input(name, value, "it must be a finite number");
}

// An angle must be finite; a direction (cos psi, sin psi) finite and unit to
// PatchAngle::kUnitTolerance (dot products of unit vectors are unit to a few roundings).
void require_valid_orientation(const PatchAngle& psi) {
  if (!psi.is_direction()) {
    require_finite("psi", psi.radians());
    return;
  }
  const auto [c, s] = psi.cos_sin();
  const auto invalid = [&](const std::string& rule) {
    return support::InvalidValue("friction input psi", "(cos, sin) = (" + shortest(c) + ", " + shortest(s) + ")", rule);
  };
  if (!std::isfinite(c) || !std::isfinite(s)) throw invalid("the direction of the major axis must be finite");
  const double excess = std::abs((c * c + s * s) - 1.0);
  if (!(excess <= PatchAngle::kUnitTolerance)) {
    throw invalid("the direction of the major axis must be a unit vector, |cos^2 + sin^2 - 1| <= " +
                  shortest(PatchAngle::kUnitTolerance) + " (here " + shortest(excess) + ")");
  }
}

}  // namespace

BatchError::BatchError(std::size_t index, std::exception_ptr cause, const std::string& cause_message)
    : std::invalid_argument("contact " + std::to_string(index) + ": " + cause_message),
      index_(index),
      cause_(std::move(cause)),
      cause_message_(cause_message) {}

void FrictionLaw::evaluate(std::span<const ContactInput> in, std::span<FrictionForces> out) const {
  if (in.size() != out.size()) {
    throw std::invalid_argument("a batch of " + std::to_string(in.size()) + " contacts needs as many results, not " +
                                std::to_string(out.size()));
  }
  // The valid prefix is evaluated, then the first invalid contact is reported.
  std::size_t valid = 0;
  std::exception_ptr invalid;
  std::string message;
  for (; valid < in.size(); ++valid) {
    try {
      validate(in[valid]);
    } catch (const std::invalid_argument& e) {
      invalid = std::current_exception();
      message = e.what();
      break;
    }
  }
  do_evaluate_batch(in.first(valid), out.first(valid));
  if (invalid) throw BatchError(valid, invalid, message);
}

void FrictionLaw::do_evaluate_batch(std::span<const ContactInput> in, std::span<FrictionForces> out) const {
  for (std::size_t i = 0; i < in.size(); ++i) {
    try {
      out[i] = do_evaluate(in[i]);
    } catch (const std::exception& e) {
      throw BatchError(i, std::current_exception(), e.what());
    }
  }
}

PoleDenominators FrictionLaw::pole_denominators(const ContactInput& /*in*/) const {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  return {nan, nan, nan};
}

void validate(const ContactInput& in) {
  require_finite("U", in.U);
  require_finite("Omega", in.Omega);
  require_finite("a", in.a);
  require_finite("b", in.b);
  require_valid_orientation(in.psi);
  require_finite("N", in.N);
  require_finite("k", in.k);
  if (in.U < 0.0) throw invalid_input("U", in.U, "the slip speed must be >= 0 m/s (e1 points along the slip)");
  if (in.a <= 0.0) throw invalid_input("a", in.a, "the major semi-axis must be > 0 m");
  if (in.b <= 0.0) throw invalid_input("b", in.b, "the minor semi-axis must be > 0 m");
  if (in.b > in.a)
    throw invalid_input("b", in.b, "the minor semi-axis must not exceed the major semi-axis a = " + shortest(in.a) + " m");
  if (in.N < 0.0) throw invalid_input("N", in.N, "the normal force must be >= 0 N");
  if (in.k < 0.0) throw invalid_input("k", in.k, "the friction coefficient must be >= 0");
  // Scales every law multiplies by or divides by: overflow would turn finite input into inf or
  // NaN output, and a zero axis ratio is no ellipse.
  constexpr double kMinNormal = std::numeric_limits<double>::min();
  const double mu = in.b / in.a;
  if (mu < kMinNormal) {
    throw invalid_input("b", in.b, "the axis ratio b/a = " + shortest(mu) + " (a = " + shortest(in.a) +
                                       " m) is below the smallest normal double, " + shortest(kMinNormal) +
                                       ": a thinner patch is a line");
  }
  const double kN = in.k * in.N;
  if (!std::isfinite(kN)) {
    throw invalid_input("N", in.N, "with k = " + shortest(in.k) + ", k N = " + shortest(kN) +
                                       " overflows: the largest friction force must be a finite double (N)");
  }
  if (!std::isfinite(kN * in.a)) {
    throw invalid_input("a", in.a, "with k N = " + shortest(kN) + " N, k N a = " + shortest(kN * in.a) +
                                       " overflows: the largest friction moment must be a finite double (N m)");
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

LawPromises LawPromises::closed_form_without_F2() {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::even;  // F2 = 0
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;  // psi plays no part
  p.psi_mirror = true;
  p.dissipative = true;
  p.tolerance = 1e-14;  // rounding of a closed form
  return p;
}

}  // namespace frictionlab::friction
