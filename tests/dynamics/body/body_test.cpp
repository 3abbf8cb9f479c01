#include "dynamics/body/body.h"

#include <gtest/gtest.h>

#include <string>

namespace frictionlab::dynamics {
namespace {

// docs/model.md §6 prints 3 significant digits.
constexpr double kPrintedTol = 5e-5;

std::string error_of(const BodySpec& spec) {
  try {
    (void)make_body(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

BodySpec egg(const std::string& preset) {
  BodySpec s;
  s.preset = preset;
  s.mass = 2.0;
  return s;
}

TEST(DynBody, EggPrintedPutsTheCentreOfMassAtTheOrigin) {
  const Body b = make_body(egg("egg-printed"));
  EXPECT_EQ(b.com, 0.0);
  EXPECT_NEAR(b.A, 0.0502, kPrintedTol);
  EXPECT_NEAR(b.C, 0.0559, kPrintedTol);
}

TEST(DynBody, EggHomogeneousPutsTheCentreOfMassAtTheCentroid) {
  const Body b = make_body(egg("egg-homogeneous"));
  EXPECT_NEAR(b.com, 0.0705, kPrintedTol);
  EXPECT_NEAR(b.A, 0.0403, kPrintedTol);
  EXPECT_NEAR(b.C, 0.0559, kPrintedTol);
}

TEST(DynBody, OverridesReplaceEachMassProperty) {
  BodySpec s = egg("egg-homogeneous");
  s.com = 0.01;
  const Body b1 = make_body(s);
  EXPECT_NEAR(b1.A, b1.homogeneous.transverse_about(0.01), 1e-15);  // A follows com by parallel axes
  s.A = 0.05;
  s.C = 0.06;
  const Body b2 = make_body(s);
  EXPECT_EQ(b2.A, 0.05);
  EXPECT_EQ(b2.C, 0.06);
  EXPECT_EQ(b2.com, 0.01);
}

TEST(DynBody, ChiTwoCoefficientsMakeABody) {
  BodySpec s;
  s.chi2 = {0.01, 0.0, -1.0};  // sphere R = 0.1
  s.mass = 1.0;
  const Body b = make_body(s);
  EXPECT_NEAR(b.C, 0.4 * 0.01, 1e-15);
  EXPECT_NEAR(b.com, 0.0, 1e-15);
}

TEST(DynBody, ErrorsNameTheKeyAndTheRule) {
  BodySpec s = egg("egg-printed");
  s.mass = -1.0;
  EXPECT_NE(error_of(s).find("body.mass = -1"), std::string::npos) << error_of(s);

  s = egg("egg-printed");
  s.com = 0.3;
  EXPECT_NE(error_of(s).find("body.com = 0.3"), std::string::npos) << error_of(s);

  s = egg("egg-printed");
  s.A = 0.01;  // C = 0.0559 > 2A
  EXPECT_NE(error_of(s).find("C <= 2A"), std::string::npos) << error_of(s);

  s = egg("egg-printed");
  s.radius = 0.1;
  EXPECT_NE(error_of(s).find("body.radius is only used by the 'sphere' preset"), std::string::npos) << error_of(s);

  s = egg("cube");
  EXPECT_NE(error_of(s).find("body.profile = 'cube' is not a known preset"), std::string::npos) << error_of(s);

  s = egg("sphere");
  EXPECT_NE(error_of(s).find("body.radius is required"), std::string::npos) << error_of(s);

  s = egg("sphere");
  s.chi2 = {1.0, 0.0, -1.0};
  EXPECT_NE(error_of(s).find("both given"), std::string::npos) << error_of(s);
}

}  // namespace
}  // namespace frictionlab::dynamics
