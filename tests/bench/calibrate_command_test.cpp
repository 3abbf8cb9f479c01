// `frictionlab calibrate`, run as a user runs it: a tiny study writes its files; bad options give
// one error line and a non-zero exit.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {
namespace calibrate_command_test {

std::filesystem::path temp_out(const char* tag) {
  return std::filesystem::temp_directory_path() /
         (std::string("frictionlab_calibrate_cmd_") + tag + "_" + std::to_string(::getpid()));
}

TEST(CalibrateCommand, TinyStudyWritesTheFiles) {
  const auto out = temp_out("ok");
  const auto r = run_frictionlab("calibrate --out " + out.string() +
                                 " --laws decoupled --s-points 5 --mu-points 2 --psi-points 3 --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");  // progress goes to stderr
  for (const char* f : {"calibration.csv", "scan.csv", "curves.csv", "calibration_tables.md",
                        "plots/calibration_scan.gp", "plots/calibration_forces.gp"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  std::filesystem::remove_all(out);
}

TEST(CalibrateCommand, LegendsShowLawSpecsAsTheyAre) {
  // The forces figure names each engine law by its spec, decoupled:r_spin=...: escaped for
  // gnuplot's enhanced text, where '_' would make "spin=..." a subscript (support::gnuplot_text).
  const auto out = temp_out("legend");
  const auto r = run_frictionlab("calibrate --out " + out.string() +
                                 " --laws decoupled --s-points 5 --mu-points 2 --psi-points 3 --no-plots");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out / "plots" / "calibration_forces.gp");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::filesystem::remove_all(out);
  EXPECT_NE(text.find("title 'decoupled:r\\_spin="), std::string::npos) << text;
  EXPECT_EQ(text.find("r_spin"), std::string::npos) << text;
  EXPECT_EQ(text.find("noenhanced"), std::string::npos) << text;
}

TEST(CalibrateCommand, BadOptionsGiveOneLineAndNonZeroExit) {
  const std::string out = " --out " + temp_out("bad").string();
  for (const auto& [args, fragment] :
       {std::pair<std::string, std::string>{"calibrate" + out + " --laws nope", "unknown engine law 'nope'"},
        {"calibrate" + out + " --pressures gaussian", "pressure model 'gaussian'"},
        {"calibrate" + out + " --s-points 1", "s points = 1 is invalid"},
        {"calibrate", "--out is required"},
        {"calibrate --sphere 0.01 --load 10 --friction 0.2", "--sphere requires --modulus"},
        {"calibrate --sphere 0.01 --load 10 --modulus 1e9 --friction 0.2 --poisson 0.7", "--poisson = 0.7 is invalid"},
        {"calibrate --sphere -1 --load 10 --modulus 1e9 --friction 0.2", "--sphere = -1 is invalid"},
        {"calibrate --sphere 0.01 --load 10 --modulus 1e9 --friction 0.2" + out, "--out is for the calibration study"}}) {
    const auto r = run_frictionlab(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  }
}

// --sphere: the Hertz radius a = (3 N R/(4 E*))^(1/3) (Johnson 1985, eq. 4.22) of a steel ball on
// steel, and the settings exact at pure spin, from the closed forms of docs/engines.md §4:
// MuJoCo mu3 = (3 pi/16) k a, Bullet s = (3 pi/16) a, Chrono (3 pi/16) k a, Gazebo's coefficient k.
TEST(CalibrateCommand, SphereModePrintsEachEnginesSettingForTheHertzRadius) {
  const double R = 0.01, N = 10.0, E = 210e9, nu = 0.3, k = 0.2;
  const double e_star = 1.0 / (2.0 * (1.0 - nu * nu) / E);
  const double a = std::cbrt(3.0 * N * R / (4.0 * e_star));
  const double c = 3.0 * std::numbers::pi / 16.0;
  const auto r = run_frictionlab("calibrate --sphere 0.01 --load 10 --modulus 210e9 --plane-modulus 210e9 --friction 0.2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The table's cells by row: | engine | setting | unit | exact at pure spin | least worst |.
  const auto cell = [&](const std::string& engine, int column) {
    const auto at = r.out.find("| " + engine);
    EXPECT_NE(at, std::string::npos) << engine << "\n" << r.out;
    if (at == std::string::npos) return std::nan("");
    std::string row = r.out.substr(at, r.out.find('\n', at) - at);
    for (int i = 0; i <= column; ++i) row = row.substr(row.find('|') + 1);
    return std::stod(row.substr(0, row.find('|')));
  };
  const auto near = [](double got, double expected) { return std::abs(got - expected) <= 5e-4 * expected; };  // 4 digits
  EXPECT_TRUE(near(cell("MuJoCo", 3), c * k * a)) << r.out;
  EXPECT_TRUE(near(cell("Bullet", 3), c * a)) << r.out;
  EXPECT_TRUE(near(cell("Chrono", 3), c * k * a)) << r.out;
  EXPECT_TRUE(near(cell("Gazebo classic (ODE) | torsional", 3), k)) << r.out;
  EXPECT_TRUE(near(cell("Gazebo classic (ODE) | <patch_radius>", 3), a)) << r.out;
  // The least worst values lie below the pure-spin ones (the exact torque falls with the slip).
  for (const char* engine : {"MuJoCo", "Bullet", "Chrono"}) EXPECT_LT(cell(engine, 4), cell(engine, 3)) << engine;
  EXPECT_NE(r.out.find("a = (3 N R/(4 E*))^(1/3) = "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace frictionlab::testing
