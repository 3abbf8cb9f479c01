// Hertz's elliptic contact (dynamics/contact/hertz_ellipse.h) against closed forms and against the
// elliptic integrals evaluated independently, by direct adaptive quadrature of their definitions
// K(e) = ∫ dθ/sqrt(1 - e^2 sin^2 θ), E(e) = ∫ sqrt(1 - e^2 sin^2 θ) dθ over [0, pi/2]
// (Gauss–Kronrod, not the Carlson forms Boost.Math's ellint_* use).
#include "dynamics/contact/hertz_ellipse.h"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace frictionlab::dynamics {
namespace hertz_ellipse_test {

constexpr double pi = std::numbers::pi;
// The quadrature is converged to ~1e-15; the solver returns mu to 2 ulps; the relations below
// lose at most a few digits to the cancellation in K - E for the smallest e tested (e^2 ~ 1e-2).
constexpr double kRelTol = 1e-11;

struct KE {
  double K, E;
};

KE quadrature(double mu) {
  const double e2 = (1.0 - mu) * (1.0 + mu);
  using GK = boost::math::quadrature::gauss_kronrod<double, 61>;
  const double K = GK::integrate([e2](double t) { return 1.0 / std::sqrt(1.0 - e2 * std::sin(t) * std::sin(t)); }, 0.0,
                                 pi / 2, 15, 1e-15);
  const double E =
      GK::integrate([e2](double t) { return std::sqrt(1.0 - e2 * std::sin(t) * std::sin(t)); }, 0.0, pi / 2, 15, 1e-15);
  return {K, E};
}

// Johnson's form of the eccentricity equation, B/A = ((a/b)^2 E - K)/(K - E).
double ratio_by_quadrature(double mu) {
  const KE q = quadrature(mu);
  return (q.E / (mu * mu) - q.K) / (q.K - q.E);
}

TEST(DynHertzEllipse, EqualRadiiGiveTheCircleOfTheSphere) {
  for (const double R : {1e-3, 0.05, 1.0, 37.0}) {
    const HertzEllipse h = hertz_ellipse(R, R);
    EXPECT_EQ(h.mu, 1.0);
    // a^2 = R delta (not the section's 2 R delta), N = (4/3) E* sqrt(R) delta^(3/2).
    EXPECT_NEAR(h.a2_per_depth, R, 4e-16 * R);
    EXPECT_NEAR(h.stiffness_per_modulus, 4.0 / 3.0 * std::sqrt(R), 4e-16 * std::sqrt(R));
  }
}

TEST(DynHertzEllipse, CurvatureRatioMatchesJohnsonsFormByQuadrature) {
  for (const double mu : {0.99, 0.9, 0.7, 0.5, 0.3, 0.1, 0.03, 0.01}) {
    const double expected = ratio_by_quadrature(mu);
    EXPECT_NEAR(hertz_curvature_ratio(mu), expected, kRelTol * expected) << "mu = " << mu;
  }
  EXPECT_NEAR(hertz_curvature_ratio(1.0), 1.0, 1e-15);
}

TEST(DynHertzEllipse, SolvesTheEccentricityEquationOverSixDecades) {
  for (const double rho : {1.001, 1.1, 1.5, 2.0, 3.0, 10.0, 100.0, 1e3, 1e4, 1e6}) {
    const HertzEllipse h = hertz_ellipse(rho, 1.0);
    ASSERT_GT(h.mu, 0.0);
    ASSERT_LT(h.mu, 1.0);
    EXPECT_NEAR(ratio_by_quadrature(h.mu), rho, 1e-10 * rho) << "rho = " << rho;
    // The order of the radii does not matter.
    EXPECT_EQ(hertz_ellipse(1.0, rho).mu, h.mu);
  }
}

// The solver returns the root to rounding: the curvature ratio B/A falls strictly with mu, so
// moving mu by 16 ulps either way brackets the requested ratio. Log-uniform ratios from the circle
// to 1e14 (the guess table and beyond it).
TEST(DynHertzEllipse, SolvesTheEccentricityEquationToRounding) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-12.0, 14.0);
  for (int i = 0; i < 4000; ++i) {
    const double rho = 1.0 + std::pow(10.0, u(rng));
    const HertzEllipse h = hertz_ellipse(rho, 1.0);
    const double step = 16.0 * std::numeric_limits<double>::epsilon() * h.mu;
    if (h.mu == 1.0) {
      EXPECT_LE(rho - 1.0, 2e-12) << "rho = " << rho;
      continue;
    }
    EXPECT_GT(hertz_curvature_ratio(h.mu - step), rho) << "rho - 1 = " << rho - 1.0;
    EXPECT_LT(hertz_curvature_ratio(std::min(h.mu + step, 1.0)), rho) << "rho - 1 = " << rho - 1.0;
  }
}

