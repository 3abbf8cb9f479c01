#pragma once
// Random numbers that are the same on every machine and with every standard library, for the
// seeded parts of a study (random and Latin-hypercube designs, replica perturbations).
//
// The engine is std::mt19937_64, whose output sequence the C++ standard fixes ([rand.predef]: the
// 10000th output of a default-constructed engine is 9981545732273789042). The distributions are
// our own, because std::uniform_real_distribution and std::shuffle are left to each library:
//   uniform()   the top 53 bits of one output, times 2^-53: a double in [0, 1) on the grid k 2^-53;
//   below(n)    an integer in [0, n) by rejection of the biased top range (Lemire's method without
//               the multiply: plain modulo with rejection), exactly uniform;
//   permutation Fisher-Yates with below().
// Independent streams for (seed, a, b) come from derive_seed(), splitmix64 mixing (Steele, Lea &
// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014), so that a start's
// replicas do not depend on which thread or rank ran what first.

#include <cstdint>
#include <random>
#include <vector>

namespace frictionlab::dynamics::ensemble {

/// One splitmix64 step of `x`: a bijection of 64-bit words that spreads every input bit.
[[nodiscard]] std::uint64_t splitmix64(std::uint64_t x);

/// The seed of an independent stream for the pair (a, b) under the study's `seed`.
[[nodiscard]] std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0);

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1): (output >> 11) * 2^-53.
  [[nodiscard]] double uniform();
  /// Uniform in [lo, hi).
  [[nodiscard]] double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n); n > 0.
  [[nodiscard]] std::uint64_t below(std::uint64_t n);
  /// 0, 1, ..., n-1 in a uniformly random order (Fisher-Yates).
  [[nodiscard]] std::vector<long> permutation(long n);

 private:
  std::mt19937_64 engine_;
};

}  // namespace frictionlab::dynamics::ensemble
