#pragma once
// The dense seeded check set on which a tabulated or fitted law is compared with `exact`
// (docs/exact-table.md "Accuracy", docs/fit.md §4): mu = b/a log-uniform in [mu_min, 1], psi
// uniform in [0, 2 pi), the spin's sign random; the slip ratio s a third log-uniform in
// [1e-4, 1e4], a third just inside the rim, s_rim (1 - d), a third just outside, s_rim (1 + d),
// d log-uniform in [1e-6, 0.3]: the points where a smooth approximation of the exact law, whose
// derivatives jump at the rim, is worst. Not the nodes of any table, not the fit's training set.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace frictionlab::friction {

/// One point of the check set, dimensionless: a = N = k = 1, U = s, Omega = omega = +-1.
struct CheckPoint {
  double s, mu, psi, omega;
};

/// The slip ratio at which the ICR (s sin psi, s cos psi) is on the rim of the patch.
inline double rim_slip_ratio(double mu, double psi) {
  const double sn = std::sin(psi);
  const double c = std::cos(psi) / mu;
  return 1.0 / std::sqrt(sn * sn + c * c);
}

/// n points of the check set for axis ratios in [mu_min, 1], drawn from std::mt19937_64(seed).
inline std::vector<CheckPoint> check_set(int n, std::uint64_t seed, double mu_min) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<CheckPoint> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    CheckPoint p;
    p.mu = std::pow(mu_min, uni(rng));
    p.psi = 2.0 * std::numbers::pi * uni(rng);
    p.omega = uni(rng) < 0.5 ? 1.0 : -1.0;
    const double d = std::pow(10.0, -6.0 + (6.0 + std::log10(0.3)) * uni(rng));
    switch (i % 3) {
      case 0: p.s = std::pow(10.0, -4.0 + 8.0 * uni(rng)); break;
      case 1: p.s = rim_slip_ratio(p.mu, p.psi) * (1.0 - d); break;
      default: p.s = rim_slip_ratio(p.mu, p.psi) * (1.0 + d); break;
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace frictionlab::friction
