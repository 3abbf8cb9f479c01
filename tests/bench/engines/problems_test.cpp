// The problems of the engines' side by side (bench/engines/problems.h), their measures
// (bench/engines/measures.h) and frictionlab's own rows against the closed forms.
#include "bench/engines/problems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "bench/engines/frictionlab_runs.h"
#include "bench/engines/measures.h"

namespace frictionlab::engines {
namespace problems_test {

const std::filesystem::path kScenarios = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";

const Problem& find(const std::vector<Problem>& problems, const std::string& id) {
  for (const Problem& p : problems) {
    if (p.id == id) return p;
  }
  throw std::runtime_error("no problem " + id);
}

std::filesystem::path temp(const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "engine_problems" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(EngineProblems, TheSpinDownClosedFormIsTheSpinMomentOfAHertzPatchOnASolidSphere) {
  // C omega' = -(3 pi/16) k m g a with C = (2/5) m R^2 (docs/engines.md §6): T = C omega0/M0.
  const double m = 1.3, R = 0.04, k = 0.25, g = 9.81, a = 2e-3, w0 = 17.0;
  const double C = 0.4 * m * R * R, M0 = 3.0 * std::numbers::pi / 16.0 * k * m * g * a;
  EXPECT_NEAR(spin_down_time(w0, R, k, g, a), C * w0 / M0, 1e-12 * C * w0 / M0);
  // Sliding: v' = -k g, R omega' = (5/2) k g (C = 2/5 m R^2) until v = R omega.
  const double v0 = 2.0, ts = slide_to_roll_time(v0, k, g);
  EXPECT_NEAR(v0 - k * g * ts, 2.5 * k * g * ts, 1e-12);
  EXPECT_NEAR((v0 - k * g * ts) / v0, 5.0 / 7.0, 1e-15);
}

TEST(EngineProblems, AreBuiltFromTheShippedScenarios) {
  const auto problems = make_problems(kScenarios);
  ASSERT_EQ(problems.size(), 4u);
  const Problem& top = find(problems, "tippe-top");
  EXPECT_DOUBLE_EQ(top.spec.body.radius, 0.015);
  EXPECT_DOUBLE_EQ(top.spec.body.com[2], -0.003);
  EXPECT_DOUBLE_EQ(top.spec.body.inertia[0], 8e-7);
  EXPECT_DOUBLE_EQ(top.spec.body.inertia[2], 7e-7);
  // Tilted by 0.1 rad, spinning at 180 1/s about its axis (world frame).
  EXPECT_NEAR(axis_vertical(top.spec.start.orientation), std::cos(0.1), 1e-12);
  const auto& w = top.spec.start.omega;
  EXPECT_NEAR(std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), 180.0, 1e-9);
  EXPECT_NEAR(w[2], 180.0 * std::cos(0.1), 1e-9);
  // The tippe top's static patch: 0.5 mm by the scenario's choice of lambda.
  EXPECT_NEAR(top.patch_radius, 5e-4, 1e-6);
  EXPECT_NEAR(top.spin_c, 3.0 * std::numbers::pi / 16.0, 1e-9);
  const Problem& puck = find(problems, "puck");
  EXPECT_EQ(puck.spec.body.shape, Body::Shape::disk);
  EXPECT_NEAR(puck.spin_c, 2.0 / 3.0, 1e-9);  // uniform pressure on a circle
  // The classical terminal ratio of the uniform disk (Farkas et al. 2003), to its three digits.
  EXPECT_NEAR(puck.answer, 0.653, 5e-4);
  const Problem& spin = find(problems, "spin-down");
  // a = sqrt(2 R |eps_s|), |eps_s| = (m g/lambda)^(2/3): the section of the sphere at its static depth.
  const double eps = std::cbrt(std::pow(9.81 / 1e7, 2.0));
  EXPECT_NEAR(spin.patch_radius, std::sqrt(2.0 * 0.05 * eps), 1e-9);
}

TEST(EngineProblems, MissingScenarioFolderIsAnError) {
  EXPECT_THROW((void)make_problems(kScenarios / "no-such-folder"), std::exception);
}

TEST(EngineFrictionlabRows, TheSpinDownFallsTo1PercentAt099TheClosedFormTime) {
  const auto problems = make_problems(kScenarios);
  const Problem& p = find(problems, "spin-down");
  const FrictionlabRun r = run_frictionlab(p, p.law, temp("spin"));
  const Measure m = measure(p, r.run.samples);
  const double T = spin_down_time(20.0, 0.05, 0.2, 9.81, p.patch_radius);
  EXPECT_NEAR(m.value, 0.99 * T, 1e-6 * T);
}

TEST(EngineFrictionlabRows, TheSlidingSphereRollsAtFiveSeventhsFromTheClosedFormTime) {
  const auto problems = make_problems(kScenarios);
  const Problem& p = find(problems, "slide-to-roll");
  const FrictionlabRun r = run_frictionlab(p, p.law, temp("slide"));
  const Measure m = measure(p, r.run.samples);
  EXPECT_NEAR(m.value, 5.0 / 7.0, 1e-6 * 5.0 / 7.0);
  // The slip falls linearly to zero at t_s: to 1 % of v0 at 0.99 t_s.
  const double ts = slide_to_roll_time(2.0, 0.2, 9.81);
  EXPECT_NEAR(m.time, 0.99 * ts, 1e-6 * ts);
}

// Samples of a body spinning about the vertical, its spin falling linearly to zero at T.
std::vector<Sample> linear_spin_down(double w0, double T, double dt) {
  std::vector<Sample> out;
  for (int i = 0; i * dt <= 1.5 * T; ++i) {
    Sample s;
    s.t = i * dt;
    s.omega[2] = std::max(0.0, w0 * (1.0 - s.t / T));
    out.push_back(s);
  }
  return out;
}

TEST(EngineMeasures, SpinDownIsInterpolatedExactlyForALinearDecay) {
  Problem p;
  p.id = "spin-down";
  const Measure m = measure(p, linear_spin_down(20.0, 3.5, 0.07));  // T on a sample: the decay is linear between samples
  EXPECT_NEAR(m.value, 0.99 * 3.5, 1e-12);
  EXPECT_NEAR(m.time, 0.999 * 3.5, 1e-12);
}

TEST(EngineMeasures, TippeTopInversionIsWhenTheAxisPassesMinus09) {
  // The axis turns at a constant rate from 0.1 rad to pi: gamma3 = cos(theta), below -0.9 at
  // theta = acos(-0.9), horizontal at pi/2.
  Problem p;
  p.id = "tippe-top";
  std::vector<Sample> samples;
  const double rate = 1.0;  // rad/s
  for (int i = 0; i <= 40000; ++i) {
    Sample s;
    s.t = i * 1e-4;
    const double theta = std::min(std::numbers::pi, 0.1 + rate * s.t);
    s.orientation = {std::cos(0.5 * theta), std::sin(0.5 * theta), 0.0, 0.0};
    samples.push_back(s);
  }
  const Measure m = measure(p, samples);
  EXPECT_NEAR(m.value, (std::acos(-0.9) - 0.1) / rate, 1e-6);
  EXPECT_NEAR(m.time, (0.5 * std::numbers::pi - 0.1) / rate, 1e-6);
}

TEST(EngineMeasures, EmptyRunAndUnknownProblemAreErrors) {
  Problem p;
  p.id = "spin-down";
  EXPECT_THROW((void)measure(p, {}), std::invalid_argument);
  p.id = "juggling";
  EXPECT_THROW((void)measure(p, linear_spin_down(1.0, 1.0, 0.1)), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::engines
