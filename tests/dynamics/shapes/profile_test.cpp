#include "dynamics/shapes/profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace frictionlab::dynamics {
namespace profile_test {

// Poles are polished roots of P: exact to a few ulps of the body length.
constexpr double kPoleTol = 1e-14;

std::string error_of(const std::vector<double>& chi2) {
  try {
    Profile p(chi2, "body.chi2");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DynProfile, SpherePresetHasPolesAtPlusMinusR) {
  const Profile s = Profile::sphere(0.1);
  EXPECT_NEAR(s.z_lo(), -0.1, kPoleTol);
  EXPECT_NEAR(s.z_hi(), 0.1, kPoleTol);
  EXPECT_NEAR(s.max_radius(), 0.1, 1e-9);  // sampled maximum: Chebyshev nodes include the centre
}

TEST(DynProfile, SpheroidPresetHasPolesAtPlusMinusPolarSemiAxis) {
  const Profile s = Profile::spheroid(0.2, 0.05);
  EXPECT_NEAR(s.z_lo(), -0.05, kPoleTol);
  EXPECT_NEAR(s.z_hi(), 0.05, kPoleTol);
}

TEST(DynProfile, PaperEggIsConvexBetweenItsTwoLowerRoots) {
  const Profile egg = Profile::paper_egg();
  EXPECT_NEAR(egg.z_lo(), -0.1, kPoleTol);
  EXPECT_NEAR(egg.z_hi(), 0.252, kPoleTol);
  // docs/model.md §6: about 0.53 m wide and 0.352 m long.
  EXPECT_NEAR(2.0 * egg.max_radius(), 0.529, 1e-3);
  EXPECT_NEAR(egg.length(), 0.352, kPoleTol);
  const auto& c = egg.chi2().coefficients();
  ASSERT_EQ(c.size(), 4u);
  EXPECT_NEAR(c[0], 0.06048, 1e-15);
  EXPECT_NEAR(c[1], 0.3144, 1e-15);
  EXPECT_NEAR(c[2], -2.704, 1e-15);
  EXPECT_NEAR(c[3], 2.0, 1e-15);
}

TEST(DynProfile, RejectsAProfileWithoutRealRoots) {
  const std::string e = error_of({1.0, 0.0, 1.0});
  EXPECT_NE(e.find("body.chi2 = [1, 0, 1]"), std::string::npos) << e;
  EXPECT_NE(e.find("positive on a bounded interval"), std::string::npos) << e;
}

TEST(DynProfile, RejectsANonConvexPeanut) {
  // (1 - z^2)(0.3 + z^2): a waist at z = 0.
  const std::string e = error_of({0.3, 0.0, 0.7, 0.0, -1.0});
  EXPECT_NE(e.find("not strictly convex"), std::string::npos) << e;
}

TEST(DynProfile, RejectsAConicalPole) {
  // (1 - z)^2 (1 + z): the pole at z = 1 is a double root.
  const std::string e = error_of({1.0, -1.0, -1.0, 1.0});
  EXPECT_NE(e.find("not a valid body profile"), std::string::npos) << e;
  EXPECT_TRUE(e.find("multiple root") != std::string::npos || e.find("not strictly convex") != std::string::npos)
      << e;
}

TEST(DynProfile, RejectsSeveralBodies) {
  // -(z^2 - 1)(z^2 - 4)(z^2 - 9) > 0 on (-1, 1), (2, 3) and (-3, -2).
  const std::string e = error_of({36.0, 0.0, -49.0, 0.0, 14.0, 0.0, -1.0});
  EXPECT_NE(e.find("several bounded intervals"), std::string::npos) << e;
}

TEST(DynProfile, RejectsLowDegreeAndNonFiniteCoefficients) {
  EXPECT_NE(error_of({1.0, 2.0}).find("degree >= 2"), std::string::npos);
  EXPECT_NE(error_of({1.0, NAN, -1.0}).find("finite"), std::string::npos);
  EXPECT_THROW((void)Profile::sphere(-1.0), std::invalid_argument);
  EXPECT_THROW((void)Profile::spheroid(0.1, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics
