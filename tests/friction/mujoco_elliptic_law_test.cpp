// MuJoCo's condim-4 elliptic cone, maximally dissipative: on the cone's boundary, the most
// dissipative point of it (found by a search independent of the closed form), the ellipsoidal law
// with Rb = torsional/k, and its limits.

#include "friction/mujoco_elliptic_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "friction/ellipsoidal_law.h"

namespace frictionlab::friction {
namespace mujoco_elliptic_law_test {

// Closed forms of a handful of operations: 1e-14 relative.
constexpr double kHandTol = 1e-14;

TEST(MujocoEllipticLaw, HandValue) {
  // k = 1/2, torsional = 1/100 m, N = 4: F0 = kN = 2, M0 = N torsional = 1/25. U = 3, Omega = 200:
  // r = k U/(torsional Omega) = 1.5/2 = 3/4, sqrt(1 + r^2) = 5/4: F1 = 2 (3/5) = 6/5,
  // M = (1/25)(4/5) = 0.032.
  const MujocoEllipticLaw law(0.01);
  const auto f = law.evaluate({3.0, 200.0, 0.02, 0.01, 0.4, 4.0, 0.5});
  EXPECT_NEAR(f.F1, 1.2, kHandTol);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_NEAR(f.M, 0.032, kHandTol * 0.032);
}

TEST(MujocoEllipticLaw, PureSpinTorqueIsNTimesTorsionalWhateverK) {
  // The cone bounds |tau| <= torsional fn independently of mu1 = k: at pure spin the torque is on
  // that bound, and with k = 0 there is no tangential force but the torque stays.
  const double T = 3e-4, N = 9.81;
  const MujocoEllipticLaw law(T);
  for (const double k : {0.0, 0.05, 1.0}) {
    const auto f = law.evaluate({0.0, -12.0, 0.003, 0.003, 0.0, N, k});
    EXPECT_EQ(f.F1, 0.0);
    EXPECT_NEAR(f.M, -N * T, kHandTol * N * T) << "k = " << k;
  }
  const auto slip_only = law.evaluate({0.4, 3.0, 0.003, 0.003, 0.0, N, 0.0});
  EXPECT_EQ(slip_only.F1, 0.0);
  EXPECT_NEAR(slip_only.M, N * T, kHandTol * N * T);
  const auto slide = law.evaluate({0.4, 0.0, 0.003, 0.003, 0.0, N, 0.7});
  EXPECT_EQ(slide.F1, 0.7 * N);
  EXPECT_EQ(slide.M, 0.0);
  const auto rest = law.evaluate({0.0, 0.0, 0.003, 0.003, 0.0, N, 0.7});
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.M, 0.0);
}

TEST(MujocoEllipticLaw, OnTheBoundaryOfTheEllipticCone) {
  // (f1/mu1)^2 + (f2/mu2)^2 + (tau/mu3)^2 = fn^2 with f1 = F1, f2 = F2 = 0, tau = M, mu1 = k,
  // mu3 = torsional, fn = N: the sliding contact is on MuJoCo's cone.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double T = std::pow(10.0, -5.0 + 3.0 * u01(rng));
    const MujocoEllipticLaw law(T);
    const double k = 0.01 + 2.0 * u01(rng);
    const double N = 0.1 + 100.0 * u01(rng);
    const double Omega = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, -2.0 + 4.0 * u01(rng));
    const double U = std::pow(10.0, -4.0 + 6.0 * u01(rng)) * (T / k) * std::abs(Omega);
    const auto f = law.evaluate({U, Omega, 0.01, 0.004, 2.0, N, k});
    EXPECT_NEAR(std::hypot(f.F1 / k, f.F2 / k, f.M / T), N, 1e-14 * N);
    EXPECT_GE(f.F1 * U + f.M * Omega, 0.0);
  }
}

// The most dissipative point of the cone's section at fn = N, f2 = 0 (f1 = kN cos theta,
// tau = N torsional sin theta), by a scan of kScanPoints angles: each coordinate within
// kScanTol of its range (half a step of the angle, with margin).
constexpr int kScanPoints = 200000;
constexpr double kScanTol = 1.2 * std::numbers::pi / kScanPoints;

