// The exact law for each pressure model (friction/pressure.h) against the closed forms derived in
// docs/pressure-models.md §2 (pure spin, the uniform circle for every slip ratio, the fast-slip
// rule), symmetries, and against exact-reference (an independent 2-D quadrature) on a seeded set.

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "friction/exact_law.h"
#include "friction/exact_reference_law.h"
#include "friction/pressure.h"
#include "friction/registry.h"

namespace frictionlab::friction {
namespace exact_law_pressure_test {

constexpr double kPi = std::numbers::pi;
// The accuracy `exact` promises for the uniform and punch pressures (per kN and kNa).
constexpr double kTol = kExactLawPressureAccuracy;
const Pressure kAll[] = {Pressure::hertz, Pressure::uniform, Pressure::punch};

std::string spec_of(Pressure p) { return "exact:pressure=" + std::string(pressure_name(p)); }

// a = 1, N = 1, k = 1: forces per kN, moment per kNa.
ContactInput unit(double s, double mu, double psi, double omega = 1.0) {
  return {s * std::abs(omega), omega, 1.0, mu, psi, 1.0, 1.0};
}

// The uniform circle, docs/pressure-models.md §2 (Contensou-Erismann), in long double:
// F1/kN and M/kNa at slip ratio u. The u >= 1 moment cancels like u^4: good to ~1e-14 for u <= 20.
struct Circle {
  double f1, m;
};
Circle uniform_circle(double u_in) {
  const long double u = u_in;
  const long double u2 = u * u;
  const long double pi = std::numbers::pi_v<long double>;
  if (u == 1.0L) return {static_cast<double>(8.0L / (3.0L * pi)), static_cast<double>(8.0L / (9.0L * pi))};  // (1 - u^2) K -> 0
  if (u < 1.0L) {
    const long double K = boost::math::ellint_1(u);
    const long double E = boost::math::ellint_2(u);
    return {static_cast<double>(4.0L / (3.0L * pi * u) * ((1.0L + u2) * E - (1.0L - u2) * K)),
            static_cast<double>(4.0L / (9.0L * pi) * ((4.0L - 2.0L * u2) * E - (1.0L - u2) * K))};
  }
  const long double K = boost::math::ellint_1(1.0L / u);
  const long double E = boost::math::ellint_2(1.0L / u);
  return {static_cast<double>(4.0L / (3.0L * pi) * ((1.0L + u2) * E - (u2 - 1.0L) * K)),
          static_cast<double>(4.0L * u / (9.0L * pi) * ((4.0L - 2.0L * u2) * E + (2.0L * u2 - 5.0L + 3.0L / u2) * K))};
}

TEST(ExactPressure, SpecsMakeTheLawWithItsPressure) {
  for (const Pressure p : kAll) {
    const auto law = make_law(spec_of(p));
    EXPECT_EQ(law->name(), "exact");
    EXPECT_EQ(law->spec(), spec_of(p));
    const auto* exact = dynamic_cast<const ExactLaw*>(law.get());
    ASSERT_NE(exact, nullptr);
    EXPECT_EQ(exact->pressure(), p);
  }
  EXPECT_EQ(dynamic_cast<const ExactLaw&>(*make_law("exact")).pressure(), Pressure::hertz);
}

TEST(ExactPressure, PureSpinOfACircle) {
  // Hertz (3 pi/16) kNa, uniform (2/3) kNa, punch (pi/4) kNa; F1 = F2 = 0.
  const double expected[] = {3.0 * kPi / 16.0, 2.0 / 3.0, kPi / 4.0};
  for (int i = 0; i < 3; ++i) {
    const ExactLaw law(kAll[i]);
    for (const double omega : {2.0, -2.0}) {
      const FrictionForces f = law.evaluate({0.0, omega, 0.01, 0.01, 0.4, 20.0, 0.3});
      const double kNa = 0.3 * 20.0 * 0.01;
      EXPECT_NEAR(f.F1, 0.0, kTol * 6.0) << pressure_name(kAll[i]);
      EXPECT_NEAR(f.F2, 0.0, kTol * 6.0) << pressure_name(kAll[i]);
      EXPECT_NEAR(f.M, std::copysign(expected[i], omega) * kNa, kTol * kNa) << pressure_name(kAll[i]);
    }
  }
}

TEST(ExactPressure, PureSpinOfAnEllipseIsTheFactorTimesE) {
  // M = c k N a E(e), c = 3/8, 4/(3 pi), 1/2.
  const double factor[] = {3.0 / 8.0, 4.0 / (3.0 * kPi), 0.5};
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(pressure_pure_spin_factor(kAll[i]), factor[i]);
    const ExactLaw law(kAll[i]);
    for (const double mu : {0.01, 0.05, 0.3, 0.7, 0.999}) {
      const double E = boost::math::ellint_2(std::sqrt((1.0 - mu) * (1.0 + mu)));
      EXPECT_NEAR(law.evaluate(unit(0.0, mu, 0.9)).M, factor[i] * E, kTol)
          << pressure_name(kAll[i]) << " mu = " << mu;
    }
  }
}

TEST(ExactPressure, UniformCircleForEverySlipRatio) {
  const ExactLaw law(Pressure::uniform);
  for (const double u : {1e-4, 1e-2, 0.1, 0.5, 0.9, 0.999, 1.0, 1.001, 1.1, 2.0, 5.0, 20.0}) {
    const Circle c = uniform_circle(u);
    for (const double psi : {0.0, 1.1}) {  // a circle: psi does not matter
      const FrictionForces f = law.evaluate(unit(u, 1.0, psi));
      EXPECT_NEAR(f.F1, c.f1, kTol) << "u = " << u;
      EXPECT_NEAR(f.F2, 0.0, kTol) << "u = " << u;
      EXPECT_NEAR(f.M, c.m, kTol) << "u = " << u;
    }
  }
}

TEST(ExactPressure, FastSlipCoefficientsAreTheSecondMoments) {
  // F1 = kN (1 - m2 d3/(2 s^2)), F2 = kN m2 d4/(2 s^2), M = kNa m2 d3/s + O(s^-3), m2 = 1/5, 1/4,
  // 1/3: measured at s = 1e3, where the law integrates (its expansion starts at 1e8) and the
  // next terms are ~1e-6 relative.
  const double m2[] = {0.2, 0.25, 1.0 / 3.0};
  const double s = 1e3;
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(pressure_second_moment(kAll[i]), m2[i]);
    const ExactLaw law(kAll[i]);
    for (const double mu : {0.05, 0.4, 1.0}) {
      for (const double psi : {0.0, 0.7, 2.0}) {
        const double d3 = std::cos(psi) * std::cos(psi) + mu * mu * std::sin(psi) * std::sin(psi);
        const double d4 = (1.0 - mu * mu) * std::sin(2.0 * psi);
        const FrictionForces f = law.evaluate(unit(s, mu, psi));
        SCOPED_TRACE(std::string(pressure_name(kAll[i])) + " mu = " + std::to_string(mu) + " psi = " + std::to_string(psi));
        EXPECT_NEAR((1.0 - f.F1) * s * s, 0.5 * m2[i] * d3, 2e-4);
        EXPECT_NEAR(f.F2 * s * s, 0.5 * m2[i] * d4, 2e-4);
        EXPECT_NEAR(f.M * s, m2[i] * d3, 1e-5);
      }
    }
  }
}

