// What the paper job keeps of a run and reads back (dynamics/paper/run_record.h): thinning,
// the comparison series, and summary.json read back to the same numbers.

#include "dynamics/paper/run_record.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "dynamics/body/scenario.h"
#include "dynamics/body/summary_json.h"

namespace frictionlab::dynamics::paper {
namespace run_record_test {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_run_record_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(PaperRunRecord, ThinnedRowsCountTheFirstEveryNthAndTheLast) {
  EXPECT_EQ(thinned_rows(0, 10), 0);
  EXPECT_EQ(thinned_rows(1, 10), 1);
  EXPECT_EQ(thinned_rows(2, 10), 2);     // 0 and the last
  EXPECT_EQ(thinned_rows(11, 10), 2);    // 0, 10 (the last)
  EXPECT_EQ(thinned_rows(12, 10), 3);    // 0, 10, 11
  EXPECT_EQ(thinned_rows(15731, 10), 1574);
  EXPECT_EQ(thinned_rows(7, 1), 7);
}

TEST(PaperRunRecord, ThinCsvKeepsTheHeaderEveryNthRowAndTheLast) {
  const fs::path dir = scratch("thin");
  std::string text = "t,x\n";
  for (int i = 0; i < 12; ++i) text += std::to_string(i) + "," + std::to_string(i * i) + "\n";
  std::ofstream(dir / "a.csv") << text;
  EXPECT_EQ(thin_csv(dir / "a.csv", 5), 4);
  EXPECT_EQ(slurp(dir / "a.csv"), "t,x\n0,0\n5,25\n10,100\n11,121\n");
  EXPECT_EQ(csv_data_rows(dir / "a.csv"), 4);
  EXPECT_EQ(thin_csv(dir / "a.csv", 1), 4);  // nothing to do
  EXPECT_EQ(csv_data_rows(dir / "missing.csv"), -1);
  EXPECT_THROW((void)thin_csv(dir / "missing.csv", 5), std::runtime_error);
  fs::remove_all(dir);
}

TEST(PaperRunRecord, TheComparisonSeriesReadsBackBitForBit) {
  const fs::path dir = scratch("series");
  ComparisonSeries full;
  for (int i = 0; i <= 25; ++i) {
    full.t.push_back(0.01 * i);
    full.gamma3.push_back(1.0 / (3.0 + i));
    full.gamma3_smooth.push_back(-0.1 * i / 7.0);
    full.axis_x.push_back(std::sin(0.1 * i) / 3.0);
    full.axis_y.push_back(-std::cos(0.1 * i) / 7.0);
    full.axis_z.push_back(1.0 / (1.0 + i));
  }
  const ComparisonSeries thinned = thin_series(full, 10);
  ASSERT_EQ(thinned.t.size(), 4u);  // 0, 10, 20, 25
  EXPECT_EQ(thinned.t[3], full.t[25]);
  EXPECT_EQ(thinned.axis_y[2], full.axis_y[20]);
  write_comparison_series(dir / "gamma3.csv", thinned);
  const ComparisonSeries back = read_comparison_series(dir / "gamma3.csv");
  EXPECT_EQ(back.t, thinned.t);
  EXPECT_EQ(back.gamma3, thinned.gamma3);
  EXPECT_EQ(back.gamma3_smooth, thinned.gamma3_smooth);
  EXPECT_EQ(back.axis_x, thinned.axis_x);
  EXPECT_EQ(back.axis_y, thinned.axis_y);
  EXPECT_EQ(back.axis_z, thinned.axis_z);
  std::ofstream(dir / "bad.csv") << "t,gamma3,gamma3_mean_1s,axis_x,axis_y,axis_z\n0,1,2,3,4\n";
  EXPECT_THROW((void)read_comparison_series(dir / "bad.csv"), std::runtime_error);
  std::ofstream(dir / "long.csv") << "t,gamma3,gamma3_mean_1s,axis_x,axis_y,axis_z\n0,1,2,3,4,5,6\n";
  EXPECT_THROW((void)read_comparison_series(dir / "long.csv"), std::runtime_error);
  // A record of an older job (without the axis) is not read back: the run is done again.
  std::ofstream(dir / "old.csv") << "t,gamma3,gamma3_mean_1s\n0,1,2\n";
  EXPECT_THROW((void)read_comparison_series(dir / "old.csv"), std::runtime_error);
  fs::remove_all(dir);
}

TEST(PaperRunRecord, EveryTerminationReasonIsFoundByItsName) {
  for (int i = 0; i <= static_cast<int>(Termination::flat_face); ++i) {
    const auto t = static_cast<Termination>(i);
    EXPECT_EQ(termination_named(to_string(t)), t) << to_string(t);
  }
  EXPECT_FALSE(termination_named("resting").has_value());
}

// summary.json as dynamics writes it, read back: the fields the report uses, to the last bit.
TEST(PaperRunRecord, ASummaryReadsBackToTheSameNumbers) {
  const Scenario scenario =
      load_scenario(fs::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios" / "sphere-sliding.toml");
  RunSummary s;
  s.reason = Termination::law_pole;
  s.message = "the denominator of F2 passes through 0";
  s.rule = "a rule";
  s.t_final = 0.3162729541;
  s.steps = 261;
  s.rejected_steps = 12;
  s.rhs_calls = 4480;
  s.samples = 33;
  s.sample_rhs_calls = 3792;
  s.hermite_samples = 1;
  s.wall_time = 0.0123;
  s.liftoffs = 5;
  s.landings = 4;
  s.min_normal_force = 0.1 * 9.81 / 3.0;
  s.initial_energy = 281.67508546461;
  s.final_energy = 1.0 / 3.0;
  s.max_gamma_drift = 6e-10;
  s.x_final = make_state({0.1, -0.2, 0.3}, {1.0 / 7.0, 2.0, -3.0}, {0.6, 0.0, 0.8}, -1.5e-4);
  slide_work(s.x_final) = 244.7;
  spin_work(s.x_final) = -0.0137;
  const double weight = scenario.body.mass * scenario.contact.g;

  const RunSummary b = summary_from_json(support::Json::parse(support::json_text(summary_json(scenario, s))), weight);
  EXPECT_EQ(b.reason, s.reason);
  EXPECT_EQ(b.message, s.message);
  EXPECT_EQ(b.rule, s.rule);
  EXPECT_EQ(b.t_final, s.t_final);
  EXPECT_EQ(b.steps, s.steps);
  EXPECT_EQ(b.rejected_steps, s.rejected_steps);
  EXPECT_EQ(b.rhs_calls, s.rhs_calls);
  EXPECT_EQ(b.samples, s.samples);
  EXPECT_EQ(b.sample_rhs_calls, s.sample_rhs_calls);
  EXPECT_EQ(b.hermite_samples, s.hermite_samples);
  EXPECT_EQ(b.wall_time, s.wall_time);
  EXPECT_EQ(b.liftoffs, s.liftoffs);
  EXPECT_EQ(b.landings, s.landings);
  EXPECT_NEAR(b.min_normal_force, s.min_normal_force, 1e-15 * s.min_normal_force);  // through N/(m g)
  EXPECT_EQ(b.initial_energy, s.initial_energy);
  EXPECT_EQ(b.final_energy, s.final_energy);
  EXPECT_EQ(b.max_gamma_drift, s.max_gamma_drift);
  EXPECT_EQ(b.x_final, s.x_final);

  support::Json broken = summary_json(scenario, s);
  broken["termination"]["reason"] = "resting";
  EXPECT_THROW((void)summary_from_json(broken, weight), std::runtime_error);
  broken = summary_json(scenario, s);
  broken.erase("steps");
  EXPECT_THROW((void)summary_from_json(broken, weight), std::runtime_error);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
