// exact-table (friction/exact_table_law.h) against exact (friction/exact_law.h), for each pressure
// model: a dense seeded random check of its promised accuracy (the check set of
// docs/exact-table.md, not the table's nodes), its limits at exactly the limit, continuity and
// smoothness where its two blocks meet (the rim) and across the axes psi = 0, pi/2, the rejection
// of b/a < 0.01, the axes and the circle. The accuracy test prints its set size, largest errors and
// worst points: docs/exact-table.md quotes them.

#include <boost/math/special_functions/ellint_2.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "friction/exact_law.h"
#include "friction/exact_table.h"
#include "friction/exact_table_law.h"
#include "friction/pressure.h"
#include "friction/registry.h"
#include "tests/friction/dense_check_set.h"
#include "tests/friction/hertz_closed_forms.h"

namespace frictionlab::friction {
namespace exact_table_law_test {

constexpr double kPi = std::numbers::pi;
// The promise: per kN (F1, F2) and per kNa (M), against exact, for b/a >= 0.01.
constexpr double kAccuracy = kExactTableAccuracy;
// Points of the dense check per pressure (the size of the feasibility study's check set,
// docs/exact-table.md "Accuracy (measured)").
constexpr int kCheckPoints = 200000;
// U = 0: M = c_p E(e) kNa by the fit of friction/elliptic_e_fit.h (relative error 1.3e-14), then
// two roundings: relative to kNa.
constexpr double kPureSpinTolerance = 3e-14;
// The two blocks take the same data on the rim: they meet to a few roundings of O(1) sums.
constexpr double kRimGapTolerance = 1e-12;
// Where the law switches to the fast-slip expansion (s = 1e8) the table is within ~1e-9 of exact
// (measured 4e-10 to 7e-10 at s = 1e6..1e8): the step there is that small.
constexpr double kFastSlipStepTolerance = 1e-9;

const Pressure kPressures[] = {Pressure::hertz, Pressure::uniform, Pressure::punch};

std::string spec_of(Pressure p) { return "exact-table:pressure=" + std::string(pressure_name(p)); }

// a = N = k = 1: forces per kN, moment per kNa; s = U/(a|Omega|).
ContactInput unit(double s, double mu, double psi, double omega = 1.0) { return {s, omega, 1.0, mu, psi, 1.0, 1.0}; }

double output(const FrictionForces& f, int k) { return k == 0 ? f.F1 : (k == 1 ? f.F2 : f.M); }
const char* const kOutputNames[] = {"F1/kN", "F2/kN", "M/kNa"};

struct Worst {
  double error = 0.0;
  CheckPoint at{};
};

class ExactTablePressure : public ::testing::TestWithParam<Pressure> {
 protected:
  Pressure pressure() const { return GetParam(); }
};

std::string pressure_test_name(const ::testing::TestParamInfo<Pressure>& p) {
  return std::string(pressure_name(p.param));
}

INSTANTIATE_TEST_SUITE_P(EveryPressure, ExactTablePressure, ::testing::ValuesIn(kPressures), pressure_test_name);

// ---------------------------------------------------------------------------------------------
// (1) Accuracy

TEST_P(ExactTablePressure, WithinItsPromiseOfExactOnTheDenseCheckSet) {
  const ExactLaw exact(pressure());
  const ExactTableLaw table(pressure());
  const auto set = check_set(kCheckPoints, 2024, kExactTableMinAxisRatio);
  Worst worst[3];
  for (const CheckPoint& p : set) {
    const ContactInput in = unit(p.s, p.mu, p.psi, p.omega);
    const FrictionForces e = exact.evaluate(in);
    const FrictionForces t = table.evaluate(in);
    for (int k = 0; k < 3; ++k) {
      const double err = std::abs(output(t, k) - output(e, k));
      // NaN fails too: max() would skip it
      if (!(err <= worst[k].error)) worst[k] = {err, p};
    }
  }
  std::ostringstream report;
  report << std::setprecision(4) << spec_of(pressure()) << ": " << set.size()
         << " points of the check set (seed 2024), max |table - exact|:";
  for (int k = 0; k < 3; ++k) {
    const CheckPoint& w = worst[k].at;
    report << "\n  " << kOutputNames[k] << " " << std::scientific << worst[k].error << std::defaultfloat
           << " at s = " << w.s << ", b/a = " << w.mu << ", psi = " << w.psi << ", s/s_rim = "
           << w.s / rim_slip_ratio(w.mu, w.psi) << ", Omega " << (w.omega > 0.0 ? "> 0" : "< 0");
    RecordProperty(std::string("max_error_") + (k == 0 ? "F1_kN" : (k == 1 ? "F2_kN" : "M_kNa")), worst[k].error);
  }
  std::cout << report.str() << "\n";
  RecordProperty("points", static_cast<int>(set.size()));
  for (int k = 0; k < 3; ++k) EXPECT_LE(worst[k].error, kAccuracy) << kOutputNames[k] << "\n" << report.str();
}

TEST_P(ExactTablePressure, SpecMakesTheLawWithItsPressureAndPromises) {
  const auto law = make_law(spec_of(pressure()));
  EXPECT_EQ(law->name(), "exact-table");
  const auto* table = dynamic_cast<const ExactTableLaw*>(law.get());
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->pressure(), pressure());
  const LawPromises p = law->promises();
  EXPECT_EQ(p.tolerance, kAccuracy);
  EXPECT_EQ(p.min_axis_ratio, 0.01);
  EXPECT_EQ(p.pure_spin_factor, pressure_pure_spin_factor(pressure()));
  EXPECT_TRUE(p.exact_pure_spin && p.whole_domain && p.bounded && p.dissipative);
  EXPECT_EQ(canonical_law_spec("exact-table"), canonical_law_spec("exact-table:pressure=hertz"));
}

TEST(ExactTable, LayoutIsTheDesigns) {
  // docs/exact-table.md "Storage": 29 x 50 x 34 x 3 + 29 x 194 x 34 x 3 doubles.
  EXPECT_EQ(ExactTable::of(Pressure::hertz).bytes(), 5774016u);
  // Built once per pressure per process: the same object every time.
  EXPECT_EQ(&ExactTable::of(Pressure::punch), &ExactTable::of(Pressure::punch));
  EXPECT_NE(&ExactTable::of(Pressure::punch), &ExactTable::of(Pressure::hertz));
}

// ---------------------------------------------------------------------------------------------
// (2) Limits, at exactly the limit and next to it

TEST_P(ExactTablePressure, NoLoadOrNoFrictionCoefficientGivesZero) {
  const ExactTableLaw law(pressure());
  for (const ContactInput& in : {ContactInput{0.3, 2.0, 0.01, 0.004, 0.7, 0.0, 0.4},
                                 ContactInput{0.3, 2.0, 0.01, 0.004, 0.7, 10.0, 0.0}}) {
    const FrictionForces f = law.evaluate(in);
    EXPECT_EQ(f.F1, 0.0);
    EXPECT_EQ(f.F2, 0.0);
    EXPECT_EQ(f.M, 0.0);
  }
}

TEST_P(ExactTablePressure, PureSlidingIsCoulombExactly) {
  const ExactTableLaw law(pressure());
  const double kN = 10.0 * 0.4;
  for (const double psi : {0.0, 0.7, kPi / 2}) {
    const FrictionForces f = law.evaluate({0.3, 0.0, 0.01, 0.004, psi, 10.0, 0.4});
    EXPECT_EQ(f.F1, kN);
    EXPECT_EQ(f.F2, 0.0);
    EXPECT_EQ(f.M, 0.0);
  }
  // U = Omega = 0: no direction; zero, as exact.
  const FrictionForces rest = law.evaluate({0.0, 0.0, 0.01, 0.004, 0.7, 10.0, 0.4});
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.F2, 0.0);
  EXPECT_EQ(rest.M, 0.0);
  // s = U/(a|Omega|) beyond the doubles (a|Omega| subnormal): pure sliding too.
  const FrictionForces fast = law.evaluate({1e300, -1e-300, 1e-10, 1e-11, 0.7, 10.0, 0.4});
  EXPECT_EQ(fast.F1, kN);
  EXPECT_EQ(fast.F2, 0.0);
  EXPECT_EQ(fast.M, 0.0);
}

