// The patch's orientation (friction/patch_angle.h): an angle carries std::cos and std::sin of it
// bit for bit, a direction is kept as given and its angle is the one of the line, in [0, pi).

#include "friction/patch_angle.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace frictionlab::friction {
namespace patch_angle_test {

constexpr double kPi = std::numbers::pi;
// atan2 of a unit direction and the cosine and sine of its double angle agree to a few roundings.
constexpr double kAngleTolerance = 4e-16;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

TEST(PatchAngle, DefaultIsTheMajorAxisAlongTheSlip) {
  constexpr PatchAngle p;
  EXPECT_EQ(bits(p.cos_sin().c), bits(1.0));
  EXPECT_EQ(bits(p.cos_sin().s), bits(0.0));
  EXPECT_EQ(bits(p.radians()), bits(0.0));
  EXPECT_FALSE(p.is_direction());
}

TEST(PatchAngle, AnAngleGivesStdCosAndSinOfItBitForBit) {
  // Read at run time (volatile): the reference is the library's std::cos and std::sin, as every
  // law computed them from the angle before.
  volatile double angles[] = {0.0, -0.0, 0.3, -0.3, 1.0, kPi / 2.0, kPi, -kPi, 3.0 * kPi, 1e-300, 1e22, -1e300};
  for (const double psi : angles) {
    const PatchAngle p = psi;  // implicit: a double is an angle
    EXPECT_EQ(bits(p.cos_sin().c), bits(std::cos(psi))) << "psi = " << psi;
    EXPECT_EQ(bits(p.cos_sin().s), bits(std::sin(psi))) << "psi = " << psi;
    EXPECT_EQ(bits(p.radians()), bits(psi)) << "the angle is kept as given, not folded";
    EXPECT_FALSE(p.is_direction());
  }
}

TEST(PatchAngle, ADirectionIsKeptAsGiven) {
  const PatchAngle p = PatchAngle::from_direction(0.6, -0.8);
  EXPECT_EQ(p.cos_sin().c, 0.6);
  EXPECT_EQ(p.cos_sin().s, -0.8);
  EXPECT_TRUE(p.is_direction());
}

TEST(PatchAngle, ADirectionsAngleIsTheLinesInZeroToPi) {
  // The major axis is a line: (c, s) and (-c, -s) are the same patch, and the angle reported is
  // the one in [0, pi). Closed forms: cos 2psi = c^2 - s^2 and sin 2psi = 2 c s for both.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uni(-kPi, kPi);
  for (int i = 0; i < 1000; ++i) {
    const double theta = uni(rng);
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    const double psi = PatchAngle::from_direction(c, s).radians();
    EXPECT_GE(psi, 0.0);
    EXPECT_LT(psi, kPi);
    EXPECT_NEAR(std::cos(2.0 * psi), (c - s) * (c + s), 4.0 * kAngleTolerance) << "theta = " << theta;
    EXPECT_NEAR(std::sin(2.0 * psi), 2.0 * c * s, 4.0 * kAngleTolerance) << "theta = " << theta;
    const double expected = theta >= 0.0 ? theta : theta + kPi;
    EXPECT_NEAR(psi, expected, kAngleTolerance * 8.0) << "theta = " << theta;
  }
}

TEST(PatchAngle, ADirectionOnTheSlipLineHasAngleZero) {
  // Along -e1, with either zero: atan2 gives +-pi, the line's angle is 0; just above -e1 atan2
  // rounds to pi, which is the same line too.
  EXPECT_EQ(PatchAngle::from_direction(-1.0, 0.0).radians(), 0.0);
  EXPECT_EQ(PatchAngle::from_direction(-1.0, -0.0).radians(), 0.0);
  EXPECT_EQ(PatchAngle::from_direction(-1.0, 1e-300).radians(), 0.0);
  EXPECT_EQ(PatchAngle::from_direction(1.0, 0.0).radians(), 0.0);
  EXPECT_EQ(PatchAngle::from_direction(0.0, 1.0).radians(), kPi / 2.0);
  EXPECT_EQ(PatchAngle::from_direction(0.0, -1.0).radians(), kPi / 2.0);
}

}  // namespace
}  // namespace frictionlab::friction
