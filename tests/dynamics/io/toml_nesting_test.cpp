// The nesting rule of TOML input (dynamics/io/toml_nesting.h): depths counted by hand on small texts,
// and documents nested far beyond the limit refused with std::invalid_argument naming the rule,
// where toml++ alone recursed out of the stack (a segmentation fault) on each of them.
#include "dynamics/io/toml_nesting.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dynamics/body/scenario.h"

namespace frictionlab::dynamics {
namespace toml_nesting_test {

// Far beyond the limit: at this depth toml++ 3.3 crashed the process.
constexpr int kDeep = 40000;

std::string repeated(const std::string& piece, int n, const std::string& separator = "") {
  std::string out;
  for (int i = 0; i < n; ++i) (out += (i ? separator : "")) += piece;
  return out;
}

// The four ways TOML nests, `n` levels deep each.
std::vector<std::pair<std::string, std::string>> nested_documents(int n) {
  return {
      {"table header", "[" + repeated("a", n - 1, ".") + "]\nx = 1\n"},
      {"dotted key", repeated("a", n, ".") + " = 1\n"},
      {"inline tables", "x = " + repeated("{a=", n - 1) + "1" + repeated("}", n - 1) + "\n"},
      {"nested arrays", "x = " + repeated("[", n - 1) + "1" + repeated("]", n - 1) + "\n"},
  };
}

TEST(DynTomlNesting, CountsEachKindOfLevel) {
  EXPECT_EQ(toml_nesting("").depth, 0);
  EXPECT_EQ(toml_nesting("x = 1").depth, 1);
  EXPECT_EQ(toml_nesting("a.b.c = 1").depth, 3);
  EXPECT_EQ(toml_nesting("[t]\nx = 1").depth, 2);
  EXPECT_EQ(toml_nesting("[t.u]\na.b = 1").depth, 4);
  EXPECT_EQ(toml_nesting("[[t]]\nx = 1").depth, 3);  // x in a table in the array t
  EXPECT_EQ(toml_nesting("x = [1, 2]").depth, 2);
  EXPECT_EQ(toml_nesting("x = [[1], [2, [3]]]").depth, 4);
  EXPECT_EQ(toml_nesting("x = {y = {z = 1}}").depth, 3);
  EXPECT_EQ(toml_nesting("x = [{a.b = 1}, {}]").depth, 4);
  EXPECT_EQ(toml_nesting("[t]\nx = [\n  [1],\n  [2],\n]\ny = 1").depth, 4);
  // A header resets the depth of the keys after it.
  EXPECT_EQ(toml_nesting("[a.b.c]\n[d]\nx = 1").depth, 3);
}

TEST(DynTomlNesting, StringsAndCommentsDoNotNest) {
  EXPECT_EQ(toml_nesting("x = \"[[[{{{a.b.c\"").depth, 1);
  EXPECT_EQ(toml_nesting("x = 'a.b[['\ny = \"\\\"[[\"").depth, 1);
  EXPECT_EQ(toml_nesting("\"a.b.c\" = 1").depth, 1);
  EXPECT_EQ(toml_nesting("[\"a.b\".c]\nx = 1").depth, 3);
  EXPECT_EQ(toml_nesting("x = 1 # [[[[ a.b.c\n# [a.b.c.d]").depth, 1);
  EXPECT_EQ(toml_nesting("x = \"\"\"\n[[[[\na.b.c = 1\n\"\"\"\ny = 2").depth, 1);
  EXPECT_EQ(toml_nesting("x = '''[[[[''''\ny = 2").depth, 1);
  EXPECT_EQ(toml_nesting("x = 1.5e3\nt = 1979-05-27T07:32:00Z").depth, 1);
}

TEST(DynTomlNesting, NamesTheLineOfTheDeepestPoint) {
  const TomlNesting n = toml_nesting("x = 1\n\n[a.b]\nc.d = 2\n");
  EXPECT_EQ(n.depth, 4);
  EXPECT_EQ(n.line, 4u);
}

TEST(DynTomlNesting, TheLimitItselfIsAccepted) {
  for (const auto& [kind, text] : nested_documents(kMaxTomlNesting)) {
    EXPECT_EQ(toml_nesting(text).depth, kMaxTomlNesting) << kind;
    EXPECT_NO_THROW(check_toml_nesting(text, "t.toml")) << kind;
  }
  for (const auto& [kind, text] : nested_documents(kMaxTomlNesting + 1))
    EXPECT_THROW(check_toml_nesting(text, "t.toml"), std::invalid_argument) << kind;
}

std::string scenario_error(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    (void)parse_scenario(text, "deep.toml", overrides);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(DynTomlNesting, ADeeplyNestedScenarioIsRefusedNotACrash) {
  for (const auto& [kind, text] : nested_documents(kDeep)) {
    const std::string error = scenario_error(text);
    EXPECT_EQ(error.rfind("deep.toml:", 0), 0u) << kind << ": " << error;
    EXPECT_NE(error.find("nested more than 64 levels deep"), std::string::npos) << kind << ": " << error;
  }
}

TEST(DynTomlNesting, ADeeplyNestedOverrideIsRefusedNotACrash) {
  const std::string scenario = "[body]\nprofile = \"sphere\"\n";
  const std::vector<std::string> overrides = {
      repeated("a", kDeep, ".") + "=1",                                   // the key
      "run.x=" + repeated("[", kDeep) + "1" + repeated("]", kDeep),       // the value
      "run.x=" + repeated("{a=", kDeep) + "1" + repeated("}", kDeep),
      repeated("a", kMaxTomlNesting, ".") + "=[1]",                       // together
  };
  for (const auto& o : overrides) {
    const std::string error = scenario_error(scenario, {o});
    EXPECT_NE(error.find("nested more than 64 levels deep"), std::string::npos) << o.substr(0, 40) << ": " << error;
  }
}

}  // namespace
}  // namespace frictionlab::dynamics