TEST_P(ExactTablePressure, PureSpinHasNoForceAndTheEllipticMoment) {
  const ExactTableLaw law(pressure());
  const double cp = pressure_pure_spin_factor(pressure());
  for (const double mu : {0.01, 0.0137, 0.1, 0.5, 0.999, 1.0}) {
    for (const double omega : {3.0, -3.0}) {
      const ContactInput in{0.0, omega, 0.5, 0.5 * mu, 0.4, 10.0, 0.3};  // b/a = mu exactly
      const FrictionForces f = law.evaluate(in);
      const double kNa = 10.0 * 0.3 * 0.5;
      const double e = std::sqrt((1.0 - mu) * (1.0 + mu));
      const double expected = std::copysign(cp * boost::math::ellint_2(e) * kNa, omega);
      EXPECT_EQ(f.F1, 0.0);
      EXPECT_EQ(f.F2, 0.0);
      EXPECT_NEAR(f.M, expected, kPureSpinTolerance * kNa) << "b/a = " << mu;
    }
  }
}

TEST_P(ExactTablePressure, NearEveryLimitItStaysWithExact) {
  // 1e-8 from each limit: slow slip s = 1e-8 (near pure spin), fast slip s = 1e8 (near pure
  // sliding, both sides of the switch to the expansion), the smallest axis ratio.
  const ExactLaw exact(pressure());
  const ExactTableLaw table(pressure());
  for (const double mu : {0.01, 0.01 * (1.0 + 1e-8), 0.3, 1.0 - 1e-8, 1.0}) {
    for (const double psi : {0.0, 0.4, 2.0}) {
      for (const double s : {1e-8, 1e8 * (1.0 - 1e-15), 1e8 * (1.0 + 1e-15)}) {
        const FrictionForces e = exact.evaluate(unit(s, mu, psi));
        const FrictionForces t = table.evaluate(unit(s, mu, psi));
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(output(t, k), output(e, k), kAccuracy) << kOutputNames[k] << " s = " << s << ", b/a = " << mu;
        }
      }
      // The step where the expansion takes over.
      const FrictionForces below = table.evaluate(unit(1e8 * (1.0 - 1e-15), mu, psi));
      const FrictionForces above = table.evaluate(unit(1e8 * (1.0 + 1e-15), mu, psi));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(output(below, k), output(above, k), kFastSlipStepTolerance);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// (3) Continuity and smoothness where the blocks meet (the rim) and across the axes

// The ICR on the rim, at 200 seeded (b/a, psi): the inside block (s one part in 1e14 below the rim)
// and the outside block (above) agree to rounding.
TEST_P(ExactTablePressure, TheTwoBlocksMeetAtTheRim) {
  const ExactTableLaw law(pressure());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double gap = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mu = std::pow(kExactTableMinAxisRatio, uni(rng));
    const double psi = kPi * uni(rng);
    const double rim = rim_slip_ratio(mu, psi);
    const FrictionForces in = law.evaluate(unit(rim * (1.0 - 1e-14), mu, psi));
    const FrictionForces out = law.evaluate(unit(rim * (1.0 + 1e-14), mu, psi));
    for (int k = 0; k < 3; ++k) gap = std::max(gap, std::abs(output(in, k) - output(out, k)));
  }
  std::cout << spec_of(pressure()) << ": largest step across the rim " << gap << "\n";
  EXPECT_LE(gap, kRimGapTolerance);
}

// One-sided slopes s dF/ds at the rim (s = s_rim) of F1, F2, M, from inside (side = -1) or outside
// (+1). Near the rim both the law and the table go like f0 + D x + c x^(3/2) + O(x^2),
// x = |s/s_rim - 1| (the rim terms of docs/exact-table.md; the table's radial maps are square
// roots there), so the difference quotient over h is D + c h^(1/2) + O(h); 2 q(h) - q(4h) removes
// the h^(1/2) term, leaving O(h) = 1e-8 and rounding ~1e-16/h = 1e-8.
std::array<double, 3> rim_slopes(const FrictionLaw& law, double mu, double psi, int side) {
  constexpr double h = 1e-8;
  const double rim = rim_slip_ratio(mu, psi);
  const auto at = [&](double x) { return law.evaluate(unit(rim * (1.0 + side * x), mu, psi)); };
  const FrictionForces f0 = at(1e-15);
  const FrictionForces f1 = at(h);
  const FrictionForces f4 = at(4.0 * h);
  std::array<double, 3> slopes{};
  for (int k = 0; k < 3; ++k) {
    const double q1 = side * (output(f1, k) - output(f0, k)) / h;
    const double q4 = side * (output(f4, k) - output(f0, k)) / (4.0 * h);
    slopes[k] = 2.0 * q1 - q4;
  }
  return slopes;
}

// The largest jump of s dF/ds across the rim over `n` seeded rim points (b/a log-uniform in
// [0.01, 1], psi uniform in [0, pi/2]), and the largest slope.
struct RimJump {
  double jump = 0.0;
  double slope = 0.0;
};

RimJump rim_jump(const FrictionLaw& law, int n) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  RimJump r;
  for (int i = 0; i < n; ++i) {
    const double mu = std::pow(kExactTableMinAxisRatio, uni(rng));
    const double psi = 0.5 * kPi * uni(rng);
    const auto out = rim_slopes(law, mu, psi, +1);
    const auto in = rim_slopes(law, mu, psi, -1);
    for (int k = 0; k < 3; ++k) {
      r.jump = std::max(r.jump, std::abs(out[k] - in[k]));
      r.slope = std::max({r.slope, std::abs(out[k]), std::abs(in[k])});
    }
  }
  return r;
}

