// Every run of a study, numbered and grouped into tasks (dynamics/ensemble/ensemble_plan.h).

#include "dynamics/ensemble/ensemble_plan.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <stdexcept>

#include "dynamics/rigid_rolling/inertia_misalignment.h"

namespace frictionlab::dynamics::ensemble {
namespace ensemble_plan_test {

const std::filesystem::path kStudies = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "studies";

Study study(const std::string& text) { return parse_study(text, "t.toml", kStudies); }

const std::string kGrid = R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "pade-reconstructed", "moller-ellipsoidal"]
set = ["run.t_end=0.5"]
[[vary]]
key = "initial.gamma3"
values = [0.9, 0.5]
[[vary]]
key = "initial.omega3"
min = 10
max = 30
points = 3
[replicas]
count = 3
size = 1e-6
)";

TEST(EnsemblePlan, RunsAreNumberedStartReplicaLaw) {
  const EnsemblePlan p = EnsemblePlan::make(study(kGrid));
  EXPECT_EQ(p.starts(), 6);
  EXPECT_EQ(p.replicas(), 3);
  EXPECT_EQ(p.laws(), 3);
  EXPECT_EQ(p.runs(), 54);
  for (long i = 0; i < p.runs(); ++i) EXPECT_EQ(p.run_index(p.run_id(i)), i);
  const RunId id = p.run_id(p.run_index({.start = 4, .replica = 2, .law = 1}));
  EXPECT_EQ(id.start, 4);
  EXPECT_EQ(id.replica, 2);
  EXPECT_EQ(id.law, 1);
  EXPECT_EQ(p.start_values(0), (std::vector<double>{0.9, 10.0}));
  EXPECT_EQ(p.start_values(5), (std::vector<double>{0.5, 30.0}));
}

TEST(EnsemblePlan, TasksPairReplicasAndCoverEveryRunOnce) {
  const EnsemblePlan p = EnsemblePlan::make(study(kGrid));
  EXPECT_EQ(p.pairs_per_start(), 2);
  EXPECT_EQ(p.tasks(), 12);
  std::multiset<long> runs;
  for (long t = 0; t < p.tasks(); ++t) {
    const Task task = p.task(t);
    EXPECT_LE(task.replica_count, 2);
    for (long r = task.first_replica; r < task.first_replica + task.replica_count; ++r)
      for (int law = 0; law < p.laws(); ++law) runs.insert(p.run_index({task.start, r, law}));
  }
  EXPECT_EQ(runs.size(), static_cast<std::size_t>(p.runs()));
  EXPECT_EQ(std::set<long>(runs.begin(), runs.end()).size(), runs.size());
  EXPECT_EQ(p.task(1).first_replica, 2);
  EXPECT_EQ(p.task(1).replica_count, 1) << "three replicas: pairs (0, 1) and (2)";
}

TEST(EnsemblePlan, ARunsScenarioHasItsStartReplicaAndLaw) {
  const EnsemblePlan p = EnsemblePlan::make(study(kGrid));
  const Scenario s = p.scenario({.start = 3, .replica = 0, .law = 2});  // gamma3 0.5, omega3 10
  EXPECT_EQ(s.law, "moller-ellipsoidal");
  EXPECT_NEAR(s.initial.gamma[2], 0.5, 1e-15);  // the scenario normalises gamma again
  EXPECT_NEAR(s.initial.gamma[0], std::sqrt(0.75), 1e-15);
  EXPECT_EQ(s.initial.omega, Eigen::Vector3d(0.0, 0.0, 10.0));
  EXPECT_EQ(s.run.t_end, 0.5) << "the study's set";
  EXPECT_EQ(p.overrides({3, 0, 2}).back(), "contact.law=moller-ellipsoidal");
  // Replicas of one start differ a little; the laws of one replica share the start exactly.
  const Scenario r1 = p.scenario({3, 1, 0});
  EXPECT_NE(r1.initial.gamma, s.initial.gamma);
  EXPECT_LT((r1.initial.gamma - s.initial.gamma).norm(), 1e-5);
  EXPECT_EQ(p.scenario({3, 1, 1}).initial.gamma, r1.initial.gamma);
  EXPECT_EQ(p.scenario({3, 1, 1}).initial.omega, r1.initial.omega);
}

