// The printed Padé law, eqs. (8)-(9), against values worked out by hand from the printed formulas.

#include "friction/pade_printed_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace frictionlab::friction {
namespace pade_printed_law_test {

constexpr double pi = std::numbers::pi;
// The hand values below are exact rationals times powers of pi, evaluated once; 1e-14 relative
// covers the rounding of a dozen floating-point operations.
constexpr double kHandTol = 1e-14;

ContactInput contact(double U, double Omega, double a, double b, double psi, double N, double k) {
  return {U, Omega, a, b, psi, N, k};
}

TEST(PadePrintedLaw, CoefficientsForAQuarterPowerFriendlyEllipse) {
  // mu = 1/16 makes every power of mu rational: mu^(1/4) = 1/2, mu^(3/4) = 1/8, mu^(1/2) = 1/4,
  // mu^(5/4) = 1/32, mu^(7/4) = 1/128. psi = pi/4: cos^2 psi = 1/2, sin 2psi = 1, cos 2psi = 0.
  // d3 = (255/256)(1/2) + 1/256 = 257/512;  d4 = 255/256;  d5 = 1/2;  d6 = 1/2.
  // a1 = 3 pi (257/512)(1/2) / (80/8) = 771 pi / 10240
  // a2 = 257/5120;  a3 = -255/2560;  a4 = -8 / (3 (1/8) pi (1/2)) = -128/(3 pi)
  // b1 = -16 (257/512)(1/2) / (15 pi / 128) = -514/(15 pi);  b2 = (1/2)/(1/32) = 16
  // M0/(alpha F0) = (3 pi/16)(1/4) = 3 pi/64
  const auto c = pade_printed_coefficients(1.0 / 16.0, pi / 4.0);
  EXPECT_NEAR(c.a1, 771.0 * pi / 10240.0, kHandTol);
  EXPECT_NEAR(c.a2, 257.0 / 5120.0, kHandTol);
  EXPECT_NEAR(c.a3, -255.0 / 2560.0, kHandTol);
  EXPECT_NEAR(c.a4, -128.0 / (3.0 * pi), 10 * kHandTol);
  EXPECT_NEAR(c.b1, -514.0 / (15.0 * pi), 10 * kHandTol);
  EXPECT_NEAR(c.b2, 16.0, 10 * kHandTol);
  EXPECT_NEAR(c.m0_over_alpha_f0, 3.0 * pi / 64.0, kHandTol);
}

TEST(PadePrintedLaw, ForcesForAQuarterPowerFriendlyEllipse) {
  // a = 2, b = 1/8 (mu = 1/16), psi = pi/4, U = 1, Omega = 1, N = 3, k = 1/2:
  // F0 = 3/2, U^2 = 1, U alpha|Omega| = 2, alpha^2 Omega^2 = 4.
  // F1 = (3/2)(1 + 2 a1) / (1 + 2 a1 + 4 a2) = (3/2)(1 + 771 pi/5120)/(1 + 771 pi/5120 + 257/1280)
  // F2 = -(3/2) 2 / (1 + 2 a3 + 4 a4) = -3 / (1 - 255/1280 - 512/(3 pi))
  // M0 = (3 pi/64) 2 (3/2) = 9 pi/64;  M = M0 (2 b1 + 4) / (16 + 2 b1 + 4)
  const double r = 771.0 * pi / 5120.0;
  const double F1 = 1.5 * (1.0 + r) / (1.0 + r + 257.0 / 1280.0);
  const double F2 = -3.0 / (1.0 - 255.0 / 1280.0 - 512.0 / (3.0 * pi));
  const double b1 = -514.0 / (15.0 * pi);
  const double M = 9.0 * pi / 64.0 * (2.0 * b1 + 4.0) / (20.0 + 2.0 * b1);
  // Evaluated: F1 = 1.32007353747, F2 = 0.0560495116060, M = 4.33667145884 (N, N, N m).
  // Note M > M0 = 0.4418 N m: the printed b1 < 0 puts a pole of M near this slip ratio.
  const PadePrintedLaw law;
  const auto f = law.evaluate(contact(1.0, 1.0, 2.0, 0.125, pi / 4.0, 3.0, 0.5));
  EXPECT_NEAR(f.F1, F1, kHandTol * 10);
  EXPECT_NEAR(f.F2, F2, kHandTol * 10);
  EXPECT_NEAR(f.M, M, kHandTol * 100);
  EXPECT_NEAR(f.F1, 1.32007353747, 1e-10);
  EXPECT_NEAR(f.F2, 0.0560495116060, 1e-12);
  EXPECT_NEAR(f.M, 4.33667145884, 1e-10);
}

TEST(PadePrintedLaw, PrintedF2IsOddInOmegaAndMIsOdd) {
  // As printed F2 carries Omega to the first power: reversing the spin reverses F2 (the exact F2
  // does not change). F1 depends on |Omega| only.
  const PadePrintedLaw law;
  const auto p = law.evaluate(contact(1.0, 1.0, 2.0, 0.125, pi / 4.0, 3.0, 0.5));
  const auto m = law.evaluate(contact(1.0, -1.0, 2.0, 0.125, pi / 4.0, 3.0, 0.5));
  EXPECT_DOUBLE_EQ(m.F1, p.F1);
  EXPECT_DOUBLE_EQ(m.F2, -p.F2);
  EXPECT_DOUBLE_EQ(m.M, -p.M);
}

TEST(PadePrintedLaw, CircleAtUnitSlipRatio) {
  // mu = 1: d3 = d5 = 1, d4 = d6 = 0, so a1 = 3 pi/80, a2 = 1/10, b1 = -16/(15 pi), b2 = 1, a4 = -inf.
  // U = alpha Omega (s = 1): F1/F0 = (1 + 3pi/80)/(1 + 3pi/80 + 1/10) = 0.917885365844
  //                          M/M0 = (b1 + 1)/(1 + b1 + 1) = 0.397760677171, M0 = (3 pi/16) a kN
  //                          F2 = 0 (the limit of a4 -> -inf).
  const PadePrintedLaw law;
  const double a = 0.01, N = 20.0, k = 0.3, Omega = 50.0;
  const auto f = law.evaluate(contact(a * Omega, Omega, a, a, 0.7, N, k));
  const double F1 = (1.0 + 3.0 * pi / 80.0) / (1.1 + 3.0 * pi / 80.0);
  const double b1 = -16.0 / (15.0 * pi);
  EXPECT_NEAR(f.F1 / (k * N), F1, kHandTol);
  EXPECT_NEAR(f.F1 / (k * N), 0.917885365844, 1e-12);
  EXPECT_NEAR(f.M / (3.0 * pi / 16.0 * a * k * N), (b1 + 1.0) / (b1 + 2.0), kHandTol);
  EXPECT_NEAR(f.M / (3.0 * pi / 16.0 * a * k * N), 0.397760677171, 1e-12);
  EXPECT_EQ(f.F2, 0.0);
}

TEST(PadePrintedLaw, PureSlidingAndPureSpinLimits) {
  const PadePrintedLaw law;
  // Omega = 0: F1 = F0 U^2/U^2 = kN, F2 = M = 0 exactly.
  const auto slide = law.evaluate(contact(0.3, 0.0, 2.0, 0.5, 0.4, 10.0, 0.2));
  EXPECT_EQ(slide.F1, 2.0);
  EXPECT_EQ(slide.F2, 0.0);
  EXPECT_EQ(slide.M, 0.0);
  // U = 0: F1 = F2 = 0 and M = M0 sign(Omega), M0 = (3 pi/16) sqrt(mu) a kN.
  for (const double Omega : {-3.0, 3.0}) {
    const auto spin = law.evaluate(contact(0.0, Omega, 2.0, 0.5, 0.4, 10.0, 0.2));
    EXPECT_EQ(spin.F1, 0.0);
    EXPECT_EQ(spin.F2, 0.0);
    EXPECT_NEAR(spin.M, std::copysign(3.0 * pi / 16.0 * 0.5 * 2.0 * 2.0, Omega), kHandTol);
  }
}

TEST(PadePrintedLaw, UndefinedPointsReturnTheirDocumentedLimits) {
  const PadePrintedLaw law;
  // U = Omega = 0: every ratio is 0/0; defined as no friction, as for the exact law at rest.
  const auto rest = law.evaluate(contact(0.0, 0.0, 1.0, 0.5, 0.3, 1.0, 0.5));
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.F2, 0.0);
  EXPECT_EQ(rest.M, 0.0);
  // sin 2psi = 0 makes a4 infinite: F2 = 0, at exactly psi = 0; near it F2 is small and finite.
  EXPECT_TRUE(std::isinf(pade_printed_coefficients(0.5, 0.0).a4));
  EXPECT_EQ(law.evaluate(contact(1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 1.0)).F2, 0.0);
  const auto near = law.evaluate(contact(1.0, 1.0, 1.0, 0.5, 1e-8, 1.0, 1.0));
  EXPECT_TRUE(std::isfinite(near.F2));
  EXPECT_LT(std::abs(near.F2), 1e-7);
  // No load: nothing, whatever the velocities.
  const auto unloaded = law.evaluate(contact(1.0, 1.0, 1.0, 0.5, 0.3, 0.0, 0.5));
  EXPECT_EQ(unloaded.F1, 0.0);
  EXPECT_EQ(unloaded.M, 0.0);
}

