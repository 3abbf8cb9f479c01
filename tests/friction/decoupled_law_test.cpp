// Decoupled friction — the Hertz pure-spin torque by default, or a torsional length r_spin (the
// engines' law): closed forms of its torque, limits, symmetries, and the exact law.

#include "friction/decoupled_law.h"

#include <gtest/gtest.h>

#include "friction/exact_law.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace frictionlab::friction {
namespace decoupled_law_test {

constexpr double pi = std::numbers::pi;
// Closed forms evaluated with a few operations and tgamma (accurate to a few ulp), compared with
// Boost's ellint_2 (accurate to a few ulp): 1e-14 relative leaves room for both.
constexpr double kClosedFormTol = 1e-14;

TEST(DecoupledLaw, CircleSpinTorque) {
  // mu = 1: E(0) = pi/2, M0 = (3 pi/16) kN a.
  const DecoupledLaw law;
  const auto f = law.evaluate({0.2, 3.0, 0.02, 0.02, 0.0, 50.0, 0.3});
  EXPECT_EQ(f.F1, 15.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_NEAR(f.M, 3.0 * pi / 16.0 * 15.0 * 0.02, kClosedFormTol);
}

TEST(DecoupledLaw, SpinTorqueAtModulusOneOverRootTwo) {
  // mu = 1/sqrt 2 gives e^2 = 1/2, where K = Gamma(1/4)^2/(4 sqrt pi) and, by Legendre's relation,
  // E = K/2 + pi/(4K) (DLMF 19.20.2 and 19.7.1). a = 2, b = sqrt 2, kN = 1: M0 = (3/4) E.
  const double K = std::pow(std::tgamma(0.25), 2) / (4.0 * std::sqrt(pi));
  const double E = K / 2.0 + pi / (4.0 * K);
  const DecoupledLaw law;
  const auto f = law.evaluate({0.0, -1.0, 2.0, std::sqrt(2.0), 1.0, 1.0, 1.0});
  EXPECT_EQ(f.F1, 0.0);
  EXPECT_NEAR(f.M, -0.75 * E, kClosedFormTol);
}

TEST(DecoupledLaw, SpinTorqueAtExtremeAxisRatios) {
  const DecoupledLaw law;
  // A needle: mu -> 0, E -> 1, M0 -> (3/8) kN a. At mu = 1e-300, e rounds to 1 exactly.
  EXPECT_NEAR(law.evaluate({0.0, 1.0, 1.0, 1e-300, 0.0, 1.0, 1.0}).M, 0.375, kClosedFormTol);
  // Near the circle: E(e) = (pi/2)(1 - e^2/4 + O(e^4)), e^2 = 1 - mu^2 ~ 2e-10.
  const double mu = 1.0 - 1e-10;
  const double e2 = (1.0 - mu) * (1.0 + mu);
  EXPECT_NEAR(law.evaluate({0.0, 1.0, 1.0, mu, 0.0, 1.0, 1.0}).M,
              0.375 * pi / 2.0 * (1.0 - e2 / 4.0), kClosedFormTol);
}

TEST(DecoupledLaw, LimitsExactlyNearAndAway) {
  const DecoupledLaw law;
  const double a = 0.5, b = 0.25, kN = 2.0;
  const double M0 = law.evaluate({0.0, 1.0, a, b, 0.0, kN, 1.0}).M;
  const auto rest = law.evaluate({0.0, 0.0, a, b, 0.0, kN, 1.0});
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.M, 0.0);
  // The decoupled law is discontinuous: any slip at all gives the full kN, any spin the full M0.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(law.evaluate({tiny, 0.0, a, b, 0.0, kN, 1.0}).F1, kN);
  EXPECT_EQ(law.evaluate({1e-8, 0.0, a, b, 0.0, kN, 1.0}).F1, kN);
  EXPECT_EQ(law.evaluate({1.0, 1e-8, a, b, 0.0, kN, 1.0}).M, M0);
  EXPECT_EQ(law.evaluate({1.0, -1e-8, a, b, 0.0, kN, 1.0}).M, -M0);
  EXPECT_EQ(law.evaluate({1.0, 0.0, a, b, 0.0, kN, 1.0}).M, 0.0);
  const auto away = law.evaluate({3.0, 7.0, a, b, 1.2, kN, 1.0});
  EXPECT_EQ(away.F1, kN);
  EXPECT_EQ(away.F2, 0.0);
  EXPECT_EQ(away.M, M0);
  // No load, no friction.
  const auto unloaded = law.evaluate({3.0, 7.0, a, b, 1.2, 0.0, 1.0});
  EXPECT_EQ(unloaded.F1, 0.0);
  EXPECT_EQ(unloaded.M, 0.0);
}

TEST(DecoupledLaw, SymmetriesAndDissipationOnRandomInputs) {
  const DecoupledLaw law;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const double a = 0.01 + u01(rng);
    const double b = a * (0.05 + 0.95 * u01(rng));
    const double U = u01(rng);
    const double Omega = 10.0 * (u01(rng) - 0.5);
    const double psi = pi * u01(rng);
    const ContactInput in{U, Omega, a, b, psi, 2.0, 0.3};
    const auto p = law.evaluate(in);
    auto flipped = in;
    flipped.Omega = -Omega;
    const auto m = law.evaluate(flipped);
    EXPECT_EQ(m.F1, p.F1);
    EXPECT_EQ(m.M, -p.M);
    auto turned = in;
    turned.psi = psi + pi;
    EXPECT_EQ(law.evaluate(turned).M, p.M);
    EXPECT_GE(p.F1 * U + p.M * Omega, 0.0);
  }
}

