#include "dynamics/core/log_histogram.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionlab::dynamics {
namespace {

const double kLogLowest = std::log10(LogHistogram::kLowest);
const int kLogBins =
    static_cast<int>(std::lround((std::log10(LogHistogram::kHighest) - kLogLowest) * LogHistogram::kBinsPerDecade));

int bin_of(double value) {
  const double x = (std::log10(value) - kLogLowest) * LogHistogram::kBinsPerDecade;
  if (!(x > 0.0)) return 0;
  return std::min(kLogBins - 1, static_cast<int>(x));
}

// The value at the fraction f in [0, 1] of the bin's width in log(value).
double inside(int bin, double f) {
  return std::pow(10.0, kLogLowest + (bin + f) / LogHistogram::kBinsPerDecade);
}

}  // namespace

LogHistogram::LogHistogram() : bins_(static_cast<std::size_t>(kLogBins), 0.0) {}

void LogHistogram::add(double value, double weight) {
  if (!(value >= 0.0) || !std::isfinite(value) || !(weight >= 0.0) || !std::isfinite(weight)) return;
  ++count_;
  total_ += weight;
  max_ = std::max(max_, value);
  if (value == 0.0) {
    zero_weight_ += weight;
    return;
  }
  min_positive_ = min_positive_ == 0.0 ? value : std::min(min_positive_, value);
  bins_[static_cast<std::size_t>(bin_of(value))] += weight;
}

double LogHistogram::quantile(double q) const {
  if (!(total_ > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double target = std::clamp(q, 0.0, 1.0) * total_;
  double cumulative = zero_weight_;
  if (cumulative >= target && zero_weight_ > 0.0) return 0.0;
  for (std::size_t i = 0; i < bins_.size(); ++i) {
    const double before = cumulative;
    cumulative += bins_[i];
    if (bins_[i] > 0.0 && cumulative >= target) {
      const double f = std::clamp((target - before) / bins_[i], 0.0, 1.0);
      return std::clamp(inside(static_cast<int>(i), f), min_positive_, max_);
    }
  }
  return max_;  // rounding of the running sum: the last bin
}

}  // namespace frictionlab::dynamics
