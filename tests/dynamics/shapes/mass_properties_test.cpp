#include "dynamics/shapes/mass_properties.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace frictionlab::dynamics {
namespace mass_properties_test {

// The quadrature is exact for these polynomial integrands: only rounding remains.
constexpr double kExactRelTol = 1e-12;
// docs/model.md §6 prints the egg's values to 3 significant digits: half a unit in the last digit.
constexpr double kPrintedTol = 5e-5;

constexpr double pi = std::numbers::pi;

TEST(DynMassProperties, SphereMatchesClosedForm) {
  const double R = 0.1, m = 3.0;
  const MassProperties p = homogeneous_mass_properties(Profile::sphere(R), m);
  EXPECT_NEAR(p.volume, 4.0 / 3.0 * pi * R * R * R, kExactRelTol * p.volume);
  EXPECT_NEAR(p.centroid, 0.0, kExactRelTol * R);
  EXPECT_NEAR(p.C, 0.4 * m * R * R, kExactRelTol * p.C);
  EXPECT_NEAR(p.A, 0.4 * m * R * R, kExactRelTol * p.A);
}

TEST(DynMassProperties, SpheroidMatchesClosedForm) {
  for (const auto& [a, c] : {std::pair{0.2, 0.05}, std::pair{0.05, 0.2}}) {
    const double m = 1.5;
    const MassProperties p = homogeneous_mass_properties(Profile::spheroid(a, c), m);
    EXPECT_NEAR(p.volume, 4.0 / 3.0 * pi * a * a * c, kExactRelTol * p.volume);
    EXPECT_NEAR(p.C, 0.4 * m * a * a, kExactRelTol * p.C);
    EXPECT_NEAR(p.A, 0.2 * m * (a * a + c * c), kExactRelTol * p.A);
  }
}

TEST(DynMassProperties, OffsetSphereHasItsCentroidAtTheCentreAndParallelAxes) {
  const double R = 0.1, z0 = 0.3, m = 2.0;
  // R^2 - (z - z0)^2
  const Profile s({R * R - z0 * z0, 2.0 * z0, -1.0});
  const MassProperties p = homogeneous_mass_properties(s, m);
  EXPECT_NEAR(p.centroid, z0, kExactRelTol * z0);
  EXPECT_NEAR(p.A, 0.4 * m * R * R, kExactRelTol * p.A);
  EXPECT_NEAR(p.transverse_about(0.0), 0.4 * m * R * R + m * z0 * z0, kExactRelTol * p.A);
}

TEST(DynMassProperties, PaperEggMatchesModelNotesAndExactIntegrals) {
  const MassProperties p = homogeneous_mass_properties(Profile::paper_egg(), 2.0);
  // Independent values (docs/model.md §6).
  EXPECT_NEAR(p.centroid, 0.0705, kPrintedTol);
  EXPECT_NEAR(p.C, 0.0559, kPrintedTol);
  EXPECT_NEAR(p.A, 0.0403, kPrintedTol);               // about the centroid (egg-homogeneous)
  EXPECT_NEAR(p.transverse_about(0.0), 0.0502, kPrintedTol);  // about z = 0 (egg-printed)
  // The same integrals in exact rational arithmetic (Python fractions, polynomial antiderivatives).
  EXPECT_NEAR(p.volume, 0.051336105600036465, kExactRelTol * p.volume);
  EXPECT_NEAR(p.centroid, 0.070488256227758, kExactRelTol * p.centroid);
  EXPECT_NEAR(p.C, 0.0559023604286731, kExactRelTol * p.C);
  EXPECT_NEAR(p.A, 0.040280821575514845, kExactRelTol * p.A);
  EXPECT_NEAR(p.transverse_about(0.0), 0.05021801010757498, kExactRelTol * p.A);
}

TEST(DynMassProperties, RejectsANonPositiveMass) {
  EXPECT_THROW((void)homogeneous_mass_properties(Profile::sphere(1.0), 0.0), std::invalid_argument);
  EXPECT_THROW((void)homogeneous_mass_properties(Profile::sphere(1.0), NAN), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics
