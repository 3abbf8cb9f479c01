#include "dynamics/body/scenario.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace frictionlab::dynamics {
namespace scenario_test {

const char* kGood = R"(
name = "test"
[body]
profile = "sphere"
radius = 0.05
mass = 1
[contact]
k = 0.2
lambda = 1e7
[initial]
gamma = [0, 0, 1]
omega = [0, 0, 20]
eps = "static"
[run]
t_end = 2
)";

// Parses kGood with one line replaced (or appended to a section) and returns the error message.
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    (void)parse_scenario(text, "test.toml", overrides);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(DynScenario, ParsesAGoodScenarioWithDefaults) {
  const Scenario s = parse_scenario(kGood, "test.toml");
  EXPECT_EQ(s.name, "test");
  EXPECT_EQ(s.body_spec.preset, "sphere");
  EXPECT_EQ(*s.body_spec.radius, 0.05);
  EXPECT_EQ(s.contact.g, 9.81);
  EXPECT_EQ(s.law, "exact");
  EXPECT_EQ(s.run.integrator.method, "rk8pd");
  EXPECT_EQ(s.run.t_end, 2.0);
  EXPECT_NEAR(s.initial.eps, -std::cbrt((9.81 / 1e7) * (9.81 / 1e7)), 1e-18);  // "static"
  EXPECT_EQ(s.initial.omega.z(), 20.0);
  EXPECT_NE(s.resolved_toml.find("radius"), std::string::npos);
}

TEST(DynScenario, OverridesUseTheSameKeyPaths) {
  const Scenario s = parse_scenario(
      kGood, "test.toml",
      {"run.t_end=0.5", "contact.law=pade-printed", "initial.gamma=[0, 0.6, 0.8]", "run.integrator=\"rkck\"",
       "body.mass=2.5", "initial.eps=-1e-4"});
  EXPECT_EQ(s.run.t_end, 0.5);
  EXPECT_EQ(s.law, "pade-printed");
  EXPECT_NEAR(s.initial.gamma.y(), 0.6, 1e-15);
  EXPECT_EQ(s.run.integrator.method, "rkck");
  EXPECT_EQ(s.body.mass, 2.5);
  EXPECT_EQ(s.initial.eps, -1e-4);
  EXPECT_EQ(s.overrides.size(), 6u);
}

// The body is built once, when the scenario is resolved, and travels with it.
TEST(DynScenario, CarriesItsBuiltBody) {
  const Scenario s = parse_scenario(kGood, "test.toml");
  constexpr double kMass = 1.0, kRadius = 0.05;
  EXPECT_EQ(s.body.mass, kMass);
  EXPECT_NEAR(s.body.axisymmetric->A, 0.4 * kMass * kRadius * kRadius, 1e-15);  // solid sphere: 2/5 m R^2
  EXPECT_NEAR(s.body.axisymmetric->C, 0.4 * kMass * kRadius * kRadius, 1e-15);
  EXPECT_NEAR(s.body.axisymmetric->profile.z_hi() - s.body.axisymmetric->profile.z_lo(), 2.0 * kRadius, 1e-15);
}

// A file is parsed once; each run resolves its own overrides from the parsed document.
TEST(DynScenario, ADocumentIsParsedOnceAndResolvedPerRun) {
  const ScenarioDocument doc = ScenarioDocument::parse(kGood, "test.toml");
  const Scenario plain = doc.resolve();
  const Scenario printed = doc.resolve({"contact.law=pade-printed", "run.t_end=0.5"});
  EXPECT_EQ(plain.law, "exact");
  EXPECT_EQ(plain.run.t_end, 2.0);
  EXPECT_TRUE(plain.overrides.empty());
  EXPECT_EQ(printed.law, "pade-printed");
  EXPECT_EQ(printed.run.t_end, 0.5);
  EXPECT_EQ(printed.overrides.size(), 2u);
  EXPECT_EQ(doc.resolve().run.t_end, 2.0);  // overrides apply to a copy
}

