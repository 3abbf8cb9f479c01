#pragma once
// Error statistics of a law's values against reference values, with non-finite values kept apart.
//
// The error at a point is value - reference (absolute: the study's values are already per kN or
// per kNa, so they are O(1)). A NaN or infinite value of the law (e.g. at the pole of the printed
// Padé F2) is counted and located, never folded into the max or the RMS, so that one bad point
// does not hide how good or bad the law is everywhere else.

#include <cstddef>
#include <limits>
#include <span>

namespace frictionlab::accuracy {

/// "No such point".
inline constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();

struct ErrorStats {
  std::size_t finite = 0;               ///< points where value and reference are both finite
  std::size_t nonfinite = 0;            ///< points where the value is NaN or +-inf
  std::size_t reference_nonfinite = 0;  ///< points with a finite value but a non-finite reference
  std::size_t first_nonfinite = kNoIndex;  ///< index of the first non-finite value
  double max_abs = std::numeric_limits<double>::quiet_NaN();  ///< max |error| over finite points
  std::size_t max_index = kNoIndex;     ///< where max_abs occurs (the first such index)
  double rms = std::numeric_limits<double>::quiet_NaN();      ///< sqrt(mean error^2), finite points
  double median_abs = std::numeric_limits<double>::quiet_NaN();  ///< nearest-rank 50% of |error|
  double p95_abs = std::numeric_limits<double>::quiet_NaN();     ///< nearest-rank 95% of |error|
};

/// Statistics of value[i] - reference[i] over all i (the spans have the same length). Indices in
/// the result are positions in the spans. With no finite point, max_abs, rms, median_abs and
/// p95_abs are NaN. The nearest-rank q-quantile of n sorted values is the ceil(q n)-th one.
[[nodiscard]] ErrorStats error_stats(std::span<const double> value, std::span<const double> reference);

}  // namespace frictionlab::accuracy
