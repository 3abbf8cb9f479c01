#include "dynamics/ensemble/sample_statistics.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <limits>
#include <set>

namespace frictionlab::dynamics::ensemble {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

long total(const CategoryCounts& c) {
  long n = 0;
  for (const auto& [k, v] : c) n += v;
  return n;
}

long count_of(const CategoryCounts& c, const std::string& k) {
  const auto it = c.find(k);
  return it == c.end() ? 0 : it->second;
}

}  // namespace

double quantile(std::vector<double> x, double p) {
  x.erase(std::remove_if(x.begin(), x.end(), [](double v) { return !std::isfinite(v); }), x.end());
  if (x.empty()) return kNaN;
  std::sort(x.begin(), x.end());
  const double h = static_cast<double>(x.size() - 1) * std::clamp(p, 0.0, 1.0);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, x.size() - 1);
  return x[lo] + (h - static_cast<double>(lo)) * (x[hi] - x[lo]);
}

double total_variation(const CategoryCounts& a, const CategoryCounts& b) {
  const double na = static_cast<double>(total(a));
  const double nb = static_cast<double>(total(b));
  if (na == 0.0 || nb == 0.0) return kNaN;
  std::set<std::string> keys;
  for (const auto& [k, v] : a) keys.insert(k);
  for (const auto& [k, v] : b) keys.insert(k);
  double sum = 0.0;
  for (const auto& k : keys)
    sum += std::abs(static_cast<double>(count_of(a, k)) / na - static_cast<double>(count_of(b, k)) / nb);
  return 0.5 * sum;
}

double chi_square_homogeneity_p(const CategoryCounts& a, const CategoryCounts& b) {
  const double na = static_cast<double>(total(a));
  const double nb = static_cast<double>(total(b));
  if (na == 0.0 || nb == 0.0) return kNaN;
  std::set<std::string> keys;
  for (const auto& [k, v] : a)
    if (v > 0) keys.insert(k);
  for (const auto& [k, v] : b)
    if (v > 0) keys.insert(k);
  if (keys.size() < 2) return 1.0;
  const double n = na + nb;
  double x2 = 0.0;
  for (const auto& k : keys) {
    const double oa = static_cast<double>(count_of(a, k));
    const double ob = static_cast<double>(count_of(b, k));
    const double col = oa + ob;
    const double ea = na * col / n;
    const double eb = nb * col / n;
    x2 += (oa - ea) * (oa - ea) / ea + (ob - eb) * (ob - eb) / eb;
  }
  const boost::math::chi_squared_distribution<double> dist(static_cast<double>(keys.size() - 1));
  return boost::math::cdf(boost::math::complement(dist, x2));
}

}  // namespace frictionlab::dynamics::ensemble
