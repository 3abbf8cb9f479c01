// Input validation shared by every law (friction/law.h), and the registry of laws by name.

#include "friction/law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "friction/registry.h"

namespace frictionlab::friction {
namespace {

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
      {with([](auto& c) { c.U = -1e-12; }), "U = -9.9999999999999998e-13 is invalid"},
      {with([](auto& c) { c.U = kNaN; }), "U = nan is invalid: it must be a finite number"},
      {with([](auto& c) { c.Omega = kInf; }), "Omega = inf"},
      {with([](auto& c) { c.a = 0.0; }), "a = 0 is invalid: the major semi-axis must be > 0 m"},
      {with([](auto& c) { c.b = -1.0; }), "b = -1 is invalid"},
      {with([](auto& c) { c.b = 1.5; }), "b = 1.5 is invalid: the minor semi-axis must not exceed"},
      {with([](auto& c) { c.psi = kNaN; }), "psi = nan"},
      {with([](auto& c) { c.N = -2.0; }), "N = -2 is invalid: the normal force must be >= 0 N"},
      {with([](auto& c) { c.k = -0.1; }), "k = -0.10000000000000001 is invalid"},
  };
  for (const auto& c : cases) {
    const auto msg = rejection(c.in);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << "message: '" << msg << "'";
  }
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
