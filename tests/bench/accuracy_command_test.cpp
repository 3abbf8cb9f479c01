// `frictionlab accuracy`, run as a user runs it: a tiny study writes its files; bad options give
// one error line and a non-zero exit.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace accuracy_command_test {

std::size_t count_lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

std::filesystem::path temp_out(const char* tag) {
  return std::filesystem::temp_directory_path() /
         (std::string("frictionlab_accuracy_cmd_") + tag + "_" + std::to_string(::getpid()));
}

TEST(AccuracyCommand, TinyStudyWritesTheFiles) {
  const auto out = temp_out("ok");
  const auto r = run_frictionlab("accuracy --out " + out.string() +
                                 " --laws pade-printed --s-points 5 --mu-points 2 --psi-points 3 --no-plots --points");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");  // progress goes to stderr
  EXPECT_NE(r.err.find("accuracy: pade-printed"), std::string::npos) << r.err;
  for (const char* f : {"summary.csv", "summary_by_mu.csv", "summary_by_region.csv", "accuracy_tables.md",
                        "README.md", "points/exact.csv", "points/pade-printed.csv",
                        "plots/heat_pade-printed.gp"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  std::filesystem::remove_all(out);
}

std::uintmax_t folder_bytes(const std::filesystem::path& dir) {
  std::uintmax_t bytes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) bytes += entry.file_size();
  return bytes;
}

// The default study (200 000 points, six laws) writes what a laptop user accepts: the summaries,
// tables and figure data, no per-point tables (165 MB; --points asks for them). The figures are
// left out (--no-plots: gnuplot may be missing; they add ~1 MB, docs/accuracy.md).
TEST(AccuracyCommand, TheDefaultStudyWritesUnder20MBAndNoPerPointTables) {
  const auto out = temp_out("default");
  const auto r = run_frictionlab("accuracy --out " + out.string() + " --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "points")) << "per-point tables written unasked";
  EXPECT_TRUE(std::filesystem::exists(out / "summary.csv"));
  EXPECT_LT(folder_bytes(out), 20'000'000u);
  const std::string readme = slurp(out / "README.md");
  EXPECT_NE(readme.find("not written by this run: add `--points`"), std::string::npos) << readme;
  std::filesystem::remove_all(out);
}

TEST(AccuracyCommand, ProgressLinesGiveTheUnitsOfTheErrors) {
  // The errors are dimensionless multiples of k·N (F1, F2) and k·N·a (M): "F1 0.2" alone reads as
  // 0.2 N, and kN as kilonewtons.
  const auto out = temp_out("units");
  const auto r = run_frictionlab("accuracy --out " + out.string() +
                                 " --laws pade-printed --s-points 5 --mu-points 2 --psi-points 3 --no-plots");
  std::filesystem::remove_all(out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string number = "[-+0-9.e]+|inf|nan";
  const std::regex line("(^|\n)accuracy: pade-printed: (" + number + ") s; max \\|error\\| F1 (" + number +
                        ") k·N, F2 (" + number + ") k·N, M (" + number + ") k·N·a\n");
  EXPECT_TRUE(std::regex_search(r.err, line)) << r.err;
}

TEST(AccuracyCommand, FigureTextShowsLawSpecsAsTheyAre) {
  // A law spec's '_' is markup to gnuplot's enhanced text: every title and key entry escapes it.
  const auto out = temp_out("figure_text");
  const auto r = run_frictionlab("accuracy --out " + out.string() +
                                 " --laws decoupled:r_spin=0.001 --s-points 5 --mu-points 2 --psi-points 3 --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int scripts = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out / "plots")) {
    if (entry.path().extension() != ".gp") continue;
    ++scripts;
    std::ifstream in(entry.path());
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(text.find("decoupled:r\\_spin=0.001"), std::string::npos) << entry.path() << "\n" << text;
    EXPECT_EQ(text.find("decoupled:r_spin"), std::string::npos) << entry.path() << "\n" << text;
  }
  EXPECT_GE(scripts, 2);
  std::filesystem::remove_all(out);
}

void expect_one_line_error(const std::string& args, const std::string& fragment);

TEST(AccuracyCommand, SpecsForTheLawsAndTheReferenceAreEchoedVerbatim) {
  // The laws for a uniform pressure, against the exact law for that pressure.
  const auto out = temp_out("spec");
  const auto r = run_frictionlab("accuracy --out " + out.string() +
                                 " --reference exact:pressure=uniform --laws 'exact:pressure=punch;pade-printed'"
                                 " --s-points 5 --mu-points 2 --psi-points 3 --no-plots --points");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("against 'exact:pressure=uniform'"), std::string::npos) << r.err;
  for (const char* f : {"points/exact_pressure-uniform.csv", "points/exact_pressure-punch.csv",
                        "points/pade-printed.csv", "plots/heat_exact_pressure-punch.gp"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  std::ifstream summary(out / "summary.csv");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\nexact:pressure=punch,"), std::string::npos) << text;
  std::filesystem::remove_all(out);
  expect_one_line_error("accuracy --out " + out.string() + " --reference exact:pressure=flat",
                        "pressure must be one of hertz, uniform, punch");
}

void expect_one_line_error(const std::string& args, const std::string& fragment) {
  const auto r = run_frictionlab(args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
}

TEST(AccuracyCommand, BadOptionsGiveOneLineAndNonZeroExit) {
  const std::string out = " --out " + temp_out("bad").string();
  expect_one_line_error("accuracy" + out + " --s-points 1", "s points = 1 is invalid");
  expect_one_line_error("accuracy" + out + " --psi-points 24", "psi points = 24 is invalid");
  expect_one_line_error("accuracy" + out + " --laws pade-printed,nope", "unknown friction law 'nope'");
  expect_one_line_error("accuracy" + out + " --laws exact-reference", "too slow");
  EXPECT_FALSE(std::filesystem::exists(temp_out("bad")));
  const auto missing = run_frictionlab("accuracy --s-points 5");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find("--out is required"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace frictionlab::testing
