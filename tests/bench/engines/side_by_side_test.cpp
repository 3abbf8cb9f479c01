// engines_side_by_side end to end, briefly (two problems, no scan, no plots): two runs give the
// same numbers, every engine built has its rows, and bad input is one error line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/engines/engine_list.h"

namespace side_by_side_test {

const std::string kExe = ENGINES_EXE;
const std::string kScenarios = std::string(FRICTIONLAB_SOURCE_DIR) + "/data/scenarios";

struct Result {
  int status = 0;
  std::string output;  // standard error and output together
};

Result run(const std::string& args) {
  Result r;
  const std::string cmd = kExe + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, "popen failed"};
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p)) r.output += buf;
  r.status = pclose(p);
  return r;
}

// engines.csv without its cpu_s column (the 12th), which is a measurement of this machine.
std::vector<std::string> numbers(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  std::string line;
  while (std::getline(in, line)) {
    // Split on commas outside quotes.
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) {
        fields.emplace_back();
      } else {
        fields.back() += c;
      }
    }
    if (fields.size() > 11) fields.erase(fields.begin() + 11);
    std::string joined;
    for (const auto& f : fields) joined += f + '|';
    rows.push_back(joined);
  }
  return rows;
}

TEST(EnginesSideBySide, TwoRunsGiveTheSameNumbersAndEveryBuiltEngineHasItsRows) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "engines_side_by_side";
  std::filesystem::remove_all(dir);
  const std::string args = "--scenarios " + kScenarios + " --problems slide-to-roll,puck --no-scan --no-plots --out ";
  const Result a = run(args + (dir / "a").string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Result b = run(args + (dir / "b").string());
  ASSERT_EQ(b.status, 0) << b.output;
  const auto na = numbers(dir / "a" / "engines.csv"), nb = numbers(dir / "b" / "engines.csv");
  // frictionlab's row and four settings per engine, for two problems, and the header.
  const auto engines = frictionlab::engines::built_engines();
  EXPECT_EQ(na.size(), 1 + 2 * (1 + 4 * engines.size()));
  EXPECT_EQ(na, nb);
  for (const auto& e : engines) EXPECT_NE(a.output.find(e->name() + " "), std::string::npos) << e->name();
  const bool all_built = frictionlab::engines::missing_engines().empty();
  EXPECT_EQ(a.output.find("not built") == std::string::npos, all_built) << a.output;
}

TEST(EnginesSideBySide, AnUnknownProblemIsOneErrorLine) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "engines_side_by_side_bad";
  const Result r = run("--scenarios " + kScenarios + " --problems juggling --out " + dir.string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("engines_side_by_side: error: --problems: 'juggling' is not a problem"), std::string::npos)
      << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
