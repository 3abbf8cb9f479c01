#include "friction/support/json.h"

#include <gtest/gtest.h>

#include <limits>

namespace frictionlab::support {
namespace json_test {

TEST(SupportJson, KeepsKeysInTheOrderAdded) {
  Json j;
  j["zeta"] = 1;
  j["alpha"] = 2;
  const std::string text = json_text(j);
  EXPECT_LT(text.find("zeta"), text.find("alpha")) << text;
}

TEST(SupportJson, NonFiniteNumbersAreNull) {
  Json j;
  j["nan"] = std::numeric_limits<double>::quiet_NaN();
  j["inf"] = -std::numeric_limits<double>::infinity();
  const Json back = Json::parse(json_text(j));
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_TRUE(back["inf"].is_null());
}

TEST(SupportJson, NumbersReadBackExactly) {
  Json j;
  const double values[] = {0.1, 1.0 / 3.0, 1e-300, 2.2250738585072014e-308, 123456.789};
  for (const double v : values) j["v"].push_back(v);
  const Json back = Json::parse(json_text(j));
  for (std::size_t i = 0; i < std::size(values); ++i) EXPECT_EQ(back["v"][i].get<double>(), values[i]);
}

TEST(SupportJson, InvalidUtf8IsReplacedNotThrown) {
  Json j;
  j["source"] = std::string("scen\xff" "ario.toml");
  std::string text;
  ASSERT_NO_THROW(text = json_text(j));
  EXPECT_EQ(Json::parse(text)["source"].get<std::string>(), "scen\xEF\xBF\xBD" "ario.toml");
}

TEST(SupportJson, EndsWithANewline) {
  const std::string text = json_text(Json::object());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace frictionlab::support