// scenario.toml, written beside a run, is the resolved scenario: read back from any file name it
// gives the same name, law and values (numbers to the last bit), with no overrides left to apply.
TEST(DynScenario, TheResolvedTomlReadsBackAsTheSameScenario) {
  const std::string no_name = replace(kGood, "name = \"test\"", "");
  const Scenario s = parse_scenario(no_name, "data/sphere-x.toml",
                                    {"contact.law=pade-printed", "initial.v=[0.30000000000000004, 0, 1e-300]",
                                     "run.t_end=0.1"});
  ASSERT_EQ(s.name, "sphere-x");
  const Scenario back = parse_scenario(s.resolved_toml, "out/scenario.toml");
  EXPECT_EQ(back.name, "sphere-x");
  EXPECT_EQ(back.law, "pade-printed");
  EXPECT_EQ(back.initial.v.x(), 0.30000000000000004);
  EXPECT_EQ(back.initial.v.z(), 1e-300);
  EXPECT_EQ(back.initial.eps, s.initial.eps);
  EXPECT_EQ(back.initial.gamma, s.initial.gamma);
  EXPECT_EQ(back.run.t_end, 0.1);
  EXPECT_EQ(back.resolved_toml, s.resolved_toml);
  // The law is recorded even where the file left it to the default.
  EXPECT_NE(parse_scenario(kGood, "t.toml").resolved_toml.find("law = 'exact'"), std::string::npos);
}

TEST(DynScenario, NormalisesGammaOrRejectsAVectorFarFromUnit) {
  const Scenario s = parse_scenario(replace(kGood, "gamma = [0, 0, 1]", "gamma = [0.2431, 0, 0.97]"), "t");
  EXPECT_NEAR(s.initial.gamma.norm(), 1.0, 1e-15);
  const std::string e = error_of(replace(kGood, "gamma = [0, 0, 1]", "gamma = [0, 0, 0.5]"));
  EXPECT_NE(e.find("initial.gamma = [0, 0, 0.5] has length 0.5"), std::string::npos) << e;
}

// Each bad scenario gives one error that names the key (and the file).
struct BadCase {
  const char* what;
  std::string text;
  std::vector<std::string> overrides;
  const char* expected;
};

// Each case gives one line containing its expected text.
void expect_errors(const std::vector<BadCase>& cases) {
  for (const auto& c : cases) {
    const std::string e = error_of(c.text, c.overrides);
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.what << ": got '" << e << "'";
    EXPECT_EQ(e.find('\n'), std::string::npos) << c.what << ": one line, got '" << e << "'";
  }
}

TEST(DynScenario, EachBadScenarioGivesOneClearError) {
  const std::vector<BadCase> cases = {
      {"unknown key", replace(kGood, "t_end = 2", "t_end = 2\nt_edn = 3"), {}, "unknown key run.t_edn"},
      {"unknown section", std::string(kGood) + "[output]\nx = 1\n", {}, "unknown key output"},
      {"unknown top-level key", replace(kGood, "name = \"test\"", "nam = \"x\""), {}, "unknown key nam"},
      {"wrong type", replace(kGood, "t_end = 2", "t_end = \"2\""), {}, "run.t_end must be a number, got a string"},
      {"wrong vector length", replace(kGood, "omega = [0, 0, 20]", "omega = [0, 20]"), {},
       "initial.omega must have 3 components"},
      {"missing key", replace(kGood, "k = 0.2", ""), {}, "contact.k is required"},
      {"missing section", replace(kGood, "[run]\nt_end = 2", ""), {}, "section [run] is required"},
      {"negative friction", replace(kGood, "k = 0.2", "k = -0.2"), {}, "contact.k = -0.2 is invalid"},
      {"non-convex profile",
       replace(kGood, "profile = \"sphere\"\nradius = 0.05", "chi2 = [0.3, 0, 0.7, 0, -1]"), {},
       "not strictly convex"},
      {"unknown preset", replace(kGood, "profile = \"sphere\"", "profile = \"cube\""), {},
       "body.profile = 'cube' is not a known preset"},
      {"bad t_end", replace(kGood, "t_end = 2", "t_end = -1"), {}, "run.t_end = -1 is invalid"},
      {"unknown stepper", replace(kGood, "t_end = 2", "t_end = 2\nintegrator = \"euler\""), {},
       "run.integrator = 'euler' is not a known stepper"},
      {"bad eps string", replace(kGood, "eps = \"static\"", "eps = \"low\""), {}, "initial.eps must be a number"},
      {"TOML syntax", replace(kGood, "k = 0.2", "k = = 0.2"), {}, "test.toml:"},
      {"override unknown key", kGood, {"run.tend=3"}, "unknown key run.tend"},
      {"override bad value", kGood, {"run.t_end=abc"}, "run.t_end must be a number, got a string"},
      {"override without =", kGood, {"run.t_end"}, "must have the form key=value"},
      {"override into a value", kGood, {"run.t_end.x=1"}, "run.t_end is not a section"},
  };
  expect_errors(cases);
}

