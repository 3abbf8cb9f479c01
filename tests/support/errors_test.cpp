#include "friction/support/errors.h"

#include <gtest/gtest.h>

#include <array>
#include <limits>

namespace frictionlab::support {
namespace errors_test {

TEST(SupportErrors, NamesKeyValueAndRule) {
  const InvalidValue e = invalid_value("body.mass", 1e-300, "it must be >= 1e-06 kg");
  EXPECT_STREQ(e.what(), "body.mass = 1e-300 is invalid: it must be >= 1e-06 kg");
  EXPECT_EQ(e.key(), "body.mass");
}

TEST(SupportErrors, IsAnInvalidArgument) {
  EXPECT_THROW(throw invalid_value("--jobs", -1LL, "it must be >= 0"), std::invalid_argument);
  try {
    throw invalid_value("--jobs", -1LL, "it must be >= 0");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--jobs = -1 is invalid: it must be >= 0");
  }
}

TEST(SupportErrors, QuotesStringsAndListsVectors) {
  EXPECT_STREQ(invalid_value("contact.law", std::string_view("fast"), "unknown law").what(),
               "contact.law = 'fast' is invalid: unknown law");
  const std::array<double, 3> omega = {0.0, 0.0, 1e300};
  EXPECT_STREQ(invalid_value("initial.omega", omega, "too fast").what(),
               "initial.omega = [0, 0, 1e+300] is invalid: too fast");
}

TEST(SupportErrors, PrintsNonFiniteValuesInOneSpelling) {
  EXPECT_STREQ(invalid_value("k", -std::numeric_limits<double>::quiet_NaN(), "finite").what(),
               "k = nan is invalid: finite");
  EXPECT_STREQ(invalid_value("k", -std::numeric_limits<double>::infinity(), "finite").what(),
               "k = -inf is invalid: finite");
}

TEST(SupportErrors, MessageFormKeepsTheKey) {
  const InvalidValue e("run.t_end", "run.t_end is required");
  EXPECT_STREQ(e.what(), "run.t_end is required");
  EXPECT_EQ(e.key(), "run.t_end");
}

TEST(SupportErrors, OneLineFoldsLineBreaksAndBlanks) {
  EXPECT_EQ(one_line("  The following argument was not expected:\n  frction\n\nRun with --help  "),
            "The following argument was not expected: frction Run with --help");
  EXPECT_EQ(one_line("plain"), "plain");
  EXPECT_EQ(one_line("\n\t \n"), "");
}

}  // namespace
}  // namespace frictionlab::support