TEST(MujocoEllipticLaw, DissipatesMostOnTheCone) {
  const double T = 5e-4, k = 0.4, N = 20.0;
  const MujocoEllipticLaw law(T);
  for (const double s : {0.0, 0.05, 0.6, 1.0, 2.5, 60.0}) {  // s = k U/(T |Omega|)
    for (const double Omega : {-9.0, 9.0}) {
      const double U = s * T * std::abs(Omega) / k;
      double best = -1.0, best_theta = 0.0;
      for (int j = 0; j < kScanPoints; ++j) {
        const double theta = 2.0 * std::numbers::pi * j / kScanPoints;
        const double power = k * N * std::cos(theta) * U + N * T * std::sin(theta) * Omega;
        if (power > best) {
          best = power;
          best_theta = theta;
        }
      }
      const auto f = law.evaluate({U, Omega, 0.002, 0.002, 0.0, N, k});
      EXPECT_NEAR(f.F1, k * N * std::cos(best_theta), kScanTol * k * N) << "s = " << s;
      EXPECT_NEAR(f.M, N * T * std::sin(best_theta), kScanTol * N * T) << "s = " << s;
    }
  }
}

TEST(MujocoEllipticLaw, IsTheEllipsoidalLawWithRbTorsionalOverK) {
  // Rb = mu3/mu1 = torsional/k (docs/engines.md §1): the same forces, to the rounding of two
  // orders of the same few operations (4e-15 relative).
  constexpr double kTwoPathsTol = 4e-15;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double T = std::pow(10.0, -5.0 + 3.0 * u01(rng));
    const double k = 0.02 + u01(rng);
    const MujocoEllipticLaw mujoco(T);
    const EllipsoidalLaw ellipsoidal(T / k);
    const double Omega = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, -1.0 + 3.0 * u01(rng));
    const double U = std::pow(10.0, -3.0 + 6.0 * u01(rng)) * (T / k) * std::abs(Omega);
    const ContactInput in{U, Omega, 0.01, 0.002, 0.3, 7.0, k};
    const auto f = mujoco.evaluate(in);
    const auto g = ellipsoidal.evaluate(in);
    EXPECT_NEAR(f.F1, g.F1, kTwoPathsTol * k * 7.0);
    EXPECT_NEAR(f.M, g.M, kTwoPathsTol * 7.0 * T);
  }
}

TEST(MujocoEllipticLaw, ExtremeMagnitudesWithoutSpuriousOverflow) {
  // r = k U/(T |Omega|) with k U or T |Omega| outside the normal double range, r ordinary: the
  // expected r is formed independently as (k/T)(U/|Omega|), each quotient a normal double.
  const double N = 2.0;
  const auto check = [N](double T, double k, double U, double Omega) {
    const double r = (k / T) * (U / Omega);
    const auto f = MujocoEllipticLaw(T).evaluate({U, Omega, 1.0, 1.0, 0.0, N, k});
    const double F1 = r / std::sqrt(1.0 + r * r), M = 1.0 / std::sqrt(1.0 + r * r);
    EXPECT_NEAR(f.F1 / (k * N), F1, 1e-14 * F1) << "U = " << U;
    EXPECT_NEAR(f.M / (N * T), M, 1e-14 * M) << "U = " << U;
  };
  check(0.5, 1e3, 1e306, 1e308);  // k U = 1e309 overflows: r = 20
  // k U = 2^-1040/3 is subnormal (about 33 significant bits), T |Omega| = 2^-1032 exactly:
  // r = 2^-8/3, which a quotient of the rounded product would miss by about 1e-10 relative.
  check(std::ldexp(1.0, -10), 1.0 / 3.0, std::ldexp(1.0, -1040), std::ldexp(1.0, -1022));
  // A torque limit N torsional that overflows is refused; below 1 m it cannot overflow.
  const ContactInput heavy{0.0, 1.0, 1.0, 1.0, 0.0, 1e308, 1e-3};
  EXPECT_THROW((void)MujocoEllipticLaw(10.0).evaluate(heavy), std::invalid_argument);
  EXPECT_EQ(MujocoEllipticLaw(1.0).evaluate(heavy).M, 1e308);
}

TEST(MujocoEllipticLaw, RejectsABadCoefficientNamingIt) {
  for (const double T : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::infinity()}) {
    try {
      const MujocoEllipticLaw law(T);
      ADD_FAILURE() << "torsional = " << T << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("torsional = ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
