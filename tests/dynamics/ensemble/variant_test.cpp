// A study's variants LAW@PATCH (dynamics/ensemble/variant.h): the law under another contact model,
// on the same starts as the reference, compared by the same statistics as a law.

#include "dynamics/ensemble/variant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "dynamics/ensemble/ensemble_plan.h"
#include "dynamics/ensemble/feature_comparison.h"
#include "dynamics/ensemble/task_execution.h"
#include "dynamics/body/scenario_run.h"

namespace frictionlab::dynamics::ensemble {
namespace variant_test {

const std::filesystem::path kStudies = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "studies";
const std::filesystem::path kScenario = kStudies / ".." / "scenarios" / "egg-printed-a.toml";

// Case a of the printed egg for 0.4 s, two replicas: `exact` (the scenario's section patch), the
// same model named explicitly, and the Hertz patch.
const std::string kStudy = R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "exact@section", "exact@hertz"]
set = ["run.t_end=0.4", "run.output_dt=0.01"]
[replicas]
count = 2
size = 1e-9
)";

EnsemblePlan plan(const std::string& text) { return EnsemblePlan::make(parse_study(text, "t.toml", kStudies)); }

std::map<long, RunRecord> run_all(const EnsemblePlan& p) {
  std::map<long, RunRecord> out;
  for (long t = 0; t < p.tasks(); ++t) {
    TaskOrder order;
    order.task = p.task(t);
    for (long i = 0; i < p.runs(); ++i) order.todo.push_back(i);
    EXPECT_TRUE(execute_task(p, order, {}, [&](FinishedRun&& r) { out[r.record.run] = r.record; }));
  }
  return out;
}

