// `frictionlab laws` and `frictionlab friction`, run as a user runs them.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "friction/batch.h"
#include "friction/registry.h"
#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace {

std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

TEST(LawsCommand, ListsEveryLawOnOneLineAndEachParameterBelowIt) {
  const auto r = run_frictionlab("laws");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto laws = friction::list_laws();
  std::size_t parameters = 0;
  std::size_t with_aliases = 0;
  for (const auto& law : laws) {
    EXPECT_NE(r.out.find("\n" + law.name + " "), std::string::npos) << law.name;
    for (const auto& p : law.parameters) EXPECT_NE(r.out.find("    " + p.describe() + "\n"), std::string::npos) << p.key;
    parameters += law.parameters.size();
    with_aliases += law.aliases.empty() ? 0 : 1;
  }
  EXPECT_GE(parameters, 1u);  // exact:pressure=...
  // A header line saying how to write a spec, one line per law, one for its aliases if it has
  // any, one per parameter.
  EXPECT_EQ(r.out.rfind("Laws, and the parameters a spec NAME:KEY=VALUE[,KEY=VALUE] may set", 0), 0u) << r.out;
  EXPECT_EQ(count_lines(r.out), 1 + laws.size() + with_aliases + parameters);
}

TEST(LawsCommand, ListsEachLawOnceWithItsOtherNames) {
  // The old names of the engines' laws at their defaults are aliases: not lines of their own, but
  // named on the line below their law.
  const auto r = run_frictionlab("laws");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("\nmoller-ellipsoidal "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\ncoulomb-decoupled "), std::string::npos) << r.out;
  const auto below = [&](const std::string& law) {
    const auto at = r.out.find("\n" + law + " ");
    if (at == std::string::npos) return std::string();
    const auto start = r.out.find('\n', at + 1) + 1;
    return r.out.substr(start, r.out.find('\n', start) - start);
  };
  EXPECT_EQ(below("ellipsoidal"), "    also named moller-ellipsoidal");
  EXPECT_EQ(below("decoupled"), "    also named coulomb-decoupled");
}

TEST(FrictionCommand, AnAliasIsEchoedAndGivesItsTargetsForces) {
  const std::string contact = " --U 0.01 --Omega 3 --a 0.01 --b 0.005 --psi 0.2 --N 10 --k 0.3";
  const auto alias = run_frictionlab("friction --law pade-printed,coulomb-decoupled" + contact);
  const auto target = run_frictionlab("friction --law pade-printed,decoupled" + contact);
  ASSERT_EQ(alias.exit_code, 0) << alias.err;
  ASSERT_EQ(target.exit_code, 0) << target.err;
  const auto second_line = [](const std::string& s) { return s.substr(s.find('\n') + 1); };
  const std::string a = second_line(alias.out);
  const std::string t = second_line(target.out);
  ASSERT_EQ(a.rfind("coulomb-decoupled,", 0), 0u) << alias.out;
  ASSERT_EQ(t.rfind("decoupled,", 0), 0u) << target.out;
  EXPECT_EQ(a.substr(a.find(',')), t.substr(t.find(',')));
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

// A CSV file under a fresh temporary directory, removed with it.
struct TempCsv {
  std::filesystem::path dir;
  std::filesystem::path path;
  explicit TempCsv(const std::string& tag, const std::string& content)
      : dir(fresh_temp_dir(tag)), path(dir / "in.csv") {
    std::filesystem::create_directories(dir);
    std::ofstream(path) << content;
  }
  ~TempCsv() { std::filesystem::remove_all(dir); }
};

const std::string kTable =
    "case,U,Omega,a,b,psi,N,k\n"
    "1,0.1,10,0.01,0.004,0.3,20,0.1\n"
    "2,0,-10,0.01,0.01,0,20,0.1\n";

std::string library_output(const std::vector<std::string>& names, const std::string& csv) {
  std::vector<std::unique_ptr<friction::FrictionLaw>> made;
  std::vector<const friction::FrictionLaw*> laws;
  for (const auto& n : names) {
    made.push_back(friction::make_law(n));
    laws.push_back(made.back().get());
  }
  std::istringstream in(csv);
  std::ostringstream out;
  friction::evaluate_csv(laws, in, out);
  return out.str();
}

TEST(FrictionCommand, ReadsATableFromAFileGivenByPathOrByInput) {
  const TempCsv file("friction_path", kTable);
  const auto positional = run_frictionlab("friction --law pade-printed " + file.path.string());
  ASSERT_EQ(positional.exit_code, 0) << positional.err;
  EXPECT_EQ(positional.out, library_output({"pade-printed"}, kTable));
  const auto option = run_frictionlab("friction --law pade-printed --input " + file.path.string());
  ASSERT_EQ(option.exit_code, 0) << option.err;
  EXPECT_EQ(option.out, positional.out);
  const auto dash = run_frictionlab("friction --law pade-printed - < " + file.path.string());
  ASSERT_EQ(dash.exit_code, 0) << dash.err;
  EXPECT_EQ(dash.out, positional.out);
}

TEST(FrictionCommand, SeveralLawsAddALawColumn) {
  const TempCsv file("friction_laws", kTable);
  const auto r = run_frictionlab("friction --law exact,pade-printed " + file.path.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, library_output({"exact", "pade-printed"}, kTable));
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')), "case,U,Omega,a,b,psi,N,k,law,F1,F2,M");
  // One contact, two laws: one line per law, the law first.
  const auto single = run_frictionlab(
      "friction --law pade-printed,coulomb-decoupled --U 0.5 --Omega 0 --a 0.01 --b 0.005 --psi 0.2 --N 10 --k 0.3");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  EXPECT_EQ(single.out, "pade-printed,3,0,0\ncoulomb-decoupled,3,0,0\n");
  const auto twice = run_frictionlab("friction --law exact,exact " + file.path.string());
  EXPECT_EQ(twice.exit_code, 1);
  EXPECT_NE(twice.err.find("law 'exact' is listed twice"), std::string::npos) << twice.err;
}

TEST(FrictionCommand, LawSpecsWorkAndAreEchoedVerbatim) {
  // A spec denotes a law with parameters; the output names each law by its spec as typed.
  const TempCsv file("friction_specs", kTable);
  const auto r = run_frictionlab("friction --law 'exact:pressure=hertz,pade-printed' " + file.path.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, library_output({"exact:pressure=hertz", "pade-printed"}, kTable));
  EXPECT_NE(r.out.find(",exact:pressure=hertz,"), std::string::npos) << r.out;
  // exact:pressure=hertz is exact: the same numbers.
  const std::string contact = " --U 0.1 --Omega 10 --a 0.01 --b 0.004 --psi 0.3 --N 20 --k 0.1";
  const auto plain = run_frictionlab("friction --law exact" + contact);
  const auto spec = run_frictionlab("friction --law exact:pressure=hertz" + contact);
  ASSERT_EQ(spec.exit_code, 0) << spec.err;
  EXPECT_EQ(spec.out, plain.out);
  const auto both = run_frictionlab("friction --law 'pade-printed;exact:pressure=hertz'" + contact);
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_EQ(both.out.substr(both.out.find('\n') + 1), "exact:pressure=hertz," + plain.out);
  // The same law twice under two spellings, and a bad value: one line each.
  const auto twice = run_frictionlab("friction --law exact,exact:pressure=hertz" + contact);
  EXPECT_EQ(twice.exit_code, 1);
  EXPECT_NE(twice.err.find("'exact:pressure=hertz' is the same law as 'exact'"), std::string::npos) << twice.err;
  const auto bad = run_frictionlab("friction --law exact:pressure=flat" + contact);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(count_lines(bad.err), 1u) << bad.err;
  EXPECT_NE(bad.err.find("pressure = 'flat' is not allowed: pressure must be one of hertz"), std::string::npos)
      << bad.err;
}

TEST(FrictionCommand, PressureSpecsGiveTheirPureSpinTorque) {
  // A circle at pure spin: M = c k N a with c = 3 pi/16 (Hertz), 2/3 (uniform), pi/4 (punch)
  // (docs/pressure-models.md); k N a = 0.5 * 10 * 0.01.
  const std::string contact = " --U 0 --Omega 1 --a 0.01 --b 0.01 --psi 0 --N 10 --k 0.5";
  const double kNa = 0.05;
  const std::pair<const char*, double> cases[] = {{"exact:pressure=hertz", 3.0 * std::numbers::pi / 16.0},
                                                  {"exact:pressure=uniform", 2.0 / 3.0},
                                                  {"exact:pressure=punch", std::numbers::pi / 4.0}};
  for (const auto& [spec, c] : cases) {
    const auto r = run_frictionlab(std::string("friction --law ") + spec + contact);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const double M = std::stod(r.out.substr(r.out.rfind(',') + 1));
    EXPECT_NEAR(M, c * kNa, 1e-10 * kNa) << spec << ": " << r.out;
  }
}

TEST(FrictionCommand, OnErrorSkipAndNanKeepGoingAndWarnOnStderr) {
  const std::string csv = "U,Omega,a,b,psi,N,k\n1,0,1,1,0,1,0.5\n1,x,1,1,0,1,0.5\n1e999,0,1,1,0,1,0.5\n";
  const TempCsv file("friction_onerror", csv);
  const auto skip = run_frictionlab("friction --on-error skip " + file.path.string());
  EXPECT_EQ(skip.exit_code, 0) << skip.err;
  EXPECT_EQ(skip.out, "U,Omega,a,b,psi,N,k,F1,F2,M\n1,0,1,1,0,1,0.5,0.5,0,0\n");
  EXPECT_EQ(count_lines(skip.err), 2u) << skip.err;
  EXPECT_NE(skip.err.find("frictionlab: warning: input line 3: column Omega = 'x' is not a number (row skipped)"),
            std::string::npos)
      << skip.err;
  EXPECT_NE(skip.err.find("input line 4: column U = '1e999' is out of the range of a double"), std::string::npos)
      << skip.err;
  const auto nan = run_frictionlab("friction --on-error nan " + file.path.string());
  EXPECT_EQ(nan.exit_code, 0) << nan.err;
  EXPECT_EQ(nan.out, "U,Omega,a,b,psi,N,k,F1,F2,M\n1,0,1,1,0,1,0.5,0.5,0,0\n1,x,1,1,0,1,0.5,nan,nan,nan\n"
                     "1e999,0,1,1,0,1,0.5,nan,nan,nan\n");
  const auto stop = run_frictionlab("friction " + file.path.string());
  EXPECT_EQ(stop.exit_code, 1);
  EXPECT_EQ(stop.out, "");
  EXPECT_EQ(count_lines(stop.err), 1u) << stop.err;
  const auto bad = run_frictionlab("friction --on-error ignore " + file.path.string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--on-error = 'ignore' is not a choice: use stop, skip or nan"), std::string::npos) << bad.err;
}

TEST(FrictionCommand, AFullDiskIsAnErrorOfOneLine) {
  // /dev/full accepts the open and fails every write: the command must notice (at the latest at
  // the final flush) and say so, for one contact and for a table.
  const TempCsv file("friction_full", kTable);
  for (const std::string& args :
       {std::string("friction --U 1 --Omega 1 --a 1 --b 1 --psi 0 --N 1 --k 1 > /dev/full"),
        "friction " + file.path.string() + " > /dev/full",
        "friction --on-error nan " + file.path.string() + " > /dev/full"}) {
    const auto r = run_frictionlab(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_EQ(count_lines(r.err), 1u) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("frictionlab: error: cannot write the output", 0), 0u) << args << ": " << r.err;
  }
}

TEST(FrictionCommand, InputProblemsAreOneLine) {
  const auto dir = fresh_temp_dir("friction_inputs");
  std::filesystem::create_directories(dir);
  struct Case {
    std::string args, expect;
  };
  const TempCsv file("friction_both", kTable);
  const Case cases[] = {
      {"friction " + (dir / "missing.csv").string(), "cannot open the input " + (dir / "missing.csv").string()},
      {"friction " + dir.string(), dir.string() + " is a directory"},
      {"friction --U 1 " + file.path.string(), "give either one contact (--U ... --k) or an input table, not both"},
      {"friction --input " + file.path.string() + " " + file.path.string(), "the input is given twice"},
      // A read that fails (EIO) is neither an empty table nor the end of one: it names the file and why.
      {"friction /proc/self/mem", "frictionlab: error: reading the input '/proc/self/mem' failed: Input/output error"},
      // Standard input too (a folder as stdin: read(2) fails with EISDIR), where std::cin said "empty".
      {"friction - </", "frictionlab: error: reading standard input failed: Is a directory"},
  };
  for (const auto& c : cases) {
    const auto r = run_frictionlab(c.args);
    EXPECT_EQ(r.exit_code, 1) << c.args;
    EXPECT_EQ(count_lines(r.err), 1u) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << ": " << r.err;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::testing