TEST(EnsemblePlan, HashIdentifiesTheStudyAndItsScenario) {
  const EnsemblePlan a = EnsemblePlan::make(study(kGrid));
  EXPECT_EQ(a.hash().size(), 16u);
  EXPECT_EQ(EnsemblePlan::make(study(kGrid)).hash(), a.hash());
  EXPECT_NE(EnsemblePlan::make(study("seed = 2\n" + kGrid)).hash(), a.hash());
  EXPECT_EQ(EnsemblePlan::make(study("# a comment\n" + kGrid)).hash(), a.hash()) << "comments do not count";
  // The same study text over another scenario file.
  const auto dir = std::filesystem::temp_directory_path() / "frictionlab_plan_hash";
  std::filesystem::create_directories(dir / "studies");
  std::filesystem::create_directories(dir / "scenarios");
  std::filesystem::copy_file(kStudies / "../scenarios/egg-printed-a.toml", dir / "scenarios/egg-printed-a.toml",
                             std::filesystem::copy_options::overwrite_existing);
  const auto other = [&] { return EnsemblePlan::make(parse_study(kGrid, "t.toml", dir / "studies")).hash(); };
  EXPECT_EQ(other(), a.hash());
  std::ofstream(dir / "scenarios/egg-printed-a.toml", std::ios::app) << "# a comment\n";
  EXPECT_EQ(other(), a.hash()) << "comments do not count";
  {
    std::ifstream in(dir / "scenarios/egg-printed-a.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("k = 0.1"), 7, "k = 0.2");
    std::ofstream(dir / "scenarios/egg-printed-a.toml", std::ios::trunc) << text;
  }
  EXPECT_NE(other(), a.hash()) << "a changed value of the scenario";
  std::filesystem::remove_all(dir);
}

TEST(EnsemblePlan, SampledDesignsMapTheUnitBoxOntoTheAxes) {
  const EnsemblePlan p = EnsemblePlan::make(study(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact"]
[design]
type = "sobol"
points = 3
[[vary]]
key = "initial.gamma3"
min = 0.2
max = 0.6
[[vary]]
key = "contact.k"
min = 0.01
max = 1
scale = "log"
)"));
  ASSERT_EQ(p.starts(), 3);
  // Sobol's first point (0.5, 0.5): the middle of the linear axis, the geometric middle of the log one.
  EXPECT_NEAR(p.start_values(0)[0], 0.4, 1e-15);
  EXPECT_NEAR(p.start_values(0)[1], 0.1, 1e-15);
  EXPECT_NEAR(p.start_values(1)[0], 0.5, 1e-15);  // 0.75
  EXPECT_NEAR(p.scenario({1, 0, 0}).contact.k, std::pow(10.0, -2.0 + 0.25 * 2.0), 1e-15);
}

// body.misalignment reaches the run through the base scenario's body: the run's tensor is the
// base's turned to the start's angle (measured by the rigid_rolling module's own convention), the
// same for every replica and law of the start, and its resolved scenario writes it.
TEST(EnsemblePlan, AMisalignmentStartTurnsTheBaseBodysInertia) {
  const EnsemblePlan p = EnsemblePlan::make(study(R"(scenario = "../scenarios/rattleback-reversal.toml"
laws = ["exact", "ellipsoidal"]
[[vary]]
key = "body.misalignment"
values = [0.03, -0.005]
[replicas]
count = 2
size = 1e-6
)"));
  const Eigen::Matrix3d base = p.base().body.inertia;
  for (const long start : {0L, 1L}) {
    const double delta = start == 0 ? 0.03 : -0.005;
    const Scenario s = p.scenario({.start = start, .replica = 1, .law = 1});
    EXPECT_NEAR(rigid_rolling::misalignment_angle(s.body.inertia), delta, 1e-14);
    EXPECT_NEAR(s.body.inertia.trace(), base.trace(), 1e-15 * base.trace()) << "the moments kept";
    EXPECT_EQ(s.body.inertia(2, 2), base(2, 2));
    EXPECT_EQ(p.scenario({start, 0, 0}).body.inertia, s.body.inertia);
    EXPECT_EQ(ScenarioDocument::parse(s.resolved_toml, "resolved").resolve().body.inertia, s.body.inertia)
        << "the resolved scenario reproduces the tensor to the bit";
  }
  // A body of revolution has equal horizontal moments: nothing to turn, an error before any run.
  try {
    (void)EnsemblePlan::make(study("scenario = \"../scenarios/egg-printed-a.toml\"\nlaws = [\"exact\"]\n[[vary]]\n"
                                   "key = \"body.misalignment\"\nvalues = [0.01]\n"));
    ADD_FAILURE() << "the egg accepted body.misalignment";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("vary[0] = 'body.misalignment'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("J11 = J22"), std::string::npos) << e.what();
  }
}

// The shadow laws of the reference's runs: by default the law of every compared variant under the
// reference's contact model, once each, never the reference's own; or the study's list.
TEST(EnsemblePlan, TheShadowLawsAreTheComparedLawsUnderTheReferencesContactModel) {
  const std::string head = "scenario = \"../scenarios/egg-printed-a.toml\"\n";
  const auto shadow = [&](const std::string& rest) { return EnsemblePlan::make(study(head + rest)).shadow_laws(); };
  using L = std::vector<std::string>;
  EXPECT_EQ(shadow("laws = [\"exact\", \"pade-reconstructed\", \"moller-ellipsoidal\"]\n"),
            (L{"pade-reconstructed", "moller-ellipsoidal"}));
  EXPECT_EQ(shadow("laws = [\"exact@section\", \"exact@hertz\", \"ellipsoidal@hertz\", \"ellipsoidal@section\"]\n"),
            (L{"ellipsoidal"}));
  EXPECT_EQ(shadow("laws = [\"exact\", \"exact@hertz\", \"ellipsoidal\", \"ellipsoidal@hertz\"]\n"), (L{"ellipsoidal"}));
  EXPECT_EQ(shadow("laws = [\"exact\"]\n"), L{});
  EXPECT_EQ(shadow("laws = [\"exact\", \"ellipsoidal\"]\nshadow = false\n"), L{});
  EXPECT_EQ(shadow("laws = [\"exact\"]\nshadow = [\"decoupled\", \"exact\"]\n"), (L{"decoupled", "exact"}));
}

TEST(EnsemblePlan, BadKeysLawsAndScenariosAreOneLineNamingThem) {
  const std::string head = "scenario = \"../scenarios/egg-printed-a.toml\"\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "laws = [\"exact\", \"pade-imagined\"]\n", "laws[1] = 'pade-imagined'"},
      {head + "laws = [\"exact\"]\n[[vary]]\nkey = \"contact.kk\"\nvalues = [1]\n", "vary[0] = 'contact.kk'"},
      {head + "laws = [\"exact\"]\n[[vary]]\nkey = \"contact.k\"\nmin = -1\nmax = 1\npoints = 2\n", "vary[0] = 'contact.k' is invalid: at min"},
      {head + "laws = [\"exact\"]\n[[vary]]\nkey = \"initial.gamma3\"\nmin = 0\nmax = 2\npoints = 2\n", "at max"},
      {head + "laws = [\"exact\"]\n[[vary]]\nkey = \"initial.omega\"\nvalues = [1]\n", "vary[0].key = 'initial.omega'"},
      {head + "laws = [\"exact\"]\nset = [\"contact.law=exact\"]\n", "set[0] = 'contact.law=exact'"},
      {head + "laws = [\"exact\"]\nset = [\"run.t_edn=1\"]\n", "run.t_edn"},
      // A study's shadow laws are its `shadow` key, not the scenario's run.shadow for every run.
      {head + "laws = [\"exact\"]\nset = [\"run.shadow=ellipsoidal\"]\n", "run.shadow is set"},
      {head + "laws = [\"exact\"]\nshadow = [\"pade-imagined\"]\n", "shadow[0] = 'pade-imagined'"},
      {"scenario = \"no-such.toml\"\nlaws = [\"exact\"]\n", "no-such.toml"},
  };
  for (const auto& [text, key] : cases) {
    try {
      (void)EnsemblePlan::make(study(text));
      ADD_FAILURE() << "accepted:\n" << text;
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(key), std::string::npos) << m;
      EXPECT_EQ(m.rfind("t.toml: ", 0), 0u) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
}

// Every shipped study plans (its keys exist in its scenario at both ends of their ranges), and the
// puck's and the tippe top's are planned with their model.
TEST(EnsemblePlan, ShippedStudiesPlanWithTheirModel) {
  for (const auto& entry : std::filesystem::directory_iterator(kStudies)) {
    if (entry.path().extension() != ".toml") continue;
    const EnsemblePlan p = EnsemblePlan::make(read_study(entry.path()));
    const std::string stem = entry.path().stem().string();
    EXPECT_EQ(p.model(), stem.rfind("puck", 0) == 0 ? RunModel::puck : RunModel::body) << stem;
  }
  const EnsemblePlan puck = EnsemblePlan::make(read_study(kStudies / "puck-map.toml"));
  EXPECT_EQ(puck.runs(), 32 * 10 * 6);
  // Start 0: the first key (initial.v1) and the second (puck.b) at their minimum.
  const puck::PuckScenario s = puck.puck_scenario({0, 0, 1});
  EXPECT_DOUBLE_EQ(s.initial.v.x(), 0.05);
  EXPECT_DOUBLE_EQ(s.puck.b, 0.005);
  EXPECT_DOUBLE_EQ(s.puck.inertia, 7.5e-5) << "kappa = 0.3 fixed by the study's set";
  EXPECT_EQ(s.law, "pade-reconstructed");
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
