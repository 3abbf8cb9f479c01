#pragma once
// The slit limit b/a -> 0 of the exact law for each pressure model (docs/pressure-models.md §6),
// written out independently of friction/exact_law.cpp so that tests can hold the law against it
// for slender patches. Dimensionless: a = 1, forces per kN, moment per kNa, Omega > 0.
//
// As b/a -> 0 with the ICR c = s (sin psi, cos psi) (ellipse frame) off the major axis, the patch
// is a load on the segment xi in [-1, 1] with the line density lambda(xi) = ∫ p dy:
//   Hertz (3/4)(1 - xi^2),   uniform (2/pi) sqrt(1 - xi^2),   punch 1/2,
// and with w = (xi - c1, -c2), r = |w|:
//   G'_1 = ∫ lambda (xi - c1)/r,   G'_2 = -c2 ∫ lambda / r,   H = ∫ lambda xi (xi - c1)/r,
//   F1 = -(sin psi G'_1 + cos psi G'_2),   F2 = cos psi G'_1 - sin psi G'_2,   M = H.
// Hertz and punch: closed forms (lambda a polynomial in u = xi - c1, J_m = ∫ u^m / r du
// elementary); uniform: the integrals are elliptic, evaluated by tanh-sinh quadrature (Boost.Math)
// split at xi = c1. Corrections at b/a = mu > 0: O(mu^2 / |c2|) (the direction of w varies across
// the patch's thickness 2 mu sqrt(1 - xi^2) on the scale |c2|), so the limit is a reference for
// ICRs with |c2| >> mu.

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <array>
#include <cmath>
#include <numbers>

#include "friction/law.h"
#include "friction/pressure.h"

namespace frictionlab::friction::test {

/// Relative tolerance of the tanh-sinh quadratures below (long double; Boost's default,
/// its square root epsilon 3e-10, let the error reach 1e-11).
inline constexpr long double kSlitQuadratureTolerance = 1e-17L;

/// ∫_{-1}^{1} lambda(xi) u^m / r dxi for m = 0, 1, 2 (u = xi - c1, r = sqrt(u^2 + c2^2)), for a
/// polynomial line density lambda = sum_j k_j u^j (j <= 2), from J_m = ∫ u^m / r du:
/// J_0 = asinh(u/|c2|), J_1 = r, J_m = u^(m-1) r / m - ((m - 1) c2^2 / m) J_(m-2).
inline std::array<long double, 3> slit_moments_polynomial(const std::array<long double, 3>& k, long double c1,
                                                          long double c2) {
  const long double b = std::abs(c2);
  const long double beta = c2 * c2;
  const long double u0 = -1.0L - c1;
  const long double u1 = 1.0L - c1;
  const long double r0 = std::sqrt(u0 * u0 + beta);
  const long double r1 = std::sqrt(u1 * u1 + beta);
  std::array<long double, 5> J{};
  J[0] = std::asinh(u1 / b) - std::asinh(u0 / b);
  J[1] = r1 - r0;
  long double p0 = 1.0L;  // u0^(m-1), u1^(m-1)
  long double p1 = 1.0L;
  for (int m = 2; m <= 4; ++m) {
    p0 *= u0;
    p1 *= u1;
    J[m] = (p1 * r1 - p0 * r0) / m - ((m - 1) * beta / m) * J[m - 2];
  }
  std::array<long double, 3> out{};
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 3; ++j) out[m] += k[j] * J[m + j];
  }
  return out;
}

/// The same moments for the uniform pressure's density (2/pi) sqrt(1 - xi^2), by tanh-sinh.
inline std::array<long double, 3> slit_moments_uniform(long double c1, long double c2) {
  const long double pi = std::numbers::pi_v<long double>;
  boost::math::quadrature::tanh_sinh<long double> rule;
  std::array<long double, 3> out{};
  for (int m = 0; m < 3; ++m) {
    const auto f = [&](long double xi) {
      const long double u = xi - c1;
      const long double lambda = 2.0L / pi * std::sqrt((1.0L - xi) * (1.0L + xi));
      long double um = 1.0L;
      for (int i = 0; i < m; ++i) um *= u;
      return lambda * um / std::sqrt(u * u + c2 * c2);
    };
    if (c1 > -1.0L && c1 < 1.0L) {
      out[m] = rule.integrate(f, -1.0L, c1, kSlitQuadratureTolerance) +
               rule.integrate(f, c1, 1.0L, kSlitQuadratureTolerance);
    } else {
      out[m] = rule.integrate(f, -1.0L, 1.0L, kSlitQuadratureTolerance);
    }
  }
  return out;
}

/// The slit limit of F1/(kN), F2/(kN), M/(kNa) at slip ratio s and angle psi, Omega > 0. With
/// `by_quadrature`, Hertz and punch too are integrated by tanh-sinh (a check of their closed forms).
inline FrictionForces slit_limit(Pressure pressure, double s, double psi, bool by_quadrature = false) {
  const long double sp = std::sin(static_cast<long double>(psi));
  const long double cp = std::cos(static_cast<long double>(psi));
  const long double c1 = s * sp;
  const long double c2 = s * cp;
  std::array<long double, 3> I{};  // ∫ lambda u^m / r, m = 0, 1, 2
  if (pressure == Pressure::uniform) {
    I = slit_moments_uniform(c1, c2);
  } else {
    // lambda = 3/4 (1 - (u + c1)^2) or 1/2, as a polynomial in u
    const std::array<long double, 3> k = pressure == Pressure::hertz
                                             ? std::array<long double, 3>{0.75L * (1.0L - c1 * c1), -1.5L * c1, -0.75L}
                                             : std::array<long double, 3>{0.5L, 0.0L, 0.0L};
    if (by_quadrature) {
      boost::math::quadrature::tanh_sinh<long double> rule;
      for (int m = 0; m < 3; ++m) {
        const auto f = [&](long double xi) {
          const long double u = xi - c1;
          long double um = 1.0L;
          for (int i = 0; i < m; ++i) um *= u;
          return (k[0] + u * (k[1] + u * k[2])) * um / std::sqrt(u * u + c2 * c2);
        };
        I[m] = (c1 > -1.0L && c1 < 1.0L) ? rule.integrate(f, -1.0L, c1, kSlitQuadratureTolerance) +
                                                rule.integrate(f, c1, 1.0L, kSlitQuadratureTolerance)
                                          : rule.integrate(f, -1.0L, 1.0L, kSlitQuadratureTolerance);
      }
    } else {
      I = slit_moments_polynomial(k, c1, c2);
    }
  }
  const long double g1 = I[1];
  const long double g2 = -c2 * I[0];
  const long double h = I[2] + c1 * I[1];  // ∫ lambda (u + c1) u / r
  return {static_cast<double>(-(sp * g1 + cp * g2)), static_cast<double>(cp * g1 - sp * g2), static_cast<double>(h)};
}

}  // namespace frictionlab::friction::test
