#pragma once
// Weighted quantiles of a non-negative quantity over a long run, in constant memory: a histogram on
// a logarithmic axis (kBinsPerDecade bins per decade from kLowest to kHighest), an exact zero bin,
// and the exact largest value. A quantile is read in the bin where the cumulative weight reaches
// it, by linear interpolation of the cumulative weight in log(value) across the bin, and clamped to
// the smallest and largest values seen: within the bin, i.e. within a factor 10^(1/kBinsPerDecade)
// (2.3 %) of the exact weighted quantile; zero exactly when the quantile falls on the zeros. Values
// below kLowest count in the lowest bin, above kHighest in the highest.
// The shadow laws' statistics use it (dynamics/core/shadow_laws.h), weighting each state by the
// time it stands for, so that a long run's median costs no memory per step.

#include <vector>

namespace frictionlab::dynamics {

class LogHistogram {
 public:
  static constexpr int kBinsPerDecade = 100;
  static constexpr double kLowest = 1e-20;
  static constexpr double kHighest = 1e10;

  LogHistogram();

  /// Counts `value` (finite, >= 0) with `weight` (>= 0); anything else is ignored.
  void add(double value, double weight);

  /// The weighted quantile q in [0, 1] (see the header comment); NaN if no weight was added.
  [[nodiscard]] double quantile(double q) const;
  /// The largest value added (0 if none).
  [[nodiscard]] double max() const { return max_; }
  /// The total weight added.
  [[nodiscard]] double weight() const { return total_; }
  /// How many values were added (with any weight).
  [[nodiscard]] long count() const { return count_; }

 private:
  std::vector<double> bins_;  // bins_[0]: exact zeros; bins_[1 + i]: the i-th logarithmic bin
  double zero_weight_ = 0.0;
  double total_ = 0.0;
  double min_positive_ = 0.0;
  double max_ = 0.0;
  long count_ = 0;
};

}  // namespace frictionlab::dynamics
