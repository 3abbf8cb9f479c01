// The ellipsoidal law of Möller, Leine & Glocker — Hertz-calibrated and with a fixed radius Rb —
// against hand values, the maximum-dissipation principle, its limits and symmetries.

#include "friction/ellipsoidal_law.h"

#include <gtest/gtest.h>

#include "friction/exact_law.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace frictionlab::friction {
namespace ellipsoidal_law_test {

constexpr double pi = std::numbers::pi;
// Hand values below are a few rationals times pi: 1e-14 relative covers the rounding of the
// handful of floating-point operations in the law and in the expected value.
constexpr double kHandTol = 1e-14;

TEST(EllipsoidalLaw, HandValueOnAThreeFourFiveTriangle) {
  // a = 2, b = 1/2: sqrt(ab) = 1, Rb = 3 pi/16. Omega = 64/(3 pi) makes Rb Omega = 4; U = 3:
  // den = 5. k = 1/2, N = 4: kN = 2. F1 = 2 (3/5) = 6/5, M = 2 Rb (4/5) = (8/5)(3 pi/16) = 3 pi/10.
  const EllipsoidalLaw law;
  const auto f = law.evaluate({3.0, 64.0 / (3.0 * pi), 2.0, 0.5, 0.3, 4.0, 0.5});
  EXPECT_NEAR(f.F1, 1.2, kHandTol);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_NEAR(f.M, 0.3 * pi, kHandTol);
}

TEST(EllipsoidalLaw, PureLimitsExactlyNearAndAway) {
  const EllipsoidalLaw law;
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

TEST(EllipsoidalLaw, CircleSpinTorqueIsTheExactHertzValue) {
  // For a circle Rb = (3 pi/16) a, the exact pure-spin torque of the Hertz patch (docs/model.md).
  const EllipsoidalLaw law;
  const auto f = law.evaluate({0.0, 5.0, 0.01, 0.01, 0.0, 100.0, 0.2});
  EXPECT_NEAR(f.M, 3.0 * pi / 16.0 * 0.2 * 100.0 * 0.01, kHandTol);
}

TEST(EllipsoidalLaw, SymmetriesAndDissipationOnRandomInputs) {
  const EllipsoidalLaw law;
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

TEST(EllipsoidalLaw, AgainstTheExactLaw) {
  // For a circle the law is exact in both pure limits; in between, and for ellipses, it is an
  // approximation whose errors the accuracy study measures (docs/accuracy.md). Here: the pure
  // limits, and that it stays within the exact law's bounds and signs everywhere on a grid:
  // 0 <= F1 <= kN, M of the sign of the exact M (the sign of Omega).
  // The exact law is accurate to kExactLawAccuracy; the pure limits agree to twice that.
  constexpr double kExactTol = 2.0 * kExactLawAccuracy;
  const ExactLaw exact;
  const EllipsoidalLaw law;
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

// ---- A fixed radius Rb (m): the law as an engine would use it, blind to the patch.

TEST(EllipsoidalLaw, FixedRadiusHandValueIgnoresThePatch) {
  // Rb = 1/2 m, Omega = 8: Rb Omega = 4; U = 3: sqrt(U^2 + Rb^2 Omega^2) = 5. kN = 2:
  // F1 = 2 (3/5) = 6/5, M = 2 Rb (4/5) = 4/5, whatever the patch's size, shape and orientation.
  const EllipsoidalLaw law(0.5);
  for (const ContactInput& in : {ContactInput{3.0, 8.0, 2.0, 0.5, 0.3, 4.0, 0.5},
                                 ContactInput{3.0, 8.0, 1e-3, 1e-4, 2.0, 4.0, 0.5}}) {
    const auto f = law.evaluate(in);
    EXPECT_NEAR(f.F1, 1.2, kHandTol);
    EXPECT_EQ(f.F2, 0.0);
    EXPECT_NEAR(f.M, 0.8, kHandTol);
  }
  const auto g = law.evaluate({3.0, -8.0, 2.0, 0.5, 0.3, 4.0, 0.5});
  EXPECT_NEAR(g.M, -0.8, kHandTol);
}

TEST(EllipsoidalLaw, FixedRadiusPureLimits) {
  const double Rb = 0.004, kN = 3.0;
  const EllipsoidalLaw law(Rb);
  // Pure spin: M = kN Rb sign(Omega), even on a patch smaller than Rb (a = 1 mm).
  const auto spin = law.evaluate({0.0, -7.0, 0.001, 0.0005, 0.4, kN, 1.0});
  EXPECT_EQ(spin.F1, 0.0);
  EXPECT_NEAR(spin.M, -kN * Rb, kHandTol * kN * Rb);
  // Pure sliding: F1 = kN, M = 0.
  const auto slide = law.evaluate({0.5, 0.0, 0.001, 0.0005, 0.4, kN, 1.0});
  EXPECT_EQ(slide.F1, kN);
  EXPECT_EQ(slide.M, 0.0);
  // At rest: zero.
  const auto rest = law.evaluate({0.0, 0.0, 0.001, 0.0005, 0.4, kN, 1.0});
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.M, 0.0);
}

TEST(EllipsoidalLaw, FixedRadiusLiesOnTheEllipsoid) {
  // Whenever the contact moves the force is on the boundary of its friction set:
  // (F1/kN)^2 + (M/(kN Rb))^2 = 1 (header comment), here to 1e-14.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double Rb = std::pow(10.0, -4.0 + 3.0 * u01(rng));
    const EllipsoidalLaw law(Rb);
    const double Omega = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, -2.0 + 4.0 * u01(rng));
    const double U = std::pow(10.0, -4.0 + 6.0 * u01(rng)) * Rb * std::abs(Omega);
    const double kN = 0.1 + 10.0 * u01(rng);
    const auto f = law.evaluate({U, Omega, 0.01, 0.005, 1.0, kN, 1.0});
    EXPECT_NEAR(std::hypot(f.F1 / kN, f.M / (kN * Rb)), 1.0, 1e-14);
    EXPECT_GT(f.M * Omega, 0.0);
  }
}

// The maximum-dissipation principle, checked by a search independent of the closed form: on the
// boundary F = F0 cos(theta), M = M0 sin(theta) of the set (|F|/F0)^2 + (M/M0)^2 <= 1, the power
// F U + M Omega is largest at the law's point. A scan of kScanPoints angles finds the maximiser to
// within half a step, pi/kScanPoints, so each coordinate to within F0 pi/kScanPoints (or M0 ...).
constexpr int kScanPoints = 200000;
constexpr double kScanTol = 1.2 * std::numbers::pi / kScanPoints;

FrictionForces most_dissipative_on_ellipse(double F0, double M0, double U, double Omega) {
  double best = -1.0, best_theta = 0.0;
  for (int j = 0; j < kScanPoints; ++j) {
    const double theta = 2.0 * std::numbers::pi * j / kScanPoints;
    const double power = F0 * std::cos(theta) * U + M0 * std::sin(theta) * Omega;
    if (power > best) {
      best = power;
      best_theta = theta;
    }
  }
  return {F0 * std::cos(best_theta), 0.0, M0 * std::sin(best_theta)};
}

TEST(EllipsoidalLaw, FixedRadiusDissipatesMost) {
  const double Rb = 0.002;
  const EllipsoidalLaw law(Rb);
  const double kN = 2.5;
  for (const double s : {0.0, 0.1, 0.7, 1.0, 3.0, 40.0}) {
    for (const double Omega : {-5.0, 5.0}) {
      const double U = s * Rb * std::abs(Omega);
      const auto f = law.evaluate({U, Omega, 0.01, 0.01, 0.0, kN, 1.0});
      const auto g = most_dissipative_on_ellipse(kN, kN * Rb, U, Omega);
      EXPECT_NEAR(f.F1, g.F1, kScanTol * kN) << "s = " << s;
      EXPECT_NEAR(f.M, g.M, kScanTol * kN * Rb) << "s = " << s;
    }
  }
}

TEST(EllipsoidalLaw, DefaultIsTheFixedRadiusOfTheHertzCircle) {
  // The default radius is (3 pi/16) sqrt(a b): the same forces as the law with that Rb fixed, to
  // the rounding of two orders of the same few operations (a few ulp: 4e-15 relative).
  constexpr double kTwoPathsTol = 4e-15;
  const double a = 0.03, b = 0.012;
  const EllipsoidalLaw hertz;
  const EllipsoidalLaw fixed(3.0 * pi / 16.0 * std::sqrt(a * b));
  for (const double U : {0.0, 1e-3, 0.02, 0.5, 30.0}) {
    for (const double Omega : {-3.0, 0.0, 2.0}) {
      const ContactInput in{U, Omega, a, b, 0.7, 5.0, 0.3};
      const auto f = hertz.evaluate(in);
      const auto g = fixed.evaluate(in);
      EXPECT_NEAR(f.F1, g.F1, kTwoPathsTol * 1.5);
      EXPECT_NEAR(f.M, g.M, kTwoPathsTol * 1.5 * a);
    }
  }
  EXPECT_TRUE(hertz.promises().bounded);
  EXPECT_FALSE(fixed.promises().bounded);  // kN Rb may exceed kN a on a smaller patch
}

TEST(EllipsoidalLaw, RejectsABadRadiusNamingIt) {
  for (const double Rb : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity()}) {
    try {
      const EllipsoidalLaw law(Rb);
      ADD_FAILURE() << "Rb = " << Rb << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("Rb = ", 0), 0u) << e.what();
    }
  }
}

TEST(EllipsoidalLaw, TorqueLimitThatOverflowsIsRejected) {
  // kN Rb overflows only for Rb > 1 m: Rb = 10 m with kN = 1e308 is refused, Rb = 1 m is not.
  const ContactInput in{0.0, 1.0, 1.0, 1.0, 0.0, 1e308, 1.0};
  EXPECT_THROW((void)EllipsoidalLaw(10.0).evaluate(in), std::invalid_argument);
  EXPECT_EQ(EllipsoidalLaw(1.0).evaluate(in).M, 1e308);
  EXPECT_FALSE(EllipsoidalLaw(10.0).promises().whole_domain);
  EXPECT_TRUE(EllipsoidalLaw(1.0).promises().whole_domain);
}

}  // namespace
}  // namespace frictionlab::friction