TEST(ExactPressure, SymmetriesHoldForEveryPressure) {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const Pressure p : kAll) {
    const ExactLaw law(p);
    for (int i = 0; i < 60; ++i) {
      const double s = std::pow(10.0, -3.0 + 6.0 * uni(rng));
      const double mu = std::pow(10.0, -2.0 * uni(rng));
      const double psi = kPi * (2.0 * uni(rng) - 1.0);
      const FrictionForces f = law.evaluate(unit(s, mu, psi));
      const FrictionForces spin = law.evaluate(unit(s, mu, psi, -1.0));
      const FrictionForces turned = law.evaluate(unit(s, mu, psi + kPi));
      const FrictionForces mirror = law.evaluate(unit(s, mu, -psi));
      SCOPED_TRACE(std::string(pressure_name(p)) + " s = " + std::to_string(s) + " mu = " + std::to_string(mu));
      EXPECT_NEAR(spin.F1, f.F1, kTol);  // even in Omega
      EXPECT_NEAR(spin.F2, f.F2, kTol);
      EXPECT_NEAR(spin.M, -f.M, kTol);  // odd
      EXPECT_NEAR(turned.F1, f.F1, kTol);  // the patch is symmetric under a half turn
      EXPECT_NEAR(turned.F2, f.F2, kTol);
      EXPECT_NEAR(turned.M, f.M, kTol);
      EXPECT_NEAR(mirror.F1, f.F1, kTol);  // mirror: F2 flips
      EXPECT_NEAR(mirror.F2, -f.F2, kTol);
      EXPECT_NEAR(mirror.M, f.M, kTol);
      EXPECT_LE(f.F1 * f.F1 + f.F2 * f.F2, 1.0 + kTol);
      EXPECT_GT(f.F1, 0.0);
      EXPECT_GT(f.M, 0.0);
    }
  }
}

