// Reproducible random numbers (dynamics/ensemble/random_stream.h).

#include "dynamics/ensemble/random_stream.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace frictionlab::dynamics::ensemble {
namespace random_stream_test {

TEST(EnsembleRandomStream, UniformIsTheTop53BitsOfTheStandardEngine) {
  // The C++ standard ([rand.predef]) fixes the 10000th output of mt19937_64 with its default
  // seed 5489: 9981545732273789042. Our uniform() of that output is its top 53 bits times 2^-53.
  RandomStream rng(5489u);
  double u = 0.0;
  for (int i = 0; i < 10000; ++i) u = rng.uniform();
  EXPECT_EQ(u, std::ldexp(static_cast<double>(9981545732273789042ULL >> 11), -53));
}

TEST(EnsembleRandomStream, UniformStaysInTheUnitIntervalWithTheRightMean) {
  RandomStream rng(42);
  double sum = 0.0;
  constexpr int kN = 100000;
  for (int i = 0; i < kN; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Mean 1/2, standard error sqrt(1/12/N) = 9.1e-4: 5 sigma.
  EXPECT_NEAR(sum / kN, 0.5, 5 * std::sqrt(1.0 / 12.0 / kN));
}

TEST(EnsembleRandomStream, BelowIsUniformOverItsRange) {
  RandomStream rng(7);
  constexpr int kBins = 6;
  constexpr int kN = 60000;
  int count[kBins] = {};
  for (int i = 0; i < kN; ++i) {
    const auto k = rng.below(kBins);
    ASSERT_LT(k, static_cast<std::uint64_t>(kBins));
    ++count[k];
  }
  // Chi-square with 5 degrees of freedom: P(chi2 > 20.5) = 0.001.
  double chi2 = 0.0;
  for (const int c : count) chi2 += (c - kN / kBins) * (c - kN / kBins) / static_cast<double>(kN / kBins);
  EXPECT_LT(chi2, 20.5);
}

TEST(EnsembleRandomStream, PermutationHoldsEveryIndexOnce) {
  RandomStream rng(3);
  auto p = rng.permutation(50);
  ASSERT_EQ(p.size(), 50u);
  std::vector<long> sorted = p;
  std::sort(sorted.begin(), sorted.end());
  for (long i = 0; i < 50; ++i) EXPECT_EQ(sorted[static_cast<std::size_t>(i)], i);
  EXPECT_NE(p, sorted) << "50 elements left in order: the shuffle did nothing";
  EXPECT_EQ(RandomStream(3).permutation(50), p) << "the same seed gives the same permutation";
}

TEST(EnsembleRandomStream, DerivedSeedsDifferForEveryPair) {
  std::set<std::uint64_t> seen;
  for (std::uint64_t a = 0; a < 30; ++a)
    for (std::uint64_t b = 0; b < 30; ++b) seen.insert(derive_seed(1, a, b));
  EXPECT_EQ(seen.size(), 900u);
  EXPECT_NE(derive_seed(1, 2, 3), derive_seed(2, 2, 3));
  EXPECT_NE(derive_seed(1, 2, 3), derive_seed(1, 3, 2));
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
