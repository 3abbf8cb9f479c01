#include "dynamics/ensemble/random_stream.h"

#include <cassert>
#include <limits>
#include <numeric>
#include <utility>

namespace frictionlab::dynamics::ensemble {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
  return splitmix64(splitmix64(splitmix64(seed) ^ a) ^ b);
}

double RandomStream::uniform() {
  constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
  return static_cast<double>(engine_() >> 11) * kTwoToMinus53;
}

std::uint64_t RandomStream::below(std::uint64_t n) {
  assert(n > 0);
  // Outputs at or above `limit` would make some residues more likely than others: draw again.
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t limit = max - (max % n + 1) % n;
  std::uint64_t x = engine_();
  while (x > limit) x = engine_();
  return x % n;
}

std::vector<long> RandomStream::permutation(long n) {
  std::vector<long> p(static_cast<std::size_t>(n));
  std::iota(p.begin(), p.end(), 0L);
  for (long i = n - 1; i > 0; --i) {
    const auto j = static_cast<long>(below(static_cast<std::uint64_t>(i) + 1));
    std::swap(p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]);
  }
  return p;
}

}  // namespace frictionlab::dynamics::ensemble
