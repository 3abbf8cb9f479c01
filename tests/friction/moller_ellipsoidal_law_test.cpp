// The ellipsoidal law of Möller, Leine & Glocker against hand values, its limits and symmetries.

#include "friction/moller_ellipsoidal_law.h"

#include <gtest/gtest.h>

#include "friction/exact_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace frictionlab::friction {
namespace {

constexpr double pi = std::numbers::pi;
// Hand values below are a few rationals times pi: 1e-14 relative covers the rounding of the
// handful of floating-point operations in the law and in the expected value.
constexpr double kHandTol = 1e-14;

TEST(MollerEllipsoidalLaw, HandValueOnAThreeFourFiveTriangle) {
  // a = 2, b = 1/2: sqrt(ab) = 1, Rb = 3 pi/16. Omega = 64/(3 pi) makes Rb Omega = 4; U = 3:
  // den = 5. k = 1/2, N = 4: kN = 2. F1 = 2 (3/5) = 6/5, M = 2 Rb (4/5) = (8/5)(3 pi/16) = 3 pi/10.
  const MollerEllipsoidalLaw law;
  const auto f = law.evaluate({3.0, 64.0 / (3.0 * pi), 2.0, 0.5, 0.3, 4.0, 0.5});
  EXPECT_NEAR(f.F1, 1.2, kHandTol);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_NEAR(f.M, 0.3 * pi, kHandTol);
}

TEST(MollerEllipsoidalLaw, PureLimitsExactlyNearAndAway) {
  const MollerEllipsoidalLaw law;
  const double a = 0.3, b = 0.12, kN = 1.7;
  const double Rb = 3.0 * pi / 16.0 * std::sqrt(a * b);
  // At rest: every ratio is 0/0; the law returns zero, as the exact law does.
  const auto rest = law.evaluate({0.0, 0.0, a, b, 0.4, kN, 1.0});
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.F2, 0.0);
  EXPECT_EQ(rest.M, 0.0);
  // Pure spin, exactly: M = kN Rb sign(Omega), F1 = 0.
  const auto spin = law.evaluate({0.0, -2.0, a, b, 0.4, kN, 1.0});
  EXPECT_EQ(spin.F1, 0.0);
  EXPECT_NEAR(spin.M, -kN * Rb, kHandTol);
  // Pure sliding, exactly: F1 = kN, M = 0.
  const auto slide = law.evaluate({0.5, 0.0, a, b, 0.4, kN, 1.0});
  EXPECT_EQ(slide.F1, kN);
  EXPECT_EQ(slide.M, 0.0);
  // Near the limits (ratio 1e-8): first-order terms, F1 = kN U/(Rb|Omega|), M = kN Rb^2 Omega/U.
  const double eps = 1e-8;
  const auto near_spin = law.evaluate({eps * Rb * 2.0, 2.0, a, b, 0.4, kN, 1.0});
  EXPECT_NEAR(near_spin.F1, kN * eps, 1e-12 * kN * eps);
  EXPECT_NEAR(near_spin.M, kN * Rb, 1e-15);
  const auto near_slide = law.evaluate({0.5, eps * 0.5 / Rb, a, b, 0.4, kN, 1.0});
  EXPECT_NEAR(near_slide.F1, kN, 1e-15);
  EXPECT_NEAR(near_slide.M, kN * Rb * eps, 1e-12 * kN * Rb * eps);
  // Away: U = Rb |Omega|: F1 = kN/sqrt 2, M = kN Rb/sqrt 2.
  const auto mid = law.evaluate({Rb * 2.0, 2.0, a, b, 0.4, kN, 1.0});
  EXPECT_NEAR(mid.F1, kN / std::sqrt(2.0), kHandTol);
  EXPECT_NEAR(mid.M, kN * Rb / std::sqrt(2.0), kHandTol);
}

TEST(MollerEllipsoidalLaw, CircleSpinTorqueIsTheExactHertzValue) {
  // For a circle Rb = (3 pi/16) a, the exact pure-spin torque of the Hertz patch (docs/model.md).
  const MollerEllipsoidalLaw law;
  const auto f = law.evaluate({0.0, 5.0, 0.01, 0.01, 0.0, 100.0, 0.2});
  EXPECT_NEAR(f.M, 3.0 * pi / 16.0 * 0.2 * 100.0 * 0.01, kHandTol);
}

TEST(MollerEllipsoidalLaw, SymmetriesAndDissipationOnRandomInputs) {
  const MollerEllipsoidalLaw law;
  std::mt19937_64 rng(20240604);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double a = 0.01 + u01(rng);
    const double b = a * (0.05 + 0.95 * u01(rng));
    const double U = std::pow(10.0, -3.0 + 6.0 * u01(rng)) * a;
    const double Omega = 1.0 + 9.0 * u01(rng);
    const double psi = pi * u01(rng);
    const ContactInput in{U, Omega, a, b, psi, 3.0, 0.4};
    const auto p = law.evaluate(in);
    auto flipped = in;
    flipped.Omega = -Omega;
    const auto m = law.evaluate(flipped);
    EXPECT_EQ(m.F1, p.F1);    // even in Omega
    EXPECT_EQ(m.M, -p.M);     // odd in Omega
    auto turned = in;
    turned.psi = psi + 1.0;   // the law cannot see the orientation
    EXPECT_EQ(law.evaluate(turned).F1, p.F1);
    EXPECT_GE(p.F1 * U + p.M * Omega, 0.0);
    EXPECT_GE(m.F1 * U + m.M * -Omega, 0.0);
  }
}

TEST(MollerEllipsoidalLaw, AgainstTheExactLaw) {
  // For a circle the law is exact in both pure limits; in between, and for ellipses, it is an
  // approximation whose errors the accuracy study measures (docs/accuracy.md). Here: the pure
  // limits, and that it stays within the exact law's bounds and signs everywhere on a grid:
  // 0 <= F1 <= kN, M of the sign of the exact M (the sign of Omega).
  // The exact law is accurate to kExactLawAccuracy; the pure limits agree to twice that.
  constexpr double kExactTol = 2.0 * kExactLawAccuracy;
  const ExactLaw exact;
  const MollerEllipsoidalLaw law;
  const auto circle_spin = law.evaluate({0.0, 3.0, 1.0, 1.0, 0.0, 1.0, 1.0});
  EXPECT_NEAR(circle_spin.M, exact.evaluate({0.0, 3.0, 1.0, 1.0, 0.0, 1.0, 1.0}).M, kExactTol);
  EXPECT_NEAR(law.evaluate({2.0, 0.0, 1.0, 0.3, 0.5, 1.0, 1.0}).F1,
              exact.evaluate({2.0, 0.0, 1.0, 0.3, 0.5, 1.0, 1.0}).F1, kExactTol);
  for (double mu : {0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0}) {
    for (int j = 0; j <= 12; ++j) {
      const double psi = pi * j / 12.0;
      for (int i = 0; i <= 120; ++i) {
        const double s = std::pow(10.0, -3.0 + 6.0 * i / 120.0);
        for (const double Omega : {-1.0, 1.0}) {
          const ContactInput in{s, Omega, 1.0, mu, psi, 1.0, 1.0};
          const auto r = law.evaluate(in);
          const auto e = exact.evaluate(in);
          EXPECT_GE(r.F1, 0.0);
          EXPECT_LE(r.F1, 1.0);
          EXPECT_GT(r.M * e.M, 0.0) << "mu = " << mu << ", s = " << s;
        }
      }
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