TEST(PadePrintedLaw, F2HasARealPoleWhereItsDenominatorVanishes) {
  // a4 < 0 as printed: U^2 + a3 U alpha|Omega| + a4 alpha^2 Omega^2 = 0 at
  // s* = (-a3 + sqrt(a3^2 - 4 a4)) / 2 > 0. F2 changes sign across s*, and grows without bound.
  const double mu = 0.5, psi = 0.6;
  const auto c = pade_printed_coefficients(mu, psi);
  ASSERT_LT(c.a4, 0.0);
  const double s_pole = (-c.a3 + std::sqrt(c.a3 * c.a3 - 4.0 * c.a4)) / 2.0;
  const PadePrintedLaw law;
  const auto below = law.evaluate(contact(s_pole * (1 - 1e-6), 1.0, 1.0, mu, psi, 1.0, 1.0));
  const auto above = law.evaluate(contact(s_pole * (1 + 1e-6), 1.0, 1.0, mu, psi, 1.0, 1.0));
  EXPECT_GT(std::abs(below.F2), 1e4);
  EXPECT_GT(std::abs(above.F2), 1e4);
  EXPECT_LT(below.F2 * above.F2, 0.0);
}

TEST(PadePrintedLaw, OnAPoleItThrowsInsteadOfReturningInfinity) {
  // 1e-12 from the F2 pole with k N = 1e300 N, |F2| ~ 1e300 / (2e-12 s*^2) leaves the double
  // range: the printed law has no value there, and says so.
  const double mu = 0.5, psi = 0.6;
  const auto c = pade_printed_coefficients(mu, psi);
  const double s_pole = (-c.a3 + std::sqrt(c.a3 * c.a3 - 4.0 * c.a4)) / 2.0;
  const PadePrintedLaw law;
  try {
    (void)law.evaluate(contact(s_pole * (1 + 1e-12), 1.0, 1.0, mu, psi, 1e300, 1.0));
    ADD_FAILURE() << "no exception on the pole";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the denominator of F2 in eq. (8) vanishes"), std::string::npos)
        << e.what();
  }
}