// The chatter event's keys (dynamics/core/chatter_watch.h): read like the other [run] thresholds, an
// unset run.chatter_step left to its scaled default, bad values named.
TEST(DynScenario, ReadsTheChatterKeys) {
  const Scenario unset = parse_scenario(kGood, "test.toml");
  EXPECT_EQ(unset.run.chatter.max_steps, kDefaultMaxChatterSteps);
  EXPECT_FALSE(unset.run.chatter.step.has_value());
  const Scenario set = parse_scenario(kGood, "test.toml", {"run.max_chatter_steps=200", "run.chatter_step=3e-8"});
  EXPECT_EQ(set.run.chatter.max_steps, 200);
  EXPECT_EQ(set.run.chatter.step, 3e-8);
  EXPECT_EQ(parse_scenario(kGood, "test.toml", {"run.max_chatter_steps=0"}).run.chatter.max_steps, 0);
  expect_errors({
      {"negative chatter budget", kGood, {"run.max_chatter_steps=-1"},
       "run.max_chatter_steps = -1 is invalid: it must be >= 0 (0: never)"},
      {"chatter budget not an integer", kGood, {"run.max_chatter_steps=1.5"}, "run.max_chatter_steps must be an integer"},
      {"zero chatter step", kGood, {"run.chatter_step=0"}, "run.chatter_step = 0 is invalid: it must be finite and > 0 s"},
  });
}

// run.pose (dynamics/core/run_options.h): on unless set false; anything but a boolean named.
TEST(DynScenario, ReadsThePoseSwitch) {
  EXPECT_TRUE(parse_scenario(kGood, "test.toml").run.pose);
  EXPECT_FALSE(parse_scenario(kGood, "test.toml", {"run.pose=false"}).run.pose);
  EXPECT_TRUE(parse_scenario(replace(kGood, "t_end = 2", "t_end = 2\npose = true"), "test.toml").run.pose);
  expect_errors({
      {"pose not a boolean", kGood, {"run.pose=1"}, "run.pose must be true or false, got an integer 1"},
  });
}

// Values outside the physically meaningful ranges (docs/dynamics.md §7) are rejected when the
// scenario is read, naming the key, instead of failing far away ("friction input U = inf").
// One case per rule; kGood is a 5 cm, 1 kg sphere.
TEST(DynScenario, ValuesOutsidePhysicalRangesNameTheirKey) {
  const std::vector<BadCase> cases = {
      {"tiny mass", kGood, {"body.mass=1e-300"}, "body.mass = 1e-300 is invalid: it must be within [1e-06, 1000000] kg"},
      {"huge mass", kGood, {"body.mass=1e300"}, "body.mass = 1e+300 is invalid"},
      {"tiny radius", kGood, {"body.radius=1e-300"}, "body.radius = 1e-300 is invalid"},
      {"huge radius", kGood, {"body.radius=1e6"}, "body.radius = 1000000 is invalid"},
      {"tiny semi-axis",
       replace(kGood, "profile = \"sphere\"\nradius = 0.05", "profile = \"spheroid\"\nsemi_axes = [1e-9, 0.05]"),
       {}, "body.semi_axes = [1e-09, 0.05] is invalid"},
      {"tiny chi2 body", replace(kGood, "profile = \"sphere\"\nradius = 0.05", "chi2 = [1e-20, 0, -1]"), {},
       "body.chi2 = [1e-20, 0, -1] is invalid"},
      {"huge chi2 body", replace(kGood, "profile = \"sphere\"\nradius = 0.05", "chi2 = [1e8, 0, -1]"), {},
       "body.chi2 = [100000000, 0, -1] is invalid"},
      {"tiny A", kGood, {"body.A=1e-300", "body.C=1e-300"}, "body.A = 1e-300 is invalid"},
      {"A beyond the body", kGood, {"body.A=1"}, "body.A = 1 is invalid"},  // > m r^2 = 0.0025
      {"tiny C", kGood, {"body.C=1e-300"}, "body.C = 1e-300 is invalid"},
      {"C beyond the body", kGood, {"body.A=0.002", "body.C=0.003"}, "body.C = 0.003 is invalid"},
      {"huge friction", kGood, {"contact.k=1e300"}, "contact.k = 1e+300 is invalid: it must be within [0, 10]"},
      {"huge stiffness", kGood, {"contact.lambda=1e300"}, "contact.lambda = 1e+300 is invalid"},
      {"tiny stiffness", kGood, {"contact.lambda=1e-300"}, "contact.lambda = 1e-300 is invalid"},
      {"too soft for the weight", kGood, {"contact.lambda=100"}, "contact.lambda = 100 is invalid: the static compression"},
      {"huge gravity", kGood, {"contact.g=1e300"}, "contact.g = 1e+300 is invalid"},
      {"negative gravity", kGood, {"contact.g=-9.81"}, "contact.g = -9.81 is invalid"},
      {"huge spin", kGood, {"initial.omega=[0, 0, 1e300]"}, "initial.omega = [0, 0, 1e+300] is invalid"},
      {"fast spin", kGood, {"initial.omega=[0, 0, 1e5]"}, "initial.omega = [0, 0, 100000] is invalid"},
      {"huge speed", kGood, {"initial.v=[1e300, 0, 0]"}, "initial.v = [1e+300, 0, 0] is invalid"},
      {"deep compression", kGood, {"initial.eps=-0.01"}, "initial.eps = -0.01 is invalid"},
      {"far above", kGood, {"initial.eps=1e300"}, "initial.eps = 1e+300 is invalid"},
  };
  expect_errors(cases);
}

