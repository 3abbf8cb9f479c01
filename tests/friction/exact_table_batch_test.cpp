// exact-table's batch (ExactTableLaw's do_evaluate_batch, friction/exact_table_batch.h), which
// evaluates blocks of contacts with their table rows prefetched and their spline weights across
// SIMD lanes, against the reference the contract of friction/law.h names: the same law evaluated
// one contact at a time. Every result must be the same double, bit for bit (the sign of a zero
// too), for each pressure and every batch size around the block's (empty, odd tails, a partial
// block, several blocks), over random contacts that mix the table's path with every special one:
// U = 0, Omega = 0 (of either sign), both, N = 0, k = 0, a circle (b = a) and b a hair below a,
// b/a at and just above the table's end (0.01), ICRs on and about the rim between the table's
// blocks, slip ratios beyond the fast-slip threshold (1e8) and beyond the doubles, magnitudes
// from subnormal to 1e300, spin of either sign, psi as an angle or a direction. A contact exact-table
// rejects after validation (b/a < 0.01) stops the batch at its index with the results before it,
// as does an invalid one. Where the processor has AVX the batch sums in 4-lane vectors and the
// per-contact path in 2-lane ones (ExactTable::contract_wide, contract): these tests then also hold
// the two sums to the same bits.

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

#include "friction/exact_table.h"
#include "friction/exact_table_law.h"
#include "friction/law.h"
#include "tests/friction/batch_checks.h"
#include "friction/pressure.h"

namespace frictionlab::friction {
namespace exact_table_batch_test {

using testing::describe;
using testing::expect_batch_is_per_contact;
using testing::same_bits;

constexpr double kPi = std::numbers::pi;
constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();
constexpr double kMinRatio = kExactTableMinAxisRatio;


// A random valid contact exact-table accepts (b/a >= 0.01): each quantity drawn from its common
// range or, often, from its special values.
class ContactMaker {
 public:
  explicit ContactMaker(std::uint64_t seed) : draws_(seed) {}

