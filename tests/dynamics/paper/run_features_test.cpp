// Feature extraction (dynamics/paper/run_features.h) on synthetic trajectories with known answers.

#include "dynamics/paper/run_features.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace frictionlab::dynamics::paper {
namespace run_features_test {

constexpr double kDt = 0.01;  // s, the paper command's sample interval
// Sampled times are on a 0.01 s grid and the moving averages are 1 s and 5 s wide: event times
// can be off by a sample plus the lag of a window edge.
constexpr double kTimeTol = 0.05;  // s
// A 10 Hz nutation of amplitude kNutation averaged over an integer number of periods leaves
// nothing; at the clipped ends of the run a fraction of a period remains.
constexpr double kNutation = 0.003;
constexpr double kNutationHz = 10.0;

// A run sampled every kDt on [0, t_end] with gamma3 = f(t) and contact everywhere.
RunSeries synthetic(double t_end, const std::function<double(double)>& f) {
  RunSeries s;
  const long n = std::lround(t_end / kDt);
  for (long i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) * kDt;
    s.push(t, f(t), 1.0, 0.0, 0.0, 0.01, 1.0, 1.0, 0.0, 0.0, 0.0, true);
  }
  return s;
}

double nutation(double t) { return kNutation * std::sin(2.0 * std::numbers::pi * kNutationHz * t); }

// Smooth step from a to b centred at t0 with width w (tanh).
double step(double t, double t0, double w, double a, double b) { return a + (b - a) * 0.5 * (1.0 + std::tanh((t - t0) / w)); }

// Case (a) as the paper tells it: up to the vertical, a short spin there, a fast tilt to
// gamma3 = -0.5, a long plateau, a slow descent to the other pole; nutation on top.
double case_a(double t) {
  double g = step(t, 1.0, 0.3, 0.97, 1.0);                 // to the vertical by ~2 s
  g = step(t, 10.0, 1.0, g, -0.5);                          // tilt around t = 10 s
  g = step(t, 60.0, 8.0, g, -1.0);                          // slow descent around t = 60 s
  return std::clamp(g + (t > 12.0 ? nutation(t) : 0.0), -1.0, 1.0);
}

TEST(PaperRunFeatures, MovingAverageOfConstantRampAndSine) {
  const RunSeries c = synthetic(10.0, [](double) { return 0.3; });
  for (const double m : moving_average(c.t, c.gamma3, 1.0)) EXPECT_NEAR(m, 0.3, 1e-14);

  const RunSeries ramp = synthetic(10.0, [](double t) { return 0.1 * t; });
  const auto mr = moving_average(ramp.t, ramp.gamma3, 1.0);
  for (std::size_t i = 100; i + 100 < mr.size(); ++i) EXPECT_NEAR(mr[i], ramp.gamma3[i], 1e-12) << ramp.t[i];
  EXPECT_GT(mr.front(), ramp.gamma3.front());  // clipped at the start: the window lies ahead

  const RunSeries sine = synthetic(10.0, nutation);
  const auto ms = moving_average(sine.t, sine.gamma3, 1.0);
  for (std::size_t i = 100; i + 100 < ms.size(); ++i) EXPECT_NEAR(ms[i], 0.0, 0.02 * kNutation) << sine.t[i];
}

TEST(PaperRunFeatures, CaseALikeRun) {
  const RunSeries s = synthetic(100.0, case_a);
  const RunFeatures f = extract_features(s);
  EXPECT_EQ(f.first_move, 1);
  EXPECT_NEAR(f.gamma3_initial, case_a(0.0), 1e-15);

  // The vertical: |gamma3| > 0.999 first where the step to 1 crosses it.
  ASSERT_TRUE(f.vertical.reached);
  EXPECT_EQ(f.vertical.pole, 1);
  double t_cross = 0.0;
  while (case_a(t_cross) <= 0.999) t_cross += kDt;
  EXPECT_NEAR(f.vertical.t_reached, t_cross, kTimeTol);
  // Left when the 1-s mean falls below 0.99, during the tilt centred at 10 s; then it moves on.
  ASSERT_TRUE(f.vertical.left);
  EXPECT_GT(f.vertical.t_left, 7.0);
  EXPECT_LT(f.vertical.t_left, 10.0);

  // Plateau at -0.5 (120 deg), reached after the tilt, held until the descent starts.
  ASSERT_TRUE(f.plateau.found);
  EXPECT_NEAR(f.plateau.gamma3, -0.5, 0.01);
  EXPECT_NEAR(f.plateau.tilt_deg(), 120.0, 1.0);
  EXPECT_GT(f.plateau.t_start, 12.0);
  EXPECT_LT(f.plateau.t_start, 20.0);
  EXPECT_FALSE(f.plateau.lasts_to_end);
  EXPECT_GT(f.plateau.t_end, 45.0);
  EXPECT_LT(f.plateau.t_end, 60.0);

  // Descent: the nutation's peak-to-peak, 2 kNutation. The 1-s mean of the curved descent is off
  // by at most |g''| W^2/24 ~ 1.3e-4 on each side, which the tolerance covers.
  EXPECT_NEAR(f.descent_oscillation, 2.0 * kNutation, 0.2 * kNutation);
  // At the end gamma3 = max(-1, -1 + nutation): the mean of the clipped sine is -1 + kNutation/pi.
  EXPECT_NEAR(f.gamma3_final_mean, -1.0 + kNutation / std::numbers::pi, 1e-4);
  EXPECT_NEAR(f.max_abs_gamma3, 1.0, 1e-12);
}

