// Tests of friction/exact_law.h against the facts of docs/model.md: closed forms, asymptotics,
// symmetries, dissipation, limits (at, near and away). The 30-digit values are in
// tests/friction/exact_law_table_test.cpp.

#include "friction/exact_law.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/friction/dimensionless_contact.h"
#include "tests/friction/hertz_closed_forms.h"

namespace frictionlab::friction {
namespace exact_law_test {

constexpr double kPi = std::numbers::pi;

// What the law promises, per kN and kNa (friction/exact_law.h); the closed forms, evaluated in
// long double, add ~1e-16. Any formula or quadrature error shows up at 1e-8 or worse.
constexpr double kClosedFormTol = kExactLawAccuracy;
// Identities between two evaluations, each within kExactLawAccuracy of the true value (the
// rounding of a perturbed psi or of rescaled inputs moves the true values by ~1e-14 at most for
// the mu >= 0.01 used here).
constexpr double kRoundingTol = 2.0 * kExactLawAccuracy;
// Slow slip, u = 1e-6: the neglected term is O(u^2) relative (1e-12); rounding of F1 ~ 1e-6
// adds ~1e-10 relative at worst.
constexpr double kSlowSlipRelTol = 1e-9;
// Fast slip at u = 1e3 and 1e4: the neglected terms are O(u^-2) relative, 1e-6 at most; the
// residuals (1 - F1) u^2 are also rounded at ~1e-16 u^2 relative to d3/10 (1e-8 at u = 1e4).
constexpr double kFastSlipRelTol = 1e-5;
// Continuity across a limit perturbed by 1e-8: |dF/dx| = O(1), so changes are ~1e-8.
constexpr double kNearLimitTol = 1e-7;

ContactInput make(double s, double mu, double psi, double omega = 1.0) {
  return dimensionless_contact(s, mu, psi, omega);
}

FrictionForces eval(const ContactInput& in) { return ExactLaw{}.evaluate(in); }

// A seeded sample over the whole domain: s log-uniform in [1e-3, 1e3], mu log-uniform in
// [0.01, 1], psi in [0, pi), both signs of Omega, physical a, N, k.
std::vector<ContactInput> random_inputs(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<ContactInput> out;
  for (int i = 0; i < n; ++i) {
    ContactInput in;
    in.a = 0.003 + 0.01 * uni(rng);
    in.b = in.a * std::pow(10.0, -2.0 * uni(rng));
    in.psi = kPi * uni(rng);
    in.Omega = (uni(rng) < 0.5 ? -1.0 : 1.0) * (1.0 + 50.0 * uni(rng));
    in.U = std::pow(10.0, -3.0 + 6.0 * uni(rng)) * in.a * std::abs(in.Omega);
    in.N = 5.0 + 20.0 * uni(rng);
    in.k = 0.05 + 0.5 * uni(rng);
    out.push_back(in);
  }
  return out;
}

TEST(ExactLaw, NameAndSummary) {
  const ExactLaw law;
  EXPECT_EQ(law.name(), "exact");
  EXPECT_FALSE(law.summary().empty());
}

TEST(ExactLaw, PureSlidingIsExactlyCoulomb) {
  for (const double mu : {0.01, 0.3, 1.0}) {
    for (const double psi : {0.0, 0.7, 2.0}) {
      ContactInput in = make(0.0, mu, psi, 0.0);
      in.U = 2.5;
      in.k = 0.3;
      in.N = 7.0;
      const FrictionForces f = eval(in);
      EXPECT_EQ(f.F1, 0.3 * 7.0);
      EXPECT_EQ(f.F2, 0.0);
      EXPECT_EQ(f.M, 0.0);
    }
  }
}

TEST(ExactLaw, PureSpinIsTheEllipticIntegralOfTheSecondKind) {
  for (const double mu : {0.01, 0.05, 0.3, 0.5, 0.7, 0.99, 1.0}) {
    for (const double omega : {2.0, -0.5}) {
      const FrictionForces f = eval(make(0.0, mu, 0.4, omega));
      EXPECT_EQ(f.F1, 0.0) << "mu = " << mu;
      EXPECT_EQ(f.F2, 0.0) << "mu = " << mu;
      EXPECT_NEAR(f.M, std::copysign(test::pure_spin_moment(mu), omega), kClosedFormTol)
          << "mu = " << mu;
    }
  }
  EXPECT_NEAR(eval(make(0.0, 1.0, 0.0)).M, 3.0 * kPi / 16.0, kClosedFormTol);
}

TEST(ExactLaw, CircleClosedFormsInsideOnAndOutsideTheRim) {
  const double us[] = {1e-8, 1e-3, 0.1, 0.5, 0.9, 1.0 - 1e-8, 1.0, 1.0 + 1e-8, 1.1,
                       1.4142,  1.4143, 1.5, 2.0, 3.0, 5.0, 10.0};
  for (const double u : us) {
    for (const double omega : {1.0, -3.0}) {
      const FrictionForces f = eval(make(u, 1.0, 0.8, omega));
      const test::CircleForces c = test::circle(u);
      EXPECT_NEAR(f.F1, c.f1, kClosedFormTol) << "u = " << u;
      EXPECT_NEAR(f.M, std::copysign(c.m, omega), kClosedFormTol) << "u = " << u;
      EXPECT_EQ(f.F2, 0.0) << "u = " << u;
    }
  }
  // The slow-slip slope of the circle, 3 pi / 8.
  EXPECT_NEAR(eval(make(1e-6, 1.0, 0.0)).F1 / 1e-6, 3.0 * kPi / 8.0, kSlowSlipRelTol);
}

TEST(ExactLaw, SlowSlipSlopeOfEllipsesMatchesKAndE) {
  constexpr double u = 1e-6;
  for (const double mu : {0.01, 0.05, 0.2, 0.5, 0.8, 0.95}) {
    for (const double psi : {0.0, 0.3, kPi / 4, 1.2, kPi / 2, 2.5}) {
      const FrictionForces f = eval(make(u, mu, psi));
      const test::SlowSlipSlopes slope = test::slow_slip_slopes(mu, psi);
      EXPECT_NEAR(f.F1 / u, slope.f1, kSlowSlipRelTol * slope.f1) << mu << " " << psi;
      EXPECT_NEAR(f.F2 / u, slope.f2, kSlowSlipRelTol * slope.f1) << mu << " " << psi;
    }
  }
}

TEST(ExactLaw, FastSlipAsymptotics) {
  for (const double u : {1e3, 1e4}) {
    for (const double mu : {0.01, 0.3, 0.7, 1.0}) {
      for (const double psi : {0.0, 0.5, 1.3, 2.8}) {
        const FrictionForces f = eval(make(u, mu, psi, -1.0));
        const test::FastSlipMoments d = test::fast_slip_moments(mu, psi);
        EXPECT_NEAR((1.0 - f.F1) * u * u, d.d3 / 10.0, kFastSlipRelTol * d.d3) << u << " " << mu;
        EXPECT_NEAR(f.F2 * u * u, d.d4 / 10.0, kFastSlipRelTol * d.d3) << u << " " << mu;
        EXPECT_NEAR(-f.M * u, d.d3 / 5.0, kFastSlipRelTol * d.d3) << u << " " << mu;
      }
    }
  }
}

TEST(ExactLaw, FastSlipExpansionTakesOverContinuously) {
  // Above s = 1e8 the law switches from quadrature to the expansion; M s is continuous there
  // to the expansion's truncation error, O(s^-2) relative.
  for (const double mu : {0.01, 0.4, 1.0}) {
    const double psi = 0.9;
    const double below = 1e8 * (1.0 - 1e-12);
    const double above = 1e8 * (1.0 + 1e-12);
    const FrictionForces fb = eval(make(below, mu, psi));
    const FrictionForces fa = eval(make(above, mu, psi));
    EXPECT_NEAR(fb.M * below, fa.M * above, 1e-12) << "mu = " << mu;
    EXPECT_NEAR(fb.F1, 1.0, 1e-15);
    EXPECT_NEAR(fa.F1, 1.0, 1e-15);
    // F2 ~ 1e-17 here: quadrature gets it to ~1e-16 kN absolute (its accuracy is relative to
    // kN), the expansion to ~1e-16 relative; they agree absolutely.
    EXPECT_NEAR(fb.F2, fa.F2, 1e-15) << "mu = " << mu;
  }
  // s overflowing to infinity (Omega denormal) is pure sliding.
  ContactInput in = make(0.0, 0.5, 0.3, 1e-310);
  in.U = 1.0;
  const FrictionForces f = eval(in);
  EXPECT_EQ(f.F1, 1.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
}

TEST(ExactLaw, DependsOnlyOnSlipRatioAxisRatioAngleAndSpinSign) {
  for (const ContactInput& in : random_inputs(40, 11)) {
    ContactInput scaled = in;
    scaled.a = in.a * 7.0;
    scaled.b = in.b * 7.0;
    scaled.U = in.U * 7.0 * 0.25;
    scaled.Omega = in.Omega * 0.25;
    scaled.N = in.N * 3.0;
    scaled.k = in.k * 0.5;
    const FrictionForces f = eval(in);
    const FrictionForces g = eval(scaled);
    const double kN = in.k * in.N;
    const double kNs = scaled.k * scaled.N;
    EXPECT_NEAR(f.F1 / kN, g.F1 / kNs, kRoundingTol);
    EXPECT_NEAR(f.F2 / kN, g.F2 / kNs, kRoundingTol);
    EXPECT_NEAR(f.M / (kN * in.a), g.M / (kNs * scaled.a), kRoundingTol);
  }
}

TEST(ExactLaw, SymmetriesInSpinAndOrientation) {
  for (const ContactInput& in : random_inputs(60, 12)) {
    const FrictionForces f = eval(in);
    const double kN = in.k * in.N;
    const double kNa = kN * in.a;
    // Omega -> -Omega: F1, F2 even, M odd (exactly: the sign is applied last).
    ContactInput flipped = in;
    flipped.Omega = -in.Omega;
    const FrictionForces g = eval(flipped);
    EXPECT_EQ(g.F1, f.F1);
    EXPECT_EQ(g.F2, f.F2);
    EXPECT_EQ(g.M, -f.M);
    // psi -> psi + pi: nothing changes.
    ContactInput turned = in;
    turned.psi = in.psi.radians() + kPi;
    const FrictionForces h = eval(turned);
    EXPECT_NEAR(h.F1, f.F1, kRoundingTol * kN);
    EXPECT_NEAR(h.F2, f.F2, kRoundingTol * kN);
    EXPECT_NEAR(h.M, f.M, kRoundingTol * kNa);
    // psi -> -psi: only F2 changes sign.
    ContactInput mirrored = in;
    mirrored.psi = -in.psi.radians();
    const FrictionForces m = eval(mirrored);
    EXPECT_NEAR(m.F1, f.F1, kRoundingTol * kN);
    EXPECT_NEAR(m.F2, -f.F2, kRoundingTol * kN);
    EXPECT_NEAR(m.M, f.M, kRoundingTol * kNa);
  }
}

TEST(ExactLaw, NoSideForceForACircleOrAlongAnAxis) {
  for (const double s : {0.01, 0.3, 0.999, 1.0, 1.3, 2.0, 40.0}) {
    for (const double mu : {0.01, 0.4, 1.0}) {
      EXPECT_EQ(eval(make(s, mu, 0.0)).F2, 0.0) << s << " " << mu;
      // cos(pi/2) = 6e-17, not 0: F2 is then of that order.
      EXPECT_NEAR(eval(make(s, mu, kPi / 2)).F2, 0.0, 1e-15) << s << " " << mu;
      EXPECT_EQ(eval(make(s, 1.0, 0.37 + mu)).F2, 0.0) << s;
    }
  }
}

TEST(ExactLaw, NeverAddsEnergy) {
  for (const ContactInput& in : random_inputs(200, 13)) {
    const FrictionForces f = eval(in);
    EXPECT_GE(f.F1 * in.U + f.M * in.Omega, 0.0);
    EXPECT_GE(f.F1, 0.0);
    EXPECT_GE(f.M * in.Omega, 0.0);
    EXPECT_LE(std::hypot(f.F1, f.F2), in.k * in.N * (1.0 + kExactLawAccuracy));  // |F| <= kN
  }
}

TEST(ExactLaw, LimitOfZeroSlipAtNearAndAway) {
  for (const double mu : {0.05, 0.6}) {
    const double psi = 0.6;
    const FrictionForces at = eval(make(0.0, mu, psi));
    const FrictionForces near = eval(make(1e-8, mu, psi));
    const FrictionForces away = eval(make(0.2, mu, psi));
    EXPECT_EQ(at.F1, 0.0);
    EXPECT_NEAR(near.F1, 1e-8 * test::slow_slip_slopes(mu, psi).f1, 1e-8 * kSlowSlipRelTol);
    EXPECT_NEAR(near.M, at.M, kNearLimitTol);
    EXPECT_GT(away.F1, near.F1);
    EXPECT_LT(away.M, at.M);  // slip lowers the spin resistance
  }
}

TEST(ExactLaw, LimitOfZeroSpinAtNearAndAway) {
  for (const double mu : {0.05, 0.6}) {
    const double psi = 1.1;
    ContactInput at = make(0.0, mu, psi, 0.0);
    at.U = 1.0;
    ContactInput near = at;
    near.Omega = 1e-8;  // s = 1e8: the edge of the fast-slip expansion
    ContactInput away = at;
    away.Omega = 0.5;  // s = 2
    const FrictionForces fa = eval(at);
    const FrictionForces fn = eval(near);
    const FrictionForces fw = eval(away);
    EXPECT_EQ(fa.F1, 1.0);
    EXPECT_EQ(fa.M, 0.0);
    EXPECT_NEAR(fn.F1, 1.0, 1e-15);
    EXPECT_NEAR(fn.M, test::fast_slip_moments(mu, psi).d3 / 5.0 * 1e-8, 1e-20);
    EXPECT_LT(fw.F1, 1.0 - 1e-3);
    EXPECT_GT(fw.M, 1e-3);
  }
}

TEST(ExactLaw, LimitOfTheCircleAtNearAndAway) {
  for (const double s : {0.3, 1.0, 1.2, 4.0}) {
    const FrictionForces at = eval(make(s, 1.0, 0.5));
    const FrictionForces near = eval(make(s, 1.0 - 1e-8, 0.5));
    const FrictionForces away = eval(make(s, 0.8, 0.5));
    EXPECT_NEAR(near.F1, at.F1, kNearLimitTol) << "s = " << s;
    EXPECT_NEAR(near.F2, at.F2, kNearLimitTol) << "s = " << s;
    EXPECT_NEAR(near.M, at.M, kNearLimitTol) << "s = " << s;
    EXPECT_GT(std::abs(away.F2), 1e-4) << "s = " << s;
  }
}

TEST(ExactLaw, IcrOnNearAndAwayFromTheRim) {
  // mu = 0.5, psi = 0, s = 0.5: the ICR is on the rim, (0, 1) exactly in the scaled frame.
  const FrictionForces on = eval(make(0.5, 0.5, 0.0));
  for (const double eps : {1e-8, -1e-8}) {
    const FrictionForces near = eval(make(0.5 * (1.0 + eps), 0.5, 0.0));
    EXPECT_NEAR(near.F1, on.F1, kNearLimitTol);
    EXPECT_NEAR(near.M, on.M, kNearLimitTol);
  }
  // Spot values below cover on, near and away; here, the rim of a slender patch from both sides.
  const double mu = 0.02;
  const double psi = 0.3;
  const double s_rim = 1.0 / std::hypot(std::sin(psi), std::cos(psi) / mu);
  const FrictionForces r0 = eval(make(s_rim, mu, psi));
  for (const double eps : {1e-8, -1e-8}) {
    const FrictionForces r1 = eval(make(s_rim * (1.0 + eps), mu, psi));
    EXPECT_NEAR(r1.F1, r0.F1, kNearLimitTol);
    EXPECT_NEAR(r1.F2, r0.F2, kNearLimitTol);
    EXPECT_NEAR(r1.M, r0.M, kNearLimitTol);
  }
}

TEST(ExactLaw, ZeroLoadZeroFrictionAndRestGiveNoForce) {
  ContactInput in = make(0.7, 0.4, 0.3, 2.0);
  in.N = 0.0;
  FrictionForces f = eval(in);
  EXPECT_EQ(f.F1, 0.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
  in.N = 1.0;
  in.k = 0.0;
  f = eval(in);
  EXPECT_EQ(f.F1, 0.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
  // U = Omega = 0: indeterminate; documented as zero.
  f = eval(make(0.0, 0.4, 0.3, 0.0));
  EXPECT_EQ(f.F1, 0.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
}

TEST(ExactLaw, SlenderPatchesStayFiniteAndDissipative) {
  // Down to b/a = 1e-12 (the table test checks the values); below, a clear error: the law is not
  // evaluated as a thicker slit, whose values differ by O(1) near psi = pi/2.
  for (const double mu : {1e-3, 1e-6, 1e-9, kExactMinAxisRatio}) {
    for (const double s : {0.0, 1e-4, 0.3, 1.0, 30.0}) {
      const FrictionForces f = eval(make(s, mu, 0.7));
      EXPECT_TRUE(std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M)) << mu;
      EXPECT_GE(f.F1, 0.0);
      EXPECT_LE(f.F1, 1.0 + kExactLawAccuracy);
      EXPECT_GE(f.M, 0.0);
    }
    EXPECT_NEAR(eval(make(0.0, mu, 0.7)).M, test::pure_spin_moment(mu), kClosedFormTol);
  }
  for (const double mu : {0.99e-12, 1e-14, 1e-300}) {
    try {
      (void)eval(make(0.5, mu, 0.7));
      ADD_FAILURE() << "no exception at mu = " << mu;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("is below 1e-12, the smallest"), std::string::npos) << e.what();
    }
  }
}

TEST(ExactLaw, SlitsNearTheMinorAxisStayFiniteAndPhysical) {
  // A slit (mu ~ 1e-9) with the ICR a few units out along the scaled minor axis sees lines nearly
  // along the slip at O(1) angles: the window quadrature must not cancel there. First the input
  // that printed -nan,-nan,inf, then a seeded sweep of the same corner: mu log-uniform in
  // [1e-12, 1e-6], psi within 1e-14..1e-6 of pi/2, s log-uniform in [1e-3, 1e3].
  const FrictionForces f = eval(make(0.5, 1e-9, 1.5707963217948966));
  EXPECT_TRUE(std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 4000; ++i) {
    const double mu = std::pow(10.0, -12.0 + 6.0 * uni(rng));
    const double psi = kPi / 2 + (uni(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, -14.0 + 8.0 * uni(rng));
    const double s = std::pow(10.0, -3.0 + 6.0 * uni(rng));
    const FrictionForces g = eval(make(s, mu, psi, uni(rng) < 0.5 ? -1.0 : 1.0));
    ASSERT_TRUE(std::isfinite(g.F1) && std::isfinite(g.F2) && std::isfinite(g.M))
        << "s = " << s << ", mu = " << mu << ", psi = " << psi;
    EXPECT_GE(g.F1, 0.0);
    EXPECT_LE(std::hypot(g.F1, g.F2), 1.0 + kClosedFormTol);
    EXPECT_LE(std::abs(g.M), test::pure_spin_moment(mu) + kClosedFormTol);
  }
}

TEST(ExactLaw, RejectsInvalidInput) {
  const ExactLaw law;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  ContactInput in = make(0.5, 0.5, 0.3);
  auto with = [&](auto change) {
    ContactInput bad = in;
    change(bad);
    return bad;
  };
  EXPECT_THROW((void)law.evaluate(with([](ContactInput& c) { c.U = -1.0; })), std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([](ContactInput& c) { c.b = 2.0; })), std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([](ContactInput& c) { c.a = 0.0; })), std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([](ContactInput& c) { c.b = 0.0; })), std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([&](ContactInput& c) { c.Omega = nan; })),
               std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([&](ContactInput& c) { c.psi = inf; })),
               std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([](ContactInput& c) { c.N = -1.0; })), std::invalid_argument);
  EXPECT_THROW((void)law.evaluate(with([](ContactInput& c) { c.k = -0.1; })), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::friction
