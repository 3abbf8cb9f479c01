#include "dynamics/paper/spin_reversals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace frictionlab::dynamics::paper {
namespace spin_reversals_test {

struct Series {
  std::vector<double> t, spin;
};

template <class F>
Series sampled(F omega, double t_end, double dt) {
  Series s;
  for (long i = 0; static_cast<double>(i) * dt <= t_end + 1e-12; ++i) {
    const double t = static_cast<double>(i) * dt;
    s.t.push_back(t);
    s.spin.push_back(omega(t));
  }
  return s;
}

TEST(PaperSpinReversals, ACosineReversesAtEachHalfTurnFirstWhereItPassesMinusTheThreshold) {
  // Omega = W cos(2 pi t/T) over two periods: four reversals, the first where cos = -theta/W,
  // i.e. t = T acos(-f)/(2 pi) (f = the fraction), found to the sample spacing; it ends at +W.
  const double W = 7.0, T = 2.0, dt = 1e-4;
  const Series s = sampled([&](double t) { return W * std::cos(2.0 * std::numbers::pi * t / T); }, 2.0 * T, dt);
  const SpinReversals r = spin_reversals(s.t, s.spin);
  EXPECT_EQ(r.count, 4);
  EXPECT_DOUBLE_EQ(r.threshold, kReversalFraction * W);
  EXPECT_NEAR(r.t_first, T * std::acos(-kReversalFraction) / (2.0 * std::numbers::pi), dt);
  EXPECT_EQ(r.final_sense, 1);
}

TEST(PaperSpinReversals, ASpinThatDiesOutReversesNeverAndEndsWithoutASense) {
  const Series s = sampled([](double t) { return -30.0 * std::exp(-t); }, 10.0, 1e-3);
  const SpinReversals r = spin_reversals(s.t, s.spin);
  EXPECT_EQ(r.count, 0);
  EXPECT_TRUE(std::isnan(r.t_first));
  EXPECT_EQ(r.final_sense, 0);  // 30 e^-10 = 1.4e-3 < 0.02 x 30
}

TEST(PaperSpinReversals, WobbleAboutZeroBelowTheThresholdIsNoReversal) {
  // A spin that decays and then rocks about 0 with 1 % of its largest value: the rounding of a rest
  // or a rocking without spin, not a reversal.
  const Series s = sampled(
      [](double t) { return t < 1.0 ? 10.0 * (1.0 - t) : 0.1 * std::sin(40.0 * t); }, 5.0, 1e-3);
  const SpinReversals r = spin_reversals(s.t, s.spin);
  EXPECT_EQ(r.count, 0);
  EXPECT_EQ(r.final_sense, 0);
}

TEST(PaperSpinReversals, TheRattlebacksOneReversalAndItsNewSense) {
  // Spun at +5 1/s, braked to 0 at t = 2 s, then spinning the other way towards -2 1/s: one
  // reversal, when Omega reaches -0.1 1/s: -2 (1 - e^-(t - 2)) = -0.1 at t = 2 - ln(0.95).
  const auto omega = [](double t) { return t < 2.0 ? 5.0 * (1.0 - t / 2.0) : -2.0 * (1.0 - std::exp(-(t - 2.0))); };
  const double dt = 1e-4;
  const Series s = sampled(omega, 8.0, dt);
  const SpinReversals r = spin_reversals(s.t, s.spin);
  EXPECT_EQ(r.count, 1);
  EXPECT_NEAR(r.t_first, 2.0 - std::log(0.95), dt);
  EXPECT_EQ(r.final_sense, -1);
}

TEST(PaperSpinReversals, EmptyZeroAndMismatchedSeries) {
  const SpinReversals empty = spin_reversals({}, {});
  EXPECT_EQ(empty.count, 0);
  EXPECT_TRUE(std::isnan(empty.threshold));
  const SpinReversals still = spin_reversals({0.0, 1.0}, {0.0, 0.0});
  EXPECT_EQ(still.count, 0);
  EXPECT_EQ(still.final_sense, 0);
  EXPECT_THROW((void)spin_reversals({0.0, 1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW((void)spin_reversals({0.0}, {1.0}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
