// Study files (dynamics/ensemble/study.h): every key read, defaults, and one clear line for each
// kind of bad input, naming the key.

#include "dynamics/ensemble/study.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace frictionlab::dynamics::ensemble {
namespace study_test {

const std::filesystem::path kFolder = "/studies";

Study parse(const std::string& text) { return parse_study(text, "s.toml", kFolder); }

constexpr const char* kMinimal = R"(scenario = "../scenarios/x.toml"
laws = ["exact"]
)";

TEST(EnsembleStudy, MinimalStudyHasOneStartOneReplicaAndDefaults) {
  const Study s = parse(kMinimal);
  EXPECT_EQ(s.name, "s");
  EXPECT_EQ(s.scenario, std::filesystem::path("/studies/../scenarios/x.toml"));
  EXPECT_EQ(s.laws, std::vector<std::string>{"exact"});
  EXPECT_EQ(s.reference_law(), "exact");
  EXPECT_EQ(s.design, DesignKind::grid);
  EXPECT_TRUE(s.vary.empty());
  EXPECT_EQ(s.replicas, 1);
  EXPECT_EQ(s.seed, 1u);
  EXPECT_EQ(s.trajectory_dt, 0.1);
  EXPECT_TRUE(s.shadow_compared) << "the compared laws shadow the reference by default";
  EXPECT_TRUE(s.shadow_laws.empty());
  EXPECT_EQ(s.text, kMinimal);
}

TEST(EnsembleStudy, ShadowIsTheComparedLawsNoneOrAList) {
  const Study off = parse(std::string(kMinimal) + "shadow = false\n");
  EXPECT_FALSE(off.shadow_compared);
  EXPECT_TRUE(off.shadow_laws.empty());
  const Study on = parse(std::string(kMinimal) + "shadow = true\n");
  EXPECT_TRUE(on.shadow_compared);
  const Study listed = parse(std::string(kMinimal) + "shadow = [\"ellipsoidal\", \"decoupled\"]\n");
  EXPECT_FALSE(listed.shadow_compared);
  EXPECT_EQ(listed.shadow_laws, (std::vector<std::string>{"ellipsoidal", "decoupled"}));
}

TEST(EnsembleStudy, EveryKeyIsRead) {
  const Study s = parse(R"(name = "n"
description = "d"
scenario = "/abs/x.toml"
laws = ["exact", "pade-printed"]
set = ["run.t_end=2", "run.output_dt=0.01"]
seed = 17
[design]
type = "lhs"
points = 12
[[vary]]
key = "initial.gamma3"
min = 0.1
max = 0.9
[[vary]]
key = "contact.k"
min = 0.01
max = 1
scale = "log"
[replicas]
count = 4
size = 1e-7
[output]
trajectory_dt = 0.5
)");
  EXPECT_EQ(s.name, "n");
  EXPECT_EQ(s.description, "d");
  EXPECT_EQ(s.scenario, std::filesystem::path("/abs/x.toml"));
  EXPECT_EQ(s.laws.size(), 2u);
  EXPECT_EQ(s.set.size(), 2u);
  EXPECT_EQ(s.seed, 17u);
  EXPECT_EQ(s.design, DesignKind::lhs);
  EXPECT_EQ(s.points, 12);
  ASSERT_EQ(s.vary.size(), 2u);
  EXPECT_EQ(s.vary[0].key, "initial.gamma3");
  EXPECT_EQ(s.vary[1].scale, AxisScale::log);
  EXPECT_EQ(s.replicas, 4);
  EXPECT_EQ(s.replica_size, 1e-7);
  EXPECT_EQ(s.trajectory_dt, 0.5);
}

TEST(EnsembleStudy, AxesMapTheUnitIntervalLinearlyOrLogarithmically) {
  VariedAxis lin{.key = "k", .min = 2.0, .max = 6.0, .points = 5, .values = {}, .scale = AxisScale::linear};
  EXPECT_EQ(lin.grid(), (std::vector<double>{2, 3, 4, 5, 6}));
  EXPECT_EQ(lin.at(0.25), 3.0);
  VariedAxis log = lin;
  log.min = 1e-3;
  log.max = 1e1;
  log.scale = AxisScale::log;
  const auto g = log.grid();
  const double expected[5] = {1e-3, 1e-2, 1e-1, 1.0, 1e1};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(g[static_cast<std::size_t>(i)], expected[i], 1e-15 * expected[i] * 10) << i;
  EXPECT_EQ(log.grid().back(), 1e1) << "the end point is exact";
  VariedAxis listed = lin;
  listed.values = {0.3, 0.1};
  EXPECT_EQ(listed.grid(), (std::vector<double>{0.3, 0.1})) << "explicit values keep their order";
}

// Each bad study gives one line that names the key (and the file).
struct BadStudy {
  std::string text;
  std::string key;  // must appear in the message
};

