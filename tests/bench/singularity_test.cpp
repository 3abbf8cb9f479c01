// Singular points and poles: the magnitude test, the denominators each law declares (for the printed
// Padé law, checked against its outputs), and the brackets they give around the real poles.

#include "bench/accuracy/singularity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "friction/pade_printed_law.h"
#include "friction/registry.h"

namespace frictionlab::accuracy {
namespace singularity_test {

constexpr double pi = std::numbers::pi;
// The study's denominators and the law share the coefficients; they differ only by the order of a
// few floating-point operations.
constexpr double kRelTol = 1e-13;

TEST(Singularity, MagnitudeAndFiniteness) {
  EXPECT_FALSE(is_singular(1.0, -0.5, 0.3));
  EXPECT_FALSE(is_singular(kSingularMagnitude, -kSingularMagnitude, 0.0));
  EXPECT_TRUE(is_singular(0.0, -10.001, 0.0));
  EXPECT_TRUE(is_singular(0.0, 0.0, 11.0));
  EXPECT_TRUE(is_singular(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0));
  EXPECT_TRUE(is_singular(0.0, std::numeric_limits<double>::infinity(), 0.0));
}

TEST(Singularity, DenominatorsAreTheOnesEachLawDeclares) {
  // The study re-derives nothing: a law with poles is watched through its own
  // pole_denominators(), a law without has none, an unknown name is an error.
  for (const auto& info : friction::list_laws()) {
    const auto den = known_denominators(info.name);
    ASSERT_EQ(den.has_value(), info.has_poles) << info.name;
    if (!den) continue;
    const auto law = friction::make_law(info.name);
    for (const double s : {0.01, 0.7, 30.0}) {
      const auto d = (*den)(s, 0.3, 0.4);
      const auto own = law->pole_denominators(to_contact({s, 0.3, 0.4, 1}));
      EXPECT_EQ(d.F1, own.F1) << info.name;
      EXPECT_EQ(d.F2, own.F2) << info.name;
      EXPECT_EQ(d.M, own.M) << info.name;
    }
  }
  EXPECT_TRUE(known_denominators("pade-printed").has_value());
  EXPECT_TRUE(known_denominators("pade-printed-minor").has_value());
  EXPECT_FALSE(known_denominators("exact").has_value());
  EXPECT_THROW((void)known_denominators("no-such-law"), std::invalid_argument);
}

// law output x denominator = numerator of eq. (8), with a = 1, |Omega| = 1, F0 = 1, alpha = c.
void expect_denominators_match_law(friction::PadeAlpha alpha, const char* name) {
  const friction::PadePrintedLaw law(alpha);
  const auto den = *known_denominators(name);
  for (const double mu : {0.05, 0.3, 0.8}) {
    for (const double psi : {0.3, pi / 4.0, 2.0, 2.9}) {
      for (const double s : {0.01, 0.7, 30.0}) {
        for (const int sign : {-1, 1}) {
          const auto k = friction::pade_printed_coefficients(mu, psi);
          const double c = alpha == friction::PadeAlpha::major ? 1.0 : mu;
          const auto f = law.evaluate(to_contact({s, mu, psi, sign}));
          const auto d = den(s, mu, psi);
          const double n1 = s * s + k.a1 * c * s;
          const double n2 = -s * c * sign;
          const double n3 = k.m0_over_alpha_f0 * c * (k.b1 * s * c * sign + c * c * sign);
          EXPECT_NEAR(f.F1 * d.F1, n1, kRelTol * std::abs(n1)) << name << " mu " << mu << " psi " << psi << " s " << s;
          EXPECT_NEAR(f.F2 * d.F2, n2, kRelTol * std::abs(n2)) << name << " mu " << mu << " psi " << psi << " s " << s;
          EXPECT_NEAR(f.M * d.M, n3, kRelTol * std::abs(n3)) << name << " mu " << mu << " psi " << psi << " s " << s;
        }
      }
    }
  }
}

TEST(Singularity, DenominatorsMatchThePrintedLawMajor) {
  expect_denominators_match_law(friction::PadeAlpha::major, "pade-printed");
}

TEST(Singularity, DenominatorsMatchThePrintedLawMinor) {
  expect_denominators_match_law(friction::PadeAlpha::minor, "pade-printed-minor");
}

TEST(Singularity, NoF2DenominatorWhereSin2PsiVanishes) {
  const auto den = *known_denominators("pade-printed");
  EXPECT_TRUE(std::isnan(den(1.0, 0.5, 0.0).F2));
  EXPECT_TRUE(std::isnan(den(1.0, 1.0, pi / 4.0).F2));  // circle: d6 = 0
}

GridSpec pole_grid() {
  GridSpec spec;  // 200 s nodes over [1e-3, 1e3]; mu in {0.5, 1}; psi every 45 degrees
  spec.mu_min = 0.5;
  spec.mu_points = 2;
  spec.psi_points = 5;
  return spec;
}

TEST(Singularity, F2PoleIsBracketedWherePrintedA4IsNegative) {
  const Grid grid{pole_grid()};
  const auto brackets = pole_brackets(grid, *known_denominators("pade-printed"));
  // psi = 45 deg, mu = 0.5: a4 < 0, the positive root of s^2 + a3 s + a4.
  const auto k = friction::pade_printed_coefficients(0.5, pi / 4.0);
  ASSERT_LT(k.a4, 0.0);
  const double s_pole = (-k.a3 + std::sqrt(k.a3 * k.a3 - 4.0 * k.a4)) / 2.0;
  std::size_t f2_at_45 = 0;
  for (const auto& b : brackets) {
    if (b.component != Component::F2) continue;
    EXPECT_EQ(b.imu, 0u) << "no F2 pole for the circle";
    EXPECT_EQ(b.ipsi, 1u) << "F2 poles only for psi in (0, pi/2)";
    EXPECT_LE(b.s_low, s_pole);
    EXPECT_GE(b.s_high, s_pole);
    ++f2_at_45;
  }
  EXPECT_EQ(f2_at_45, 1u);

  // The law itself jumps across the bracket: F2 changes sign through a pole.
  const friction::PadePrintedLaw law;
  for (const auto& b : brackets) {
    if (b.component != Component::F2) continue;
    const auto lo = law.evaluate(to_contact({b.s_low, 0.5, pi / 4.0, 1}));
    const auto hi = law.evaluate(to_contact({b.s_high, 0.5, pi / 4.0, 1}));
    EXPECT_LT(lo.F2 * hi.F2, 0.0);
  }
}

TEST(Singularity, MPolesOfTheThinPatchAreBracketed) {
  // mu = 0.05, psi = 0: b1 = -16/(15 pi) mu^(-7/4) < 0 and b1^2 > 4 b2, so the printed M has two
  // real poles, the roots of b2 s^2 + b1 s + 1.
  GridSpec spec;
  spec.mu_points = 2;
  spec.psi_points = 3;
  const Grid grid{spec};
  const auto k = friction::pade_printed_coefficients(0.05, 0.0);
  const double disc = k.b1 * k.b1 - 4.0 * k.b2;
  ASSERT_GT(disc, 0.0);
  const double r1 = (-k.b1 - std::sqrt(disc)) / (2.0 * k.b2);
  const double r2 = (-k.b1 + std::sqrt(disc)) / (2.0 * k.b2);
  std::vector<double> found;
  for (const auto& b : pole_brackets(grid, *known_denominators("pade-printed"))) {
    if (b.component == Component::M && b.imu == 0 && b.ipsi == 0) {
      found.push_back(b.s_low);
      EXPECT_TRUE((b.s_low <= r1 && r1 <= b.s_high) || (b.s_low <= r2 && r2 <= b.s_high))
          << b.s_low << " " << b.s_high;
    }
  }
  EXPECT_EQ(found.size(), 2u);
}

TEST(Singularity, MapMarksTheNegativeF2DenominatorAndLargeValues) {
  const Grid grid{pole_grid()};
  const friction::PadePrintedLaw law;
  const LawValues values = evaluate_on_grid(law, grid, 1);
  const auto den = known_denominators("pade-printed");
  const auto map = singularity_map(grid, values, den);
  const std::size_t ns = grid.s().size();
  // psi = 45 deg, mu = 0.5: F2 denominator < 0 at the smallest s (a4 < 0), > 0 at the largest.
  EXPECT_TRUE(map[(0 * 5 + 1) * ns + 0] & kF2DenominatorNegative);
  EXPECT_FALSE(map[(0 * 5 + 1) * ns + ns - 1] & kF2DenominatorNegative);
  // psi = 135 deg: a4 > 0 and a3 > 0, no sign change.
  for (std::size_t is = 0; is < ns; ++is) EXPECT_FALSE(map[(0 * 5 + 3) * ns + is] & kF2DenominatorNegative);
  // Without denominators, only the value bit can be set.
  for (const auto bits : singularity_map(grid, values, std::nullopt)) EXPECT_EQ(bits & ~kSingularValue, 0);
}

}  // namespace
}  // namespace frictionlab::accuracy
