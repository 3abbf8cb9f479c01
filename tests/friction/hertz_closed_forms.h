#pragma once
// Closed forms and asymptotics of the exact friction law over a Hertz patch, docs/model.md,
// written out independently of friction/exact_law.cpp (which never evaluates them) so that tests
// can hold the law against them. All results are dimensionless: forces per kN, moments per kNa,
// u = U / (a |Omega|), mu = b / a, e^2 = 1 - mu^2. Elliptic integrals from Boost.Math
// (boost::math::ellint_1 / ellint_2 take the modulus e).

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <cmath>
#include <numbers>

namespace frictionlab::friction::test {

/// F1 and |M| of a circular Hertz patch (no elliptic integrals appear).
struct CircleForces {
  double f1;  ///< F1 / (kN)
  double m;   ///< |M| / (kNa)
};

/// Circle, docs/model.md. For u >= 1 the bracketed terms cancel like u^4 (M) and u^2 (F1)
/// as u grows, so they are summed in long double: good to ~1e-15 for u <= 10; do not use the
/// u >= 1 branch beyond u ~ 30.
inline CircleForces circle(double u_in) {
  const long double u = u_in;
  const long double u2 = u * u;
  const long double pi = std::numbers::pi_v<long double>;
  if (u <= 1.0L) {
    return {static_cast<double>(3.0L * pi / 32.0L * u * (4.0L - u2)),
            static_cast<double>(3.0L * pi / 128.0L * (8.0L - 8.0L * u2 + 3.0L * u2 * u2))};
  }
  const long double as = std::asin(1.0L / u);
  const long double sq = std::sqrt(u2 - 1.0L);
  return {static_cast<double>(3.0L / (16.0L * u) * ((4.0L * u2 - u2 * u2) * as + (u2 + 2.0L) * sq)),
          static_cast<double>(3.0L / 64.0L *
                              ((8.0L - 8.0L * u2 + 3.0L * u2 * u2) * as + (6.0L - 3.0L * u2) * sq))};
}

/// Pure spin (U = 0): |M| / (kNa) = (3/8) E(e); for a circle 3 pi / 16.
inline double pure_spin_moment(double mu) {
  const long double e = std::sqrt((1.0L - mu) * (1.0L + mu));
  return static_cast<double>(3.0L / 8.0L * boost::math::ellint_2(e));
}

/// Slow slip (u -> 0) of an ellipse: F1 = slope_f1 u + O(u^3), F2 = slope_f2 u + O(u^3), with
/// A = K(e), B = ((1 + mu^2) K - 2 E) / e^2, slope_f1 = (3/4)(A + B cos 2psi),
/// slope_f2 = (3/4) B sin 2psi. B suffers cancellation as mu -> 1 (~1e-19 / e^4 in long
/// double): use for mu <= 0.99.
struct SlowSlipSlopes {
  double f1;
  double f2;
};

inline SlowSlipSlopes slow_slip_slopes(double mu, double psi) {
  const long double e2 = (1.0L - mu) * (1.0L + mu);
  const long double e = std::sqrt(e2);
  const long double K = boost::math::ellint_1(e);
  const long double E = boost::math::ellint_2(e);
  const long double A = K;
  const long double B = ((1.0L + static_cast<long double>(mu) * mu) * K - 2.0L * E) / e2;
  return {static_cast<double>(0.75L * (A + B * std::cos(2.0L * psi))),
          static_cast<double>(0.75L * B * std::sin(2.0L * psi))};
}

/// Fast slip (u -> inf): F1 = 1 - d3/(10 u^2), F2 = d4/(10 u^2), |M| = d3/(5 u), with the paper's
/// d3 = (1 - mu^2) cos^2 psi + mu^2 and d4 = (1 - mu^2) sin 2psi (the pressure's second moments).
struct FastSlipMoments {
  double d3;
  double d4;
};

inline FastSlipMoments fast_slip_moments(double mu, double psi) {
  const double e2 = (1.0 - mu) * (1.0 + mu);
  const double c = std::cos(psi);
  return {e2 * c * c + mu * mu, e2 * std::sin(2.0 * psi)};
}

}  // namespace frictionlab::friction::test
