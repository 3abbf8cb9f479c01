#include "dynamics/puck/terminal_ratio.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "friction/registry.h"
#include "uniform_circle_law.h"

namespace frictionlab::dynamics::puck {
namespace terminal_ratio_test {

constexpr double kPi = std::numbers::pi;

// The Hertz circle in closed form (docs/model.md §2), per kN and kNa, u = U/(a|Omega|).
double hertz_f(double u) {
  if (u <= 1.0) return 3.0 * kPi / 32.0 * u * (4.0 - u * u);
  return 3.0 / (16.0 * u) * ((4.0 * u * u - u * u * u * u) * std::asin(1.0 / u) + (u * u + 2.0) * std::sqrt(u * u - 1.0));
}
double hertz_mu(double u) {
  if (u <= 1.0) return 3.0 * kPi / 128.0 * (8.0 - 8.0 * u * u + 3.0 * u * u * u * u);
  return 3.0 / 64.0 * ((8.0 - 8.0 * u * u + 3.0 * u * u * u * u) * std::asin(1.0 / u) + (6.0 - 3.0 * u * u) * std::sqrt(u * u - 1.0));
}
double hertz_G(double kappa, double u) { return u * hertz_mu(u) / kappa - hertz_f(u); }

TEST(DynPuckTerminalRatio, TheDriftOfTheExactLawIsTheHertzClosedForm) {
  const auto exact = friction::make_law("exact");
  for (const double kappa : {0.2, 0.5, 1.0})
    for (const double u : {0.05, 0.3, 0.7, 1.0, 1.5, 4.0})
      EXPECT_NEAR(terminal_ratio_drift(*exact, kappa, u), hertz_G(kappa, u), 1e-9) << kappa << " " << u;
  // For the disk's own inertia kappa = 1/2 the closed forms give G = (9 pi/64) u^3 (u^2 - 2) for
  // u <= 1: negative, so the slip stops first (r -> 0, docs/puck.md §3).
  for (const double u : {0.1, 0.5, 0.9})
    EXPECT_NEAR(hertz_G(0.5, u), 9.0 * kPi / 64.0 * u * u * u * (u * u - 2.0), 1e-14) << u;
}

TEST(DynPuckTerminalRatio, HertzRegimesFollowFromTheLimitsOfTheDrift) {
  // G/r -> mu0/kappa - f'(0) = (3 pi/16)/kappa - 3 pi/8 as r -> 0; G -> (1/5)/kappa - 1 as r -> inf:
  // together for 1/5 < kappa < 1/2, slip first above, spin first below.
  const auto exact = friction::make_law("exact");
  const TerminalRatioAnalysis together = analyse_terminal_ratio(*exact, 0.4);
  EXPECT_EQ(together.regime, "together");
  ASSERT_EQ(together.attracting.size(), 1u);
  // The root of the closed form, by bisection (independent of the analysis' scan and TOMS 748).
  double lo = 0.1, hi = 10.0;
  for (int i = 0; i < 200; ++i) (hertz_G(0.4, 0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_NEAR(together.attracting[0], 0.5 * (lo + hi), 1e-8);
  EXPECT_NEAR(together.small_slope, 3.0 * kPi / 16.0 / 0.4 - 3.0 * kPi / 8.0, 1e-3);
  EXPECT_NEAR(together.large_limit, 0.2 / 0.4 - 1.0, 1e-3);
  EXPECT_EQ(analyse_terminal_ratio(*exact, 0.6).regime, "slip-first");
  EXPECT_EQ(analyse_terminal_ratio(*exact, 0.15).regime, "spin-first");
}

TEST(DynPuckTerminalRatio, TheUniformDiskStopsTogetherAtTheClassicalRatio) {
  // Weidman & Malhotra (2005), after Farkas et al. (2003): a uniform disk (uniform pressure,
  // kappa = 1/2) ends with v/(a omega) = 0.653; the regimes are 1/4 < kappa < 2/3 (finite ratio),
  // kappa > 2/3 (-> 0), kappa < 1/4 (-> infinity), from G/r -> (2/3)/kappa - 1 and G -> (1/4)/kappa - 1.
  const testing::UniformCircleTestLaw uniform;
  const TerminalRatioAnalysis disk = analyse_terminal_ratio(uniform, 0.5, 1e-3, 1e3, 20);
  EXPECT_EQ(disk.regime, "together");
  ASSERT_EQ(disk.attracting.size(), 1u);
  EXPECT_NEAR(disk.attracting[0], 0.653, 5e-4);
  EXPECT_EQ(analyse_terminal_ratio(uniform, 0.7, 1e-3, 1e3, 20).regime, "slip-first");
  EXPECT_EQ(analyse_terminal_ratio(uniform, 0.6, 1e-3, 1e3, 20).regime, "together");
  EXPECT_EQ(analyse_terminal_ratio(uniform, 0.3, 1e-3, 1e3, 20).regime, "together");
  EXPECT_EQ(analyse_terminal_ratio(uniform, 0.2, 1e-3, 1e3, 20).regime, "spin-first");
}

TEST(DynPuckTerminalRatio, ADecoupledLawHasOneRepellingRatio) {
  // F1 = kN, M = M0: G = r mu0/kappa - 1 rises through r = kappa/mu0: the ends depend on the start
  // (both decelerations are constant, so they stop together only if they start on that ratio).
  const auto decoupled = friction::make_law("coulomb-decoupled");
  const TerminalRatioAnalysis a = analyse_terminal_ratio(*decoupled, 0.5);
  EXPECT_EQ(a.regime, "depends");
  ASSERT_EQ(a.repelling.size(), 1u);
  EXPECT_TRUE(a.attracting.empty());
  EXPECT_NEAR(a.repelling[0], 0.5 / (3.0 * kPi / 16.0), 1e-9);
}

TEST(DynPuckTerminalRatio, RejectsBadArguments) {
  const auto exact = friction::make_law("exact");
  EXPECT_THROW((void)analyse_terminal_ratio(*exact, 0.0), std::invalid_argument);
  EXPECT_THROW((void)analyse_terminal_ratio(*exact, 0.5, 1.0, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::puck
