#pragma once
// The fixed, seeded set of contacts every friction benchmark evaluates (docs/benchmarks.md):
// s = U/(a|Omega|) log-uniform in [1e-3, 1e3], mu uniform in [0.05, 1], psi uniform in [0, pi],
// both signs of Omega, a = 1 m, N = 1 N, k = 1 (so errors read directly per kN and kNa).

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "friction/law.h"

namespace frictionlab::bench {

inline std::vector<friction::ContactInput> law_input_set(std::size_t n = 4096,
                                                         std::uint64_t seed = 20261121) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> log_s(-3.0, 3.0), mu(0.05, 1.0), psi(0.0, std::numbers::pi);
  std::vector<friction::ContactInput> set;
  set.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = std::pow(10.0, log_s(rng));
    const double Omega = (i % 2 == 0) ? 1.0 : -1.0;
    set.push_back({s, Omega, 1.0, mu(rng), psi(rng), 1.0, 1.0});
  }
  return set;
}

}  // namespace frictionlab::bench