// The limits let through what the model is meant for, up to the edges of the ranges.
TEST(DynScenario, ValuesInsideThePhysicalRangesAreAccepted) {
  for (const std::vector<std::string>& overrides : std::vector<std::vector<std::string>>{
           {"body.mass=1e-6", "contact.lambda=1e6"},
           {"body.radius=1e-4", "body.mass=1e-6", "contact.lambda=1e5"},
           {"contact.k=0"},
           {"contact.k=10"},
           {"contact.g=0", "contact.lambda=1e-3", "initial.eps=0.01"},
           {"initial.omega=[0, 0, 19000]"},  // surface at 950 m/s
           {"initial.v=[999, 0, 0]"},
           {"initial.eps=1000"}}) {
    EXPECT_NO_THROW((void)parse_scenario(kGood, "test.toml", overrides)) << ::testing::PrintToString(overrides);
  }
}

TEST(DynScenario, AFolderIsNotAScenarioFile) {
  const std::filesystem::path dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";
  try {
    (void)load_scenario(dir);
    ADD_FAILURE() << "a folder was read as a scenario";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
}

// An error caused by an override is blamed on it; an error in the file, on the file.
TEST(DynScenario, AnErrorIsBlamedOnWhatSetTheValue) {
  EXPECT_EQ(error_of(kGood, {"run.t_end=abc"}).rfind("--set run.t_end=abc: run.t_end must be a number", 0), 0u)
      << error_of(kGood, {"run.t_end=abc"});
  EXPECT_EQ(error_of(kGood, {"run.t_end=3", "body.mass=1e-300"}).rfind("--set body.mass=1e-300: body.mass = 1e-300 is invalid", 0), 0u);
  EXPECT_EQ(error_of(kGood, {"initial.omega=[0, 0, abc]"}).rfind("--set initial.omega=[0, 0, abc]: initial.omega", 0), 0u);
  EXPECT_EQ(error_of(kGood, {"run.t_end=-1"}).rfind("--set run.t_end=-1: run.t_end = -1 is invalid", 0), 0u);
  EXPECT_EQ(error_of(kGood, {"contact.law=fast"}).rfind("--set contact.law=fast: contact.law = 'fast' is invalid", 0), 0u);
  EXPECT_EQ(error_of(kGood, {"run.tend=3"}).rfind("--set run.tend=3: unknown key run.tend", 0), 0u);
  EXPECT_EQ(error_of(kGood, {"run.t_end.x=1"}).rfind("--set run.t_end.x=1: ", 0), 0u);
  EXPECT_EQ(error_of(kGood, {"run.t_end"}).rfind("--set run.t_end: ", 0), 0u);
  // The last override of a key is the one that counts.
  EXPECT_EQ(error_of(kGood, {"run.t_end=abc", "run.t_end=-2"}).rfind("--set run.t_end=-2: ", 0), 0u);
  // A bad value of the file stays the file's, whatever else is overridden.
  const std::string e = error_of(replace(kGood, "k = 0.2", "k = -1"), {"run.t_end=3"});
  EXPECT_EQ(e.rfind("test.toml: contact.k = -1 is invalid", 0), 0u) << e;
}

TEST(DynScenario, TheModelIsABodyUnlessTheFileSaysOtherwise) {
  EXPECT_EQ(ScenarioDocument::parse(kGood, "test.toml").model(), "body");
  EXPECT_NO_THROW((void)parse_scenario(kGood, "test.toml", {"model=body"}));
  EXPECT_EQ(ScenarioDocument::parse(kGood, "test.toml").model({"model=puck"}), "puck");
  EXPECT_EQ(error_of(kGood, {"model=puck"}).rfind("--set model=puck: model = \"puck\": this scenario is not a body", 0), 0u)
      << error_of(kGood, {"model=puck"});
  EXPECT_EQ(error_of(kGood, {"model=cube"}).rfind("--set model=cube: model = 'cube' is invalid", 0), 0u)
      << error_of(kGood, {"model=cube"});
  EXPECT_EQ(error_of(kGood, {"model=3"}).rfind("--set model=3: model must be a string", 0), 0u) << error_of(kGood, {"model=3"});
}

// A law spec (friction/law_spec.h) works wherever a law name does, and is kept verbatim.
TEST(DynScenario, TheLawMayBeASpecKeptVerbatim) {
  const Scenario s = parse_scenario(replace(kGood, "k = 0.2", "k = 0.2\nlaw = \"exact:pressure=hertz\""), "test.toml");
  EXPECT_EQ(s.law, "exact:pressure=hertz");
  EXPECT_NE(s.resolved_toml.find("law = 'exact:pressure=hertz'"), std::string::npos) << s.resolved_toml;
  EXPECT_EQ(parse_scenario(kGood, "test.toml", {"contact.law=exact:pressure=hertz"}).law, "exact:pressure=hertz");
  EXPECT_EQ(parse_scenario(kGood, "test.toml", {"contact.law=exact:pressure=uniform"}).law, "exact:pressure=uniform");
  const std::string e = error_of(kGood, {"contact.law=exact:pressure=flat"});
  EXPECT_EQ(e.rfind("--set contact.law=exact:pressure=flat: contact.law = 'exact:pressure=flat' is invalid", 0), 0u) << e;
  EXPECT_NE(e.find("pressure must be one of hertz"), std::string::npos) << e;
}

// The size of trajectory.csv is limited in bytes (run.max_output_bytes, dynamics/core/output_limit.h):
// a default stated in docs/dynamics.md, overridable, positive.
TEST(DynScenario, TheTrajectoryByteLimitHasItsStatedDefaultAndIsOverridable) {
  EXPECT_EQ(parse_scenario(kGood, "test.toml").run.max_output_bytes, 100'000'000);  // docs/dynamics.md §4: 100 MB
  EXPECT_EQ(parse_scenario(kGood, "test.toml", {"run.max_output_bytes=500000"}).run.max_output_bytes, 500'000);
  const std::string e = error_of(kGood, {"run.max_output_bytes=0"});
  EXPECT_EQ(e.rfind("--set run.max_output_bytes=0: run.max_output_bytes = 0 is invalid", 0), 0u) << e;
}

// A plan that would write more than the limit even at one character per value is refused before
// anything runs, naming the key, the file and the limit: 3 s at 3.3e-7 s is 9.1e6 rows of at
// least 2 bytes per column (66 bytes for the 33 columns), 600 MB > 100 MB.
TEST(DynScenario, AnOutputIntervalWhosePlanPassesTheByteLimitIsRefused) {
  const std::string e = error_of(kGood, {"run.t_end=3", "run.output_dt=3.3e-7"});
  EXPECT_EQ(e.rfind("--set run.output_dt=3.3e-7: run.output_dt = 3.3e-07 is invalid", 0), 0u) << e;
  for (const char* word : {"trajectory.csv", "run.max_output_bytes = 100000000", "66 bytes"})
    EXPECT_NE(e.find(word), std::string::npos) << word << " in " << e;
  // The same plan with the limit raised on purpose is accepted; a plan at the limit is too.
  EXPECT_NO_THROW((void)parse_scenario(kGood, "test.toml", {"run.t_end=3", "run.output_dt=3.3e-7",
                                                            "run.max_output_bytes=1000000000"}));
  EXPECT_NO_THROW((void)parse_scenario(kGood, "test.toml", {"run.t_end=1", "run.output_dt=1e-6"}));  // 66 MB
}

TEST(DynScenario, ShippedScenariosAreValid) {
  const std::filesystem::path dir = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data" / "scenarios";
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    if (ScenarioDocument::read(entry.path()).model() != "body") continue;  // the puck's: tests/dynamics/puck/
    EXPECT_NO_THROW((void)load_scenario(entry.path())) << entry.path();
    ++n;
  }
  EXPECT_GE(n, 8);  // sphere sliding, sphere spinning, egg cases a, b, c for both readings
  EXPECT_THROW((void)load_scenario(dir / "no-such-file.toml"), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab::dynamics

namespace frictionlab::dynamics {
namespace scenario_test {

// [body] of another shape kind (docs/convex-bodies.md §10): its parameters, the centre of mass as a
// point, the full inertia tensor; the pose in [initial].
TEST(DynScenario, ShapedBodiesReadTheirKeys) {
  const std::string ellipsoid = R"(
[body]
shape = "ellipsoid"
semi_axes = [0.05, 0.04, 0.03]
mass = 0.5
com = [0.001, 0, -0.002]
inertia = [[3e-4, -1e-5, 0], [-1e-5, 3.4e-4, 0], [0, 0, 4e-4]]
[contact]
k = 0.2
lambda = 1e7
[initial]
gamma = [0, 0, 1]
eps = "static"
position = [1.5, -2]
heading = 0.3
[run]
t_end = 1
)";
  const Scenario s = parse_scenario(ellipsoid, "e.toml");
  EXPECT_EQ(s.body.shape->kind(), "ellipsoid");
  EXPECT_FALSE(s.body.axisymmetric.has_value());
  EXPECT_EQ(s.body.centre_of_mass, Eigen::Vector3d(0.001, 0.0, -0.002));
  EXPECT_EQ(s.body.inertia(0, 1), -1e-5);
  EXPECT_EQ(s.body.inertia(1, 0), -1e-5);
  EXPECT_EQ(s.initial.position, Eigen::Vector2d(1.5, -2.0));
  EXPECT_EQ(s.initial.heading, 0.3);
  const StateVector x0 = initial_state(s);
  EXPECT_EQ(position(x0), Eigen::Vector2d(1.5, -2.0));
  // Heading 0.3 about the vertical from the upright start: q = (cos 0.15, 0, 0, sin 0.15).
  EXPECT_NEAR(orientation(x0)[0], std::cos(0.15), 1e-15);
  EXPECT_NEAR(orientation(x0)[3], std::sin(0.15), 1e-15);
  // The resolved text reads back as the same scenario.
  const Scenario again = parse_scenario(s.resolved_toml, "again.toml");
  EXPECT_EQ(again.body.inertia, s.body.inertia);
  EXPECT_EQ(again.body.centre_of_mass, s.body.centre_of_mass);

  const auto error = [&](const std::vector<std::string>& overrides) {
    try {
      (void)parse_scenario(ellipsoid, "e.toml", overrides);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error({"body.inertia=[[3e-4, 0], [0, 3e-4]]"}).find("body.inertia must be the full tensor"), std::string::npos);
  EXPECT_NE(error({"body.inertia=[[1, 0, 0], [0, 1, 0], [0, 0, 3]]"}).find("must not exceed the sum of the other two"), std::string::npos);
  EXPECT_NE(error({"body.inertia=[[1, 0, 0], [0, 1, 0], [0, 0, 1]]"}).find("body.inertia"), std::string::npos);  // > m r_max^2
  EXPECT_NE(error({"body.radius=0.1"}).find("body.radius"), std::string::npos);
  EXPECT_NE(error({"body.com=[0, 0, 0.1]"}).find("body.com"), std::string::npos);
  EXPECT_NE(error({"initial.position=[1, 2, 3]"}).find("initial.position"), std::string::npos);

  const std::string disk = replace(replace(ellipsoid, "shape = \"ellipsoid\"\nsemi_axes = [0.05, 0.04, 0.03]",
                                           "shape = \"toroidal-disk\"\nradius = 0.02\nrim_radius = 0.003"),
                                   "com = [0.001, 0, -0.002]\ninertia = [[3e-4, -1e-5, 0], [-1e-5, 3.4e-4, 0], [0, 0, 4e-4]]\n",
                                   "");
  const Scenario d = parse_scenario(replace(disk, "gamma = [0, 0, 1]", "gamma = [1, 0, 0]"), "d.toml");
  EXPECT_EQ(d.body.shape->kind(), "toroidal-disk");
  EXPECT_GT(d.body.inertia(2, 2), d.body.inertia(0, 0));  // the axis has the largest moment
}

}  // namespace
}  // namespace frictionlab::dynamics
