// The rocking energy of the rest rule (dynamics/body/rocking_energy.h) against the exact potential
// energy of bodies whose potential has a closed form.
#include "dynamics/body/rocking_energy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace frictionlab::dynamics {
namespace rocking_energy_test {

constexpr double kG = 9.81;

// A sphere of radius R whose centre of mass lies e below its centre (e < R), tilted by theta from
// upright: G at the height R - e cos(theta), so the potential above the equilibrium is
// m g e (1 - cos(theta)); the contact point from G is r = -R gamma + e n, n the body's axis (up at
// theta = 0), whose horizontal part is e sin(theta). Here R_c - l = e exactly.
TEST(DynRockingEnergy, IsALowerBoundOfTheEccentricSpheresPotentialAndTightForSmallTilts) {
  constexpr double R = 0.05, e = 0.01, m = 0.3;
  for (const double theta : {1e-4, 1e-2, 0.1, 0.5}) {
    const Eigen::Vector3d gamma(std::sin(theta), 0.0, std::cos(theta));  // body frame, axis e3
    const Eigen::Vector3d r = -R * gamma + e * Eigen::Vector3d::UnitZ();
    const double exact = m * kG * e * (1.0 - std::cos(theta));
    const double bound = rocking_energy(r, gamma, R, R, m, kG);
    EXPECT_LE(bound, exact) << theta;
    // m g e^2 sin^2 / (2 R) against m g e theta^2 / 2: the ratio e/R for small tilts.
    EXPECT_NEAR(bound / exact, e / R * std::pow(std::sin(theta) / theta, 2) * (theta * theta / 2) /
                                   (1.0 - std::cos(theta)),
                1e-9)
        << theta;
  }
}

TEST(DynRockingEnergy, VanishesAtAnEquilibriumAndOnAFlatOrWeightlessContact) {
  const Eigen::Vector3d gamma(0.0, 0.0, 1.0);
  EXPECT_EQ(rocking_energy(Eigen::Vector3d(0.0, 0.0, -0.02), gamma, 2.0, 0.045, 1.0, kG), 0.0);
  const Eigen::Vector3d off(0.01, 0.0, -0.02);
  EXPECT_EQ(rocking_energy(off, gamma, std::numeric_limits<double>::infinity(), 0.045, 1.0, kG), 0.0);
  EXPECT_EQ(rocking_energy(off, gamma, 2.0, 0.045, 1.0, 0.0), 0.0);
  // The larger radius is the one used: m g d^2 / (2 R_max).
  EXPECT_DOUBLE_EQ(rocking_energy(off, gamma, 0.045, 2.0, 1.0, kG), kG * 1e-4 / 4.0);
}

}  // namespace
}  // namespace frictionlab::dynamics