TEST(ExactPressure, AgreesWithTheReferenceOnASeededSet) {
  // exact-reference integrates the definition in 2-D (GSL, accurate to 1e-10): a few points per
  // pressure (about 0.1 s each), mu log-uniform in [0.01, 1], s log-uniform in [1e-2, 1e2] with
  // one ICR near the rim, psi anywhere.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const Pressure p : kAll) {
    const ExactLaw law(p);
    const ExactReferenceLaw reference(p);
    for (int i = 0; i < 5; ++i) {
      const double mu = std::pow(10.0, -2.0 * uni(rng));
      const double psi = kPi * (2.0 * uni(rng) - 1.0);
      double s = std::pow(10.0, -2.0 + 4.0 * uni(rng));
      if (i == 0) {  // the ICR just outside the rim: c~ = s (sin psi, cos psi / mu), |c~| = 1.01
        s = 1.01 / std::hypot(std::sin(psi), std::cos(psi) / mu);
      }
      const ContactInput in = unit(s, mu, psi, i % 2 == 0 ? 1.0 : -1.0);
      const FrictionForces f = law.evaluate(in);
      const FrictionForces r = reference.evaluate(in);
      SCOPED_TRACE(std::string(pressure_name(p)) + " s = " + std::to_string(s) + " mu = " + std::to_string(mu) +
                   " psi = " + std::to_string(psi));
      // Both promise 1e-10: they must agree to twice that.
      EXPECT_NEAR(f.F1, r.F1, 2.0 * kTol);
      EXPECT_NEAR(f.F2, r.F2, 2.0 * kTol);
      EXPECT_NEAR(f.M, r.M, 2.0 * kTol);
    }
  }
}

// The uniform law against the independent 2-D quadrature at the ICR scaled distance |c~| = rho
// (docs/pressure-models.md §3): both promise 1e-10, so they must agree to twice that.
void expect_uniform_matches_reference_at(double mu, double rho, double psi, double omega = 1.0) {
  static const ExactLaw law(Pressure::uniform);
  static const ExactReferenceLaw reference(Pressure::uniform);
  const double s = rho / std::hypot(std::sin(psi), std::cos(psi) / mu);
  const ContactInput in = unit(s, mu, psi, omega);
  const FrictionForces f = law.evaluate(in);
  const FrictionForces r = reference.evaluate(in);
  SCOPED_TRACE("mu = " + std::to_string(mu) + " |c~| = " + std::to_string(rho) + " psi = " + std::to_string(psi) +
               " Omega = " + std::to_string(omega));
  EXPECT_NEAR(f.F1, r.F1, 2.0 * kTol);
  EXPECT_NEAR(f.F2, r.F2, 2.0 * kTol);
  EXPECT_NEAR(f.M, r.M, 2.0 * kTol);
}

TEST(ExactPressure, UniformAgreesWithTheReferenceInsideSlenderPatches) {
  // The uniform law takes the ICR reduction in the Jacobi amplitude for the ICR inside (not too
  // near the rim) and the rim integrals elsewhere (docs/pressure-models.md §3): slender patches,
  // where 1/L is nearly singular, with the ICR at the centre, half-way, and on either side of
  // |c~| = 0.97, where the law changes route; against the independent 2-D quadrature.
  for (const double mu : {0.01, 0.04})
    for (const double rho : {1e-3, 0.5, 0.965, 0.975}) expect_uniform_matches_reference_at(mu, rho, mu < 0.02 ? 0.4 : 1.3);
}

TEST(ExactPressure, UniformAgreesWithTheReferenceInsideRoundPatches) {
  // For the ICR inside, the trapezoid rule's node count comes from a bound on the distance of
  // sqrt(D)'s branch points that grows with mu (docs/pressure-models.md §3): the fewest nodes for
  // a given |c~| are taken in round patches, checked here against the independent 2-D quadrature.
  for (const double mu : {0.6, 0.95})
    for (const double rho : {1e-3, 0.6, 0.95}) expect_uniform_matches_reference_at(mu, rho, 0.7);
}

TEST(ExactPressure, UniformAgreesWithTheReferenceOutsideTheRim) {
  // The uniform law takes the window of the ICR reduction in the variable chi of
  // rho sin phi = sin chi for the ICR outside, and the rim integrals within ~0.03 of the rim
  // (docs/pressure-models.md §3): ellipses from slender to round, the ICR on either side of that
  // boundary (|c~| = 1.02, 1.05), near (1.5), and far (6, 400, where the rule takes few nodes);
  // generic psi, both spins; against the independent 2-D quadrature.
  int i = 0;
  for (const double mu : {0.012, 0.2, 0.75}) {
    for (const double rho : {1.02, 1.05, 1.5, 6.0, 400.0}) {
      const double psi = 0.35 + 0.9 * i;  // not on an axis, where symmetry zeroes a component
      expect_uniform_matches_reference_at(mu, rho, psi, i % 2 == 0 ? 1.0 : -1.0);
      ++i;
    }
  }
}

TEST(ExactPressure, UniformAgreesWithTheReferenceWhereTheWindowIsGraded) {
  // Where L's branch points come near the real chi axis (slender patches) or the ICR near the rim,
  // the window's trapezoid rule would need more than its largest node count, and graded
  // Gauss-Legendre panels take over (docs/pressure-models.md §3): the ICR from just outside the
  // rim (|c~| = 1.0005) to |c~| = 3, the patch's axis near the slip direction (psi = 0.02) and
  // nearly across it (psi = 1.45, 1.53: there the panels graded towards the nearest singularity
  // alone were off by up to 5e-4, until panels that no rule covers were halved); both spins;
  // against the independent 2-D quadrature.
  int i = 0;
  for (const double mu : {0.014, 0.03, 0.1}) {
    for (const double rho : {1.0005, 1.02, 1.4, 3.0}) {
      for (const double psi : {0.02, 1.45, 1.53}) {
        expect_uniform_matches_reference_at(mu, rho, psi, i % 2 == 0 ? 1.0 : -1.0);
        ++i;
      }
    }
  }
}