// d ln S / d ln R of each radius against central differences of S itself (step 1e-5 in ln R:
// truncation ~1e-11, rounding ~1e-16/1e-5).
TEST(DynHertzEllipse, StiffnessElasticitiesMatchCentralDifferences) {
  const double h = 1e-5;
  const auto lnS = [](double R1, double R2) { return std::log(hertz_ellipse(R1, R2).stiffness_per_modulus); };
  for (const auto& [R1, R2] : {std::pair{2.0, 0.5}, std::pair{0.5, 2.0}, std::pair{0.3, 0.27}, std::pair{10.0, 0.01},
                               std::pair{1.0, 1.1}, std::pair{1e4, 1.0}, std::pair{1.0, 3e7}}) {
    const HertzEllipse e = hertz_ellipse(R1, R2);
    const double d1 = (lnS(R1 * std::exp(h), R2) - lnS(R1 * std::exp(-h), R2)) / (2.0 * h);
    const double d2 = (lnS(R1, R2 * std::exp(h)) - lnS(R1, R2 * std::exp(-h))) / (2.0 * h);
    EXPECT_NEAR(e.dlnS_dlnR1, d1, 1e-9) << R1 << " " << R2;
    EXPECT_NEAR(e.dlnS_dlnR2, d2, 1e-9) << R1 << " " << R2;
  }
}

// S is symmetric in the two radii and homogeneous of degree 1/2 (S ~ sqrt(R)), so at equal radii
// each elasticity is 1/4; near equal radii they tend to it continuously.
TEST(DynHertzEllipse, StiffnessElasticitiesAreAQuarterEachAtTheCircle) {
  const HertzEllipse c = hertz_ellipse(0.3, 0.3);
  EXPECT_NEAR(c.dlnS_dlnR1, 0.25, 1e-15);
  EXPECT_NEAR(c.dlnS_dlnR2, 0.25, 1e-15);
  for (const double x : {1e-3, 1e-6, 1e-9}) {
    const HertzEllipse e = hertz_ellipse(1.0 + x, 1.0);
    EXPECT_NEAR(e.dlnS_dlnR1, 0.25, x) << x;
    EXPECT_NEAR(e.dlnS_dlnR2, 0.25, x) << x;
  }
}

// Hertz's relations between the curvatures, the approach, the load and the ellipse hold at the
// computed a, b, N (Johnson 1985, §4.2; docs/contact-models.md §2), with K, E by quadrature.
TEST(DynHertzEllipse, HertzsRelationsHoldAtTheComputedEllipse) {
  const double E_star = 1.1e11, delta = 2e-5;
  for (const auto& [R_major, R_minor] : {std::pair{2.0, 0.5}, std::pair{0.3, 0.29}, std::pair{10.0, 0.01}}) {
    const HertzEllipse h = hertz_ellipse(R_major, R_minor);
    const double a = std::sqrt(h.a2_per_depth * delta), b = h.mu * a;
    const double N = E_star * h.stiffness_per_modulus * delta * std::sqrt(delta);
    const double p0 = 3.0 * N / (2.0 * pi * a * b);
    const KE q = quadrature(h.mu);
    const double e2 = 1.0 - h.mu * h.mu;
    const double A = (p0 / E_star) * b / (e2 * a * a) * (q.K - q.E);
    const double B = (p0 / E_star) * b / (e2 * a * a) * (a * a / (b * b) * q.E - q.K);
    EXPECT_NEAR(A, 0.5 / R_major, kRelTol * 0.5 / R_major) << R_major << " " << R_minor;
    EXPECT_NEAR(B, 0.5 / R_minor, kRelTol * 0.5 / R_minor) << R_major << " " << R_minor;
    EXPECT_NEAR((p0 / E_star) * b * q.K, delta, kRelTol * delta) << R_major << " " << R_minor;
  }
}

