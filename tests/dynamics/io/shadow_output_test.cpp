// Shadow laws on whole runs (run.shadow; dynamics/io/shadow_output.h, dynamics/core/shadow_laws.h):
// the run is unchanged, a law against itself is exactly right, and on motions whose answer is known
// (a sphere spinning in place, a sphere sliding fast) the errors are the laws' own.

#include "dynamics/io/shadow_output.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "bench/accuracy/study.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"
#include "dynamics/puck/puck_scenario.h"
#include "dynamics/puck/puck_scenario_run.h"
#include "friction/registry.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics {
namespace shadow_output_test {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab_shadow_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// shadow.csv as columns by name (no name in these tests needs quoting).
std::map<std::string, std::vector<double>> read_columns(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream h(line);
  for (std::string name; std::getline(h, name, ',');) names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::size_t i = 0;
    for (std::string cell; std::getline(r, cell, ','); ++i) columns[names.at(i)].push_back(std::stod(cell));
    EXPECT_EQ(i, names.size()) << line;
  }
  return columns;
}

const char* kSphere = R"(
[body]
profile = "sphere"
radius = 0.05
mass = 1
[contact]
k = 0.2
lambda = 1e7
law = "exact"
[initial]
gamma = [0, 0, 1]
eps = "static"
[run]
t_end = 0.1
output_dt = 0.005
)";

TEST(DynShadowOutput, ALawAgainstItselfIsExactlyRightAtEveryStateAndTheRunIsUnchanged) {
  // Sliding and spinning on a tilted sphere (every output of the law matters). `exact` and
  // `exact:pressure=hertz` are the same law: both shadows are exactly zero.
  const std::vector<std::string> motion = {"initial.v=[1.5, 0, 0]", "initial.omega=[0.3, 0, 15]",
                                           "initial.gamma=[0.1, 0, 0.99498743710662]"};
  std::vector<std::string> with = motion;
  with.push_back(R"(run.shadow=["exact", "exact:pressure=hertz"])");
  const auto plain_dir = fresh_dir("plain");
  const auto shadow_dir = fresh_dir("self");
  const ScenarioRun plain = run_scenario(parse_scenario(kSphere, "sphere.toml", motion), plain_dir);
  const ScenarioRun shadowed = run_scenario(parse_scenario(kSphere, "sphere.toml", with), shadow_dir);
  EXPECT_EQ(plain.summary.steps, shadowed.summary.steps);
  EXPECT_TRUE(slurp(plain.trajectory_csv) == slurp(shadowed.trajectory_csv)) << "the shadow changed the run";
  EXPECT_FALSE(std::filesystem::exists(plain_dir / "shadow.csv"));

  const auto c = read_columns(shadow_dir / "shadow.csv");
  ASSERT_EQ(c.at("t").size(), 21u);  // the trajectory's samples, t = 0, 0.005, ..., 0.1
  for (const char* law : {"exact", "exact:pressure=hertz"}) {
    for (const char* out : {"dF1", "dF2", "dM", "dP"}) {
      for (double v : c.at(std::string(out) + "[" + law + "]")) EXPECT_EQ(v, 0.0) << out << " " << law;
    }
  }
  const auto summary = support::Json::parse(slurp(shadowed.summary_json));
  const auto& s = summary["shadow"];
  EXPECT_EQ(s["steps"], shadowed.summary.steps);
  EXPECT_EQ(s["laws"].size(), 2u);
  for (const auto& law : s["laws"]) {
    EXPECT_EQ(law["errors"]["contact"]["F"]["max"], 0.0);
    EXPECT_EQ(law["errors"]["contact"]["M"]["max"], 0.0);
    EXPECT_EQ(law["difference_J"], 0.0);
    EXPECT_EQ(law["failures"], 0);
  }
  EXPECT_EQ(s["csv"]["rows"], 21);
  std::filesystem::remove_all(plain_dir);
  std::filesystem::remove_all(shadow_dir);
}

