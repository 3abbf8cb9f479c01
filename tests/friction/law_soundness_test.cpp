// Soundness of every registered law (in the manner of Ceres' loss-function tests): one suite run
// over list_laws(). What every law must do: finite output or std::invalid_argument for every valid
// input, the limits N = 0, Omega = 0, U = 0 and U = Omega = 0. What a law promises
// (FrictionLaw::promises(), from its registry entry): the parity of each output in Omega,
// pi-periodicity and the mirror symmetry in psi, dissipation, the bounds |F| <= kN and
// |M| <= kN a, the exact pure-spin torque. No test here branches on a law's name.

#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <numbers>
#include <memory>
#include <random>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "friction/law.h"
#include "friction/registry.h"
#include "tests/friction/hertz_closed_forms.h"
#include "friction/reference_laws.h"

namespace frictionlab::friction {
namespace law_soundness_test {

// exact-reference (GSL) lives in its own library: registered here, as the command does.
[[maybe_unused]] const bool kReferenceLawsRegistered = (friction::register_reference_laws(), true);

constexpr double kPi = std::numbers::pi;

// Points per check; a slow law (milliseconds per call) gets a few, enough to exercise each check.
constexpr int kPoints = 300;
constexpr int kSlowLawPoints = 3;
constexpr int kFuzzPoints = 4000;
constexpr int kSlowLawFuzzPoints = 12;
// Symmetries are checked away from a declared pole, where rounding of psi + pi is amplified
// without bound: a point is skipped if a denominator, relative to 1 + s^2, is below this.
constexpr double kPoleMargin = 1e-6;

int points(const LawInfo& info, int normal, int slow) { return info.slow ? slow : normal; }

// Well-conditioned contacts for the symmetry checks: s log-uniform in [1e-3, 1e3], mu
// log-uniform in [0.01, 1], psi in (-pi, pi), a, N, k in physical ranges, both spins.
std::vector<ContactInput> moderate_inputs(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<ContactInput> out;
  for (int i = 0; i < n; ++i) {
    ContactInput in;
    in.a = 0.001 + 0.05 * uni(rng);
    in.b = in.a * std::pow(10.0, -2.0 * uni(rng));
    in.psi = kPi * (2.0 * uni(rng) - 1.0);
    in.Omega = (i % 2 == 0 ? 1.0 : -1.0) * std::pow(10.0, -1.0 + 3.0 * uni(rng));
    in.U = std::pow(10.0, -3.0 + 6.0 * uni(rng)) * in.a * std::abs(in.Omega);
    in.N = 0.1 + 100.0 * uni(rng);
    in.k = 0.01 + uni(rng);
    out.push_back(in);
  }
  return out;
}

// 10^x with x uniform in [-300, 300], or 0 with probability `zero`.
double extreme_magnitude(std::mt19937_64& rng, double zero) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  if (uni(rng) < zero) return 0.0;
  return std::pow(10.0, -300.0 + 600.0 * uni(rng));
}

// Every input at an extreme but valid magnitude, 1e-300..1e300, independently: sizes of the patch
// (b <= a by swapping), speeds, loads, angles. Some are rejected by validate() (k N overflowing,
// b/a below the double range); the rest must give finite output.
std::vector<ContactInput> extreme_inputs(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<ContactInput> out;
  for (int i = 0; i < n; ++i) {
    ContactInput in;
    in.U = extreme_magnitude(rng, 0.05);
    in.Omega = (uni(rng) < 0.5 ? -1.0 : 1.0) * extreme_magnitude(rng, 0.05);
    in.a = extreme_magnitude(rng, 0.0);
    in.b = extreme_magnitude(rng, 0.0);
    if (in.b > in.a) std::swap(in.a, in.b);
    if (uni(rng) < 0.1) in.b = in.a;  // circles
    in.psi = (uni(rng) < 0.5 ? -1.0 : 1.0) * (uni(rng) < 0.5 ? kPi * uni(rng) : extreme_magnitude(rng, 0.05));
    in.N = extreme_magnitude(rng, 0.02);
    in.k = extreme_magnitude(rng, 0.02);
    out.push_back(in);
  }
  return out;
}

// Every valid axis ratio and slip ratio, at extreme magnitudes: mu = b/a log-uniform in
// [1e-12, 1] (the smallest any law accepts; laws with a larger min_axis_ratio reject the rest),
// s = U/(a |Omega|) log-uniform in [1e-12, 1e12] (one in 20 zero), psi anywhere for a third, within
// 1e-12..1e-2 of an axis (0 or pi/2, either side) for the rest: the ICR near the minor axis of the
// slip, or near the major axis, where a slender patch's integrals are hardest. a, Omega 1e-100..1e100
// (U follows from s), N, k 1e-6..1e6. (extreme_inputs draws a and b independently over 600 decades:
// b/a lands in [1e-12, 1] for one input in 50, its slip ratio is mostly 0 or beyond 1e100, and it
// never reached the slender patches' quadratures.)
std::vector<ContactInput> every_axis_ratio_inputs(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const auto log_uniform = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * uni(rng)); };
  std::vector<ContactInput> out;
  for (int i = 0; i < n; ++i) {
    ContactInput in;
    in.a = log_uniform(-100.0, 100.0);
    in.b = in.a * log_uniform(-12.0, 0.0);
    const double s = uni(rng) < 0.05 ? 0.0 : log_uniform(-12.0, 12.0);
    in.Omega = (uni(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(-100.0, 100.0);
    in.U = s * in.a * std::abs(in.Omega);
    const double side = uni(rng) < 0.5 ? -1.0 : 1.0;
    const double kind = uni(rng);
    if (kind < 1.0 / 3.0) {
      in.psi = kPi * (2.0 * uni(rng) - 1.0);
    } else {
      in.psi = (kind < 2.0 / 3.0 ? 0.0 : kPi / 2) + side * log_uniform(-12.0, -2.0);
    }
    in.N = log_uniform(-6.0, 6.0);
    in.k = log_uniform(-6.0, 6.0);
    out.push_back(in);
  }
  return out;
}

bool finite(const FrictionForces& f) {
  return std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M);
}

