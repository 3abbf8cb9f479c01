#include "bench/accuracy/error_stats.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace frictionlab::accuracy {
namespace {

// The ceil(q n)-th smallest of `v` (1-based), reordering `v`.
double nearest_rank(std::vector<double>& v, double q) {
  assert(!v.empty());
  const auto n = static_cast<double>(v.size());
  auto rank = static_cast<std::size_t>(std::ceil(q * n));
  rank = std::clamp<std::size_t>(rank, 1, v.size());
  const auto nth = v.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(v.begin(), nth, v.end());
  return *nth;
}

}  // namespace

ErrorStats error_stats(std::span<const double> value, std::span<const double> reference) {
  assert(value.size() == reference.size());
  ErrorStats st;
  std::vector<double> abs_err;
  abs_err.reserve(value.size());
  double sum_sq = 0.0;
  double max_abs = -1.0;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!std::isfinite(value[i])) {
      ++st.nonfinite;
      if (st.first_nonfinite == kNoIndex) st.first_nonfinite = i;
      continue;
    }
    if (!std::isfinite(reference[i])) {
      ++st.reference_nonfinite;
      continue;
    }
    const double e = std::abs(value[i] - reference[i]);
    abs_err.push_back(e);
    sum_sq += e * e;
    if (e > max_abs) {
      max_abs = e;
      st.max_index = i;
    }
  }
  st.finite = abs_err.size();
  if (st.finite == 0) return st;
  st.max_abs = max_abs;
  st.rms = std::sqrt(sum_sq / static_cast<double>(st.finite));
  st.median_abs = nearest_rank(abs_err, 0.5);
  st.p95_abs = nearest_rank(abs_err, 0.95);
  return st;
}

}  // namespace frictionlab::accuracy
