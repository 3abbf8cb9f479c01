#pragma once
// What the tests of a law's own batch (FrictionLaw::do_evaluate_batch: fit_batch_test.cpp,
// exact_table_batch_test.cpp) share: the check that every result of a batch is the per-contact
// evaluation's, bit for bit (the reference the contract of friction/law.h names), and the random
// draws their contact makers mix special values with.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "friction/law.h"
#include "friction/pressure.h"

namespace frictionlab::friction::testing {

inline bool same_bits(double x, double y) {
  return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
}
inline bool same_bits(const FrictionForces& x, const FrictionForces& y) {
  return same_bits(x.F1, y.F1) && same_bits(x.F2, y.F2) && same_bits(x.M, y.M);
}

inline std::string describe(const ContactInput& c) {
  std::ostringstream s;
  s.precision(17);
  const auto [cos_psi, sin_psi] = c.psi.cos_sin();
  s << "U " << c.U << " Omega " << c.Omega << " a " << c.a << " b " << c.b << " (cos psi, sin psi) (" << cos_psi << ", "
    << sin_psi << ")" << (c.psi.is_direction() ? " given" : " from an angle") << " N " << c.N << " k " << c.k;
  return s.str();
}

/// Each result of `law`'s batch over `contacts` is its per-contact evaluation's, bit for bit
/// (the first 10 differences reported).
inline void expect_batch_is_per_contact(const FrictionLaw& law, const std::vector<ContactInput>& contacts) {
  std::vector<FrictionForces> out(contacts.size(), FrictionForces{-1.0, -1.0, -1.0});
  law.evaluate(std::span<const ContactInput>(contacts), std::span<FrictionForces>(out));
  int reported = 0;
  for (std::size_t i = 0; i < contacts.size() && reported < 10; ++i) {
    const FrictionForces one = law.evaluate(contacts[i]);
    const bool same = same_bits(out[i], one);
    if (!same) ++reported;
    EXPECT_TRUE(same) << "contact " << i << " of " << contacts.size() << ": " << describe(contacts[i])
                      << std::hexfloat << "\n  batch " << out[i].F1 << ", " << out[i].F2 << ", " << out[i].M
                      << "\n  alone " << one.F1 << ", " << one.F2 << ", " << one.M;
  }
}

/// Seeded draws that mix a quantity's common range with its special values.
class SpecialDraws {
 public:
  explicit SpecialDraws(std::uint64_t seed) : rng_(seed) {}
  double uni() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  double log_uniform(double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * uni()); }
  /// One of `special` with probability 1/2 (each alike), else `common`.
  double pick(std::initializer_list<double> special, double common) {
    if (uni() < 0.5) return common;
    const auto i = static_cast<std::size_t>(uni() * static_cast<double>(special.size()));
    return special.begin()[i < special.size() ? i : special.size() - 1];
  }

 private:
  std::mt19937_64 rng_;
};

inline const Pressure kEveryPressure[] = {Pressure::hertz, Pressure::uniform, Pressure::punch};

inline std::string pressure_test_name(const ::testing::TestParamInfo<Pressure>& p) {
  return std::string(pressure_name(p.param));
}

}  // namespace frictionlab::friction::testing