TEST(DynShadowOutput, OnASphereSpinningInPlaceTheErrorsAreThePureSpinErrors) {
  // v = 0, omega along the vertical: U = 0 exactly throughout, a circular Hertz patch (b/a = 1).
  // The exact pure-spin moment is (3/8) k N a E(0) = (3 pi/16) k N a (docs/model.md): each law's
  // shadow dM is its own pure-spin moment minus that, no law has a force at U = 0, and the
  // ellipsoidal law (Rb calibrated on it) is exact there.
  const auto dir = fresh_dir("spin");
  const std::vector<std::string> laws = {"ellipsoidal", "pade-printed", "pade-reconstructed", "mujoco-elliptic",
                                         "decoupled"};
  std::string list;
  for (const auto& l : laws) list += (list.empty() ? "" : ",") + l;
  const Scenario s = parse_scenario(kSphere, "sphere.toml", {"initial.omega=[0, 0, 20]", "run.shadow=" + list});
  const ScenarioRun run = run_scenario(s, dir);
  const auto c = read_columns(dir / "shadow.csv");
  std::vector<std::unique_ptr<friction::FrictionLaw>> made;
  for (const auto& l : laws) made.push_back(friction::make_law(l));
  const double M_exact_per_kNa = 3.0 * std::numbers::pi / 16.0;
  for (std::size_t row = 0; row < c.at("t").size(); ++row) {
    ASSERT_EQ(c.at("b_over_a")[row], 1.0);
    ASSERT_EQ(c.at("s")[row], 0.0);  // U = 0 exactly
    for (std::size_t i = 0; i < laws.size(); ++i) {
      const std::string& l = laws[i];
      EXPECT_EQ(c.at("dF1[" + l + "]")[row], 0.0) << l;
      EXPECT_EQ(c.at("dF2[" + l + "]")[row], 0.0) << l;
      // The law's own pure-spin moment on the row's patch (Omega > 0; at U = 0 only its sign matters).
      const double a = c.at("a")[row], N = c.at("N")[row], k = 0.2;
      const double M_law = made[i]->evaluate({0.0, 1.0, a, a, friction::PatchAngle(), N, k}).M / (k * N * a);
      EXPECT_NEAR(c.at("dM[" + l + "]")[row], M_law - M_exact_per_kNa, 1e-12) << l << " at row " << row;
    }
    EXPECT_NEAR(c.at("dM[ellipsoidal]")[row], 0.0, 1e-12);
  }
  const auto summary = support::Json::parse(slurp(run.summary_json));
  EXPECT_GT(summary["shadow"]["phase_time_s"]["rolling-spin"].get<double>(), 0.09);  // spins throughout
  std::filesystem::remove_all(dir);
}

TEST(DynShadowOutput, OnAFastSlideEveryLawsForceErrorIsWithinTheAccuracyStudysFastSlipBound) {
  // A sphere sliding at 2 m/s with a slow spin: s = U/(a |Omega|) stays above 100 for the 0.1 s.
  // The bound: each law's largest |F1 - exact| and |F2 - exact| per kN over the accuracy study's
  // region s > 10 (bench/accuracy/study.h), on a grid of its own (s from 10 to 1e4, b/a 0.5 and 1).
  accuracy::StudyOptions o;
  o.grid.s_points = 40;
  o.grid.s_min = 10.0;
  o.grid.s_max = 1e4;
  o.grid.mu_points = 2;
  o.grid.mu_min = 0.5;
  o.grid.psi_points = 5;
  o.threads = 1;
  const accuracy::StudyResult study = accuracy::run_study(o);
  std::size_t fast = 0;
  while (study.regions[fast].name != "s > 10") ++fast;

  std::string list;
  for (const auto& l : study.summaries) list += (list.empty() ? "" : ",") + l.law;
  const auto dir = fresh_dir("fast");
  const Scenario s = parse_scenario(kSphere, "sphere.toml",
                                    {"initial.v=[2, 0, 0]", "initial.omega=[0, 0, 1]", "run.shadow=" + list});
  (void)run_scenario(s, dir);
  const auto c = read_columns(dir / "shadow.csv");
  for (double v : c.at("s")) ASSERT_GT(v, 100.0);
  for (const auto& l : study.summaries) {
    const double bound_F1 = l.by_region[fast].error[0].max_abs;
    const double bound_F2 = l.by_region[fast].error[1].max_abs;
    ASSERT_TRUE(std::isfinite(bound_F1) && std::isfinite(bound_F2)) << l.law;
    for (double v : c.at("dF1[" + l.law + "]")) EXPECT_LE(std::abs(v), bound_F1) << l.law;
    for (double v : c.at("dF2[" + l.law + "]")) EXPECT_LE(std::abs(v), bound_F2) << l.law;
  }
  std::filesystem::remove_all(dir);
}

