#include "dynamics/puck/puck_scenario.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "dynamics/puck/puck_scenario_run.h"

namespace frictionlab::dynamics::puck {
namespace {

const char* kDisk = R"(
model = "puck"
[puck]
mass = 0.16
a = 0.03
[contact]
k = 0.2
[initial]
v = [1.0, 0.5]
omega = 30
[run]
t_end = 5
)";

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    (void)parse_puck_scenario(text, "disk.toml", overrides);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DynPuckScenario, DefaultsAreADiskOfUniformPlateInertiaAndTheExactLaw) {
  const PuckScenario s = parse_puck_scenario(kDisk, "dir/disk.toml");
  EXPECT_EQ(s.name, "disk");
  EXPECT_EQ(s.puck.b, 0.03);
  EXPECT_FALSE(s.inertia_given);
  EXPECT_DOUBLE_EQ(s.puck.inertia, 0.16 * 0.03 * 0.03 / 2.0);  // m a^2/2
  EXPECT_EQ(s.law, "exact");
  EXPECT_EQ(s.g, 9.81);
  EXPECT_EQ(s.initial.v, Eigen::Vector2d(1.0, 0.5));
  EXPECT_EQ(s.initial.heading, 0.0);
  EXPECT_EQ(s.run.t_end, 5.0);
  const PuckScenario e = parse_puck_scenario(kDisk, "disk.toml", {"puck.b=0.01", "puck.inertia=1e-4", "initial.heading=0.5"});
  EXPECT_EQ(e.puck.b, 0.01);
  EXPECT_EQ(e.puck.inertia, 1e-4);
  EXPECT_TRUE(e.inertia_given);
  EXPECT_EQ(initial_state(e)[PuckLayout::kHeading], 0.5);
}

TEST(DynPuckScenario, TheDocumentSaysWhichModelItIs) {
  EXPECT_EQ(ScenarioDocument::parse(kDisk, "disk.toml").model(), "puck");
  EXPECT_EQ(ScenarioDocument::parse("[body]\nmass = 1\n", "b.toml").model(), "body");
  // A body-of-revolution reader refuses a puck, naming the key.
  try {
    (void)ScenarioDocument::parse(kDisk, "disk.toml").resolve();
    ADD_FAILURE() << "a puck resolved as a body";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("model"), std::string::npos) << e.what();
  }
  EXPECT_NE(error_of(kDisk, {"model=cube"}).find("--set model=cube: model = 'cube' is invalid"), std::string::npos)
      << error_of(kDisk, {"model=cube"});
}

TEST(DynPuckScenario, BadValuesNameTheirKeyAndWhoSetThem) {
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"puck.b=0.05"}, "--set puck.b=0.05: puck.b = 0.05 is invalid"},
      {{"puck.mass=-1"}, "puck.mass = -1 is invalid"},
      {{"puck.a=1e9"}, "puck.a = 1000000000 is invalid"},
      {{"puck.inertia=1e-30"}, "puck.inertia = 1e-30 is invalid"},
      {{"contact.k=20"}, "contact.k = 20 is invalid"},
      {{"contact.law=nope"}, "contact.law = 'nope' is invalid: unknown friction law 'nope'"},
      {{"initial.v=[1, 2, 3]"}, "initial.v must have 2 components"},
      {{"initial.omega=1e9"}, "initial.omega = 1000000000 is invalid"},
      {{"puck.radius=1"}, "unknown key puck.radius"},
      {{"run.settle_time=1"}, "unknown key run.settle_time"},
      {{"run.t_end=-1"}, "run.t_end = -1 is invalid"},
      {{"run.integrator=euler"}, "run.integrator = 'euler' is not a known stepper"},
  };
  for (const auto& [overrides, expected] : cases) {
    const std::string e = error_of(kDisk, overrides);
    EXPECT_NE(e.find(expected), std::string::npos) << overrides.front() << " gave: " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
  }
  EXPECT_NE(error_of("model = \"puck\"\n[contact]\nk = 0.1\n[run]\nt_end = 1\n").find("section [puck] is required"),
            std::string::npos);
  EXPECT_NE(error_of("[puck]\nmass = 1\na = 0.1\n[contact]\nk = 0.1\n[run]\nt_end = 1\n").find("model = \"puck\" is required"),
            std::string::npos);
}

TEST(DynPuckScenario, TheResolvedScenarioReproducesTheRun) {
  const PuckScenario s = parse_puck_scenario(kDisk, "disk.toml", {"puck.b=0.02", "contact.law=pade-reconstructed"});
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "puck_scenario_test";
  std::filesystem::remove_all(dir);
  const PuckScenarioRun first = run_puck_scenario(s, dir / "a");
  const PuckScenario again = load_puck_scenario(dir / "a" / "scenario.toml");
  EXPECT_EQ(again.law, "pade-reconstructed");
  EXPECT_EQ(again.name, "disk");
  const PuckScenarioRun second = run_puck_scenario(again, dir / "b");
  const auto slurp = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(slurp(dir / "a" / "trajectory.csv"), slurp(dir / "b" / "trajectory.csv"));
  EXPECT_GT(first.summary.samples, 10);
  EXPECT_NE(slurp(dir / "a" / "summary.json").find("\"terminal_ratio\""), std::string::npos);
}

TEST(DynPuckScenario, ShippedPuckScenariosAreValid) {
  const std::filesystem::path dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml" || ScenarioDocument::read(entry.path()).model() != "puck") continue;
    EXPECT_NO_THROW((void)load_puck_scenario(entry.path())) << entry.path();
    ++n;
  }
  EXPECT_GE(n, 3);  // disk, ellipse, ring
}

}  // namespace
}  // namespace frictionlab::dynamics::puck
