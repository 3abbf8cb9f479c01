#include "dynamics/body/body_scales.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/dynamics/test_support.h"

namespace frictionlab::dynamics {
namespace body_scales_test {

constexpr double kSizeRelTol = 1e-13;

TEST(DynBodyScales, TheSizeOfASphereAboutItsCentreIsItsRadius) {
  EXPECT_NEAR(body_size(Profile::sphere(0.05), 0.0), 0.05, kSizeRelTol * 0.05);
}

TEST(DynBodyScales, TheSizeIsTheDistanceFromTheCentreOfMassToTheFarthestSurfacePoint) {
  // Centre of mass 4 mm below the centre of a 2 cm sphere: the far pole is 2.4 cm away.
  EXPECT_NEAR(body_size(Profile::sphere(0.02), -0.004), 0.024, kSizeRelTol * 0.024);
  // A spheroid about its centre: the larger semi-axis.
  EXPECT_NEAR(body_size(Profile::spheroid(0.2, 0.05), 0.0), 0.2, kSizeRelTol * 0.2);
  EXPECT_NEAR(body_size(Profile::spheroid(0.05, 0.2), 0.0), 0.2, kSizeRelTol * 0.2);
}

TEST(DynBodyScales, TheEggsSizeMatchesABruteForceSearch) {
  // max over the meridian of sqrt(P(z) + (z - com)^2) on 2e5 points: the grid misses the maximum
  // by at most (dz/2)^2 |Q''|/2 ~ 1e-12 m^2, far below the tolerance.
  const Profile egg = Profile::paper_egg();
  for (const double com : {0.0, 0.0704883}) {
    double best = 0.0;
    const int n = 200000;
    for (int i = 0; i <= n; ++i) {
      const double z = egg.z_lo() + (egg.z_hi() - egg.z_lo()) * i / n;
      best = std::max(best, std::max(0.0, egg.chi2()(z)) + (z - com) * (z - com));
    }
    EXPECT_NEAR(body_size(egg, com), std::sqrt(best), 1e-9) << "com = " << com;
  }
}

TEST(DynBodyScales, ScalesFollowFromTheSizeMassGravityAndHertzStiffness) {
  const Body body = testing::sphere_body(0.05, 1.0);
  const PlaneContact plane{0.2, 1e7, 9.81};
  const BodyScales s = body_scales(body, plane);
  EXPECT_DOUBLE_EQ(s.size, 0.05);
  EXPECT_DOUBLE_EQ(s.speed, std::sqrt(9.81 * 0.05));
  EXPECT_DOUBLE_EQ(s.rate, std::sqrt(9.81 / 0.05));
  EXPECT_DOUBLE_EQ(s.energy, 9.81 * 0.05);
  EXPECT_DOUBLE_EQ(s.compression, std::abs(plane.static_height(9.81)));
  // omega_n^2 = N'(eps_s)/m: the Hertz force differentiated numerically at the static compression.
  const double e = -s.compression, de = 1e-7 * s.compression;
  const double stiffness = (plane.normal_force(e - de) - plane.normal_force(e + de)) / (2.0 * de);
  EXPECT_NEAR(s.hertz_frequency, std::sqrt(stiffness / 1.0), 1e-8 * s.hertz_frequency);
  EXPECT_DOUBLE_EQ(s.liftoff_speed, s.hertz_frequency * s.compression);
}

TEST(DynBodyScales, WithoutGravityTheScalesUseStandardGravity) {
  const BodyScales s = body_scales(testing::sphere_body(0.05, 1.0), PlaneContact{0.2, 1e7, 0.0});
  EXPECT_EQ(s.gravity, kReferenceGravity);
  EXPECT_GT(s.speed, 0.0);
  EXPECT_GT(s.compression, 0.0);
  EXPECT_TRUE(std::isfinite(s.hertz_frequency));
}

}  // namespace
}  // namespace frictionlab::dynamics