// Is `in` within kPoleMargin of a pole the law declares?
bool near_pole(const FrictionLaw& law, const ContactInput& in) {
  if (!law.has_poles() || in.Omega == 0.0) return false;
  const double s = slip_ratio(in.U, in.a, in.Omega);
  const PoleDenominators d = law.pole_denominators(in);
  for (const double x : {d.F1, d.F2, d.M}) {
    if (std::abs(x) < kPoleMargin * (1.0 + s * s)) return true;
  }
  return false;
}

// The expected change of an output under Omega -> -Omega.
double parity_sign(Parity p) { return p == Parity::odd ? -1.0 : 1.0; }

}  // namespace

// gtest prints a parameter with this (its name) rather than as bytes.
void PrintTo(const LawInfo& info, std::ostream* os) { *os << info.spec; }

namespace law_soundness_test {

class LawSoundness : public ::testing::TestWithParam<LawInfo> {
 protected:
  void SetUp() override { law_ = make_law(GetParam().spec); }
  const LawInfo& info() const { return GetParam(); }
  const LawPromises& promises() const { return GetParam().promises; }
  const FrictionLaw& law() const { return *law_; }

 private:
  std::unique_ptr<FrictionLaw> law_;
};

TEST_P(LawSoundness, NoLoadNoFriction) {
  for (const auto& base : moderate_inputs(points(info(), 40, kSlowLawPoints), 1)) {
    ContactInput in = base;
    in.N = 0.0;
    const FrictionForces f = law().evaluate(in);
    EXPECT_EQ(f.F1, 0.0);
    EXPECT_EQ(f.F2, 0.0);
    EXPECT_EQ(f.M, 0.0);
  }
}

TEST_P(LawSoundness, PureSlidingIsCoulomb) {
  // Omega = 0: every patch point slides with the centre, so F = kN along the slip, no moment.
  for (const auto& base : moderate_inputs(points(info(), 40, kSlowLawPoints), 2)) {
    ContactInput in = base;
    in.Omega = 0.0;
    const FrictionForces f = law().evaluate(in);
    const double kN = in.k * in.N;
    EXPECT_NEAR(f.F1, kN, promises().tolerance * kN);
    EXPECT_NEAR(f.F2, 0.0, promises().tolerance * kN);
    EXPECT_NEAR(f.M, 0.0, promises().tolerance * kN * in.a);
  }
}

TEST_P(LawSoundness, PureSpinHasNoNetForce) {
  // U = 0: the slip field is odd under rotation of the patch by pi, so the force vanishes; the
  // moment opposes the spin and, for a law that promises to be bounded, cannot exceed kN a (an
  // engine's fixed torsional length does not know the patch: mujoco-elliptic).
  for (const auto& base : moderate_inputs(points(info(), 40, kSlowLawPoints), 3)) {
    ContactInput in = base;
    in.U = 0.0;
    const FrictionForces f = law().evaluate(in);
    const double kN = in.k * in.N;
    const double kNa = kN * in.a;
    EXPECT_NEAR(f.F1, 0.0, promises().tolerance * kN);
    EXPECT_NEAR(f.F2, 0.0, promises().tolerance * kN);
    EXPECT_GT(f.M * in.Omega, 0.0);
    if (promises().bounded) {
      EXPECT_LE(std::abs(f.M), kNa);
    }
    if (promises().exact_pure_spin) {
      // (3/8) E(e) for Hertz pressure: scaled to the law's own pressure
      const double moment = test::pure_spin_moment(in.b / in.a) * promises().pure_spin_factor / (3.0 / 8.0);
      EXPECT_NEAR(f.M, std::copysign(moment, in.Omega) * kNa,
                  promises().tolerance * kNa);
    }
  }
}

TEST_P(LawSoundness, RestGivesNoFriction) {
  // U = Omega = 0: the traction has no direction; every law documents zero there.
  ContactInput in{0.0, 0.0, 0.02, 0.01, 0.3, 10.0, 0.2};
  const FrictionForces f = law().evaluate(in);
  EXPECT_EQ(f.F1, 0.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
}

TEST_P(LawSoundness, ParityInOmegaAsPromised) {
  const LawPromises& p = promises();
  for (const auto& in : moderate_inputs(points(info(), kPoints, kSlowLawPoints), 4)) {
    if (near_pole(law(), in)) continue;
    ContactInput flipped = in;
    flipped.Omega = -in.Omega;
    const FrictionForces f = law().evaluate(in);
    const FrictionForces g = law().evaluate(flipped);
    const double kN = in.k * in.N;
    const double tol = p.tolerance * kN;
    if (p.F1_in_Omega != Parity::none) {
      EXPECT_NEAR(g.F1, parity_sign(p.F1_in_Omega) * f.F1, tol);
    }
    if (p.F2_in_Omega != Parity::none) {
      EXPECT_NEAR(g.F2, parity_sign(p.F2_in_Omega) * f.F2, tol);
    }
    if (p.M_in_Omega != Parity::none) {
      EXPECT_NEAR(g.M, parity_sign(p.M_in_Omega) * f.M, tol * in.a);
    }
  }
}

TEST_P(LawSoundness, SymmetriesInPsiAsPromised) {
  const LawPromises& p = promises();
  for (const auto& in : moderate_inputs(points(info(), kPoints, kSlowLawPoints), 5)) {
    ContactInput turned = in;
    turned.psi = in.psi.radians() + kPi;
    ContactInput mirrored = in;
    mirrored.psi = -in.psi.radians();
    if (near_pole(law(), in) || near_pole(law(), turned) || near_pole(law(), mirrored)) continue;
    const FrictionForces f = law().evaluate(in);
    const double kN = in.k * in.N;
    const double tol = p.tolerance * kN;
    if (p.pi_periodic_in_psi) {
      const FrictionForces g = law().evaluate(turned);
      EXPECT_NEAR(g.F1, f.F1, tol);
      EXPECT_NEAR(g.F2, f.F2, tol);
      EXPECT_NEAR(g.M, f.M, tol * in.a);
    }
    if (p.psi_mirror) {
      const FrictionForces g = law().evaluate(mirrored);
      EXPECT_NEAR(g.F1, f.F1, tol);
      EXPECT_NEAR(g.F2, -f.F2, tol);
      EXPECT_NEAR(g.M, f.M, tol * in.a);
    }
  }
}

// The output bits, or that it threw std::invalid_argument (all NaN).
FrictionForces evaluated(const FrictionLaw& law, const ContactInput& in) {
  try {
    return law.evaluate(in);
  } catch (const std::invalid_argument&) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
}

TEST_P(LawSoundness, ADirectionGivesWhatItsAngleGivesBitForBit) {
  // A law reads cos psi and sin psi from the input (friction/patch_angle.h) and nothing else of
  // psi: given the direction (std::cos psi, std::sin psi) it returns the very bits it returns for
  // the angle psi. (A law that formed the angle again would see atan2 folded to [0, pi), psi + pi
  // for half of these, and round differently.)
  auto inputs = moderate_inputs(points(info(), kPoints, kSlowLawPoints), 8);
  for (const auto& in : extreme_inputs(points(info(), kPoints, kSlowLawPoints), 9)) inputs.push_back(in);
  const auto same = [](double x, double y) {
    return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y) || (std::isnan(x) && std::isnan(y));
  };
  for (const auto& in : inputs) {
    ContactInput turned = in;
    const double psi = in.psi.radians();
    turned.psi = PatchAngle::from_direction(std::cos(psi), std::sin(psi));
    const FrictionForces f = evaluated(law(), in);
    const FrictionForces g = evaluated(law(), turned);
    EXPECT_TRUE(same(f.F1, g.F1) && same(f.F2, g.F2) && same(f.M, g.M))
        << "psi = " << psi << ": (" << f.F1 << ", " << f.F2 << ", " << f.M << ") by the angle, (" << g.F1 << ", "
        << g.F2 << ", " << g.M << ") by the direction";
  }
}

// Checks the promised dissipation and bounds at `in`, where `f` is the law's value.
void expect_promised_bounds(const LawPromises& p, const ContactInput& in, const FrictionForces& f) {
  const double kN = in.k * in.N;
  if (kN == 0.0) return;  // k N underflowed: no friction, nothing to bound
  const double tol = p.tolerance;
  // In units of kN and kN a, so that no product overflows at extreme magnitudes.
  const double f1 = f.F1 / kN;
  const double f2 = f.F2 / kN;
  const double m = f.M / kN / in.a;
  if (p.bounded) {
    EXPECT_LE(std::hypot(f1, f2), 1.0 + tol);
    EXPECT_LE(std::abs(m), 1.0 + tol);
  }
  if (p.dissipative && in.Omega != 0.0) {
    // (F1 U + M Omega) / (kN a |Omega|) = f1 s + m sign(Omega) >= 0.
    const double s = slip_ratio(in.U, in.a, in.Omega);
    const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
    if (std::isinf(s)) {
      EXPECT_GE(f1, -tol);
    } else {
      EXPECT_GE(f1 * s + m * sign, -tol * (1.0 + s));
    }
  } else if (p.dissipative) {
    EXPECT_GE(f1 * in.U, 0.0);
  }
}

TEST_P(LawSoundness, DissipationAndBoundsAsPromised) {
  for (const auto& in : moderate_inputs(points(info(), kPoints, kSlowLawPoints), 6)) {
    SCOPED_TRACE("U = " + std::to_string(in.U) + ", Omega = " + std::to_string(in.Omega));
    expect_promised_bounds(promises(), in, law().evaluate(in));
  }
}

// Every input valid by validate() gives finite output, except that a law rejects b/a below its
// min_axis_ratio with std::invalid_argument, and a law that does not promise its whole domain
// may throw it elsewhere too (on a pole); the output keeps the promised bounds and dissipation.
// Returns how many inputs were valid.
int expect_finite_or_rejected(const FrictionLaw& law, const LawPromises& promises,
                              const std::vector<ContactInput>& inputs) {
  int valid = 0;
  for (const auto& in : inputs) {
    try {
      validate(in);
    } catch (const std::invalid_argument&) {
      continue;
    }
    ++valid;
    std::ostringstream where;
    where.precision(17);
    where << "U = " << in.U << ", Omega = " << in.Omega << ", a = " << in.a << ", b = " << in.b
          << ", psi = " << in.psi.radians() << ", N = " << in.N << ", k = " << in.k;
    FrictionForces f;
    const bool accepted = in.b / in.a >= promises.min_axis_ratio;
    try {
      f = law.evaluate(in);
    } catch (const std::invalid_argument& e) {
      EXPECT_FALSE(accepted && promises.whole_domain) << where.str() << ": " << e.what();
      continue;
    }
    EXPECT_TRUE(accepted) << where.str() << ": b/a below the law's smallest axis ratio, not rejected";
    EXPECT_TRUE(finite(f)) << where.str() << " gives F1 = " << f.F1 << ", F2 = " << f.F2
                           << ", M = " << f.M;
    if (!finite(f)) continue;
    SCOPED_TRACE(where.str());
    expect_promised_bounds(promises, in, f);
  }
  return valid;
}

// Many contacts in one call give what evaluate() gives each, bit for bit; the batch stops at the
// first contact that is invalid or rejected, naming its index, with the results before it kept.
TEST_P(LawSoundness, ABatchGivesEachContactsValuesAndStopsAtTheFirstItRejects) {
  std::vector<ContactInput> inputs = every_axis_ratio_inputs(points(info(), 200, kSlowLawPoints), 11);
  // The single evaluations; the batch is cut before the first one the law rejects.
  std::vector<FrictionForces> single;
  std::exception_ptr rejected;
  for (const auto& in : inputs) {
    try {
      single.push_back(law().evaluate(in));
    } catch (const std::invalid_argument&) {
      rejected = std::current_exception();
      break;
    }
  }
  const std::size_t first_rejected = single.size();
  std::vector<FrictionForces> batch(inputs.size());
  try {
    law().evaluate(std::span<const ContactInput>(inputs), std::span<FrictionForces>(batch));
    EXPECT_EQ(first_rejected, inputs.size()) << "the batch accepted what evaluate() rejects";
  } catch (const BatchError& e) {
    EXPECT_EQ(e.index(), first_rejected) << e.what();
    EXPECT_NE(std::string(e.what()).find("contact " + std::to_string(first_rejected) + ": "), std::string::npos);
  }
  for (std::size_t i = 0; i < first_rejected; ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(batch[i].F1), std::bit_cast<std::uint64_t>(single[i].F1)) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(batch[i].F2), std::bit_cast<std::uint64_t>(single[i].F2)) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(batch[i].M), std::bit_cast<std::uint64_t>(single[i].M)) << i;
  }
  // An invalid contact (N < 0) in the middle: index named, the results before it kept.
  inputs.resize(std::min<std::size_t>(first_rejected, 6));
  if (inputs.size() < 3) return;
  inputs[2].N = -1.0;
  std::vector<FrictionForces> part(inputs.size());
  try {
    law().evaluate(std::span<const ContactInput>(inputs), std::span<FrictionForces>(part));
    ADD_FAILURE() << "N = -1 accepted";
  } catch (const BatchError& e) {
    EXPECT_EQ(e.index(), 2u);
    EXPECT_NE(std::string(e.what()).find("friction input N"), std::string::npos) << e.what();
    EXPECT_THROW(std::rethrow_exception(e.cause()), std::invalid_argument);
  }
  EXPECT_EQ(part[1].M, single[1].M);
  std::vector<FrictionForces> wrong(inputs.size() + 1);
  EXPECT_THROW(law().evaluate(std::span<const ContactInput>(inputs), std::span<FrictionForces>(wrong)),
               std::invalid_argument);
}

