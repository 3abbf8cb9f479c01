// Input validation shared by every law (friction/law.h), and the registry of laws by name.

#include "friction/law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "friction/registry.h"
#include "friction/reference_laws.h"

namespace frictionlab::friction {
namespace law_test {

// exact-reference (GSL) lives in its own library: registered here, as the command does.
[[maybe_unused]] const bool kReferenceLawsRegistered = (friction::register_reference_laws(), true);

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The message of the std::invalid_argument thrown for `in`, or "" if none.
std::string rejection(const ContactInput& in) {
  try {
    validate(in);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Validate, AcceptsTheBoundaryOfTheDomain) {
  EXPECT_EQ(rejection({0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0}), "");       // rest, circle, no load
  EXPECT_EQ(rejection({1.0, -5.0, 1.0, 1e-6, -7.0, 3.0, 2.0}), "");     // thin, negative psi
}

TEST(Validate, NamesTheValueAndTheRule) {
  const ContactInput good{1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 0.1};
  struct Case {
    ContactInput in;
    std::string expect;
  };
  auto with = [&](auto edit) {
    ContactInput in = good;
    edit(in);
    return in;
  };
  const Case cases[] = {
      {with([](auto& c) { c.U = -1e-12; }), "U = -1e-12 is invalid"},
      {with([](auto& c) { c.U = kNaN; }), "U = nan is invalid: it must be a finite number"},
      {with([](auto& c) { c.Omega = kInf; }), "Omega = inf"},
      {with([](auto& c) { c.a = 0.0; }), "a = 0 is invalid: the major semi-axis must be > 0 m"},
      {with([](auto& c) { c.b = -1.0; }), "b = -1 is invalid"},
      {with([](auto& c) { c.b = 1.5; }), "b = 1.5 is invalid: the minor semi-axis must not exceed"},
      // Values print round-trip: b one ulp above a = 1 is not shown as 1.
      {with([](auto& c) { c.b = 1.0000000000000002; }),
       "b = 1.0000000000000002 is invalid: the minor semi-axis must not exceed the major semi-axis a = 1 m"},
      {with([](auto& c) { c.psi = kNaN; }), "psi = nan"},
      {with([](auto& c) { c.N = -2.0; }), "N = -2 is invalid: the normal force must be >= 0 N"},
      {with([](auto& c) { c.k = -0.1; }), "k = -0.1 is invalid"},
  };
  for (const auto& c : cases) {
    const auto msg = rejection(c.in);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << "message: '" << msg << "'";
  }
}

TEST(Validate, RejectsScalesOutsideTheDoubleRange) {
  // Every input finite, but a scale every law needs is not a double: the largest force k N, the
  // largest moment k N a, or the axis ratio b/a (a thinner patch than the smallest normal double
  // is a line).
  const ContactInput good{1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 0.1};
  struct Case {
    ContactInput in;
    std::string expect;
  };
  auto with = [&](auto edit) {
    ContactInput in = good;
    edit(in);
    return in;
  };
  const Case cases[] = {
      {with([](auto& c) { c.k = 1e200; c.N = 1e200; }), "k N = inf overflows"},
      {with([](auto& c) { c.k = 1e200; c.N = 1e100; c.a = 1e10; c.b = 1.0; }), "k N a = inf overflows"},
      {with([](auto& c) { c.a = 1e300; c.b = 1e-300; }), "b = 1e-300 is invalid: the axis ratio b/a = 0 ("},
      {with([](auto& c) { c.a = 1.0; c.b = 1e-310; }), "is below the smallest normal double, 2.2250738585072014e-308"},
  };
  for (const auto& c : cases) {
    const auto msg = rejection(c.in);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << "message: '" << msg << "'";
  }
  // At the edge of the range: accepted.
  EXPECT_EQ(rejection(with([](auto& c) { c.k = 1e150; c.N = 1e150; c.a = 1e-10; c.b = 1e-10; })), "");
  EXPECT_EQ(rejection(with([](auto& c) { c.a = 1.0; c.b = std::numeric_limits<double>::min(); })), "");
  EXPECT_EQ(rejection(with([](auto& c) { c.k = 1e-200; c.N = 1e-200; })), "");  // k N underflows: no friction
}

TEST(ContactInput, TakesThePatchAngleAsADouble) {
  ContactInput in{1.0, 2.0, 1.0, 0.5, 0.3, 1.0, 0.1};
  EXPECT_EQ(in.psi.radians(), 0.3);
  in.psi = -0.7;
  EXPECT_EQ(in.psi.radians(), -0.7);
  EXPECT_FALSE(in.psi.is_direction());
  EXPECT_EQ(ContactInput{}.psi.radians(), 0.0);
}

TEST(Validate, AcceptsADirectionUnitToRounding) {
  ContactInput in{1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 0.1};
  for (const double theta : {0.0, 0.3, -2.0, 3.0}) {
    in.psi = PatchAngle::from_direction(std::cos(theta), std::sin(theta));
    EXPECT_EQ(rejection(in), "") << "theta = " << theta;
  }
  in.psi = PatchAngle::from_direction(0.6, -0.8);
  EXPECT_EQ(rejection(in), "");
  // |c^2 + s^2 - 1| = 8e-13 and 1.2e-12 about the tolerance 1e-12.
  in.psi = PatchAngle::from_direction(1.0 + 4e-13, 0.0);
  EXPECT_EQ(rejection(in), "");
  in.psi = PatchAngle::from_direction(1.0 + 6e-13, 0.0);
  EXPECT_NE(rejection(in), "");
}

TEST(Validate, RefusesADirectionThatIsNotUnitNamingItAndTheRule) {
  ContactInput in{1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 0.1};
  in.psi = PatchAngle::from_direction(0.6, 0.81);
  const std::string msg = rejection(in);
  EXPECT_NE(msg.find("friction input psi = (cos, sin) = (0.6, 0.81) is invalid"), std::string::npos) << msg;
  EXPECT_NE(msg.find("|cos^2 + sin^2 - 1| <= 1e-12"), std::string::npos) << msg;
  in.psi = PatchAngle::from_direction(0.0, 0.0);
  EXPECT_NE(rejection(in).find("(cos, sin) = (0, 0) is invalid"), std::string::npos) << rejection(in);
}

TEST(Validate, RefusesANonFiniteDirection) {
  ContactInput in{1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 0.1};
  in.psi = PatchAngle::from_direction(kNaN, 0.0);
  EXPECT_NE(rejection(in).find("friction input psi = (cos, sin) = (nan, 0) is invalid: the direction of the major axis must be finite"),
            std::string::npos)
      << rejection(in);
  in.psi = PatchAngle::from_direction(1.0, kInf);
  EXPECT_NE(rejection(in).find("(cos, sin) = (1, inf) is invalid"), std::string::npos) << rejection(in);
}

TEST(Validate, RefusesANonFiniteAngle) {
  ContactInput in{1.0, 1.0, 1.0, 0.5, 0.0, 1.0, 0.1};
  in.psi = kInf;
  EXPECT_NE(rejection(in).find("friction input psi = inf is invalid: it must be a finite number"), std::string::npos)
      << rejection(in);
}

TEST(Registry, EveryListedLawIsMadeByItsNameAndValidatesInput) {
  const auto laws = list_laws();
  ASSERT_GE(laws.size(), 3u);
  for (const auto& info : laws) {
    SCOPED_TRACE(info.name);
    EXPECT_FALSE(info.summary.empty());
    const auto law = make_law(info.name);
    EXPECT_EQ(law->name(), info.name);
    EXPECT_THROW((void)law->evaluate({1.0, 1.0, 1.0, 2.0, 0.0, 1.0, 0.1}), std::invalid_argument);
  }
}

TEST(Registry, ExactlyOneReferenceLawAndItIsExact) {
  // The reference is a registry fact, not a name callers repeat: `exact`, listed first.
  const auto laws = list_laws();
  int references = 0;
  for (const auto& info : laws) references += info.reference ? 1 : 0;
  EXPECT_EQ(references, 1);
  ASSERT_FALSE(laws.empty());
  EXPECT_TRUE(laws.front().reference);
  EXPECT_EQ(reference_law_name(), "exact");
  EXPECT_EQ(make_reference_law()->name(), "exact");
  EXPECT_FALSE(law_info("exact").slow);
}

TEST(Registry, FactsAreTheLawsOwn) {
  // has_poles and promises come from the law itself; slow marks the GSL cross-check only.
  for (const auto& info : list_laws()) {
    SCOPED_TRACE(info.name);
    const auto law = make_law(info.name);
    EXPECT_EQ(info.has_poles, law->has_poles());
    EXPECT_EQ(info.promises.tolerance, law->promises().tolerance);
    EXPECT_EQ(info.promises.dissipative, law->promises().dissipative);
    const LawInfo again = law_info(info.name);
    EXPECT_EQ(again.slow, info.slow);
    EXPECT_EQ(again.reference, info.reference);
  }
  EXPECT_TRUE(law_info("exact-reference").slow);
  EXPECT_TRUE(law_info("pade-printed").has_poles);
  EXPECT_FALSE(law_info("pade-reconstructed").has_poles);
  EXPECT_THROW((void)law_info("nope"), std::invalid_argument);
}

TEST(Registry, UnknownNameListsTheKnownOnes) {
  try {
    (void)make_law("pade");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("unknown friction law 'pade'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("exact"), std::string::npos) << msg;
    EXPECT_NE(msg.find("pade-printed"), std::string::npos) << msg;
  }
}

TEST(Registry, NoLoadMeansNoFrictionForEveryLaw) {
  // N = 0: no law may produce friction.
  for (const auto& info : list_laws()) {
    const auto f = make_law(info.name)->evaluate({0.4, -2.0, 1.0, 0.3, 0.5, 0.0, 0.3});
    EXPECT_EQ(f.F1, 0.0) << info.name;
    EXPECT_EQ(f.F2, 0.0) << info.name;
    EXPECT_EQ(f.M, 0.0) << info.name;
  }
}

}  // namespace
}  // namespace frictionlab::friction