// A regression pin, in its own suite: the bound below is a measured value with a margin, not a
// promise of the design (which does not make the blocks' slopes agree at the rim).
class ExactTableRimSlopeRegressionPin : public ExactTablePressure {};
INSTANTIATE_TEST_SUITE_P(EveryPressure, ExactTableRimSlopeRegressionPin, ::testing::ValuesIn(kPressures),
                         pressure_test_name);

TEST_P(ExactTableRimSlopeRegressionPin, ItsSlopeAcrossTheRimJumpsOnlyByTheTablesSlopeError) {
  // The design does not force the two blocks' slopes at the rim to agree (docs/exact-table.md,
  // "Node layout and scheme"): each block's zero-slope end condition makes dF/ds finite there, and
  // each block's slope carries its own interpolation error, largest in the inside block's last
  // radial cell. So the table's slope jumps at the rim by its slope error. Measured (2026-11-29,
  // this test's print): up to 6.9e-4 (Hertz), 5.5e-3 (uniform), 2.3e-3 (punch) in s dF/ds per kN
  // (kNa), worst with the ICR near the end of the major axis, against slopes up to 0.57, 0.63,
  // 1.0 (other seeds: the same magnitudes, punch up to 5.5e-3); exact's own jump, estimated the
  // same way, is below 3e-6: the estimate resolves it. The bound, 2e-2, is the largest measured
  // jump times ~3.5, and far below what losing C^1 there looks like: without the zero-slope end
  // conditions the slope grows like 1/sqrt(x) (the radial maps), ~1e4 times larger at this h.
  constexpr double kRimSlopeJump = 2e-2;
  const RimJump table = rim_jump(ExactTableLaw(pressure()), 4000);
  const RimJump exact = rim_jump(ExactLaw(pressure()), 200);
  std::cout << spec_of(pressure()) << ": 4000 rim points, largest jump of s dF/ds across the rim " << table.jump
            << " (largest slope " << table.slope << "); exact, 200 points: " << exact.jump << "\n";
  EXPECT_LE(table.jump, kRimSlopeJump);
  EXPECT_LE(exact.jump, 1e-4);  // the estimate sees a C^1 function as one
}

