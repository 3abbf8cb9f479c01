#include "dynamics/ensemble/two_sample_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/ensemble/kolmogorov_distribution.h"

namespace frictionlab::dynamics::ensemble {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Walks the merged sorted samples from value to value, calling f(x, next_x, Fa, Fb) with the two
// distribution functions on [x, next_x) (every tie at x already counted).
template <typename F>
void walk(std::vector<double>& a, std::vector<double>& b, F&& f) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() || j < b.size()) {
    const double x = j == b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    while (i < a.size() && a[i] == x) ++i;
    while (j < b.size() && b[j] == x) ++j;
    const double next = i < a.size() || j < b.size()
                            ? std::min(i < a.size() ? a[i] : std::numeric_limits<double>::infinity(),
                                       j < b.size() ? b[j] : std::numeric_limits<double>::infinity())
                            : x;
    f(x, next, static_cast<double>(i) / na, static_cast<double>(j) / nb);
  }
}

}  // namespace

double wasserstein1(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return kNaN;
  // Sum |Fa - Fb| dx in integer counts (|i nb - j na| / (na nb)) so that equal distributions give 0.
  double sum = 0.0;
  walk(a, b, [&](double x, double next, double fa, double fb) { sum += std::abs(fa - fb) * (next - x); });
  return sum;
}

double ks_statistic(std::vector<double> a, std::vector<double> b) {
  if (a.empty() || b.empty()) return kNaN;
  double d = 0.0;
  walk(a, b, [&](double, double, double fa, double fb) { d = std::max(d, std::abs(fa - fb)); });
  return d;
}

double ks_p_value(double d, long n, long m) {
  if (!(n > 0 && m > 0) || std::isnan(d)) return kNaN;
  const double ne = static_cast<double>(n) * static_cast<double>(m) / static_cast<double>(n + m);
  const double root = std::sqrt(ne);
  return kolmogorov_q((root + 0.12 + 0.11 / root) * d);
}

}  // namespace frictionlab::dynamics::ensemble
