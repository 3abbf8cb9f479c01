// Tests of dynamics/puck/puck_study.h and puck_study_report.h on a small study: the measured
// terminal ratio against the closed form of the Hertz disk, the law list, the files written.

#include "dynamics/puck/puck_study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "dynamics/puck/puck_study_report.h"
#include "friction/registry.h"

namespace frictionlab::dynamics::puck {
namespace puck_study_test {

const std::filesystem::path kScenarios = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";

PuckStudyOptions small_study() {
  PuckStudyOptions o;
  o.scenario_dir = kScenarios;
  o.laws = {"exact"};
  o.kappas = {0.3};
  o.run_kappas = {0.3};
  o.start_ratios = {0.25, 4.0};
  return o;
}

// The Hertz circle, 1/4 <= kappa <= 1/2: G(u) = u mu(u)/kappa - f(u) = 0 with the closed forms of
// docs/model.md §2 (u <= 1) is 3u^4 - (8 - 4 kappa) u^2 + 8 - 16 kappa = 0, whose root in (0, 1] is
// u*^2 = (2/3)(2 - kappa - sqrt(kappa^2 + 8 kappa - 2)): sqrt(2/3) at kappa = 0.3.
TEST(DynPuckStudy, TheDiskEndsOnTheClosedFormRatioFromEitherSide) {
  const PuckStudyResults r = run_puck_study(small_study());
  const double kappa = 0.3;
  const double expected = std::sqrt(2.0 / 3.0 * (2.0 - kappa - std::sqrt(kappa * kappa + 8.0 * kappa - 2.0)));
  ASSERT_EQ(r.disk.size(), 2u);
  for (const auto& d : r.disk) {
    EXPECT_EQ(d.summary.reason, Termination::rest) << d.summary.message;
    // Approach r - r* ~ v^0.93 (the analysis' exponent): at the stop, v ~ 1e-6 sqrt(g a), the
    // ratio is within ~1e-5 of r*.
    EXPECT_NEAR(d.summary.terminal_ratio, expected, 1e-4) << "from r0 = " << d.start_ratio;
    EXPECT_NEAR(d.summary.slip_stop_time, d.summary.spin_stop_time, 1e-3 * d.summary.slip_stop_time);
  }
  ASSERT_EQ(r.theory.size(), 1u);
  ASSERT_EQ(r.theory[0].analysis.attracting.size(), 1u);
  EXPECT_NEAR(r.theory[0].analysis.attracting[0], expected, 1e-9);
  ASSERT_EQ(r.ellipse.size(), 1u);
  EXPECT_EQ(r.ellipse[0].summary.reason, Termination::rest);
}

TEST(DynPuckStudy, DefaultLawsAreEveryFastLawAndTheRefusedSpecsAreListed) {
  std::vector<std::string> unavailable;
  const auto laws = default_study_laws(&unavailable);
  for (const auto& info : friction::list_laws()) {
    const bool listed = std::find(laws.begin(), laws.end(), info.name) != laws.end();
    EXPECT_EQ(listed, !info.slow) << info.name;
  }
  for (const auto& spec : unavailable) EXPECT_THROW((void)friction::make_law(spec), std::invalid_argument) << spec;
}

TEST(DynPuckStudy, RejectsBadOptionsNamingThem) {
  PuckStudyOptions o = small_study();
  o.laws = {"no-such-law"};
  try {
    (void)run_puck_study(o);
    FAIL() << "accepted an unknown law";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--laws"), std::string::npos) << e.what();
  }
  o = small_study();
  o.run_kappas = {-1.0};
  EXPECT_THROW((void)run_puck_study(o), std::invalid_argument);
  o = small_study();
  o.scenario_dir = kScenarios / "no-such-folder";
  EXPECT_THROW((void)run_puck_study(o), std::invalid_argument);
}

TEST(DynPuckStudy, WritesTheReportAndTables) {
  const PuckStudyResults r = run_puck_study(small_study());
  const auto out = std::filesystem::path(::testing::TempDir()) / "puck-study-test";
  std::filesystem::remove_all(out);
  const auto problems = write_puck_study(r, out, "test", /*plots=*/false);
  EXPECT_TRUE(problems.empty());
  for (const char* f : {"puck-study.md", "theory.csv", "disk.csv", "ellipse.csv"})
    EXPECT_TRUE(std::filesystem::is_regular_file(out / f)) << f;
  std::ifstream disk(out / "disk.csv");
  std::string header, row;
  std::getline(disk, header);
  int rows = 0;
  while (std::getline(disk, row)) ++rows;
  EXPECT_EQ(rows, 2);
}

TEST(DynPuckStudy, LegendsShowLawSpecsAsTheyAre) {
  // A law spec's '_' is markup to gnuplot's enhanced text (r_spin: "r" with a subscript "spin"):
  // every key entry escapes it (support::gnuplot_text).
  PuckStudyOptions o = small_study();
  o.laws = {"exact", "decoupled:r_spin=0.001"};
  o.run_kappas = {0.5};  // the ratio figure draws kappa = 1/2
  o.start_ratios = {4.0};
  const PuckStudyResults r = run_puck_study(o);
  const auto out = std::filesystem::path(::testing::TempDir()) / "puck-study-legends";
  std::filesystem::remove_all(out);
  (void)write_puck_study(r, out, "test", /*plots=*/true);  // whether gnuplot drew them is not this test's concern
  for (const char* script : {"drift.gp", "regimes.gp", "ratio.gp", "paths.gp"}) {
    std::ifstream in(out / "figures" / script);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(text.find("title 'decoupled:r\\_spin=0.001'"), std::string::npos) << script << "\n" << text;
    EXPECT_EQ(text.find("r_spin"), std::string::npos) << script << "\n" << text;
  }
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace frictionlab::dynamics::puck
