// fit's batch (FitLaw's do_evaluate_batch, friction/fit_batch.h), which evaluates blocks of
// contacts across SIMD lanes, against the independent reference the contract of friction/law.h
// names: the same law evaluated one contact at a time. Every result must be the same double, bit
// for bit (the sign of a zero too), for each pressure and every batch size around the block's
// (odd tails, a partial block, several blocks), over random contacts that mix the common case with
// every special one: U = 0, Omega = 0 (of either sign), both, N = 0, k = 0, a circle, axis ratios
// where E(e) leaves its fit (below 0.01), speeds and sizes from subnormal to 1e300 (a Omega
// beyond the doubles or below the normal ones), spin of either sign, psi as an angle or a
// direction. An invalid contact stops the batch at its index with the results before it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "friction/fit_law.h"
#include "friction/law.h"
#include "tests/friction/batch_checks.h"
#include "friction/pressure.h"

namespace frictionlab::friction {
namespace fit_batch_test {

using testing::describe;
using testing::expect_batch_is_per_contact;
using testing::same_bits;

constexpr double kPi = std::numbers::pi;
constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();
constexpr double kSmallestNormal = std::numeric_limits<double>::min();


// A random valid contact: each quantity drawn from its common range or, often, from its special
// values.
class ContactMaker {
 public:
  explicit ContactMaker(std::uint64_t seed) : draws_(seed) {}

  ContactInput make() {
    for (;;) {
      ContactInput c;
      c.U = pick({0.0, kSubnormal, log_uniform(-320.0, -300.0), log_uniform(-300.0, 300.0), 1e300},
                 log_uniform(-3.0, 3.0));
      const double spin = pick({0.0, kSubnormal * 3.0, kSmallestNormal, log_uniform(-320.0, -300.0),
                                log_uniform(-300.0, 300.0), 1e300},
                               log_uniform(-3.0, 3.0));
      c.Omega = uni() < 0.5 ? -spin : spin;  // -0.0 too
      c.a = pick({log_uniform(-300.0, 300.0), 1e-300, 1e300}, log_uniform(-6.0, 1.0));
      const double mu = pick({1.0, 0.01, 0.01 * (1.0 - 1e-15), log_uniform(-4.0, -2.0), 1e-300, kSmallestNormal},
                             log_uniform(-2.0, 0.0));
      c.b = std::fmin(c.a * mu, c.a);
      const double psi = pick({0.0, kPi / 2.0, -kPi, 1e3}, -10.0 + 20.0 * uni());
      c.psi = uni() < 0.5 ? PatchAngle(psi) : PatchAngle::from_direction(std::cos(psi), std::sin(psi));
      c.N = pick({0.0, log_uniform(-300.0, 300.0)}, log_uniform(-3.0, 3.0));
      c.k = pick({0.0, log_uniform(-300.0, 0.0)}, uni());
      try {
        validate(c);
        return c;
      } catch (const std::invalid_argument&) {  // e.g. k N a overflows: draw again
      }
    }
  }

  std::vector<ContactInput> make(std::size_t n) {
    std::vector<ContactInput> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back(make());
    return v;
  }

 private:
  testing::SpecialDraws draws_;
  double uni() { return draws_.uni(); }
  double log_uniform(double lo, double hi) { return draws_.log_uniform(lo, hi); }
  double pick(std::initializer_list<double> special, double common) { return draws_.pick(special, common); }
};

class FitBatch : public ::testing::TestWithParam<Pressure> {
 protected:
  FitLaw law() const { return FitLaw(GetParam()); }
};


INSTANTIATE_TEST_SUITE_P(EveryPressure, FitBatch, ::testing::ValuesIn(testing::kEveryPressure), testing::pressure_test_name);

TEST_P(FitBatch, EveryBatchSizeGivesThePerContactResultsBitForBit) {
  ContactMaker maker(11);
  for (const std::size_t n : {0, 1, 2, 3, 7, 8, 9, 15, 16, 17, 31, 33, 1000}) {
    SCOPED_TRACE("batch of " + std::to_string(n));
    expect_batch_is_per_contact(law(), maker.make(n));
  }
}

TEST_P(FitBatch, ManyRandomContactsGiveThePerContactResultsBitForBit) {
  ContactMaker maker(12);
  expect_batch_is_per_contact(law(), maker.make(100000));
}

// The common contact alone (no special value), where every lane takes the general formula.
TEST_P(FitBatch, OrdinaryContactsGiveThePerContactResultsBitForBit) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<ContactInput> contacts;
  for (int i = 0; i < 20000; ++i) {
    const double a = 0.001 + 0.05 * uni(rng), mu = std::pow(0.01, uni(rng));
    const double Omega = (uni(rng) - 0.5) * 40.0, U = std::pow(10.0, -3.0 + 6.0 * uni(rng)) * a * std::abs(Omega);
    contacts.push_back({U, Omega, a, a * mu, 2.0 * kPi * uni(rng), 100.0 * uni(rng), uni(rng)});
  }
  expect_batch_is_per_contact(law(), contacts);
}

// Every combination of the special values, in one batch.
TEST_P(FitBatch, EveryCombinationOfSpecialValuesGivesThePerContactResultsBitForBit) {
  std::vector<ContactInput> contacts;
  for (const double U : {0.0, kSubnormal, 1e-300, 0.3, 1e300})
    for (const double Omega : {0.0, -0.0, kSubnormal, -kSubnormal, 1e-300, -1e-300, 2.0, -2.0, 1e300, -1e300})
      for (const double a : {1e-300, 0.02, 1e300})
        for (const double mu : {1.0, 0.5, 0.01, 0.005, 1e-300})
          for (const double N : {0.0, 3.0})
            for (const double k : {0.0, 0.4}) {
              const ContactInput c{U, Omega, a, a * mu, 0.7, N, k};
              try {
                validate(c);
                contacts.push_back(c);
              } catch (const std::invalid_argument&) {
              }
            }
  ASSERT_GT(contacts.size(), 1000u);
  expect_batch_is_per_contact(law(), contacts);
}

// The contract's error path: an invalid contact stops the batch at its index, the results before
// it written (the per-contact ones), none after.
TEST_P(FitBatch, AnInvalidContactStopsTheBatchAtItsIndexWithTheResultsBefore) {
  ContactMaker maker(14);
  for (const std::size_t bad : {0, 5, 16, 40}) {
    std::vector<ContactInput> contacts = maker.make(50);
    contacts[bad].U = -1.0;  // a negative slip speed
    const FrictionForces untouched{-7.0, -7.0, -7.0};
    std::vector<FrictionForces> out(contacts.size(), untouched);
    try {
      law().evaluate(std::span<const ContactInput>(contacts), std::span<FrictionForces>(out));
      ADD_FAILURE() << "no BatchError for the contact " << bad;
    } catch (const BatchError& e) {
      EXPECT_EQ(e.index(), bad);
    }
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const FrictionForces expected = i < bad ? law().evaluate(contacts[i]) : untouched;
      EXPECT_TRUE(same_bits(out[i].F1, expected.F1) && same_bits(out[i].F2, expected.F2) &&
                  same_bits(out[i].M, expected.M))
          << "bad contact " << bad << ", result " << i;
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