TEST(DecoupledLaw, BoundsTheExactLawFromAbove) {
  // The decoupled law is exact in the pure limits and, in between, overestimates both resistances:
  // the exact law has F1 < kN and |M| < M0 whenever U > 0 and Omega != 0 (docs/model.md).
  // kExactTol: twice the exact law's promised accuracy (and this law's rounding).
  constexpr double kExactTol = 2.0 * kExactLawAccuracy;
  const ExactLaw exact;
  const DecoupledLaw law;
  for (double mu : {0.05, 0.2, 0.5, 0.8, 1.0}) {
    const ContactInput spin{0.0, -2.0, 1.5, 1.5 * mu, 0.3, 2.0, 0.5};
    EXPECT_NEAR(law.evaluate(spin).M, exact.evaluate(spin).M, kExactTol) << "mu = " << mu;
    const ContactInput slide{1.0, 0.0, 1.5, 1.5 * mu, 0.3, 2.0, 0.5};
    EXPECT_NEAR(law.evaluate(slide).F1, exact.evaluate(slide).F1, kExactTol) << "mu = " << mu;
    for (int j = 0; j <= 6; ++j) {
      for (int i = 0; i <= 60; ++i) {
        const double s = std::pow(10.0, -3.0 + 6.0 * i / 60.0);
        const ContactInput in{s, 1.0, 1.0, mu, pi * j / 6.0, 1.0, 1.0};
        const auto r = law.evaluate(in);
        const auto e = exact.evaluate(in);
        EXPECT_GE(r.F1, e.F1 - kExactTol);
        EXPECT_GE(r.M, e.M - kExactTol);
      }
    }
  }
}

// ---- A torsional length r_spin (m): M = N r_spin sign(Omega), whatever k and the patch.

TEST(DecoupledLaw, FixedLengthTorqueIsNTimesRSpin) {
  const double r_spin = 2e-4, N = 12.0;
  const DecoupledLaw law(r_spin);
  for (const double k : {0.0, 0.3, 1.5}) {
    for (const ContactInput& in : {ContactInput{0.0, 4.0, 0.01, 0.01, 0.0, N, k},
                                   ContactInput{2.0, 4.0, 1e-4, 2e-5, 1.0, N, k}}) {
      const auto f = law.evaluate(in);
      EXPECT_EQ(f.M, N * r_spin) << "k = " << k;  // one rounding, as computed
      EXPECT_EQ(f.F1, in.U > 0.0 ? k * N : 0.0);
      EXPECT_EQ(f.F2, 0.0);
      ContactInput flipped = in;
      flipped.Omega = -in.Omega;
      EXPECT_EQ(law.evaluate(flipped).M, -N * r_spin);
    }
  }
  EXPECT_EQ(law.evaluate({1.0, 0.0, 0.01, 0.01, 0.0, N, 0.3}).M, 0.0);  // no spin, no moment
  EXPECT_EQ(law.evaluate({1.0, 4.0, 0.01, 0.01, 0.0, 0.0, 0.3}).M, 0.0);  // no load, no moment
}

TEST(DecoupledLaw, ZeroLengthHasNoSpinFriction) {
  const DecoupledLaw law(0.0);
  for (const double Omega : {-3.0, 3.0}) {
    const auto f = law.evaluate({0.0, Omega, 0.01, 0.01, 0.0, 5.0, 0.4});
    EXPECT_EQ(f.F1, 0.0);
    EXPECT_EQ(f.M, 0.0);
    EXPECT_FALSE(std::signbit(f.M));
    EXPECT_EQ(law.evaluate({0.5, Omega, 0.01, 0.01, 0.0, 5.0, 0.4}).F1, 2.0);
  }
}

TEST(DecoupledLaw, DefaultIsTheFixedLengthOfTheHertzPatch) {
  // For a circle of radius a, the default torque (3 pi/16) kN a is N r_spin with
  // r_spin = (3 pi/16) k a: the two agree to the rounding of two orders of the same operations.
  constexpr double kTwoPathsTol = 4e-15;
  const double a = 0.004, k = 0.3, N = 8.0;
  const DecoupledLaw hertz;
  const DecoupledLaw fixed(3.0 * pi / 16.0 * k * a);
  const ContactInput in{0.2, -6.0, a, a, 0.0, N, k};
  EXPECT_NEAR(hertz.evaluate(in).M, fixed.evaluate(in).M, kTwoPathsTol * k * N * a);
  EXPECT_TRUE(hertz.promises().exact_pure_spin);
  EXPECT_FALSE(fixed.promises().exact_pure_spin);
  EXPECT_FALSE(fixed.promises().bounded);
}

TEST(DecoupledLaw, RejectsABadLengthNamingIt) {
  for (const double r : {-1e-3, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    try {
      const DecoupledLaw law(r);
      ADD_FAILURE() << "r_spin = " << r << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("r_spin = ", 0), 0u) << e.what();
    }
  }
  // N r_spin that overflows is refused; below 1 m it cannot overflow.
  const ContactInput heavy{0.0, 1.0, 1.0, 1.0, 0.0, 1e308, 1e-3};
  EXPECT_THROW((void)DecoupledLaw(10.0).evaluate(heavy), std::invalid_argument);
  EXPECT_EQ(DecoupledLaw(1.0).evaluate(heavy).M, 1e308);
}

}  // namespace
}  // namespace frictionlab::friction
