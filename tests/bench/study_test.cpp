// The study end to end on a tiny grid: `exact` against itself gives exactly zero errors, and the
// printed Padé law shows its known oddities (F2 odd in Omega, so the wrong sign for one spin; the
// F2 pole; M of the wrong sign at large slip from b1 < 0). Also the files and figure scripts.

#include "bench/accuracy/study.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/accuracy/plots.h"
#include "bench/accuracy/report.h"
#include "friction/registry.h"
#include "friction/reference_laws.h"

namespace frictionlab::accuracy {
namespace study_test {

// exact-reference (GSL) lives in its own library: registered here, as the command does.
[[maybe_unused]] const bool kReferenceLawsRegistered = (friction::register_reference_laws(), true);

constexpr double pi = std::numbers::pi;

GridSpec tiny_grid() {
  GridSpec spec;
  spec.s_points = 9;    // s = 10^(-3 + 0.75 k)
  spec.mu_points = 3;   // 0.05, 0.525, 1
  spec.psi_points = 5;  // 0, 45, 90, 135, 180 degrees
  return spec;
}

const StudyResult& tiny_study() {
  static const StudyResult study = [] {
    StudyOptions opt;
    opt.grid = tiny_grid();
    opt.laws = {"exact", "pade-printed"};
    opt.threads = 2;
    return run_study(opt);
  }();
  return study;
}

std::size_t count_lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  return static_cast<std::size_t>(std::count(std::istreambuf_iterator<char>(in), {}, '\n'));
}

TEST(Study, ExactAgainstItselfHasExactlyZeroError) {
  const auto& study = tiny_study();
  ASSERT_EQ(study.summaries.size(), 2u);
  const auto& self = study.summaries[0];
  EXPECT_EQ(self.law, "exact");
  for (const auto* scope : {&self.overall, &self.by_mu[0], &self.by_mu[2], &self.by_region[3]}) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(scope->error[c].max_abs, 0.0) << c;
      EXPECT_EQ(scope->error[c].rms, 0.0) << c;
      EXPECT_EQ(scope->error[c].nonfinite, 0u) << c;
      EXPECT_EQ(scope->sign[c].opposite + scope->sign[c].zero, 0u) << c;
    }
    EXPECT_EQ(scope->dissipation.violations, 0u);
    EXPECT_EQ(scope->singular_points, 0u);
  }
  EXPECT_EQ(self.overall.points, study.grid.size());
  EXPECT_FALSE(self.has_denominators);
}

TEST(Study, PrintedF2IsOddInOmegaSoOneSpinHasTheWrongSign) {
  const auto& study = tiny_study();
  const Grid& grid = study.grid;
  const auto& pade = study.values[1];
  const auto& ex = study.reference;
  ASSERT_EQ(pade.law, "pade-printed");
  const std::size_t ipsi = 1;  // 45 degrees: the exact F2 > 0
  std::size_t checked = 0;
  for (std::size_t imu = 0; imu + 1 < grid.mu().size(); ++imu) {  // not the circle (F2 = 0)
    for (std::size_t is = 0; is < grid.s().size(); ++is) {
      const std::size_t neg = grid.index(imu, ipsi, 0, is), pos = grid.index(imu, ipsi, 1, is);
      ASSERT_GT(ex.F2[neg], kSignThreshold);
      ASSERT_GT(ex.F2[pos], kSignThreshold);
      EXPECT_EQ(pade.F2[neg], -pade.F2[pos]) << "printed F2 is odd in Omega";
      // So exactly one spin has the wrong sign (where the printed F2 is not 0).
      EXPECT_EQ((pade.F2[neg] < 0.0) + (pade.F2[pos] < 0.0), 1);
      ++checked;
    }
    // Before the pole (smallest s, F2 denominator ~ a4 < 0) it is Omega < 0 that is wrong.
    EXPECT_LT(pade.F2[grid.index(imu, ipsi, 0, 0)], 0.0);
  }
  EXPECT_EQ(checked, 2u * grid.s().size());
  const auto& sum = study.summaries[1];
  const auto& neg_region = sum.by_region[3];
  EXPECT_EQ(study.regions[3].name, "Omega < 0");
  EXPECT_GT(neg_region.sign[1].opposite, 0u);
  EXPECT_GT(sum.overall.sign[1].opposite_fraction(), 0.0);
  EXPECT_GT(sum.overall.error[1].max_abs, 0.01);
}

TEST(Study, PrintedLawHasAnF2PoleAndTheWrongSignOfMAtLargeSlip) {
  const auto& study = tiny_study();
  const auto& sum = study.summaries[1];
  EXPECT_TRUE(sum.has_denominators);
  const bool f2_pole = std::any_of(sum.poles.begin(), sum.poles.end(), [](const PoleBracket& b) {
    return b.component == Component::F2 && b.ipsi == 1;
  });
  EXPECT_TRUE(f2_pole);
  // s = 1000, mu = 0.525, psi = 45 deg, Omega > 0: exact M ~ d3/(5 s) > 0; printed M ~ M0 b1/(b2 s) < 0.
  const Grid& grid = study.grid;
  const std::size_t i = grid.index(1, 1, 1, grid.s().size() - 1);
  EXPECT_GT(study.reference.M[i], 0.0);
  EXPECT_LT(study.values[1].M[i], 0.0);
}

