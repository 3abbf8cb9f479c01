// The exact law for every pressure model against its slit limit b/a -> 0 (tests/friction/slit_limit.h,
// derived in docs/pressure-models.md §6): at b/a = 1e-12 and 1e-9, for ICRs off the major axis by
// much more than b/a, where the limit's own error O(mu^2/|c2|) is below 1e-15. The uniform
// pressure once failed here by up to 8e-5 kN (its rim integrals divided an O(mu) sum by mu).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "friction/exact_law.h"
#include "friction/pressure.h"
#include "tests/friction/dimensionless_contact.h"
#include "tests/friction/slit_limit.h"

namespace frictionlab::friction {
namespace exact_law_slit_limit_test {

constexpr double kPi = std::numbers::pi;
const Pressure kAll[] = {Pressure::hertz, Pressure::uniform, Pressure::punch};

// The limit is used only where the ICR is off the major axis by at least this many times mu:
// its corrections O(mu^2/|c2|) are then below mu/kOffAxis, 1e-15 at mu = 1e-9, 1e-18 at 1e-12.
constexpr double kOffAxis = 1e6;
// The slit limit's quadrature (uniform) and closed forms (Hertz, punch) in long double agree with
// each other to 1e-15 (ClosedFormsAgreeWithQuadrature) up to this slip ratio; beyond, the closed
// forms lose accuracy like |c|^4 (1.9e-14 at s = 30, ~1e-3 at s ~ 1e4) and the fast-slip expansion
// takes over (FastSlipOfASlitIsTheExpansion; in between, the tables of tests/friction/reference).
constexpr double kLimitAccuracy = 1e-15;
constexpr double kLargestSlipRatio = 10.0;

// The accuracy each pressure's law promises (friction/exact_law.h).
double promised(Pressure p) { return p == Pressure::hertz ? kExactLawAccuracy : kExactLawPressureAccuracy; }

std::string where(Pressure p, double s, double mu, double psi, double omega) {
  std::ostringstream out;
  out.precision(17);
  out << pressure_name(p) << ": s = " << s << ", mu = " << mu << ", psi = " << psi << ", Omega = " << omega;
  return out.str();
}

TEST(ExactSlitLimit, ClosedFormsAgreeWithQuadrature) {
  // The reference checked against itself: Hertz and punch closed forms against tanh-sinh of the
  // same 1-D integrals.
  for (const Pressure p : {Pressure::hertz, Pressure::punch}) {
    for (const double s : {1e-6, 0.3, 0.99, 1.7, kLargestSlipRatio}) {
      for (const double psi : {0.0, 0.5, 1.2, 2.8}) {
        const FrictionForces closed = test::slit_limit(p, s, psi);
        const FrictionForces quad = test::slit_limit(p, s, psi, true);
        SCOPED_TRACE(where(p, s, 0.0, psi, 1.0));
        EXPECT_NEAR(closed.F1, quad.F1, kLimitAccuracy);
        EXPECT_NEAR(closed.F2, quad.F2, kLimitAccuracy);
        EXPECT_NEAR(closed.M, quad.M, kLimitAccuracy);
      }
    }
  }
}

TEST(ExactSlitLimit, LimitHasTheKnownLimits) {
  // Pure spin of a slit: M = c E(1) = c (3/8, 4/(3 pi), 1/2), F = 0; fast slip: F1 -> 1.
  const double spin[] = {3.0 / 8.0, 4.0 / (3.0 * kPi), 0.5};
  for (int i = 0; i < 3; ++i) {
    const FrictionForces f = test::slit_limit(kAll[i], 1e-9, 0.0);
    EXPECT_NEAR(f.M, spin[i], 1e-8) << pressure_name(kAll[i]);
    EXPECT_NEAR(f.F1, 0.0, 1e-7) << pressure_name(kAll[i]);
    EXPECT_NEAR(test::slit_limit(kAll[i], 1e4, 0.7).F1, 1.0, 1e-8) << pressure_name(kAll[i]);
  }
}

TEST(ExactSlitLimit, EveryPressureMatchesTheSlitLimit) {
  // s from slow to fast slip, psi generic, near the axes and across them (psi = 0: the ICR on the
  // minor axis), both spins; the ICR inside the slit's span (|c1| < 1) and beyond it.
  for (const Pressure p : kAll) {
    const ExactLaw law(p);
    for (const double mu : {1e-12, 1e-9}) {
      for (const double s : {1e-6, 1e-3, 0.3, 0.9, 1.1, 3.0, kLargestSlipRatio}) {
        for (const double psi : {0.0, 0.4, 1.2, 1.5707, 2.5, -0.7}) {
          if (s * std::abs(std::cos(psi)) < kOffAxis * mu) continue;  // the limit does not hold there
          const FrictionForces want = test::slit_limit(p, s, psi);
          for (const double omega : {1.0, -1.0}) {
            const FrictionForces f = law.evaluate(dimensionless_contact(s, mu, psi, omega));
            SCOPED_TRACE(where(p, s, mu, psi, omega));
            const double tol = promised(p) + kLimitAccuracy;
            EXPECT_NEAR(f.F1, want.F1, tol);
            EXPECT_NEAR(f.F2, want.F2, tol);
            EXPECT_NEAR(f.M, omega * want.M, tol);
          }
        }
      }
    }
  }
}

TEST(ExactSlitLimit, FastSlipOfASlitIsTheExpansion) {
  // docs/pressure-models.md §2 with the slit's d3 = cos^2 psi + mu^2 sin^2 psi, d4 = (1 - mu^2)
  // sin 2 psi: F1 = 1 - m2 d3/(2 s^2), F2 = m2 d4/(2 s^2), M = m2 d3/s, with neglected terms
  // O(s^-4) and O(s^-3) (below 1e-17 here). s = 255094.52 is the slip ratio of a fuzzed input (docs/pressure-models.md §3),
  // where the uniform law gave F1 = 1.00008 kN.
  for (const Pressure p : kAll) {
    const ExactLaw law(p);
    const double m2 = pressure_second_moment(p);
    for (const double mu : {1e-12, 1e-9}) {
      for (const double s : {1e5, 255094.52174620156, 1e7}) {
        for (const double psi : {0.0, 0.4, 1.2, 1.5707, kPi / 2, 2.5, -2.4426969214284204}) {
          const double d3 = std::cos(psi) * std::cos(psi) + mu * mu * std::sin(psi) * std::sin(psi);
          const double d4 = (1.0 - mu * mu) * std::sin(2.0 * psi);
          const FrictionForces f = law.evaluate(dimensionless_contact(s, mu, psi));
          SCOPED_TRACE(where(p, s, mu, psi, 1.0));
          EXPECT_NEAR(f.F1, 1.0 - 0.5 * m2 * d3 / (s * s), promised(p));
          EXPECT_NEAR(f.F2, 0.5 * m2 * d4 / (s * s), promised(p));
          EXPECT_NEAR(f.M, m2 * d3 / s, promised(p));
        }
      }
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