TEST(PadePrintedLaw, RejectsPatchesTooSlenderForItsCoefficients) {
  // b/a = 1e-200: mu^(-7/4) = 1e350 is not a double.
  const PadePrintedLaw law;
  try {
    (void)law.evaluate(contact(1.0, 1.0, 1.0, 1e-200, 0.3, 1.0, 1.0));
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("is below 1e-150, where the coefficients of eq. (9)"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW((void)law.evaluate(contact(1.0, 1.0, 1.0, 1e-150, 0.3, 1.0, 1.0)));
}

TEST(PadePrintedLaw, MinorAxisReadingUsesAlphaEqualB) {
  // pade-printed-minor is the same formula with alpha = b: it equals the major reading evaluated
  // with a spin scaled by b/a (alpha|Omega| is the only place alpha enters, besides M0).
  const PadePrintedLaw major(PadeAlpha::major), minor(PadeAlpha::minor);
  EXPECT_EQ(minor.name(), "pade-printed-minor");
  const double a = 2.0, b = 0.5, psi = 0.3, U = 0.7, Omega = 1.3;
  const auto fm = minor.evaluate(contact(U, Omega, a, b, psi, 1.0, 1.0));
  const auto fM = major.evaluate(contact(U, Omega * b / a, a, b, psi, 1.0, 1.0));
  EXPECT_NEAR(fm.F1, fM.F1, 1e-15);
  EXPECT_NEAR(fm.F2, fM.F2, 1e-15);
  // M0 scales with alpha: M_minor = (b/a) M_major at the scaled spin.
  EXPECT_NEAR(fm.M, fM.M * b / a, 1e-15);
}

}  // namespace
}  // namespace frictionlab::friction
