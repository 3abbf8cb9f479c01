#include "friction/pade_printed_law.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "friction/support/number_format.h"

namespace frictionlab::friction {

using support::shortest;

PadePrintedCoefficients pade_printed_coefficients(double mu, const PatchAngle& psi) {
  constexpr double pi = std::numbers::pi;
  const double mu2 = mu * mu;
  const double mu_q = std::sqrt(std::sqrt(mu));  // mu^(1/4)
  const double mu_34 = mu_q * mu_q * mu_q;       // mu^(3/4)
  // cos 2psi and sin 2psi from cos psi and sin psi: 2 psi itself may overflow.
  const auto [c, s] = psi.cos_sin();
  const double c2 = (c - s) * (c + s);
  const double s2 = 2.0 * s * c;
  const double d3 = (1.0 - mu2) * c * c + mu2;   // Eq. (9), delta_3
  const double d4 = s2 * (1.0 - mu2);            // delta_4
  const double d5 = (1.0 - mu_q) * c2 + mu_q;    // delta_5
  const double d6 = (1.0 - mu_q) * s2;           // delta_6
  PadePrintedCoefficients k{};
  k.a1 = 3.0 * pi * d3 * d5 / (80.0 * mu_34);
  k.a2 = d3 / 10.0;
  k.a3 = -d4 / 10.0;
  k.a4 = -8.0 / (3.0 * mu_34 * pi * d6);  // ±inf where d6 = 0
  k.b1 = -16.0 * d3 * d5 / (15.0 * mu_34 * mu * pi);  // mu^(7/4) = mu^(3/4) mu
  k.b2 = d5 / (mu_q * mu);                            // mu^(5/4)
  k.m0_over_alpha_f0 = 3.0 * pi / 16.0 * std::sqrt(mu);
  return k;
}

std::string_view PadePrintedLaw::name() const {
  return alpha_ == PadeAlpha::major ? "pade-printed" : "pade-printed-minor";
}

std::string_view PadePrintedLaw::summary() const {
  return alpha_ == PadeAlpha::major
             ? "Pade formulas (8)-(9) of Munitsyna (2013) as printed, alpha = major semi-axis"
             : "Pade formulas (8)-(9) of Munitsyna (2013) as printed, alpha = min(a, b)";
}

LawPromises PadePrintedLaw::promises() const {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::odd;
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;
  p.min_axis_ratio = kPadePrintedMinAxisRatio;  // and not whole_domain: its poles throw
  // Rounding, away from the poles: the coefficients reach ~mu^(-7/4) ~ 3e3 at mu = 0.01, and
  // amplify the rounding of cos, sin of a shifted psi by as much.
  p.tolerance = 1e-11;
  return p;
}

PoleDenominators PadePrintedLaw::pole_denominators(const ContactInput& in) const {
  const double mu = in.b / in.a;
  const double c = alpha_ == PadeAlpha::major ? 1.0 : mu;
  const double s = slip_ratio(in.U, in.a, in.Omega);
  const auto k = pade_printed_coefficients(mu, in.psi);
  PoleDenominators d{};
  d.F1 = s * s + k.a1 * c * s + k.a2 * c * c;
  d.F2 = std::isinf(k.a4) ? std::numeric_limits<double>::quiet_NaN() : s * s + k.a3 * c * s + k.a4 * c * c;
  d.M = k.b2 * s * s + k.b1 * c * s + c * c;
  return d;
}

FrictionForces PadePrintedLaw::do_evaluate(const ContactInput& in) const {
  const double mu = in.b / in.a;
  if (mu < kPadePrintedMinAxisRatio) {
    throw std::invalid_argument("friction input b = " + shortest(in.b) + " is invalid for " + std::string(name()) +
                                ": the axis ratio b/a = " + shortest(mu) + " is below " +
                                shortest(kPadePrintedMinAxisRatio) +
                                ", where the coefficients of eq. (9) (up to mu^(-7/4)) leave the double range");
  }
  const double F0 = in.k * in.N;
  if (F0 == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  if (in.Omega == 0.0) return {F0, 0.0, 0.0};  // eq. (8) at Omega = 0: F1 = F0 U^2/U^2, F2 = M = 0
  const double alpha = alpha_ == PadeAlpha::major ? in.a : in.b;
  const auto c = pade_printed_coefficients(mu, in.psi);
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  const double M0 = c.m0_over_alpha_f0 * alpha * F0;

  // Eq. (8) divided by (alpha Omega)^2 where sigma = U/(alpha|Omega|) <= 1, by U^2 where it is
  // larger (then in t = 1/sigma): the same rational functions, with no power of U or alpha Omega
  // formed, so nothing overflows before the division. a4 infinite (d6 = 0) gives the limit F2 = 0.
  // (+ 0.0 turns a -0 of F2 at U = 0 into +0.)
  const double sigma = slip_ratio(in.U, alpha, in.Omega);
  FrictionForces out;
  if (sigma <= 1.0) {
    const double n1 = sigma * (sigma + c.a1);
    out.F1 = F0 * n1 / (n1 + c.a2);                                                  // Eq. (8), F1
    out.F2 = std::isinf(c.a4) ? 0.0 : -F0 * sign * sigma / (sigma * (sigma + c.a3) + c.a4) + 0.0;  // F2
    out.M = M0 * sign * (c.b1 * sigma + 1.0) / (sigma * (c.b2 * sigma + c.b1) + 1.0);  // Eq. (8), M
  } else {
    const double t = 1.0 / sigma;
    const double n1 = 1.0 + c.a1 * t;
    out.F1 = F0 * n1 / (n1 + c.a2 * t * t);
    out.F2 = std::isinf(c.a4) ? 0.0 : -F0 * sign * t / (1.0 + t * (c.a3 + c.a4 * t));
    out.M = M0 * sign * t * (c.b1 + t) / (c.b2 + t * (c.b1 + t));
  }
  // A denominator of eq. (8) that vanishes (or so nearly that the quotient leaves the double
  // range) is a pole: the printed law has no value there.
  const char* pole = !std::isfinite(out.F1) ? "F1" : !std::isfinite(out.F2) ? "F2" : !std::isfinite(out.M) ? "M" : nullptr;
  if (pole) {
    const double value = pole[0] == 'M' ? out.M : pole[1] == '1' ? out.F1 : out.F2;
    throw std::invalid_argument(std::string(name()) + " is undefined at U = " + shortest(in.U) + " m/s, Omega = " +
                                shortest(in.Omega) + " 1/s, a = " + shortest(in.a) + " m, b = " + shortest(in.b) +
                                " m, psi = " + shortest(in.psi.radians()) + ": the denominator of " + pole +
                                " in eq. (8) vanishes there (a pole; " + pole + " = " + shortest(value) + ")");
  }
  return out;
}

}  // namespace frictionlab::friction
