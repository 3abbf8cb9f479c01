#include "friction/support/number_format.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>

namespace frictionlab::support {
namespace number_format_test {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Reads text back with the C library's own parser, independent of std::to_chars.
double read_back(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

TEST(SupportNumberFormat, ShortestIsShortForDecimalValues) {
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(1e-300), "1e-300");
  EXPECT_EQ(shortest(2.0), "2");
  EXPECT_EQ(shortest(-0.25), "-0.25");
  EXPECT_EQ(shortest(0.1 + 0.2), "0.30000000000000004");  // 0.1 + 0.2 is not the double nearest 0.3
}

TEST(SupportNumberFormat, ShortestReadsBackBitForBit) {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 20000; ++i) {
    const double x = std::bit_cast<double>(rng());
    if (!std::isfinite(x)) continue;
    const std::string text = shortest(x);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read_back(text)), std::bit_cast<std::uint64_t>(x)) << text;
  }
  for (const double x : {std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::min(), 0.0, 1.0 / 3.0})
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read_back(shortest(x))), std::bit_cast<std::uint64_t>(x)) << x;
}

TEST(SupportNumberFormat, NoTextIsANegativeZero) {
  // -0.0 prints as "0" everywhere (it reads back equal, 0.0 == -0.0); so does a negative value
  // that rounds to zero at the precision asked for, as printf would print "-0.00".
  EXPECT_EQ(shortest(-0.0), "0");
  std::string line = "x,";
  append_shortest(line, -0.0);
  EXPECT_EQ(line, "x,0");
  EXPECT_EQ(read_back(shortest(-0.0)), -0.0);
  EXPECT_EQ(message_number(-0.0), "0");
  EXPECT_EQ(significant(-0.0, 3), "0");
  line = "y,";
  append_significant(line, -0.0, 4);
  EXPECT_EQ(line, "y,0");
  EXPECT_EQ(fixed(-0.0, 2), "0.00");
  EXPECT_EQ(fixed(-0.001, 2), "0.00");
  EXPECT_EQ(fixed(-0.4, 0), "0");
  EXPECT_EQ(message_list(std::array<double, 2>{-0.0, -1.0}), "[0, -1]");
  // Negative values that do not round to zero keep their sign; so do the tiniest ones.
  EXPECT_EQ(fixed(-0.005001, 2), "-0.01");
  EXPECT_EQ(fixed(-0.6, 0), "-1");
  EXPECT_EQ(significant(-1e-300, 3), "-1e-300");
  EXPECT_EQ(shortest(-std::numeric_limits<double>::denorm_min()), "-5e-324");
  EXPECT_EQ(shortest(-0.25), "-0.25");
  EXPECT_EQ(without_negative_zero(-0.0), 0.0);
  EXPECT_FALSE(std::signbit(without_negative_zero(-0.0)));
  EXPECT_TRUE(std::signbit(without_negative_zero(-2.0)));
  EXPECT_TRUE(std::isnan(without_negative_zero(kNaN)));
}

TEST(SupportNumberFormat, AppendShortestAppends) {
  std::string line = "t=";
  append_shortest(line, 0.5);
  line += ',';
  append_shortest(line, -kInf);
  EXPECT_EQ(line, "t=0.5,-inf");
}

TEST(SupportNumberFormat, NonFiniteValuesHaveOneSpelling) {
  for (const auto& f : {shortest, message_number}) {
    EXPECT_EQ(f(kNaN), "nan");
    EXPECT_EQ(f(-kNaN), "nan");
    EXPECT_EQ(f(kInf), "inf");
    EXPECT_EQ(f(-kInf), "-inf");
  }
  EXPECT_EQ(fixed(-kNaN, 2), "nan");
  EXPECT_EQ(significant(kInf, 3), "inf");
}

TEST(SupportNumberFormat, MessageNumbersHaveTenSignificantDigits) {
  EXPECT_EQ(message_number(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(message_number(2.0), "2");
  EXPECT_EQ(message_number(1e300), "1e+300");
  EXPECT_EQ(message_number(123456789012.0), "1.23456789e+11");
}

TEST(SupportNumberFormat, SignificantAndFixedFollowPrintf) {
  EXPECT_EQ(significant(1234.5678, 3), "1.23e+03");
  EXPECT_EQ(significant(1e-9 * 0.1, 3), "1e-10");
  EXPECT_EQ(significant(0.000123456, 4), "0.0001235");
  EXPECT_EQ(fixed(2.5, 1), "2.5");
  EXPECT_EQ(fixed(2.0 / 3.0, 2), "0.67");
  EXPECT_EQ(fixed(1e20, 0), "100000000000000000000");
  EXPECT_EQ(fixed(-1e308, 17).substr(0, 5), "-1000");  // no truncation at the buffer's end
}

TEST(SupportNumberFormat, SignificantMatchesPrintf) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int i = 0; i < 2000; ++i) {
    const double x = std::pow(10.0, exponent(rng)) * (i % 2 ? -1.0 : 1.0);
    for (const int digits : {1, 3, 4, 10, 17}) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.*g", digits, x);
      EXPECT_EQ(significant(x, digits), buf);
      std::string appended = "x";
      append_significant(appended, x, digits);
      EXPECT_EQ(appended, "x" + std::string(buf));
    }
  }
}

TEST(SupportNumberFormat, MessageListBrackets) {
  const std::array<double, 3> v = {0.0, -1.5, 1e300};
  EXPECT_EQ(message_list(v), "[0, -1.5, 1e+300]");
  EXPECT_EQ(message_list({}), "[]");
}

}  // namespace
}  // namespace frictionlab::support
