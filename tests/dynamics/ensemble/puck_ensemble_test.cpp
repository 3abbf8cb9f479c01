// `frictionlab ensemble` on a puck scenario (`model = "puck"`, docs/puck.md): the study machinery
// runs the puck model with its own features. The same table from 1 and 2 threads; a run's features
// equal those of `frictionlab simulate` on the same scenario with the same overrides (the puck's own
// path, independent of the ensemble); a bad model and replicas of the non-chaotic puck are one line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "dynamics/ensemble/csv_row.h"
#include "friction/support/json.h"
#include "tests/cli/cli_runner.h"
#include "tests/dynamics/ensemble/runs_csv_reader.h"

namespace frictionlab {
namespace puck_ensemble_test {

namespace fs = std::filesystem;
using testing::run_frictionlab;
using testing::runs_without_wall_time;
using testing::slurp;

const fs::path kScenarios = fs::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";

// A puck study in `dir`: puck-ellipse.toml (2:1 plate) at three initial speeds, two laws.
fs::path write_puck_study(const fs::path& dir, const std::string& name, const std::string& extra = "") {
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << "scenario = \"" << (kScenarios / "puck-ellipse.toml").string() << "\"\n"
                   << "laws = [\"exact\", \"pade-reconstructed\"]\n"
                   << "set = [\"run.output_dt=0.01\", \"puck.b=0.03\"]\n"
                   << extra << "[[vary]]\nkey = \"initial.v1\"\nvalues = [0.25, 1, 4]\n";
  return p;
}

std::vector<std::string> header_of(const fs::path& runs_csv) {
  const std::string text = slurp(runs_csv);
  return dynamics::ensemble::split_csv_line(text.substr(0, text.find('\n')));
}

double field(const std::vector<std::string>& header, const std::vector<std::string>& row, const std::string& column) {
  const auto it = std::find(header.begin(), header.end(), column);
  EXPECT_NE(it, header.end()) << column;
  if (it == header.end()) return std::nan("");
  const std::string& f = row.at(static_cast<std::size_t>(it - header.begin()));
  return f.empty() ? std::nan("") : std::stod(f);
}

TEST(EnsemblePuck, APuckStudyGivesTheSameRunsWithOneThreadAndWithTwo) {
  const fs::path dir = testing::fresh_temp_dir("ensemble_puck_threads");
  const fs::path study = write_puck_study(dir, "p.toml");
  const auto r1 = run_frictionlab("ensemble " + study.string() + " --out " + (dir / "one").string() +
                                  " --threads 1 --no-figures");
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  const auto r2 = run_frictionlab("ensemble " + study.string() + " --out " + (dir / "two").string() +
                                  " --threads 2 --no-figures");
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  const auto a = runs_without_wall_time(dir / "one" / "runs.csv");
  ASSERT_EQ(a.size(), 7u) << "a header and 3 starts x 2 laws";
  EXPECT_EQ(runs_without_wall_time(dir / "two" / "runs.csv"), a);
  // The puck's own columns, not the body's.
  const auto h = header_of(dir / "one" / "runs.csv");
  for (const char* c : {"slip_stop_time", "spin_stop_time", "terminal_ratio", "path_lateral", "work_slide", "work_spin"})
    EXPECT_NE(std::find(h.begin(), h.end(), c), h.end()) << c;
  for (const char* c : {"t_vertical", "final_gamma3", "liftoffs"}) EXPECT_EQ(std::find(h.begin(), h.end(), c), h.end()) << c;
  // Every run stops (a circle or not, every coupled law brings the puck to rest in ~1 s).
  for (std::size_t i = 1; i < a.size(); ++i) EXPECT_NE(a[i].find(",rest,"), std::string::npos) << a[i];
  const std::string report = slurp(dir / "one" / "report.md");
  EXPECT_NE(report.find("slip_stop_time"), std::string::npos) << report;
  EXPECT_EQ(report.find("t_vertical"), std::string::npos) << "the body's features are not the puck's";
  fs::remove_all(dir);
}

TEST(EnsemblePuck, ARunHasTheFeaturesOfThePuckRunOfTheSameScenario) {
  const fs::path dir = testing::fresh_temp_dir("ensemble_puck_features");
  const fs::path study = write_puck_study(dir, "p.toml");
  ASSERT_EQ(run_frictionlab("ensemble " + study.string() + " --out " + (dir / "e").string() + " --threads 1 --no-figures")
                .exit_code,
            0);
  const auto h = header_of(dir / "e" / "runs.csv");
  const auto rows = testing::rows_by_run(dir / "e" / "runs.csv");
  // Run 3: start 1 (v1 = 1 m/s), law 1 (pade-reconstructed). The same scenario through `simulate`.
  const auto row = dynamics::ensemble::split_csv_line(rows.at(3));
  ASSERT_EQ(row.at(3), "pade-reconstructed");
  const auto sim = run_frictionlab("simulate " + (kScenarios / "puck-ellipse.toml").string() + " --out " +
                                   (dir / "s").string() +
                                   " --set run.output_dt=0.01 --set puck.b=0.03 --set initial.v=[1,0]"
                                   " --set contact.law=pade-reconstructed");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto j = support::Json::parse(slurp(dir / "s" / "summary.json"));
  const auto same = [&](const std::string& column, double expected) {
    EXPECT_DOUBLE_EQ(field(h, row, column), expected) << column;
  };
  same("t_final", j.at("final_time").get<double>());
  same("slip_stop_time", j.at("slip_stop_time").get<double>());
  same("spin_stop_time", j.at("spin_stop_time").get<double>());
  same("terminal_ratio", j.at("terminal_ratio").get<double>());
  same("path_along", j.at("path").at("along_initial_velocity").get<double>());
  same("path_lateral", j.at("path").at("lateral_deviation").get<double>());
  same("turned", j.at("path").at("heading_turned").get<double>());
  same("work_slide", j.at("work_sliding").get<double>());
  same("work_spin", j.at("work_spinning").get<double>());
  same("steps", j.at("steps").get<double>());
  EXPECT_EQ(row.at(4 + 1), j.at("termination").at("reason").get<std::string>()) << "reason after the one varied key";
  // The elliptic plate's path bends (F2 of an elliptic patch), the work balances the energy.
  EXPECT_GT(std::abs(field(h, row, "path_lateral")), 1e-5);
  EXPECT_NEAR(field(h, row, "work_slide") + field(h, row, "work_spin"), j.at("initial_energy").get<double>(),
              1e-9 * j.at("initial_energy").get<double>());
  // The compared law's run has no shadow columns; the reference's run (run 2) has them, equal to
  // `simulate --shadow` on its scenario.
  EXPECT_TRUE(std::isnan(field(h, row, "shadow_F_median[pade-reconstructed]")));
  const auto ref = dynamics::ensemble::split_csv_line(rows.at(2));
  ASSERT_EQ(ref.at(3), "exact");
  const auto shadowed = run_frictionlab("simulate " + (kScenarios / "puck-ellipse.toml").string() + " --out " +
                                        (dir / "r").string() +
                                        " --set run.output_dt=0.01 --set puck.b=0.03 --set initial.v=[1,0]"
                                        " --set contact.law=exact --shadow pade-reconstructed");
  ASSERT_EQ(shadowed.exit_code, 0) << shadowed.err;
  const auto law = support::Json::parse(slurp(dir / "r" / "summary.json")).at("shadow").at("laws").at(0);
  const auto& errors = law.at("errors").at("contact");
  EXPECT_EQ(field(h, ref, "shadow_F_median[pade-reconstructed]"), errors.at("F").at("median").get<double>());
  EXPECT_EQ(field(h, ref, "shadow_F_max[pade-reconstructed]"), errors.at("F").at("max").get<double>());
  EXPECT_EQ(field(h, ref, "shadow_M_median[pade-reconstructed]"), errors.at("M").at("median").get<double>());
  EXPECT_EQ(field(h, ref, "shadow_dE[pade-reconstructed]"), law.at("difference_J").get<double>());
  EXPECT_EQ(field(h, ref, "shadow_failures[pade-reconstructed]"), 0.0);
  EXPECT_GT(field(h, ref, "shadow_F_median[pade-reconstructed]"), 0.0);
  fs::remove_all(dir);
}

TEST(EnsemblePuck, ABadModelOrReplicasOfThePuckAreOneLine) {
  const fs::path dir = testing::fresh_temp_dir("ensemble_puck_bad");
  const fs::path bad_model = write_puck_study(dir, "bad_model.toml", "");
  {
    std::string text = slurp(bad_model);
    text.replace(text.find("\"puck.b=0.03\""), 13, "\"model=rocket\"");
    std::ofstream(bad_model, std::ios::trunc) << text;
  }
  const fs::path replicas = write_puck_study(dir, "replicas.toml", "[replicas]\ncount = 2\nsize = 1e-6\n");
  const fs::path body_key = dir / "body_key.toml";
  {
    std::string text = slurp(write_puck_study(dir, "tmp.toml"));
    text.replace(text.find("initial.v1"), 10, "initial.gamma3");
    std::ofstream(body_key) << text;
  }
  const fs::path out = dir / "out";
  for (const auto& [study, says] : {std::pair{bad_model, std::string("model")}, std::pair{replicas, std::string("replicas")},
                                    std::pair{body_key, std::string("initial.gamma3")}}) {
    const auto r = run_frictionlab("ensemble " + study.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 1) << study;
    EXPECT_EQ(r.err.rfind("frictionlab: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << study;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab
