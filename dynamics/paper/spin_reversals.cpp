#include "dynamics/paper/spin_reversals.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace frictionlab::dynamics::paper {

SpinReversals spin_reversals(const std::vector<double>& t, const std::vector<double>& spin, double fraction) {
  if (t.size() != spin.size())
    throw std::invalid_argument("spin_reversals: " + std::to_string(t.size()) + " times but " +
                                std::to_string(spin.size()) + " spins");
  if (!(fraction > 0.0 && fraction < 1.0))
    throw std::invalid_argument("spin_reversals: the fraction must lie in (0, 1)");
  SpinReversals r;
  if (spin.empty()) return r;
  double largest = 0.0;
  for (const double w : spin)
    if (std::isfinite(w)) largest = std::max(largest, std::abs(w));
  r.threshold = fraction * largest;
  if (!(largest > 0.0)) return r;
  int sense = 0;  // the sense last held beyond the threshold
  for (std::size_t i = 0; i < spin.size(); ++i) {
    const double w = spin[i];
    const int now = w >= r.threshold ? 1 : (w <= -r.threshold ? -1 : 0);
    if (now == 0) continue;
    if (sense != 0 && now != sense) {
      if (r.count == 0) r.t_first = t[i];
      ++r.count;
    }
    sense = now;
  }
  const double last = spin.back();
  r.final_sense = last >= r.threshold ? 1 : (last <= -r.threshold ? -1 : 0);
  return r;
}

}  // namespace frictionlab::dynamics::paper