std::string error_of(const std::string& text) {
  try {
    (void)plan(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EnsembleVariant, SplitsTheLawFromItsContactModel) {
  const Variant h = parse_variant("exact@hertz", "laws[1]");
  EXPECT_EQ(h.law, "exact");
  EXPECT_EQ(h.patch, "hertz");
  EXPECT_EQ(variant_overrides(h), (std::vector<std::string>{"contact.law=exact", "contact.patch=hertz"}));
  const Variant l = parse_variant("decoupled:r_spin=0", "laws[0]");
  EXPECT_EQ(l.law, "decoupled:r_spin=0");
  EXPECT_EQ(l.patch, "");
  EXPECT_EQ(variant_overrides(l), (std::vector<std::string>{"contact.law=decoupled:r_spin=0"}));
}

TEST(EnsembleVariant, BadVariantsAreOneLineNamingTheirKey) {
  for (const std::string bad : {"@hertz", "exact@", "exact@hertz@section"}) {
    std::string message;
    try {
      (void)parse_study("scenario = \"x.toml\"\nlaws = [\"exact\", \"" + bad + "\"]\n", "t.toml", kStudies);
    } catch (const std::invalid_argument& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("t.toml: laws[1] = '" + bad + "' is invalid"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // Known at planning: the contact model, and a study that sets the patch twice.
  const std::string unknown = error_of(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "exact@herz"]
)");
  EXPECT_NE(unknown.find("laws[1] = 'exact@herz' is invalid"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("known: section, hertz"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find('\n'), std::string::npos) << unknown;
  const std::string bad_law = error_of(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "nolaw@hertz"]
)");
  EXPECT_NE(bad_law.find("laws[1] = 'nolaw@hertz' is invalid"), std::string::npos) << bad_law;
  const std::string twice = error_of(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "exact@hertz"]
set = ["contact.patch=hertz"]
)");
  EXPECT_NE(twice.find("set[0] = 'contact.patch=hertz' is invalid"), std::string::npos) << twice;
  // Without variants the study may still set the patch of every run.
  EXPECT_EQ(error_of(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "pade-reconstructed"]
set = ["contact.patch=hertz"]
)"),
            "");
}

TEST(EnsembleVariant, EveryVariantOfAReplicaStartsTheSameUnderItsOwnModel) {
  const EnsemblePlan p = plan(kStudy);
  for (long replica = 0; replica < 2; ++replica) {
    const Scenario ref = p.scenario({0, replica, 0});
    const Scenario hertz = p.scenario({0, replica, 2});
    EXPECT_EQ(ref.contact.patch, PatchModel::section);
    EXPECT_EQ(p.scenario({0, replica, 1}).contact.patch, PatchModel::section);
    EXPECT_EQ(hertz.contact.patch, PatchModel::hertz);
    EXPECT_EQ(hertz.law, "exact");
    EXPECT_GT(hertz.contact.E_star, 0.0);
    EXPECT_EQ(hertz.initial.gamma, ref.initial.gamma);
    EXPECT_EQ(hertz.initial.omega, ref.initial.omega);
    EXPECT_EQ(hertz.initial.v, ref.initial.v);
  }
}

TEST(EnsembleVariant, TheSameModelNamedTwiceIsAtZeroDistanceAndTheHertzPatchIsNot) {
  const EnsemblePlan p = plan(kStudy);
  const auto rows = run_all(p);
  ASSERT_EQ(rows.size(), 6u);
  for (long replica = 0; replica < 2; ++replica) {
    const RunRecord& a = rows.at(p.run_index({0, replica, 0}));
    const RunRecord& b = rows.at(p.run_index({0, replica, 1}));
    const RunRecord& h = rows.at(p.run_index({0, replica, 2}));
    EXPECT_EQ(b.law, "exact@section");
    EXPECT_EQ(h.law, "exact@hertz");
    EXPECT_EQ(b.steps, a.steps);
    EXPECT_EQ(b.work_slide, a.work_slide);
    EXPECT_EQ(b.work_spin, a.work_spin);
    EXPECT_EQ(b.diverge_ref, "exact");
    EXPECT_TRUE(std::isnan(b.t_diverge)) << "identical runs never part";
    EXPECT_EQ(h.diverge_ref, "exact");
    // A patch sqrt(2) smaller at the same load dissipates spin more slowly (docs/contact-models.md §2).
    EXPECT_NE(h.work_spin, a.work_spin);
    EXPECT_LT(h.work_spin, a.work_spin);
  }
  std::vector<RunRecord> list;
  for (const auto& [i, r] : rows) list.push_back(r);
  for (const auto& c : compare_features(list, p.study().laws)) {
    if (c.law != "exact@section" || c.summary.finite == 0) continue;
    EXPECT_EQ(c.distances.w1, 0.0) << c.feature;
    EXPECT_EQ(c.distances.ks, 0.0) << c.feature;
    EXPECT_EQ(c.distances.p, 1.0) << c.feature;
  }
}

TEST(EnsembleVariant, AHertzVariantsRunIsTheSingleRunOfTheScenarioWithTheHertzPatch) {
  const EnsemblePlan p = plan(R"(scenario = "../scenarios/egg-printed-a.toml"
laws = ["exact", "exact@hertz"]
set = ["run.t_end=0.4", "run.output_dt=0.01"]
)");
  const auto rows = run_all(p);
  const RunRecord& h = rows.at(p.run_index({0, 0, 1}));
  // What `frictionlab simulate egg-printed-a.toml --set ... --set contact.patch=hertz` runs.
  const Scenario s = ScenarioDocument::read(kScenario).resolve({"run.t_end=0.4", "run.output_dt=0.01", "contact.patch=hertz"});
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab-variant-" + std::to_string(::getpid()));
  const ScenarioRun single = run_scenario(s, dir);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(h.reason, to_string(single.summary.reason));
  EXPECT_EQ(h.t_final, single.summary.t_final);
  EXPECT_EQ(h.steps, single.summary.steps);
  EXPECT_EQ(h.liftoffs, single.summary.liftoffs);
  EXPECT_EQ(h.work_slide, slide_work(single.summary.x_final));
  EXPECT_EQ(h.work_spin, spin_work(single.summary.x_final));
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