TEST(PaperRunFeatures, CaseCLikeRunRisesWithoutReachingTheVertical) {
  // From -0.02 toward -1, settling at -0.5: no vertical spin, a plateau, a rise that stops short.
  // (The nutation starts late: as in the real egg-printed-c run, an early nutation could make the
  // first motion go the other way for a few hundredths of a second.)
  const RunSeries s =
      synthetic(60.0, [](double t) { return step(t, 3.0, 1.0, -0.02, -0.5) + (t > 8.0 ? nutation(t) : 0.0); });
  const RunFeatures f = extract_features(s);
  EXPECT_EQ(f.first_move, -1);
  EXPECT_FALSE(f.vertical.reached);
  EXPECT_FALSE(f.near_vertical.reached);
  ASSERT_TRUE(f.plateau.found);
  EXPECT_NEAR(f.plateau.t_from, 0.0, 1e-15);
  EXPECT_NEAR(f.plateau.gamma3, -0.5, 0.01);
  EXPECT_TRUE(f.plateau.lasts_to_end);
  EXPECT_NEAR(f.rise_extreme, 0.5, kNutation + 1e-3);  // -gamma3 at its largest before the plateau
  EXPECT_TRUE(std::isnan(f.descent_oscillation));
}

TEST(PaperRunFeatures, AVerticalReachedOnlyAtTheEndIsNotASpin) {
  // Slowly to the pole and staying there, rocking by 0.005 about it (the end of a run).
  const RunSeries s = synthetic(40.0, [](double t) { return std::min(1.0, -0.2 + 0.05 * t) - (t > 24 ? 0.005 * std::abs(std::sin(3.0 * t)) : 0.0); });
  const RunFeatures f = extract_features(s);
  ASSERT_TRUE(f.vertical.reached);
  EXPECT_EQ(f.vertical.pole, 1);
  EXPECT_FALSE(f.vertical.left);
  EXPECT_NEAR(f.vertical.duration(f.t_final), f.t_final - f.vertical.t_reached, 1e-12);
}

TEST(PaperRunFeatures, LiftOffsAreCountedBetweenSamplesAndBeforeThePlateau) {
  RunSeries s = synthetic(20.0, [](double t) { return step(t, 3.0, 0.5, -0.02, -0.5); });
  const auto lift = [&](double t0, double t1) {
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s.t[i] >= t0 && s.t[i] < t1) s.in_contact[i] = 0;
  };
  lift(1.0, 1.05);    // two flights while rising
  lift(2.0, 2.2);
  lift(15.0, 15.01);  // one on the plateau
  const RunFeatures f = extract_features(s);
  ASSERT_TRUE(f.plateau.found);
  EXPECT_GT(f.plateau.t_start, 2.2);
  EXPECT_LT(f.plateau.t_start, 15.0);
  EXPECT_EQ(f.sampled_liftoffs, 3);
  EXPECT_EQ(f.sampled_liftoffs_before_plateau, 2);
  EXPECT_NEAR(f.last_sampled_liftoff, 15.0, 1e-9);
}

TEST(PaperRunFeatures, EmptyAndShortRuns) {
  const RunFeatures empty = extract_features(RunSeries{});
  EXPECT_TRUE(std::isnan(empty.t_final));
  EXPECT_FALSE(empty.vertical.reached);
  EXPECT_FALSE(empty.plateau.found);

  const RunSeries one = synthetic(0.0, [](double) { return 0.97; });
  const RunFeatures f1 = extract_features(one);
  EXPECT_EQ(f1.t_final, 0.0);
  EXPECT_EQ(f1.first_move, 0);
  EXPECT_FALSE(f1.plateau.found);
}

TEST(PaperRunFeatures, InvalidThresholdsAreRejected) {
  const RunSeries s = synthetic(1.0, [](double) { return 0.5; });
  for (const auto& change : std::vector<std::function<void(FeatureThresholds&)>>{
           [](FeatureThresholds& t) { t.vertical = 1.0; },
           [](FeatureThresholds& t) { t.near_vertical = 0.9995; },
           [](FeatureThresholds& t) { t.smoothing_window = 0.0; },
           [](FeatureThresholds& t) { t.plateau_window = -1.0; },
           [](FeatureThresholds& t) { t.plateau_band = std::nan(""); },
           [](FeatureThresholds& t) { t.plateau_rate = 0.0; },
           [](FeatureThresholds& t) { t.first_move = 0.0; }}) {
    FeatureThresholds th;
    change(th);
    EXPECT_THROW((void)extract_features(s, th), std::invalid_argument);
  }
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