// Near equal curvatures the ellipse tends to the circle continuously: B/A = 1 + (3/4) e^2 + O(e^4),
// so mu = 1 - (2/3)(rho - 1) + O((rho - 1)^2).
TEST(DynHertzEllipse, NearlyEqualCurvaturesTendToTheCircle) {
  for (const double x : {1e-3, 1e-5, 1e-7, 1e-9, 1e-11}) {
    const HertzEllipse h = hertz_ellipse(1.0 + x, 1.0);
    EXPECT_NEAR(h.mu, 1.0 - 2.0 / 3.0 * x, 2.0 * x * x + 4e-16) << "rho - 1 = " << x;
    EXPECT_NEAR(h.a2_per_depth, 1.0, 2.0 * x) << "rho - 1 = " << x;
    EXPECT_NEAR(h.stiffness_per_modulus, 4.0 / 3.0, 2.0 * x) << "rho - 1 = " << x;
  }
}

TEST(DynHertzEllipse, RejectsRadiiThatAreNotPositive) {
  for (const double R : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")})
    EXPECT_THROW((void)hertz_ellipse(R, 1.0), std::invalid_argument) << R;
}

TEST(DynHertzEllipse, EffectiveModulusFollowsItsDefinition) {
  // Steel on steel: 1/E* = 2 (1 - 0.09)/210e9.
  EXPECT_NEAR(effective_modulus(210e9, 0.3, 210e9, 0.3), 210e9 / (2.0 * 0.91), 1e-4);
  // A rigid plane: E* = E1/(1 - nu1^2).
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(effective_modulus(3e9, 0.4, inf, 0.3), 3e9 / (1.0 - 0.16));
  EXPECT_DOUBLE_EQ(effective_modulus(1e6, 0.5, 1e6, -0.5), 1.0 / (0.75e-6 + 0.75e-6));
}

TEST(DynHertzEllipse, BadElasticConstantsNameTheirKey) {
  const auto message = [](double E1, double nu1, double E2, double nu2) -> std::string {
    try {
      (void)effective_modulus(E1, nu1, E2, nu2);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message(-2e9, 0.3, 1e9, 0.3).rfind("contact.E1 = -2000000000 is invalid: Young's modulus must be > 0", 0), 0u)
      << message(-2e9, 0.3, 1e9, 0.3);
  EXPECT_EQ(message(1e9, 0.3, 0.0, 0.3).rfind("contact.E2 = 0 is invalid", 0), 0u) << message(1e9, 0.3, 0.0, 0.3);
  EXPECT_EQ(message(1e9, 0.6, 1e9, 0.3).rfind("contact.nu1 = 0.6 is invalid: Poisson's ratio must lie in (-1, 0.5]", 0), 0u)
      << message(1e9, 0.6, 1e9, 0.3);
  EXPECT_EQ(message(1e9, 0.3, 1e9, -1.0).rfind("contact.nu2 = -1 is invalid", 0), 0u) << message(1e9, 0.3, 1e9, -1.0);
  EXPECT_EQ(message(std::nan(""), 0.3, 1e9, 0.3).rfind("contact.E1", 0), 0u);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message(inf, 0.3, inf, 0.3).rfind("contact.E1 = inf is invalid: the plane and the body cannot both be rigid", 0), 0u)
      << message(inf, 0.3, inf, 0.3);
}

}  // namespace
}  // namespace frictionlab::dynamics
