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
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "friction/batch.h"
#include "friction/registry.h"
#include "tests/cli/cli_runner.h"
#include "friction/reference_laws.h"

namespace frictionlab::testing {
namespace friction_command_test {

// The command registers exact-reference (GSL); so does this process, to compare its listing.
[[maybe_unused]] const bool kReferenceLawsRegistered = (frictionlab::friction::register_reference_laws(), true);

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

TEST(LawsCommand, DefinesKnBeforeItsFirstUse) {
  // The summaries write forces per kN: the first line that writes kN (as a word, or kNa) says
  // what it is, k·N (friction coefficient times normal force), not kilonewtons.
  const auto r = run_frictionlab("laws");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  const std::regex kn("(^|[^A-Za-z0-9_])kNa?([^A-Za-z0-9_]|$)");
  for (std::string line; std::getline(lines, line);) {
    if (!std::regex_search(line, kn)) continue;
    EXPECT_NE(line.find("kN = k·N"), std::string::npos) << "the first kN is not defined: " << line;
    EXPECT_NE(line.find("kNa = k·N·a"), std::string::npos) << line;
    return;
  }
  ADD_FAILURE() << "no law summary writes kN any more: " << r.out;
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
  // The header, pade-printed's row, then the row of the alias or of its target.
  const auto third_line = [](const std::string& s) { return s.substr(s.find('\n', s.find('\n') + 1) + 1); };
  const std::string a = third_line(alias.out);
  const std::string t = third_line(target.out);
  ASSERT_EQ(a.rfind("coulomb-decoupled,", 0), 0u) << alias.out;
  ASSERT_EQ(t.rfind("decoupled,", 0), 0u) << target.out;
  EXPECT_EQ(a.substr(a.find(',')), t.substr(t.find(',')));
}

TEST(FrictionCommand, SingleContactPrintsAHeaderAndARowPerLaw) {
  // Pure sliding under any law: F1 = k·N = 0.3 * 10, no spin moment.
  const auto r = run_frictionlab(
      "friction --law pade-printed --U 0.5 --Omega 0 --a 0.01 --b 0.005 --psi 0.2 --N 10 --k 0.3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "law,F1,F2,M\npade-printed,3,0,0\n");  // 0.3 * 10 rounds to exactly 3 in double arithmetic
}

TEST(FrictionCommand, OneLawAndSeveralGiveTheSameColumns) {
  // A reader of the output need not know how many laws were asked for: the same header, and each
  // row names its law, for one contact and for a table.
  const std::string contact = " --U 0.1 --Omega 10 --a 0.01 --b 0.004 --psi 0.3 --N 20 --k 0.1";
  const auto one = run_frictionlab("friction --law exact" + contact);
  const auto two = run_frictionlab("friction --law exact,pade-printed" + contact);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const auto lines = [](const std::string& s) {
    std::vector<std::string> v;
    std::istringstream in(s);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
  };
  const auto a = lines(one.out), b = lines(two.out);
  ASSERT_EQ(a.size(), 2u) << one.out;
  ASSERT_EQ(b.size(), 3u) << two.out;
  EXPECT_EQ(a[0], "law,F1,F2,M");
  EXPECT_EQ(b[0], a[0]);
  EXPECT_EQ(b[1], a[1]) << "the first law's row does not depend on the others";

  const std::string csv = "U,Omega,a,b,psi,N,k\n0.1,10,0.01,0.004,0.3,20,0.1\n";
  const auto dir = fresh_temp_dir("friction_columns");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "in.csv") << csv;
  const auto table_one = run_frictionlab("friction --law exact " + (dir / "in.csv").string());
  const auto table_two = run_frictionlab("friction --law exact,pade-printed " + (dir / "in.csv").string());
  std::filesystem::remove_all(dir);
  ASSERT_EQ(table_one.exit_code, 0) << table_one.err;
  ASSERT_EQ(table_two.exit_code, 0) << table_two.err;
  const auto ta = lines(table_one.out), tb = lines(table_two.out);
  ASSERT_EQ(ta.size(), 2u) << table_one.out;
  ASSERT_EQ(tb.size(), 3u) << table_two.out;
  EXPECT_EQ(ta[0], "U,Omega,a,b,psi,N,k,law,F1,F2,M");
  EXPECT_EQ(tb[0], ta[0]);
  EXPECT_EQ(tb[1], ta[1]);
  // The table's row is the input row then the single contact's row.
  EXPECT_EQ(ta[1], "0.1,10,0.01,0.004,0.3,20,0.1," + a[1]);
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

TEST(FrictionCommand, WritesNoNegativeZero) {
  // Pure spin: the exact law's F1 is -0.0 (arithmetic residue; the exact F1 is 0). A table shows
  // "0", not "-0", for one contact and in a batch.
  const friction::ContactInput spin{0.0, 100.0, 0.004, 0.002, 0.0, 19.62, 0.1};
  const auto f = friction::make_law("exact")->evaluate(spin);
  ASSERT_TRUE(f.F1 == 0.0 && std::signbit(f.F1)) << "the case no longer makes a -0: pick another";
  const auto r = run_frictionlab("friction --law exact --U 0 --Omega 100 --a 0.004 --b 0.002 --psi 0 --N 19.62 --k 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("law,F1,F2,M\nexact,0,0,", 0), 0u) << r.out;
  const TempCsv file("friction_zero", "U,Omega,a,b,psi,N,k\n0,100,0.004,0.002,0,19.62,0.1\n");
  const auto table = run_frictionlab("friction --law exact " + file.path.string());
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("\n0,100,0.004,0.002,0,19.62,0.1,exact,0,0,"), std::string::npos) << table.out;
  EXPECT_EQ(table.out.find(",-0"), std::string::npos) << table.out;
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

TEST(FrictionCommand, SeveralLawsGiveARowPerLaw) {
  const TempCsv file("friction_laws", kTable);
  const auto r = run_frictionlab("friction --law exact,pade-printed " + file.path.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, library_output({"exact", "pade-printed"}, kTable));
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')), "case,U,Omega,a,b,psi,N,k,law,F1,F2,M");
  // One contact, two laws: the header, then one line per law, the law first.
  const auto single = run_frictionlab(
      "friction --law pade-printed,coulomb-decoupled --U 0.5 --Omega 0 --a 0.01 --b 0.005 --psi 0.2 --N 10 --k 0.3");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  EXPECT_EQ(single.out, "law,F1,F2,M\npade-printed,3,0,0\ncoulomb-decoupled,3,0,0\n");
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
  const std::string forces = plain.out.substr(plain.out.find("\nexact,") + 7);
  EXPECT_EQ(spec.out, "law,F1,F2,M\nexact:pressure=hertz," + forces);
  const auto both = run_frictionlab("friction --law 'pade-printed;exact:pressure=hertz'" + contact);
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_EQ(both.out.substr(both.out.rfind('\n', both.out.size() - 2) + 1), "exact:pressure=hertz," + forces);
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
  EXPECT_EQ(skip.out, "U,Omega,a,b,psi,N,k,law,F1,F2,M\n1,0,1,1,0,1,0.5,exact,0.5,0,0\n");
  EXPECT_EQ(count_lines(skip.err), 2u) << skip.err;
  EXPECT_NE(skip.err.find("frictionlab: warning: input line 3: column Omega = 'x' is not a number (row skipped)"),
            std::string::npos)
      << skip.err;
  EXPECT_NE(skip.err.find("input line 4: column U = '1e999' is out of the range of a double"), std::string::npos)
      << skip.err;
  const auto nan = run_frictionlab("friction --on-error nan " + file.path.string());
  EXPECT_EQ(nan.exit_code, 0) << nan.err;
  EXPECT_EQ(nan.out, "U,Omega,a,b,psi,N,k,law,F1,F2,M\n1,0,1,1,0,1,0.5,exact,0.5,0,0\n1,x,1,1,0,1,0.5,exact,nan,nan,nan\n"
                     "1e999,0,1,1,0,1,0.5,exact,nan,nan,nan\n");
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
