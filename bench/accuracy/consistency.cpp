#include "bench/accuracy/consistency.h"

#include <cassert>
#include <cmath>

namespace frictionlab::accuracy {

DissipationStats dissipation_stats(std::span<const double> power) {
  DissipationStats st;
  for (std::size_t i = 0; i < power.size(); ++i) {
    const double p = power[i];
    if (!std::isfinite(p)) {
      ++st.nonfinite;
      continue;
    }
    ++st.checked;
    if (p < 0.0) {
      ++st.violations;
      if (p < st.worst) {
        st.worst = p;
        st.worst_index = i;
      }
    }
  }
  return st;
}

void SignStats::add(double value, double reference, double threshold) {
  if (!std::isfinite(value) || !(std::abs(reference) > threshold)) return;
  ++considered;
  if (value == 0.0) {
    ++zero;
  } else if ((value < 0.0) != (reference < 0.0)) {
    ++opposite;
  }
}

SignStats sign_stats(std::span<const double> value, std::span<const double> reference,
                     double threshold) {
  assert(value.size() == reference.size());
  SignStats st;
  for (std::size_t i = 0; i < value.size(); ++i) st.add(value[i], reference[i], threshold);
  return st;
}

}  // namespace frictionlab::accuracy