TEST(ExactPressure, ForceNeverPointsAlongTheSlip) {
  // F1 >= 0 for every centrally symmetric pressure: the points rho and -rho carry the same
  // pressure and slide with v = U e1 +- Omega J rho =: v1, v2, and with U e1 = (v1 + v2)/2,
  // (v1/|v1| + v2/|v2|).(v1 + v2) = (|v1| + |v2|)(1 + cos(v1, v2)) >= 0. Fuzzed over every axis
  // ratio the law accepts, slow to fast slip, psi near the axes, and the two fuzzed inputs of
  // docs/pressure-models.md §3 (the uniform law gave F1 = -1.6e-4 kN at the second, slip ratio 4e-8, b/a = 1e-12).
  std::mt19937_64 rng(1910);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<ContactInput> inputs = {unit(255094.52174620156, 1.0025254830532505e-12, -2.4426969214284204),
                                      unit(3.9575557720477157e-08, 1.0753224871646648e-12, 3.0505797375823827)};
  for (int i = 0; i < 3000; ++i) {
    const double mu = std::pow(10.0, -12.0 * uni(rng));
    const double s = std::pow(10.0, -12.0 + 24.0 * uni(rng));
    double psi = kPi * (2.0 * uni(rng) - 1.0);
    if (i % 2 == 1) psi = (uni(rng) < 0.5 ? 0.0 : kPi / 2) + (uni(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, -12.0 + 10.0 * uni(rng));
    inputs.push_back(unit(s, mu, psi, uni(rng) < 0.5 ? 1.0 : -1.0));
  }
  for (const Pressure p : kAll) {
    const ExactLaw law(p);
    const double tol = p == Pressure::hertz ? kExactLawAccuracy : kExactLawPressureAccuracy;
    for (const ContactInput& in : inputs) {
      const FrictionForces f = law.evaluate(in);
      EXPECT_GE(f.F1, -tol) << pressure_name(p) << " s = " << in.U << " mu = " << in.b << " psi = " << in.psi.radians();
      EXPECT_LE(std::hypot(f.F1, f.F2), 1.0 + tol) << pressure_name(p) << " s = " << in.U << " mu = " << in.b
                                                     << " psi = " << in.psi.radians();
    }
  }
}

TEST(ExactPressure, FiniteOnSlenderPatchesAtEverySlipRatio) {
  for (const Pressure p : kAll) {
    const ExactLaw law(p);
    for (const double mu : {1e-3, 1e-6, 1e-12}) {
      for (const double s : {0.0, 1e-6, 0.5, 1.0, 3.0, 1e5, 1e12}) {
        for (const double psi : {0.0, 0.3, kPi / 2}) {
          const FrictionForces f = law.evaluate(unit(s, mu, psi));
          EXPECT_TRUE(std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M))
              << pressure_name(p) << " mu = " << mu << " s = " << s << " psi = " << psi;
        }
      }
    }
  }
}

// The ICR on the rim to the last bit: slip speeds within a few ulps of the one that puts the ICR
// on the rim (rho^2 = s^2 (sin^2 psi + cos^2 psi/mu^2) = 1), where the routes inside and outside
// meet and sqrt(rho^2) may round to 1 with rho^2 > 1 (the uniform pressure's graded window had a
// branch point on its end there and returned NaN: U = 0.24651415936864718, b/a = 0.1, psi =
// 1.164600151803648). Every output finite, and the neighbours within the law's accuracy of each
// other (the law is continuous there).
TEST(ExactPressure, AnIcrOnTheRimToTheLastBitIsFiniteAndContinuous) {
  for (const Pressure pressure : kAll) {
    const ExactLaw law(pressure);
    const double tol = pressure == Pressure::hertz ? kExactLawAccuracy : kTol;
    for (const double mu : {1.0, 0.5, 0.1, 0.03, 0.01, 1e-3, 1e-5}) {
      for (int j = 0; j <= 36; ++j) {
        const double psi = kPi * j / 36.0;
        const double k = std::sqrt(std::pow(std::sin(psi), 2) + std::pow(std::cos(psi) / mu, 2));
        double U = 1.0 / k;
        for (int n = 0; n < 6; ++n) U = std::nextafter(U, 0.0);
        FrictionForces first{};
        for (int n = 0; n < 12; ++n, U = std::nextafter(U, 1.0)) {
          ContactInput in;
          in.U = U;
          in.Omega = 1.0;
          in.a = 1.0;
          in.b = mu;
          in.psi = PatchAngle(psi);
          in.N = 1.0;
          in.k = 1.0;
          const FrictionForces f = law.evaluate(in);
          ASSERT_TRUE(std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M))
              << pressure_name(pressure) << " mu " << mu << " psi " << psi << " U " << U;
          if (n == 0) first = f;
          EXPECT_NEAR(f.F1, first.F1, tol) << pressure_name(pressure) << " mu " << mu << " psi " << psi;
          EXPECT_NEAR(f.F2, first.F2, tol) << pressure_name(pressure) << " mu " << mu << " psi " << psi;
          EXPECT_NEAR(f.M, first.M, tol) << pressure_name(pressure) << " mu " << mu << " psi " << psi;
        }
      }
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
