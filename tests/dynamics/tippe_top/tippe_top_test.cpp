// Tests of dynamics/tippe_top/: the inversion watch, Jellett's quantity and the tippe top of
// data/scenarios/tippe-top.toml (Leine & Glocker 2003). Expected values come from closed forms
// (interpolated crossings), conservation laws (Jellett's integral without a spin moment, its exact
// rate -M gamma.r with one, the energy balance) and the source (the top inverts).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "dynamics/body/body.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"
#include "dynamics/tippe_top/tippe_top_observables.h"
#include "dynamics/tippe_top/tippe_top_study.h"
#include "dynamics/tippe_top/tippe_top_study_report.h"
#include "slide_only_law.h"

namespace frictionlab::dynamics::tippe_top {
namespace tippe_top_test {

const std::filesystem::path kScenario =
    std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios" / "tippe-top.toml";

// Jellett's quantity is conserved to the integration error: steps of relative error ~1e-9 (the
// scenario's tolerances) over ~1e3-1e4 steps.
constexpr double kJellettTol = 1e-6;
// The trapezoidal rule for ∫ M gamma.r dt over samples 1e-4 s apart: M and gamma.r vary on the
// nutation's time scale (~1e-2 s), error ~ (1e-4/1e-2)^2 of the change at most.
constexpr double kIdentityTol = 1e-4;
// Energy: never rising beyond the integration error, and balanced by the friction work.
constexpr double kEnergyTol = 1e-7;

TEST(DynTippeTopObservables, InversionWatchInterpolatesTheCrossings) {
  InversionWatch w;
  w.add(0.0, 0.99);
  w.add(1.0, 0.5);
  w.add(2.0, -0.5);  // crosses 0 at t = 1.5
  w.add(3.0, -0.8);
  w.add(4.0, -1.0);  // crosses -0.9 at t = 3.5
  w.add(5.0, -0.95);
  EXPECT_TRUE(w.started_upright());
  EXPECT_DOUBLE_EQ(w.horizontal_time(), 1.5);
  EXPECT_DOUBLE_EQ(w.inversion_time(), 3.5);
  EXPECT_DOUBLE_EQ(w.min_gamma3(), -1.0);
  EXPECT_DOUBLE_EQ(w.min_gamma3_time(), 4.0);
}

TEST(DynTippeTopObservables, AnInversionNeedsAnUprightStart) {
  InversionWatch w;
  w.add(0.0, 0.5);  // not near +1
  w.add(1.0, -0.95);
  EXPECT_FALSE(w.started_upright());
  EXPECT_TRUE(std::isnan(w.inversion_time()));
  EXPECT_DOUBLE_EQ(w.horizontal_time(), 0.5 / 1.45);
}

TEST(DynTippeTopObservables, JellettsQuantityIsAngularMomentumDotContactPoint) {
  BodySpec spec;
  spec.preset = "sphere";
  spec.radius = 1.0;
  spec.mass = 10.0;
  spec.A = 2.0;
  spec.C = 3.0;
  const Body body = make_body(spec);
  StateVector x = make_state(Eigen::Vector3d::Zero(), {1.0, -2.0, 5.0}, Eigen::Vector3d::UnitZ(), 0.0);
  ContactState c;
  c.point.r = Eigen::Vector3d(0.5, 0.25, -1.0);
  c.gamma = Eigen::Vector3d(0.0, 0.6, 0.8);
  c.friction.M = 4.0;
  c.in_contact = true;
  EXPECT_DOUBLE_EQ(jellett_quantity(body, x, c), 2.0 * 0.5 + 2.0 * -2.0 * 0.25 + 3.0 * 5.0 * -1.0);
  EXPECT_DOUBLE_EQ(jellett_rate(c), -4.0 * (0.6 * 0.25 - 0.8));
  c.in_contact = false;
  EXPECT_EQ(jellett_rate(c), 0.0);
}

// Without a spin moment L.r is an exact integral of the motion of a sphere, whatever the sliding
// force (dynamics/tippe_top/tippe_top_observables.h).
// The spin moment's effect is the study's point: its default set must run the decoupled law with
// the exact pure-spin torque and without any spin moment, now that the registry has them.
TEST(DynTippeTopStudy, DefaultLawsIncludeTheSpinMomentVariants) {
  std::vector<std::string> unavailable;
  const auto laws = default_tippe_top_laws(&unavailable);
  EXPECT_TRUE(unavailable.empty());
  for (const std::string spec : {"exact", "decoupled", "decoupled:r_spin=0"})
    EXPECT_EQ(std::count(laws.begin(), laws.end(), spec), 1) << spec;
}

TEST(DynTippeTopStudy, LegendsShowLawSpecsAsTheyAre) {
  // The key of gamma3.png named decoupled:r_spin=0 as "decoupled:r" with a subscript "spin=0": a
  // '_' is markup to the enhanced-text terminal. The legend's text is escaped (support::gnuplot_text).
  TippeTopStudyResults r;
  r.laws = {"exact", "decoupled:r_spin=0"};
  for (const auto& law : r.laws) {
    TippeTopRun run;
    run.law = law;
    run.gamma3_curve = {{0.0, 1.0}, {1.0, -1.0}};
    run.jellett_curve = {{0.0, 1.0}, {1.0, 1.0}};
    r.runs.push_back(run);
  }
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "frictionlab_tippe_top_legend";
  std::filesystem::remove_all(out);
  (void)write_tippe_top_study(r, out, "test", true);  // figures not drawn (no gnuplot) are not this test's concern
  for (const char* script : {"gamma3.gp", "jellett.gp"}) {
    std::ifstream in(out / "figures" / script);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(text.find("title 'decoupled:r\\_spin=0'"), std::string::npos) << script << "\n" << text;
    EXPECT_EQ(text.find("r_spin"), std::string::npos) << script << "\n" << text;
  }
  std::filesystem::remove_all(out);
}

TEST(DynTippeTop, JellettsQuantityIsConservedWithoutASpinMoment) {
  const Scenario s = load_scenario(kScenario, {"run.t_end=0.5", "run.output_dt=1e-3"});
  const testing::SlideOnlyTestLaw law;
  const BodyOnPlane sys(s.body, s.contact, law);
  struct Jellett final : Observer {
    const Body* body = nullptr;
    double j0 = std::numeric_limits<double>::quiet_NaN(), worst = 0.0, slide = 0.0;
    void sample(const Sample& x) override {
      const double j = jellett_quantity(*body, x.x, x.contact);
      if (std::isnan(j0)) j0 = j;
      worst = std::max(worst, std::abs(j - j0) / std::abs(j0));
      slide = slide_work(x.x);
    }
  } obs;
  obs.body = &sys.body();
  const RunSummary r = simulate(sys, initial_state(s), s.run, &obs);
  ASSERT_EQ(r.reason, Termination::t_end) << r.message;
  EXPECT_GT(obs.slide, 0.0) << "the top slides: the sliding force acts";
  EXPECT_LT(obs.worst, kJellettTol);
}

// With the exact law's spin moment, L.r(t) - L.r(0) = -∫ M gamma.r dt, and the change is real.
TEST(DynTippeTop, ASpinMomentChangesJellettsQuantityByExactlyItsIntegral) {
  TippeTopStudyOptions o;
  o.output_dt = 1e-4;
  o.overrides = {"run.t_end=0.5"};
  const TippeTopRun run = run_tippe_top(kScenario, "exact", o);
  ASSERT_EQ(run.summary.reason, Termination::t_end) << run.summary.message;
  EXPECT_LT(run.jellett_identity_error, kIdentityTol * run.max_jellett_change);
  EXPECT_GT(run.max_jellett_change, 1e3 * kJellettTol) << "the spin moment does change L.r";
}

TEST(DynTippeTop, EnergyNeverRisesAndBalancesTheFrictionWork) {
  TippeTopStudyOptions o;
  o.overrides = {"run.t_end=0.5"};
  const TippeTopRun run = run_tippe_top(kScenario, "exact", o);
  ASSERT_EQ(run.summary.reason, Termination::t_end) << run.summary.message;
  EXPECT_LE(run.max_energy_rise, kEnergyTol);
  EXPECT_LE(run.energy_balance_error, kEnergyTol);
}

// The physical fact of the source (Leine & Glocker 2003; the inversion condition 1 - alpha < A/C <
// 1 + alpha holds): this top turns over. It must do so without any stop on the way, and end only
// after it (a false rest or stagnation during the fast spin would end it upright).
TEST(DynTippeTop, TheSourcesTopInvertsWithTheExactLaw) {
  const TippeTopRun run = run_tippe_top(kScenario, "exact", TippeTopStudyOptions{});
  EXPECT_TRUE(run.started_upright);
  ASSERT_TRUE(std::isfinite(run.inversion_time)) << "min gamma3 " << run.min_gamma3 << "; "
                                                 << to_string(run.summary.reason) << ": " << run.summary.message;
  EXPECT_LT(run.horizontal_time, run.inversion_time);
  EXPECT_LT(run.min_gamma3, kInvertedGamma3);
  EXPECT_GT(run.summary.t_final, run.inversion_time);
  const Termination end = run.summary.reason;
  EXPECT_TRUE(end == Termination::rest || end == Termination::rolling || end == Termination::t_end)
      << to_string(end) << ": " << run.summary.message;
  EXPECT_LE(run.max_energy_rise, kEnergyTol);
}

}  // namespace
}  // namespace frictionlab::dynamics::tippe_top