TEST(DynShadowOutput, TheOwnDissipationOfASlidingSphereFollowsItsClosedForm) {
  // A sphere launched at U0 without spin slides until it rolls: U(t) = U0 - (7/2) k g t for
  // t < t* = 2 U0/(7 k g), then rolls in stick (U = 0): the friction work is k m g U0 t*/2 =
  // m U0^2/7, and the trapezoidal rule over the steps (linear U) gets it. With Omega = 0 every law
  // gives F1 = kN, F2 = M = 0 (a promise of every law, friction/law.h): no law differs there.
  const auto dir = fresh_dir("slide");
  const double U0 = 2.0, m = 1.0;
  const Scenario s = parse_scenario(kSphere, "sphere.toml",
                                    {"initial.v=[2, 0, 0]", "run.t_end=0.5", "run.rest_slip_speed=1e-6",
                                     "run.shadow=pade-printed,ellipsoidal,decoupled"});
  const ScenarioRun run = run_scenario(s, dir);
  const auto summary = support::Json::parse(slurp(run.summary_json));
  const auto& sh = summary["shadow"];
  EXPECT_NEAR(sh["own_trapezoid_J"].get<double>(), m * U0 * U0 / 7.0, 1e-3 * m * U0 * U0 / 7.0);
  EXPECT_NEAR(sh["run_work_J"].get<double>(), m * U0 * U0 / 7.0, 1e-3 * m * U0 * U0 / 7.0);
  for (const auto& law : sh["laws"]) {
    EXPECT_EQ(law["difference_J"], 0.0) << law["law"];
    EXPECT_EQ(law["dissipated_J"], sh["run_work_J"]) << law["law"];
  }
  EXPECT_GT(sh["phase_time_s"]["sliding"].get<double>(), 0.0);
  EXPECT_GT(sh["phase_time_s"]["near-rest"].get<double>(), 0.0);  // rolls in stick after t*
  std::filesystem::remove_all(dir);
}

TEST(DynShadowOutput, ThePuckCarriesShadowLawsToo) {
  const auto dir = fresh_dir("puck");
  const std::string toml = R"(
model = "puck"
[puck]
a = 0.05
b = 0.02
mass = 1
[contact]
k = 0.3
law = "exact:pressure=uniform"
[initial]
v = [1, 0]
omega = 20
[run]
t_end = 2
output_dt = 0.01
)";
  const auto doc = ScenarioDocument::parse(toml, "puck.toml");
  const auto scenario = puck::resolve_puck(doc, {"run.shadow=[\"exact:pressure=uniform\", \"ellipsoidal\"]"});
  const puck::PuckScenarioRun run = puck::run_puck_scenario(scenario, dir);
  const auto c = read_columns(dir / "shadow.csv");
  for (double v : c.at("dM[exact:pressure=uniform]")) EXPECT_EQ(v, 0.0);
  double largest = 0.0;
  for (double v : c.at("dM[ellipsoidal]")) largest = std::max(largest, std::abs(v));
  EXPECT_GT(largest, 1e-3);  // a different law, visibly
  const auto summary = support::Json::parse(slurp(run.summary_json));
  EXPECT_EQ(summary["shadow"]["phase_time_s"]["bouncing"], 0.0);  // a rigid plane
  EXPECT_EQ(summary["shadow"]["laws"][1]["law"], "ellipsoidal");
  std::filesystem::remove_all(dir);
}

TEST(DynShadowOutput, ABadShadowSpecIsAnErrorNamingTheKey) {
  try {
    (void)parse_scenario(kSphere, "sphere.toml", {"run.shadow=[\"no-such-law\"]"});
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("run.shadow"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no-such-law"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)parse_scenario(kSphere, "sphere.toml", {"run.shadow=[1, 2]"}), std::invalid_argument);
  // A list in one string is the law-list grammar: specs with parameters stay whole.
  const Scenario s = parse_scenario(kSphere, "sphere.toml", {"run.shadow=exact:pressure=uniform,ellipsoidal"});
  ASSERT_EQ(s.run.shadow.size(), 2u);
  EXPECT_EQ(s.run.shadow[0], "exact:pressure=uniform");
  EXPECT_EQ(s.run.shadow[1], "ellipsoidal");
}

TEST(DynShadowOutput, ALawNameWithACommaIsQuotedInTheHeader) {
  EXPECT_EQ(shadow_csv_header({"a:x=1,y=2"}),
            "t,phase,s,b_over_a,a,psi,N,\"dF1[a:x=1,y=2]\",\"dF2[a:x=1,y=2]\",\"dM[a:x=1,y=2]\",\"dP[a:x=1,y=2]\"\n");
}

}  // namespace
}  // namespace frictionlab::dynamics
