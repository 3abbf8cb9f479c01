#include "friction/pade_printed_law.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace frictionlab::friction {

PadePrintedCoefficients pade_printed_coefficients(double mu, double psi) {
  constexpr double pi = std::numbers::pi;
  const double mu2 = mu * mu;
  const double mu_q = std::sqrt(std::sqrt(mu));  // mu^(1/4)
  const double mu_34 = mu_q * mu_q * mu_q;       // mu^(3/4)
  const double c = std::cos(psi);
  const double c2 = std::cos(2.0 * psi);
  const double s2 = std::sin(2.0 * psi);
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

PoleDenominators PadePrintedLaw::pole_denominators(const ContactInput& in) const {
  const double mu = in.b / in.a;
  const double c = alpha_ == PadeAlpha::major ? 1.0 : mu;
  const double s = in.U / (in.a * std::abs(in.Omega));
  const auto k = pade_printed_coefficients(mu, in.psi);
  PoleDenominators d{};
  d.F1 = s * s + k.a1 * c * s + k.a2 * c * c;
  d.F2 = std::isinf(k.a4) ? std::numeric_limits<double>::quiet_NaN() : s * s + k.a3 * c * s + k.a4 * c * c;
  d.M = k.b2 * s * s + k.b1 * c * s + c * c;
  return d;
}

FrictionForces PadePrintedLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  if (F0 == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  const double mu = in.b / in.a;
  const double alpha = alpha_ == PadeAlpha::major ? in.a : in.b;
  const auto c = pade_printed_coefficients(mu, in.psi);

  const double U = in.U;
  const double w = alpha * in.Omega;     // alpha Omega
  const double aw = std::abs(w);         // alpha |Omega|
  const double UU = U * U;
  const double Uaw = U * aw;             // U alpha |Omega|
  const double ww = w * w;               // alpha^2 Omega^2

  FrictionForces out;
  // Eq. (8), first line.
  out.F1 = F0 * (UU + c.a1 * Uaw) / (UU + c.a1 * Uaw + c.a2 * ww);
  // Eq. (8), second line; a4 infinite (d6 = 0) gives the limit F2 = 0.
  // (+ 0.0 turns the -0 of Omega = 0 into +0.)
  out.F2 = std::isinf(c.a4) ? 0.0 : -F0 * U * w / (UU + c.a3 * Uaw + c.a4 * ww) + 0.0;
  // Eq. (8), third line.
  const double M0 = c.m0_over_alpha_f0 * alpha * F0;
  out.M = M0 * (c.b1 * U * w + w * aw) / (c.b2 * UU + c.b1 * Uaw + ww);
  return out;
}

}  // namespace frictionlab::friction
