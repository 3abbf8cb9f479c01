// Distances between two samples (dynamics/ensemble/two_sample_distance.h) against closed forms.

#include "dynamics/ensemble/two_sample_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dynamics/ensemble/kolmogorov_distribution.h"
#include "dynamics/ensemble/random_stream.h"

namespace frictionlab::dynamics::ensemble {
namespace two_sample_distance_test {

std::vector<double> uniform_grid(int n, double shift) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(shift + (i + 0.5) / n);
  return v;
}

TEST(EnsembleTwoSampleDistance, ShiftedSamplesAreTheirShiftApart) {
  // Two uniform samples, one shifted by s: F_b(x) = F_a(x - s), so W1 = s (for any s), and their
  // KS statistic is the mass in a window of width s: ceil(s n)/n for a grid of n points (shifts
  // off the grid's multiples of 1/n, where rounding would decide the ties).
  for (const double s : {0.0, 0.013, 0.2512, 0.5031, 3.0}) {
    const auto a = uniform_grid(200, 0.0);
    const auto b = uniform_grid(200, s);
    EXPECT_NEAR(wasserstein1(a, b), s, 1e-12) << s;
    EXPECT_NEAR(ks_statistic(a, b), std::min(1.0, std::ceil(s * 200 - 1e-9) / 200.0), 1e-12) << s;
  }
  // Random uniform samples: W1 of a sample and itself shifted is the shift, whatever the sample.
  RandomStream rng(5);
  std::vector<double> a(333);
  for (auto& x : a) x = rng.uniform();
  std::vector<double> b = a;
  for (auto& x : b) x += 0.125;
  EXPECT_NEAR(wasserstein1(a, b), 0.125, 1e-12);
}

TEST(EnsembleTwoSampleDistance, IdenticalSamplesAreZeroApartWithPValueOne) {
  const std::vector<double> a{3.0, 1.0, 2.0, 2.0, 7.0};
  EXPECT_EQ(wasserstein1(a, a), 0.0);
  EXPECT_EQ(ks_statistic(a, a), 0.0);
  EXPECT_EQ(ks_p_value(0.0, 5, 5), 1.0);
  std::vector<double> shuffled{2.0, 7.0, 1.0, 3.0, 2.0};
  EXPECT_EQ(wasserstein1(a, shuffled), 0.0) << "order does not matter";
}

TEST(EnsembleTwoSampleDistance, SmallSamplesByHand) {
  // {0, 1} vs {0.5}: |F_a - F_b| = 1/2 on [0, 1): W1 = 1/2, D = 1/2.
  EXPECT_DOUBLE_EQ(wasserstein1({0.0, 1.0}, {0.5}), 0.5);
  EXPECT_DOUBLE_EQ(ks_statistic({0.0, 1.0}, {0.5}), 0.5);
  // {1, 2, 3} vs {2.5}: F_a(2) = 2/3, F_b(2) = 0: D = 2/3; W1 = 1.5 * 2/3 ... by pieces:
  // [1,2): 1/3, [2,2.5): 2/3 * 0.5, [2.5,3): 1/3 * 0.5: W1 = 1/3 + 1/3 + 1/6 = 5/6.
  EXPECT_DOUBLE_EQ(ks_statistic({1.0, 2.0, 3.0}, {2.5}), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(wasserstein1({1.0, 2.0, 3.0}, {2.5}), 5.0 / 6.0);
  // Ties across the samples: {1, 1, 2} vs {1, 2, 2}: F differ by 1/3 on [1, 2): D = W1 = 1/3.
  EXPECT_DOUBLE_EQ(ks_statistic({1.0, 1.0, 2.0}, {1.0, 2.0, 2.0}), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(wasserstein1({1.0, 1.0, 2.0}, {1.0, 2.0, 2.0}), 1.0 / 3.0);
  EXPECT_TRUE(std::isnan(wasserstein1({}, {1.0})));
  EXPECT_TRUE(std::isnan(ks_statistic({1.0}, {})));
}

TEST(EnsembleTwoSampleDistance, EqualSizesAgreeWithTheSortedPairing) {
  // For samples of equal size W1 is the mean distance of the sorted samples paired in order
  // (the optimal transport on the line): an independent computation.
  RandomStream rng(11);
  std::vector<double> a(257);
  std::vector<double> b(257);
  for (auto& x : a) x = rng.uniform();
  for (auto& x : b) x = std::pow(rng.uniform(), 2.0) * 1.3;
  std::vector<double> sa = a;
  std::vector<double> sb = b;
  std::sort(sa.begin(), sa.end());
  std::sort(sb.begin(), sb.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < sa.size(); ++i) sum += std::abs(sa[i] - sb[i]);
  EXPECT_NEAR(wasserstein1(a, b), sum / static_cast<double>(sa.size()), 1e-13);
}

TEST(EnsembleTwoSampleDistance, PValueUsesStephensEffectiveSize) {
  // n = m = 50: N_e = 25, the factor sqrt(25) + 0.12 + 0.11/5 = 5.142; D chosen so that the
  // argument is the tabulated 5 % point 1.358 gives p = 0.05 (to the table's three decimals).
  const double d = 1.358 / 5.142;
  EXPECT_NEAR(ks_p_value(d, 50, 50), 0.05, 0.0006);
  EXPECT_NEAR(ks_p_value(d, 50, 50), kolmogorov_q(1.358), 1e-15);
  // Unequal sizes: n = 20, m = 80, N_e = 16: factor 4 + 0.12 + 0.0275.
  EXPECT_NEAR(ks_p_value(0.3, 20, 80), kolmogorov_q(0.3 * 4.1475), 1e-15);
  EXPECT_EQ(ks_p_value(1.0, 1000, 1000), kolmogorov_q(1.0 * (std::sqrt(500.0) + 0.12 + 0.11 / std::sqrt(500.0))));
}

TEST(EnsembleTwoSampleDistance, PValueIsSmallForDifferentAndNotForEqualDistributions) {
  RandomStream rng(21);
  std::vector<double> a(400);
  std::vector<double> b(400);
  std::vector<double> c(400);
  for (auto& x : a) x = rng.uniform();
  for (auto& x : b) x = rng.uniform();
  for (auto& x : c) x = rng.uniform() + 0.2;
  EXPECT_GT(ks_p_value(ks_statistic(a, b), 400, 400), 0.01) << "same distribution (this seed: not in the 1 % tail)";
  EXPECT_LT(ks_p_value(ks_statistic(a, c), 400, 400), 1e-6) << "shifted by 0.2";
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