TEST_P(ExactTablePressure, SmoothAcrossTheAxesOfThePatch) {
  // F1 and M are even in psi about psi = 0 and psi = pi/2 (F2 is odd, and an odd function has no
  // kink), exactly so in the table (it reads |Xt|, |Yt|). They are C^1 there iff their one-sided
  // slope at the axis is 0. It is estimated as 2 q(h) - q(2h) from difference quotients q (an even
  // smooth function has q(h) = a h + O(h^3)); a kink would leave its half-jump. The zero-slope end
  // condition at zeta = 0 is what makes psi = pi/2 smooth (there zeta ~ |psi - pi/2|); psi = 0 is
  // smooth through the map zeta = |Ys|/rho ~ 1 - O(psi^2). Measured: below 1e-8 per radian; the
  // bound 1e-6 leaves room for rounding (1e-16/h) and the O(h^2) rest on slender patches.
  constexpr double kAxisSlope = 1e-6;
  constexpr double h = 1e-6;
  const ExactTableLaw law(pressure());
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double largest = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double mu = std::pow(kExactTableMinAxisRatio, uni(rng));
    const double s = std::pow(10.0, -2.0 + 4.0 * uni(rng));
    for (const double axis : {0.0, kPi / 2}) {
      const FrictionForces f0 = law.evaluate(unit(s, mu, axis));
      const FrictionForces f1 = law.evaluate(unit(s, mu, axis + h));
      const FrictionForces f2 = law.evaluate(unit(s, mu, axis + 2.0 * h));
      for (const int k : {0, 2}) {
        const double q1 = (output(f1, k) - output(f0, k)) / h;
        const double q2 = (output(f2, k) - output(f0, k)) / (2.0 * h);
        largest = std::max(largest, std::abs(2.0 * q1 - q2));
        EXPECT_LE(std::abs(2.0 * q1 - q2), kAxisSlope)
            << kOutputNames[k] << " at psi = " << axis << ", s = " << s << ", b/a = " << mu;
      }
    }
  }
  std::cout << spec_of(pressure()) << ": largest one-sided slope of F1, M at psi = 0, pi/2: " << largest << "\n";
}

