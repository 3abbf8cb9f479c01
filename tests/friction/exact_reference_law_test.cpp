// Tests of friction/exact_reference_law.h: the brute-force GSL quadrature against the closed
// forms of docs/model.md, and the semi-analytic ExactLaw against it on a seeded random set.
// The reference costs milliseconds per call: the sets are kept small.

#include "friction/exact_reference_law.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "friction/exact_law.h"
#include "tests/friction/dimensionless_contact.h"
#include "tests/friction/hertz_closed_forms.h"

namespace frictionlab::friction {
namespace {

constexpr double kPi = std::numbers::pi;

// The accuracy the reference promises in its domain (per kN, per kNa; friction/exact_reference_law.h),
// plus that of `exact` (1e-13), which is negligible beside it.
constexpr double kReferenceTol = kExactReferenceAccuracy;

ContactInput make(double s, double mu, double psi, double omega = 1.0) {
  return dimensionless_contact(s, mu, psi, omega);
}

TEST(ExactReferenceLaw, NameAndSummary) {
  const ExactReferenceLaw law;
  EXPECT_EQ(law.name(), "exact-reference");
  EXPECT_FALSE(law.summary().empty());
}

TEST(ExactReferenceLaw, MatchesTheClosedForms) {
  const ExactReferenceLaw law;
  for (const double u : {0.5, 1.0, 2.0}) {
    const FrictionForces f = law.evaluate(make(u, 1.0, 0.3, -2.0));
    EXPECT_NEAR(f.F1, test::circle(u).f1, kReferenceTol) << "u = " << u;
    EXPECT_NEAR(f.F2, 0.0, kReferenceTol) << "u = " << u;
    EXPECT_NEAR(f.M, -test::circle(u).m, kReferenceTol) << "u = " << u;
  }
  for (const double mu : {0.05, 0.5}) {
    const FrictionForces f = law.evaluate(make(0.0, mu, 0.3));
    EXPECT_NEAR(f.M, test::pure_spin_moment(mu), kReferenceTol) << "mu = " << mu;
  }
}

TEST(ExactReferenceLaw, LimitsAndInputValidation) {
  const ExactReferenceLaw law;
  ContactInput slide = make(0.0, 0.3, 0.4, 0.0);
  slide.U = 1.0;
  const FrictionForces f = law.evaluate(slide);
  EXPECT_EQ(f.F1, 1.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
  const FrictionForces rest = law.evaluate(make(0.0, 0.3, 0.4, 0.0));
  EXPECT_EQ(rest.F1, 0.0);
  EXPECT_EQ(rest.M, 0.0);
  ContactInput bad = make(0.5, 0.3, 0.4);
  bad.b = 1.5;
  EXPECT_THROW((void)law.evaluate(bad), std::invalid_argument);
}

TEST(ExactReferenceLaw, RejectsPatchesBelowItsDomainWithAClearError) {
  // Below b/a = 0.01 its quadrature is not accurate (GSL round-off, or silently wrong values):
  // std::invalid_argument naming the ratio and the rule, never a GSL runtime error.
  const ExactReferenceLaw law;
  for (const double mu : {1e-9, 1e-6, 1e-3, 0.0099}) {
    try {
      (void)law.evaluate(make(0.5, mu, 1.5707963217948966));
      ADD_FAILURE() << "no exception at mu = " << mu;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("is below 0.01, the smallest for which its GSL quadrature"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW((void)law.evaluate(make(0.5, kExactReferenceMinAxisRatio, 1.5707963217948966)));
}

TEST(ExactReferenceLaw, SlipAboveTheDoubleRangeIsPureSliding) {
  // U / (a |Omega|) = 1e300 / 1e-300 overflows: F1 = kN to within 1e-600, no moment.
  ContactInput in = make(0.0, 0.5, 0.3, 1e-300);
  in.U = 1e300;
  const FrictionForces f = ExactReferenceLaw().evaluate(in);
  EXPECT_EQ(f.F1, 1.0);
  EXPECT_EQ(f.F2, 0.0);
  EXPECT_EQ(f.M, 0.0);
}

TEST(ExactReferenceLaw, ExactLawAgreesOnASeededRandomSet) {
  // 48 points: mu log-uniform in [0.01, 1] (every fourth exactly 0.01), psi in [0, pi), both
  // spins, and s drawn (by turns) log-uniformly in [1e-3, 1e3], within 1e-9..1e-2 of the rim
  // (inside and outside), within 1e-9..1e-2 of rho = sqrt(2), and moderately outside.
  const ExactReferenceLaw reference;
  const ExactLaw exact;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 48; ++i) {
    const double mu = (i % 4 == 0) ? 0.01 : std::pow(10.0, -2.0 * uni(rng));
    const double psi = kPi * uni(rng);
    const double omega = uni(rng) < 0.5 ? -1.0 : 1.0;
    const double side = uni(rng) < 0.5 ? -1.0 : 1.0;
    const double rho_per_s = std::hypot(std::sin(psi), std::cos(psi) / mu);
    const double near = side * std::pow(10.0, -9.0 + 7.0 * uni(rng));
    double s = 0.0;
    switch (i % 4) {
      case 0: s = std::pow(10.0, -3.0 + 6.0 * uni(rng)); break;
      case 1: s = (1.0 + near) / rho_per_s; break;
      case 2: s = (std::numbers::sqrt2 + near) / rho_per_s; break;
      default: s = std::pow(10.0, 1.5 * uni(rng)) / rho_per_s; break;
    }
    ContactInput in = make(s, mu, psi, omega);
    // Physical units on some of them.
    if (i % 3 == 0) {
      in.a = 0.02;
      in.b = 0.02 * mu;
      in.U = s * in.a * std::abs(in.Omega);
      in.N = 12.0;
      in.k = 0.2;
    }
    const double kN = in.k * in.N;
    const double kNa = kN * in.a;
    const FrictionForces r = reference.evaluate(in);
    const FrictionForces e = exact.evaluate(in);
    EXPECT_NEAR(e.F1 / kN, r.F1 / kN, kReferenceTol) << "s=" << s << " mu=" << mu << " psi=" << psi;
    EXPECT_NEAR(e.F2 / kN, r.F2 / kN, kReferenceTol) << "s=" << s << " mu=" << mu << " psi=" << psi;
    EXPECT_NEAR(e.M / kNa, r.M / kNa, kReferenceTol) << "s=" << s << " mu=" << mu << " psi=" << psi;
    worst = std::max({worst, std::abs(e.F1 - r.F1) / kN, std::abs(e.F2 - r.F2) / kN,
                      std::abs(e.M - r.M) / kNa});
  }
  RecordProperty("worst_difference", std::to_string(worst));
}

}  // namespace
}  // namespace frictionlab::friction