TEST(EnsembleStudy, BadStudiesAreOneLineNamingTheKey) {
  const std::string base = "scenario = \"x.toml\"\nlaws = [\"exact\"]\n";
  const std::vector<BadStudy> cases = {
      {"laws = [\"exact\"]\n", "scenario is required"},
      {"scenario = \"x.toml\"\n", "laws is required"},
      {"scenario = \"x.toml\"\nlaws = []\n", "laws must list"},
      {"scenario = \"x.toml\"\nlaws = [\"exact\", \"exact\"]\n", "laws[1]"},
      {"scenario = \"x.toml\"\nlaws = \"exact\"\n", "laws must be an array"},
      {base + "sead = 3\n", "unknown key sead"},
      {base + "shadow = 3\n", "shadow must be true, false or an array"},
      {base + "shadow = [\"ellipsoidal\", \"ellipsoidal\"]\n", "shadow[1] = 'ellipsoidal'"},
      {base + "shadow = [1]\n", "shadow[0] must be a string"},
      {base + "seed = -1\n", "seed = -1"},
      {base + "seed = 1.5\n", "seed must be an integer"},
      {base + "set = [\"run.t_end\"]\n", "set[0]"},
      {base + "[design]\ntype = \"sobl\"\n", "design.type = 'sobl'"},
      {base + "[design]\ntype = \"sobol\"\npoints = 4\n", "needs at least one [[vary]]"},
      {base + "[design]\ntype = \"random\"\n[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\n", "design.points is required"},
      {base + "[design]\ntype = \"random\"\npoints = 0\n[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\n", "design.points = 0"},
      {base + "[design]\npoints = 4\n", "design.points is for"},
      {base + "[design]\nkind = \"grid\"\n", "unknown key design.kind"},
      {base + "[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\n", "vary[0].points is required"},
      {base + "[[vary]]\nkey = \"contact.k\"\nmin = 1\nmax = 1\npoints = 3\n", "vary[0].max = 1"},
      {base + "[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\npoints = 1\n", "vary[0].points = 1"},
      {base + "[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\npoints = 3\nscale = \"log\"\n", "vary[0].min = 0"},
      {base + "[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\npoints = 3\nscale = \"cubic\"\n", "vary[0].scale = 'cubic'"},
      {base + "[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\npoints = 3\nstep = 1\n", "unknown key vary[0].step"},
      {base + "[[vary]]\nkey = \"contact.k\"\nvalues = [1, 2, 1]\n", "vary[0].values[2]"},
      {base + "[[vary]]\nkey = \"contact.k\"\nvalues = [1]\nmin = 0\n", "vary[0].values replaces"},
      {base + "[[vary]]\nkey = \"contact.k\"\nvalues = [\"a\"]\n", "vary[0].values[0] must be a number"},
      {base + "[[vary]]\nmin = 0\nmax = 1\npoints = 2\n", "vary[0].key is required"},
      {base + "[[vary]]\nkey = \"contact.k\"\nvalues = [1]\n[[vary]]\nkey = \"contact.k\"\nvalues = [2]\n", "vary[1].key = 'contact.k'"},
      {base + "[design]\ntype = \"lhs\"\npoints = 3\n[[vary]]\nkey = \"contact.k\"\nmin = 0\nmax = 1\npoints = 3\n", "vary[0].points is for grid"},
      {base + "vary = 3\n", "vary must be an array of tables"},
      {base + "[replicas]\ncount = 0\n", "replicas.count = 0"},
      {base + "[replicas]\ncount = 4\n", "replicas.size is required"},
      {base + "[replicas]\ncount = 4\nsize = 0.5\n", "replicas.size = 0.5"},
      {base + "[replicas]\ncount = 4\nsize = 1e-6\nseed = 2\n", "unknown key replicas.seed"},
      {base + "[output]\ntrajectory_dt = 0\n", "output.trajectory_dt = 0"},
      {base + "[output]\ntrajectory_dt = nan\n", "output.trajectory_dt = nan"},
      {base + "laws = [\"x\"]\n", "s.toml:3:"},  // TOML syntax: a redefined key, with line:column
  };
  for (const auto& c : cases) {
    try {
      (void)parse(c.text);
      ADD_FAILURE() << "accepted:\n" << c.text;
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(c.key), std::string::npos) << "message: " << m << "\nstudy:\n" << c.text;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_EQ(m.rfind("s.toml", 0), 0u) << "names the file first: " << m;
    }
  }
}

TEST(EnsembleStudy, AFolderOrAMissingFileIsAnError) {
  EXPECT_THROW((void)read_study("/"), std::invalid_argument);
  EXPECT_THROW((void)read_study("/no/such/study.toml"), std::invalid_argument);
}

// A table or dotted key 40000 deep made toml++ recurse out of the stack (a segmentation fault);
// the study reader refuses it first, naming the rule (dynamics/io/toml_nesting.h).
TEST(EnsembleStudy, ADeeplyNestedStudyIsRefusedNotACrash) {
  constexpr int kDeep = 40000;
  std::string dotted;
  for (int i = 0; i < kDeep; ++i) dotted += i ? ".a" : "a";
  for (const std::string& text : {"[" + dotted + "]\n", dotted + " = 1\n",
                                  "x = " + std::string(kDeep, '[') + std::string(kDeep, ']') + "\n"}) {
    try {
      (void)parse(text);
      ADD_FAILURE() << text.substr(0, 40) << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("s.toml:1: nested more than 64 levels deep"), std::string::npos)
          << e.what();
    }
  }
}

TEST(EnsembleStudy, ShippedStudiesRead) {
  const auto dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "studies";
  int n = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    ++n;
    const Study s = read_study(entry.path());
    EXPECT_TRUE(std::filesystem::exists(s.scenario)) << entry.path() << ": " << s.scenario;
  }
  EXPECT_GE(n, 10) << "smoke, the six cases, the two maps, the benchmarks";
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
