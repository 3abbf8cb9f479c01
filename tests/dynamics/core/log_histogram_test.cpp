#include "dynamics/core/log_histogram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace frictionlab::dynamics {
namespace log_histogram_test {

// The exact weighted quantile: the smallest value whose cumulative weight reaches q of the total
// (an independent computation by sorting).
double weighted_quantile(std::vector<std::pair<double, double>> vw, double q) {
  std::sort(vw.begin(), vw.end());
  double total = 0.0;
  for (const auto& [v, w] : vw) total += w;
  double cumulative = 0.0;
  for (const auto& [v, w] : vw) {
    cumulative += w;
    if (cumulative >= q * total) return v;
  }
  return vw.back().first;
}

const double kBinFactor = std::pow(10.0, 1.0 / LogHistogram::kBinsPerDecade);

TEST(DynLogHistogram, QuantilesAreWithinOneBinOfTheExactWeightedQuantiles) {
  std::mt19937_64 rng(42);
  std::lognormal_distribution<double> value(std::log(1e-3), 3.0);  // spread over ~8 decades
  std::uniform_real_distribution<double> weight(0.0, 2.0);
  LogHistogram h;
  std::vector<std::pair<double, double>> vw;
  for (int i = 0; i < 20000; ++i) {
    const double v = value(rng), w = weight(rng);
    h.add(v, w);
    vw.emplace_back(v, w);
  }
  for (double q : {0.01, 0.25, 0.5, 0.9, 0.95, 0.999}) {
    const double exact = weighted_quantile(vw, q);
    const double got = h.quantile(q);
    EXPECT_LE(got, exact * kBinFactor) << "q = " << q;
    EXPECT_GE(got, exact / kBinFactor) << "q = " << q;
  }
  EXPECT_EQ(h.max(), std::max_element(vw.begin(), vw.end())->first);
  EXPECT_EQ(h.count(), 20000);
}

TEST(DynLogHistogram, ZerosAreExactAndWeightDecides) {
  LogHistogram h;
  h.add(0.0, 3.0);
  h.add(1.0, 1.0);
  EXPECT_EQ(h.quantile(0.5), 0.0);   // 3/4 of the weight is at 0
  EXPECT_EQ(h.quantile(0.75), 0.0);
  EXPECT_EQ(h.quantile(0.9), 1.0);   // clamped to the largest value seen
  EXPECT_EQ(h.max(), 1.0);
}

TEST(DynLogHistogram, ASingleValueIsReturnedExactly) {
  LogHistogram h;
  h.add(0.123, 1.0);
  for (double q : {0.0, 0.5, 1.0}) EXPECT_EQ(h.quantile(q), 0.123);
}

TEST(DynLogHistogram, NothingWeighedGivesNaNAndBadValuesAreIgnored) {
  LogHistogram h;
  EXPECT_TRUE(std::isnan(h.quantile(0.5)));
  h.add(-1.0, 1.0);
  h.add(std::nan(""), 1.0);
  h.add(INFINITY, 1.0);
  h.add(1.0, -1.0);
  EXPECT_EQ(h.count(), 0);
  EXPECT_TRUE(std::isnan(h.quantile(0.5)));
  h.add(2.0, 0.0);  // counted, but weighs nothing
  EXPECT_EQ(h.count(), 1);
  EXPECT_TRUE(std::isnan(h.quantile(0.5)));
}

TEST(DynLogHistogram, ValuesBeyondTheAxisAreKeptInItsEndBins) {
  LogHistogram h;
  h.add(1e-30, 1.0);
  h.add(1e30, 1.0);
  EXPECT_LE(h.quantile(0.0), LogHistogram::kLowest * kBinFactor);  // in the lowest bin
  EXPECT_GE(h.quantile(1.0), LogHistogram::kHighest / kBinFactor);  // the highest bin
  EXPECT_EQ(h.max(), 1e30);                                          // exact
}

}  // namespace
}  // namespace frictionlab::dynamics
