// `frictionlab laws` and `frictionlab friction`, run as a user runs them.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "friction/batch.h"
#include "friction/registry.h"
#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace {

std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

TEST(LawsCommand, ListsEveryLawOnOneLine) {
  const auto r = run_frictionlab("laws");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto laws = friction::list_laws();
  EXPECT_EQ(count_lines(r.out), laws.size());
  for (const auto& law : laws) EXPECT_NE(r.out.find(law.name + " "), std::string::npos) << law.name;
}

TEST(FrictionCommand, SingleContactPrintsOneCsvLine) {
  // Pure sliding under any law: F1 = kN = 0.3 * 10, no spin moment.
  const auto r = run_frictionlab(
      "friction --law pade-printed --U 0.5 --Omega 0 --a 0.01 --b 0.005 --psi 0.2 --N 10 --k 0.3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "3,0,0\n");  // 0.3 * 10 rounds to exactly 3 in double arithmetic
}

TEST(FrictionCommand, BatchRoundTripMatchesTheLibrary) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto in_path = dir / ("frictionlab_batch_in_" + std::to_string(::getpid()) + ".csv");
  const std::string csv =
      "case,U,Omega,a,b,psi,N,k\n"
      "1,0.1,10,0.01,0.004,0.3,20,0.1\n"
      "2,0,-10,0.01,0.01,0,20,0.1\n"
      "3,1,0.5,0.02,0.001,2.5,5,0.4\n";
  std::ofstream(in_path) << csv;
  const auto r = run_frictionlab("friction --law pade-printed < " + in_path.string());
  std::filesystem::remove(in_path);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  std::istringstream in(csv);
  std::ostringstream expected;
  friction::evaluate_csv(*friction::make_law("pade-printed"), in, expected);
  EXPECT_EQ(r.out, expected.str());
  EXPECT_EQ(count_lines(r.out), 4u);
}

TEST(FrictionCommand, BadInputGivesOneLineAndNonZeroExitAndNoPartialOutput) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto in_path = dir / ("frictionlab_batch_bad_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(in_path) << "U,Omega,a,b,psi,N,k\n1,1,1,1,0,1,0.1\n1,1,1,1,0,1,zero\n";
  const auto batch = run_frictionlab("friction --law exact < " + in_path.string());
  std::filesystem::remove(in_path);
  EXPECT_NE(batch.exit_code, 0);
  EXPECT_EQ(batch.out, "");
  EXPECT_EQ(count_lines(batch.err), 1u) << batch.err;
  EXPECT_NE(batch.err.find("input line 3: column k = 'zero' is not a number"), std::string::npos)
      << batch.err;

  const auto unknown = run_frictionlab("friction --law nope --U 1 --Omega 1 --a 1 --b 1 --psi 0 --N 1 --k 1");
  EXPECT_NE(unknown.exit_code, 0);
  EXPECT_NE(unknown.err.find("unknown friction law 'nope'"), std::string::npos) << unknown.err;

  const auto missing = run_frictionlab("friction --law exact --U 1 --Omega 1");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find("--a is missing"), std::string::npos) << missing.err;

  const auto invalid = run_frictionlab("friction --U 1 --Omega 1 --a 1 --b 2 --psi 0 --N 1 --k 1");
  EXPECT_NE(invalid.exit_code, 0);
  EXPECT_NE(invalid.err.find("b = 2 is invalid"), std::string::npos) << invalid.err;
}

}  // namespace
}  // namespace frictionlab::testing