// ---------------------------------------------------------------------------------------------
// (4) Out of the table

TEST_P(ExactTablePressure, AxisRatioBelowTheTableIsRejectedNamingIt) {
  const ExactTableLaw law(pressure());
  try {
    (void)law.evaluate({0.3, 2.0, 1.0, 0.0099, 0.7, 10.0, 0.4});
    FAIL() << "b/a = 0.0099 accepted";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("b = 0.0099"), std::string::npos) << msg;
    EXPECT_NE(msg.find("b/a = 0.0099"), std::string::npos) << msg;
    EXPECT_NE(msg.find("below 0.01"), std::string::npos) << msg;
    EXPECT_NE(msg.find("exact-table"), std::string::npos) << msg;
  }
  // The table's edge itself is in.
  const FrictionForces f = law.evaluate({0.3, 2.0, 1.0, 0.01, 0.7, 10.0, 0.4});
  EXPECT_TRUE(std::isfinite(f.F1) && std::isfinite(f.F2) && std::isfinite(f.M));
}

// ---------------------------------------------------------------------------------------------
// (5) The axes and the circle

TEST_P(ExactTablePressure, OnTheAxesOfThePatchF2VanishesAndTheRestIsExacts) {
  const ExactLaw exact(pressure());
  const ExactTableLaw table(pressure());
  for (const double mu : {0.01, 0.2, 0.9}) {
    for (double s = 1e-4; s < 1e4; s *= 1.7) {
      // psi = 0 (angle), pi/2 as the direction (0, 1), and pi/2 as an angle (cos = 6e-17).
      for (const PatchAngle psi : {PatchAngle(0.0), PatchAngle::from_direction(0.0, 1.0), PatchAngle(kPi / 2)}) {
        ContactInput in = unit(s, mu, 0.0);
        in.psi = psi;
        const FrictionForces t = table.evaluate(in);
        const FrictionForces e = exact.evaluate(in);
        if (psi.is_direction() || psi.radians() == 0.0) {
          EXPECT_EQ(t.F2, 0.0) << "s = " << s << ", b/a = " << mu;
        } else {
          EXPECT_LE(std::abs(t.F2), 1e-15) << "s = " << s << ", b/a = " << mu;
        }
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(output(t, k), output(e, k), kAccuracy) << kOutputNames[k] << " s = " << s << ", b/a = " << mu;
        }
      }
    }
  }
}

TEST_P(ExactTablePressure, ACircleHasNoF2AndExactsForces) {
  const ExactLaw exact(pressure());
  const ExactTableLaw table(pressure());
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 400; ++i) {
    const double s = i % 2 == 0 ? std::pow(10.0, -4.0 + 8.0 * uni(rng)) : 1.0 + 0.2 * (uni(rng) - 0.5);
    const double psi = 2.0 * kPi * uni(rng);
    const double omega = uni(rng) < 0.5 ? 1.0 : -1.0;
    const FrictionForces t = table.evaluate(unit(s, 1.0, psi, omega));
    const FrictionForces e = exact.evaluate(unit(s, 1.0, psi, omega));
    EXPECT_EQ(t.F2, 0.0);
    EXPECT_NEAR(t.F1, e.F1, kAccuracy) << "s = " << s;
    EXPECT_NEAR(t.M, e.M, kAccuracy) << "s = " << s;
    if (pressure() == Pressure::hertz && s <= 30.0) {  // the closed forms of docs/model.md
      const test::CircleForces c = test::circle(s);
      EXPECT_NEAR(t.F1, c.f1, kAccuracy) << "s = " << s;
      EXPECT_NEAR(t.M, omega * c.m, kAccuracy) << "s = " << s;
    }
  }
}

}  // namespace
}  // namespace frictionlab::friction