  ContactInput make() {
    for (;;) {
      ContactInput c;
      c.a = pick({log_uniform(-300.0, 300.0), 1e-300, 1e300}, log_uniform(-6.0, 1.0));
      const double mu = pick({1.0, 1.0 - 1e-16, 1.0 - 1e-9, kMinRatio, kMinRatio * (1.0 + 1e-15), log_uniform(-2.0, -1.9),
                              0.5},
                             log_uniform(-2.0, 0.0));
      c.b = std::fmin(c.a * mu, c.a);
      const double spin = pick({0.0, kSubnormal * 3.0, log_uniform(-320.0, -300.0), log_uniform(-300.0, 300.0), 1e300},
                               log_uniform(-3.0, 3.0));
      c.Omega = uni() < 0.5 ? -spin : spin;  // -0.0 too
      const double psi = pick({0.0, kPi / 2.0, -kPi, 1e3}, -10.0 + 20.0 * uni());
      c.psi = uni() < 0.5 ? PatchAngle(psi) : PatchAngle::from_direction(std::cos(psi), std::sin(psi));
      // The slip ratio s = U/(a |Omega|): from its special values (0, the rim of the patch along
      // psi, past the fast-slip threshold, beyond the doubles) or log-uniform about 1.
      const double s = pick({0.0, rim_ratio(mu, psi) * (1.0 - 1e-15), rim_ratio(mu, psi), rim_ratio(mu, psi) * (1.0 + 1e-15),
                             1e8, 1e8 * (1.0 + 1e-15), 1e12, 1e300},
                            log_uniform(-4.0, 4.0));
      c.U = pick({0.0, kSubnormal, 1e300}, s * c.a * std::abs(c.Omega));
      c.N = pick({0.0, log_uniform(-300.0, 300.0)}, log_uniform(-3.0, 3.0));
      c.k = pick({0.0, log_uniform(-300.0, 0.0)}, uni());
      try {
        validate(c);
        if (std::isfinite(c.U) && c.b / c.a >= kMinRatio) return c;
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
  // The slip ratio at which the ICR (s sin psi, s cos psi) lies on the rim x^2 + (y/mu)^2 = 1.
  static double rim_ratio(double mu, double psi) {
    const double x = std::sin(psi), y = std::cos(psi) / mu;
    return 1.0 / std::sqrt(x * x + y * y);
  }
  testing::SpecialDraws draws_;
  double uni() { return draws_.uni(); }
  double log_uniform(double lo, double hi) { return draws_.log_uniform(lo, hi); }
  double pick(std::initializer_list<double> special, double common) { return draws_.pick(special, common); }
};

class ExactTableBatch : public ::testing::TestWithParam<Pressure> {
 protected:
  ExactTableLaw law() const { return ExactTableLaw(GetParam()); }
};


INSTANTIATE_TEST_SUITE_P(EveryPressure, ExactTableBatch, ::testing::ValuesIn(testing::kEveryPressure), testing::pressure_test_name);

TEST_P(ExactTableBatch, EveryBatchSizeGivesThePerContactResultsBitForBit) {
  ContactMaker maker(21);
  for (const std::size_t n : {0, 1, 2, 3, 7, 15, 16, 17, 31, 33, 1000}) {
    SCOPED_TRACE("batch of " + std::to_string(n));
    expect_batch_is_per_contact(law(), maker.make(n));
  }
}

TEST_P(ExactTableBatch, ManyRandomContactsGiveThePerContactResultsBitForBit) {
  ContactMaker maker(22);
  expect_batch_is_per_contact(law(), maker.make(100000));
}

// Contacts on the table's path alone (no limit), as a simulation hands them over: every lane of
// every block reads the table, both of its blocks, the whole range of b/a.
TEST_P(ExactTableBatch, ContactsOnTheTablesPathGiveThePerContactResultsBitForBit) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<ContactInput> contacts;
  for (int i = 0; i < 20000; ++i) {
    const double a = 0.001 + 0.05 * uni(rng), mu = std::pow(kMinRatio, uni(rng));
    const double Omega = (uni(rng) - 0.5) * 40.0, U = std::pow(10.0, -4.0 + 8.0 * uni(rng)) * a * std::abs(Omega);
    contacts.push_back({U, Omega, a, a * mu, 2.0 * kPi * uni(rng), 100.0 * uni(rng), uni(rng)});
  }
  expect_batch_is_per_contact(law(), contacts);
}

// Every combination of the special values, in one batch.
TEST_P(ExactTableBatch, EveryCombinationOfSpecialValuesGivesThePerContactResultsBitForBit) {
  std::vector<ContactInput> contacts;
  for (const double U : {0.0, kSubnormal, 1e-300, 0.3, 1e300})
    for (const double Omega : {0.0, -0.0, kSubnormal, -kSubnormal, 1e-300, -1e-300, 2.0, -2.0, 1e300, -1e300})
      for (const double a : {1e-300, 0.02, 1e300})
        for (const double mu : {1.0, 1.0 - 1e-16, 0.5, kMinRatio * (1.0 + 1e-15), kMinRatio})
          for (const double psi : {0.0, 0.7, -2.0})
            for (const double N : {0.0, 3.0})
              for (const double k : {0.0, 0.4}) {
                const ContactInput c{U, Omega, a, a * mu, psi, N, k};
                try {
                  validate(c);
                  if (c.b / c.a >= kMinRatio) contacts.push_back(c);
                } catch (const std::invalid_argument&) {
                }
              }
  ASSERT_GT(contacts.size(), 3000u);
  expect_batch_is_per_contact(law(), contacts);
}

// The contract's error path, for the two ways a batch stops: a contact validate() refuses (U < 0),
// and one it accepts but exact-table rejects (b/a below the table's end, 0.01). The batch stops at
// its index with the cause evaluate() of it alone gives; the results before it are written (the
// per-contact ones: those waiting in a partial block too), none after.
TEST_P(ExactTableBatch, ARejectedContactStopsTheBatchAtItsIndexWithTheResultsBefore) {
  ContactMaker maker(24);
  const auto invalid = [](ContactInput& c) { c.U = -1.0; };
  const auto below_table = [](ContactInput& c) { c.b = c.a * kMinRatio * (1.0 - 1e-12); };
  for (const auto& spoil : {+invalid, +below_table}) {
    for (const std::size_t bad : {0, 5, 15, 16, 17, 40}) {
      std::vector<ContactInput> contacts = maker.make(50);
      spoil(contacts[bad]);
      std::string alone;
      try {
        (void)law().evaluate(contacts[bad]);
        ADD_FAILURE() << "contact " << bad << " is not rejected alone";
      } catch (const std::invalid_argument& e) {
        alone = e.what();
      }
      const FrictionForces untouched{-7.0, -7.0, -7.0};
      std::vector<FrictionForces> out(contacts.size(), untouched);
      try {
        law().evaluate(std::span<const ContactInput>(contacts), std::span<FrictionForces>(out));
        ADD_FAILURE() << "no BatchError for the contact " << bad;
      } catch (const BatchError& e) {
        EXPECT_EQ(e.index(), bad);
        EXPECT_EQ(e.cause_message(), alone);
        EXPECT_THROW(std::rethrow_exception(e.cause()), std::invalid_argument);
      }
      for (std::size_t i = 0; i < contacts.size(); ++i) {
        const FrictionForces expected = i < bad ? law().evaluate(contacts[i]) : untouched;
        EXPECT_TRUE(same_bits(out[i], expected)) << "bad contact " << bad << ", result " << i;
      }
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
