// [contact] patch and the stiffness of the Hertz contact model (dynamics/contact/patch_model.h), read
// from scenarios.
#include "dynamics/contact/patch_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/shapes/contact_geometry.h"
#include "dynamics/contact/hertz_patch.h"
#include "dynamics/body/scenario.h"

namespace frictionlab::dynamics {
namespace patch_model_test {

const char* kSphere = R"(
[body]
profile = "sphere"
radius = 0.05
mass = 1
[contact]
k = 0.2
lambda = 1e7
[initial]
gamma = [0, 0, 1]
eps = "static"
[run]
t_end = 1
)";

std::string without_lambda() {
  std::string t = kSphere;
  return t.replace(t.find("lambda = 1e7\n"), 13, "");
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides) {
  try {
    (void)parse_scenario(text, "test.toml", overrides);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(DynPatchModel, SectionIsTheDefault) {
  const Scenario s = parse_scenario(kSphere, "test.toml");
  EXPECT_EQ(s.contact.patch, PatchModel::section);
  EXPECT_EQ(s.contact.lambda, 1e7);
  EXPECT_EQ(s.contact.E_star, 0.0);
}

TEST(DynPatchModel, HertzMatchesLambdaAtTheReferenceOrientation) {
  // A sphere: lambda = (4/3) E* sqrt(R) everywhere.
  const Scenario s = parse_scenario(kSphere, "test.toml", {"contact.patch=hertz"});
  EXPECT_EQ(s.contact.patch, PatchModel::hertz);
  EXPECT_EQ(s.contact.lambda, 1e7);
  EXPECT_NEAR(s.contact.E_star, 0.75e7 / std::sqrt(0.05), 1e-12 * s.contact.E_star);
  // The egg at its equator-most contact (gamma3 = 0): Hertz's stiffness there is lambda.
  std::string egg = kSphere;
  const std::string sphere_body = "profile = \"sphere\"\nradius = 0.05\nmass = 1";
  egg.replace(egg.find(sphere_body), sphere_body.size(), "profile = \"egg-printed\"\nmass = 2");
  const Scenario e = parse_scenario(egg, "egg.toml", {"contact.patch=hertz", "contact.lambda_gamma3=0"});
  const ContactGeometry geometry(e.body.axisymmetric->profile, e.body.axisymmetric->com);
  EXPECT_NEAR(HertzNormalContact(e.contact.E_star).stiffness(geometry, 0.0), 1e7, 1e-12 * 1e7);
  EXPECT_GT(std::abs(HertzNormalContact(e.contact.E_star).stiffness(geometry, 1.0) - 1e7), 1e5);
}

TEST(DynPatchModel, HertzWithElasticConstantsDerivesLambda) {
  const Scenario s = parse_scenario(without_lambda(), "test.toml",
                                    {"contact.patch=hertz", "contact.E1=2e9", "contact.nu1=0.4", "contact.E2=inf",
                                     "contact.nu2=0.3"});
  const double E_star = 2e9 / (1.0 - 0.16);
  EXPECT_NEAR(s.contact.E_star, E_star, 1e-15 * E_star * 4);
  EXPECT_NEAR(s.contact.lambda, 4.0 / 3.0 * E_star * std::sqrt(0.05), 1e-12 * s.contact.lambda);
  // The resolved scenario reads back as the same one.
  const Scenario again = parse_scenario(s.resolved_toml, "again.toml");
  EXPECT_EQ(again.contact.E_star, s.contact.E_star);
  EXPECT_EQ(again.contact.lambda, s.contact.lambda);
}

TEST(DynPatchModel, BadContactModelValuesNameTheirKey) {
  const std::vector<std::string> moduli = {"contact.E1=2e9", "contact.nu1=0.4", "contact.E2=inf", "contact.nu2=0.3"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> o = {"contact.patch=hertz"};
    o.insert(o.end(), moduli.begin(), moduli.end());
    o.insert(o.end(), extra.begin(), extra.end());
    return o;
  };
  struct Case {
    std::string text;
    std::vector<std::string> overrides;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {kSphere, {"contact.patch=dupin"}, "--set contact.patch=dupin: contact.patch = 'dupin' is invalid: it is not a known contact model; known: section, hertz"},
      {kSphere, {"contact.E1=2e9"}, "--set contact.E1=2e9: contact.E1 is only used with contact.patch = \"hertz\""},
      {kSphere, {"contact.lambda_gamma3=0"}, "contact.lambda_gamma3 is only used with contact.patch = \"hertz\""},
      {kSphere, with({}), "test.toml: contact.lambda and the elastic constants"},
      {without_lambda(), with({"contact.E1=-1e9"}), "--set contact.E1=-1e9: contact.E1 = -1000000000 is invalid: Young's modulus must be > 0 Pa"},
      {without_lambda(), with({"contact.nu1=0.7"}), "--set contact.nu1=0.7: contact.nu1 = 0.7 is invalid: Poisson's ratio must lie in (-1, 0.5]"},
      {without_lambda(), with({"contact.nu2=-1"}), "contact.nu2 = -1 is invalid: Poisson's ratio must lie in (-1, 0.5]"},
      {without_lambda(), {"contact.patch=hertz", "contact.E1=2e9"}, "contact.nu1 is required when any of contact.E1, nu1, E2, nu2 is given"},
      {without_lambda(), {"contact.patch=hertz"}, "contact.lambda is required (or the elastic constants"},
      {without_lambda(), {}, "test.toml: contact.lambda is required"},
      {kSphere, {"contact.patch=hertz", "contact.lambda_gamma3=1.5"}, "contact.lambda_gamma3 = 1.5 is invalid: it is the third component"},
      {kSphere, {"contact.patch=hertz", "contact.lambda=-5"}, "contact.lambda = -5 is invalid"},
  };
  for (const Case& c : cases) {
    const std::string m = error_of(c.text, c.overrides);
    EXPECT_NE(m.find(c.expected), std::string::npos) << "expected: " << c.expected << "\ngot:      " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