TEST_P(LawSoundness, FiniteOrRejectedOverExtremeMagnitudes) {
  const auto inputs = extreme_inputs(points(info(), kFuzzPoints, kSlowLawFuzzPoints), 7);
  const int valid = expect_finite_or_rejected(law(), promises(), inputs);
  // Not vacuous: most of the fuzzed inputs are valid.
  EXPECT_GT(valid, static_cast<int>(inputs.size()) / 3);
}

TEST_P(LawSoundness, FiniteBoundedAndDissipativeOverEveryAxisRatio) {
  const auto inputs = every_axis_ratio_inputs(points(info(), kFuzzPoints, kSlowLawFuzzPoints), 10);
  const int valid = expect_finite_or_rejected(law(), promises(), inputs);
  EXPECT_GT(valid, static_cast<int>(inputs.size()) * 9 / 10);
}

// Every registered law and every variant of its choice parameters (list_law_specs(): e.g. each
// pressure model of `exact`), each with its own facts.
std::vector<LawInfo> every_law_spec() {
  std::vector<LawInfo> out;
  for (const auto& spec : list_law_specs()) out.push_back(law_info(spec));
  return out;
}

// "exact:pressure=uniform" -> "exact_pressure_uniform" (test names are letters, digits and _).
std::string test_name(const ::testing::TestParamInfo<LawInfo>& p) {
  std::string name = p.param.spec;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryRegisteredLaw, LawSoundness, ::testing::ValuesIn(every_law_spec()), test_name);

}  // namespace
}  // namespace frictionlab::friction