TEST(Study, DefaultLawsAreTheRegistrysNeitherReferenceNorSlow) {
  // The study decides nothing by name: its default list is the registry's laws minus those the
  // registry marks as the reference or as slow, in registry order.
  std::vector<std::string> expected;
  for (const auto& info : friction::list_laws()) {
    if (!info.reference && !info.slow) expected.push_back(info.name);
  }
  EXPECT_EQ(default_laws(), expected);
  EXPECT_EQ(tiny_study().reference.law, friction::reference_law_name());
}

TEST(Study, DefaultLawsLeaveOutTheReferenceAndTheSlowLaw) {
  const auto laws = default_laws();
  EXPECT_EQ(std::count(laws.begin(), laws.end(), "exact"), 0);
  EXPECT_EQ(std::count(laws.begin(), laws.end(), "exact-reference"), 0);
  EXPECT_EQ(std::count(laws.begin(), laws.end(), "pade-printed"), 1);
  EXPECT_EQ(std::count(laws.begin(), laws.end(), "pade-printed-minor"), 1);
}

void expect_bad_laws(const std::vector<std::string>& laws, const GridSpec& spec, const std::string& fragment) {
  try {
    check_laws(laws, Grid{spec});
    ADD_FAILURE() << "no exception for " << fragment;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Study, BadLawListsAreRejectedWithTheReason) {
  expect_bad_laws({"pade-printed", "nope"}, tiny_grid(), "unknown friction law 'nope'");
  expect_bad_laws({"pade-printed", "pade-printed"}, tiny_grid(), "listed twice");
  expect_bad_laws({"exact-reference"}, GridSpec{}, "too slow for a grid of 200000 points");
  EXPECT_NO_THROW(check_laws({"exact-reference"}, Grid{tiny_grid()}));
}

TEST(Study, FilesHaveOneRowPerPointAndPerLaw) {
  const auto& study = tiny_study();
  const auto dir = std::filesystem::temp_directory_path() /
                   ("frictionlab_accuracy_files_" + std::to_string(::getpid()));
  RunInfo run = describe_this_run();
  run.command = "frictionlab accuracy --out test";
  StudyFiles files;
  files.point_tables = true;
  write_study_files(study, dir, run, nullptr, files);
  EXPECT_EQ(count_lines(dir / "points" / "exact.csv"), study.grid.size() + 1);
  EXPECT_EQ(count_lines(dir / "points" / "pade-printed.csv"), study.grid.size() + 1);
  EXPECT_EQ(count_lines(dir / "summary.csv"), 1u + 2u);
  EXPECT_EQ(count_lines(dir / "summary_by_mu.csv"), 1u + 2u * 3u);
  EXPECT_EQ(count_lines(dir / "summary_by_region.csv"), 1u + 2u * 5u);
  EXPECT_TRUE(std::filesystem::exists(dir / "singular" / "pade-printed.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "singular" / "exact.csv"));

  std::ifstream points(dir / "points" / "pade-printed.csv");
  std::string header, first;
  std::getline(points, header);
  std::getline(points, first);
  EXPECT_EQ(header, "s,mu,psi,sign,F1,F2,M,err_F1,err_F2,err_M,dissipation");
  EXPECT_EQ(first.rfind("0.001,0.05,0,-1,", 0), 0u) << first;

  std::ifstream md(dir / "accuracy_tables.md");
  const std::string tables((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(tables.find("| `pade-printed` |"), std::string::npos);
  EXPECT_NE(tables.find("frictionlab accuracy --out test"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Study, PlotScriptsAndFigures) {
  const auto& study = tiny_study();
  const auto dir = std::filesystem::temp_directory_path() /
                   ("frictionlab_accuracy_plots_" + std::to_string(::getpid()));
  PlotOptions opt;
  opt.draw = !detect_gnuplot_terminal().empty();
  std::ostringstream log;
  const auto rep = write_plots(study, dir, opt, &log);
  for (const char* name : {"heat_exact.gp", "heat_pade-printed.gp", "singular_pade-printed.gp",
                           "curves_mu0.5_psi45.gp", "curves_mu0.1_psi60.gp"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "plots" / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "plots" / "singular_exact.gp"));
  if (opt.draw) {
    EXPECT_TRUE(rep.failures.empty()) << log.str();
    EXPECT_EQ(rep.figures.size(), rep.scripts.size()) << log.str();
    EXPECT_TRUE(std::filesystem::exists(dir / "plots" / "heat_pade-printed.png"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::accuracy
