// The distance between two runs' axes (dynamics/paper/divergence.h): exactly zero for identical
// runs; for two runs that differ only by the chaos floor's perturbation (tolerances x0.1), positive
// and growing.

#include "dynamics/paper/divergence.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"
#include "dynamics/paper/run_series.h"

namespace frictionlab::dynamics::paper {
namespace divergence_test {

namespace fs = std::filesystem;

std::array<std::vector<double>, 3> axis_of(const RunSeries& s) { return {s.axis_x, s.axis_y, s.axis_z}; }

RunSeries run(const std::vector<std::string>& overrides, const std::string& name) {
  const Scenario s = load_scenario(fs::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios" / "egg-printed-a.toml", overrides);
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_divergence_" + name + "_" + std::to_string(::getpid()));
  SeriesRecorder recorder(s.body.mass * s.contact.g);
  (void)run_scenario(s, dir, &recorder);
  fs::remove_all(dir);
  return recorder.series();
}

TEST(PaperDivergence, TheAngleBetweenTwoAxesIsExact) {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3};
  const double a = 1e-9;  // small: atan2 keeps it where acos of the dot product would lose it
  const std::array<std::vector<double>, 3> u = {std::vector<double>{0, 0, 0, 1}, {0, 0, 0, 0}, {1, 1, 1, 0}};
  const std::array<std::vector<double>, 3> v = {std::vector<double>{0, std::sin(a), std::sin(0.5), 0},
                                                {0, 0, 0, 1},
                                                {1, std::cos(a), std::cos(0.5), 0}};
  const DistanceSeries d = axis_distance(t, u, t, v);
  ASSERT_EQ(d.angle.size(), 4u);
  EXPECT_EQ(d.angle[0], 0.0);
  EXPECT_NEAR(d.angle[1], a, 1e-24);
  EXPECT_NEAR(d.angle[2], 0.5, 1e-15);
  EXPECT_NEAR(d.angle[3], std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(parting_time(d, 0.4), 0.2);
  EXPECT_TRUE(std::isnan(parting_time(d, 2.0)));
}

TEST(PaperDivergence, OnlyTheCommonSampleTimesAreCompared) {
  const std::array<std::vector<double>, 3> u = {std::vector<double>{0, 0, 0}, {0, 0, 0}, {1, 1, 1}};
  const DistanceSeries d = axis_distance({0.0, 0.1, 0.15}, u, {0.0, 0.1, 0.2}, u);  // the last differ
  EXPECT_EQ(d.t, (std::vector<double>{0.0, 0.1}));
  EXPECT_TRUE(axis_distance({0.0}, {}, {0.0}, u).t.empty());  // no axis recorded
}

TEST(PaperDivergence, IdenticalRunsAreExactlyZeroApartAndTheFloorsRunsPartMoreAndMore) {
  // The printed egg's case a for 3 s: the same run twice, and the run with both tolerances x0.1.
  const std::vector<std::string> common = {"run.t_end=3", "run.output_dt=0.01"};
  const RunSeries a = run(common, "a");
  const RunSeries again = run(common, "again");
  std::vector<std::string> tight = common;
  tight.insert(tight.end(), {"run.abs_tol=1e-10", "run.rel_tol=1e-10"});
  const RunSeries floor = run(tight, "floor");

  const DistanceSeries same = axis_distance(a.t, axis_of(a), again.t, axis_of(again));
  ASSERT_GT(same.t.size(), 250u);
  for (double angle : same.angle) EXPECT_EQ(angle, 0.0);

  const DistanceSeries d = axis_distance(a.t, axis_of(a), floor.t, axis_of(floor));
  ASSERT_GT(d.t.size(), 250u);
  EXPECT_EQ(d.angle[0], 0.0);  // the same start
  // Positive, and growing: the largest angle of each second exceeds the last second's.
  double previous = 0.0;
  for (int second = 0; second < 3; ++second) {
    double largest = 0.0;
    for (std::size_t i = 0; i < d.t.size(); ++i) {
      if (d.t[i] > second && d.t[i] <= second + 1) largest = std::max(largest, d.angle[i]);
    }
    EXPECT_GT(largest, previous) << "second " << second;
    previous = largest;
  }
  EXPECT_GT(previous, 1e-12);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
