// The value checks every option gets (dynamics/cli/option_values.h), on an application of the
// same shape as `frictionlab`'s: what CLI11 alone clamps, wraps, reads as another number or takes
// as "not given" is refused with one message naming the option, the value and the rule.
#include "dynamics/cli/option_values.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace frictionlab::cli {
namespace option_values_test {

struct Options {
  long long count = 0;
  long steps = 0;
  unsigned long long size = 0;
  double k = -1.0;
  std::optional<double> u;
  std::vector<double> list;
  std::string law = "default";
  std::string file;
  bool flag = false;
};

// Parses `args` after "frictionlab run" with every option checked; the error message, or "" if
// the line was accepted.
std::string parse(std::vector<std::string> args, Options& o) {
  CLI::App app{"test"};
  auto* cmd = app.add_subcommand("run", "a command");
  cmd->add_option("file", o.file);
  cmd->add_option("--count", o.count);
  cmd->add_option("--max-steps", o.steps);
  cmd->add_option("--size", o.size);
  cmd->add_option("--k", o.k);
  cmd->add_option("--U", o.u);
  cmd->add_option("--list", o.list)->delimiter(',');
  cmd->add_option("--law", o.law);
  cmd->add_flag("--flag", o.flag);
  check_option_values(app);
  args.insert(args.begin(), {"frictionlab", "run"});
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const std::invalid_argument& e) {
    return e.what();
  } catch (const CLI::Error& e) {
    return std::string("CLI11: ") + e.what();
  }
  return "";
}

std::string error_of(const std::vector<std::string>& args) {
  Options o;
  return parse(args, o);
}

TEST(CliOptionValues, AnIntegerBeyondSixtyFourBitsIsRefusedNotClamped) {
  EXPECT_EQ(error_of({"--max-steps", "99999999999999999999999"}),
            "--max-steps = '99999999999999999999999' is invalid: it must be an integer from -9223372036854775808 to "
            "9223372036854775807");
  EXPECT_NE(error_of({"--count", "-99999999999999999999999"}).find("--count = '-99999999999999999999999' is invalid"),
            std::string::npos);
  Options o;
  ASSERT_EQ(parse({"--count", "9223372036854775807", "--max-steps", "-9223372036854775808"}, o), "");
  EXPECT_EQ(o.count, std::numeric_limits<long long>::max());
  EXPECT_EQ(o.steps, std::numeric_limits<long>::min());
}

TEST(CliOptionValues, IntegersAreDecimal) {
  // CLI11 alone reads 010 as 8 (octal) and 0x10 as 16.
  for (const std::string text : {"0x10", "1e6", "12abc", "", "+", "1.5", "- 1"})
    EXPECT_NE(error_of({"--count", text}).find("--count = '" + text + "' is invalid: it must be an integer in decimal"),
              std::string::npos)
        << text;
  Options o;
  ASSERT_EQ(parse({"--count", "010", "--max-steps", "-08", "--size", "000"}, o), "");
  EXPECT_EQ(o.count, 10);
  EXPECT_EQ(o.steps, -8);
  EXPECT_EQ(o.size, 0u);
  ASSERT_EQ(parse({"--count", "+12"}, o), "");
  EXPECT_EQ(o.count, 12);
}

TEST(CliOptionValues, AWholeNumberHasNoSignAndIsNotWrapped) {
  // CLI11 alone wraps -1 to 18446744073709551615.
  EXPECT_NE(error_of({"--size", "-1"}).find("--size = '-1' is invalid: it must be a whole number"), std::string::npos);
  EXPECT_NE(error_of({"--size", "18446744073709551616"}).find("from 0 to 18446744073709551615"), std::string::npos);
  Options o;
  ASSERT_EQ(parse({"--size", "18446744073709551615"}, o), "");
  EXPECT_EQ(o.size, std::numeric_limits<unsigned long long>::max());
}

TEST(CliOptionValues, ANumberThatUnderflowsOrOverflowsADoubleIsRefused) {
  // CLI11 alone reads 1e-400 as 0 (through a long double) and 1e400 as inf.
  EXPECT_EQ(error_of({"--k", "1e-400"}),
            "--k = '1e-400' is invalid: it underflows a double: a number must be 0 or of magnitude from "
            "2.2250738585072014e-308 to 1.7976931348623157e+308");
  EXPECT_NE(error_of({"--k", "1e400"}).find("--k = '1e400' is invalid: it overflows a double"), std::string::npos);
  EXPECT_NE(error_of({"--k", "-1e400"}).find("it overflows"), std::string::npos);
  EXPECT_NE(error_of({"--k", "4.9e-324"}).find("it underflows"), std::string::npos) << "subnormal: precision lost";
  EXPECT_NE(error_of({"--U", "1e-400"}).find("--U = '1e-400' is invalid"), std::string::npos);
  EXPECT_NE(error_of({"--list", "1,1e-400"}).find("--list = '1e-400' is invalid"), std::string::npos);
}

TEST(CliOptionValues, NumbersInRangeAreReadExactly) {
  Options o;
  ASSERT_EQ(parse({"--k", "2.2250738585072014e-308", "--U", "-0", "--list", "0,1.7976931348623157e308,0.1"}, o), "");
  EXPECT_EQ(o.k, DBL_MIN);
  ASSERT_TRUE(o.u.has_value());
  EXPECT_EQ(*o.u, 0.0);
  EXPECT_EQ(o.list, (std::vector<double>{0.0, DBL_MAX, 0.1}));
}

TEST(CliOptionValues, AnEmptyValueIsRefusedNotTakenForTheDefault) {
  // `simulate --law ''` ran the scenario's own law, as if --law had not been given.
  EXPECT_EQ(error_of({"--law", ""}),
            "--law = '' is invalid: it is empty: give a value, or leave the option out for its default");
  EXPECT_NE(error_of({""}).find("file = '' is invalid: it is empty"), std::string::npos);
  Options o;
  ASSERT_EQ(parse({"x.toml", "--law", "exact", "--flag"}, o), "");
  EXPECT_EQ(o.law, "exact");
  EXPECT_TRUE(o.flag);
}

TEST(CliOptionValues, AnIntOptionMustFitAnInt) {
  EXPECT_EQ(int_option("--jobs", 2147483647LL), 2147483647);
  EXPECT_EQ(int_option("--jobs", -2147483648LL), -2147483648);
  try {
    (void)int_option("--jobs", 3000000000LL);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--jobs = 3000000000 is invalid: it must be from -2147483648 to 2147483647");
  }
}

}  // namespace
}  // namespace frictionlab::cli
