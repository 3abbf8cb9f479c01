// `frictionlab calibrate`: the calibration of the engines' spin-friction laws against `exact`
// for each pressure model (docs/engines.md). A thin layer over bench/calibration.

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/calibration/calibration.h"
#include "bench/calibration/calibration_output.h"
#include "bench/calibration/sphere_settings.h"
#include "dynamics/cli/commands.h"
#include "dynamics/cli/retypable_command.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

// The largest grid: the objective evaluates every engine law on it about 150 times per pressure.
constexpr long long kMaxGridPoints = 2'000'000;

struct CalibrateOptions {
  std::string out;
  std::vector<std::string> laws;
  std::vector<std::string> pressures;
  long long s_points = static_cast<long long>(accuracy::GridSpec{}.s_points);
  long long mu_points = static_cast<long long>(accuracy::GridSpec{}.mu_points);
  long long psi_points = static_cast<long long>(accuracy::GridSpec{}.psi_points);
  long long threads = 0;
  bool no_plots = false;
  std::string command;
  calibration::SphereContact sphere;  ///< --sphere mode: radius > 0
  bool sphere_given = false;
};

std::size_t count(const char* option, long long value) {
  if (value < 0) throw support::invalid_value(option, value, "a count must not be negative");
  return static_cast<std::size_t>(value);
}

// --sphere: the engines' settings for one sphere-on-plane contact, on stdout (sphere_settings.h).
void print_sphere_settings(const calibration::SphereContact& contact) {
  calibration::validate(contact);
  const double a = calibration::hertz_radius(contact);
  const calibration::CircleCoefficients c = calibration::hertz_circle_coefficients();
  const auto n = [](double x) { return support::significant(x, 4); };
  std::cout << "Hertz contact (Johnson 1985, eq. 4.22): sphere R = " << n(contact.radius) << " m, load N = "
            << n(contact.load) << " N, E* = " << n(calibration::effective_modulus(contact))
            << " Pa: patch radius a = (3 N R/(4 E*))^(1/3) = " << n(a) << " m; k = " << n(contact.friction) << "\n"
            << "coefficient c (pure-spin torque per kNa, kN = k·N): exact at pure spin " << n(c.decoupled_spin)
            << " (3 pi/16); least worst torque over the slip range on the circle: MuJoCo's law " << n(c.mujoco_best)
            << ", the decoupled engines' " << n(c.decoupled_best) << " (docs/engines.md §3-§4)\n\n"
            << "| engine | setting | unit | exact at pure spin | least worst torque |\n|---|---|---|---|---|\n";
  for (const auto& s : calibration::engine_settings(contact, c))
    std::cout << "| " << s.engine << " | " << s.setting << " | " << s.unit << " | " << n(s.at_spin) << " | " << n(s.best)
              << " |\n";
  std::cout << "| Gazebo classic (ODE) | <patch_radius> | m | " << n(a) << " | " << n(a) << " |\n\n"
            << "The patch radius grows like N^(1/3): these values are right at N = " << n(contact.load)
            << " N only (at twice the load the pure-spin torque they give is 21 % too small).\n";
}

void run(const CalibrateOptions& opt) {
  if (opt.sphere_given) {
    if (!opt.out.empty()) throw std::invalid_argument("--out is for the calibration study: --sphere prints the engines' settings");
    print_sphere_settings(opt.sphere);
    return;
  }
  if (opt.out.empty()) throw std::invalid_argument("--out is required: name the output folder (or give --sphere R --load N --modulus E --friction k)");
  calibration::CalibrationOptions co;
  co.grid.s_points = count("--s-points", opt.s_points);
  co.grid.mu_points = count("--mu-points", opt.mu_points);
  co.grid.psi_points = count("--psi-points", opt.psi_points);
  const long double points = static_cast<long double>(co.grid.s_points) * co.grid.mu_points * co.grid.psi_points * 2;
  if (points > kMaxGridPoints) {
    throw support::invalid_value("--s-points x --mu-points x --psi-points x 2", static_cast<long long>(points),
                                 "at most " + std::to_string(kMaxGridPoints) + " grid points");
  }
  co.laws = opt.laws;
  co.pressures = opt.pressures;
  co.threads = count("--threads", opt.threads);
  co.progress = &std::cerr;
  const auto result = calibration::run_calibration(co);
  accuracy::RunInfo info = accuracy::describe_this_run();
  info.command = opt.command;
  info.seconds = result.seconds;
  const std::filesystem::path dir(opt.out);
  calibration::write_calibration_files(result, dir, info);
  const auto figures = calibration::write_calibration_plots(result, dir, !opt.no_plots, &std::cerr);
  std::cerr << "calibrate: done in " << result.seconds << " s; tables in "
            << (dir / "calibration_tables.md").string() << ", " << figures.size() << " figures" << std::endl;
}

}  // namespace

void register_calibrate_command(CLI::App& app) {
  auto opt = std::make_shared<CalibrateOptions>();
  auto* cmd = app.add_subcommand(
      "calibrate",
      "Calibration of the engines' spin-friction laws (ellipsoidal, mujoco-elliptic, decoupled) against\n"
      "`exact` for each pressure model: the coefficient exact at pure spin and the one minimising the\n"
      "largest torque error on the accuracy grid, with the errors left; writes CSV and markdown tables\n"
      "and gnuplot figures under --out (docs/engines.md); ~0.6 MB");
  cmd->add_option("--out", opt->out, "output folder (created; existing files are replaced)");
  cmd->add_option("--laws", opt->laws, "comma-separated engine laws (default: all)")->delimiter(',');
  cmd->add_option("--pressures", opt->pressures, "comma-separated pressure models of exact (default: all)")
      ->delimiter(',');
  cmd->add_option("--s-points", opt->s_points, "slip ratios, log-spaced over [1e-3, 1e3] (>= 2)")
      ->capture_default_str();
  cmd->add_option("--mu-points", opt->mu_points, "axis ratios b/a, evenly over [0.05, 1] (>= 2)")
      ->capture_default_str();
  cmd->add_option("--psi-points", opt->psi_points, "orientations, evenly over [0, pi] (odd, >= 3)")
      ->capture_default_str();
  cmd->add_option("--threads", opt->threads, "worker threads for exact (0: one per hardware thread)")
      ->capture_default_str();
  cmd->add_flag("--no-plots", opt->no_plots, "write the gnuplot data and scripts but do not run gnuplot");
  // The engines' settings for one sphere on a plane, printed instead of the study.
  auto* sphere = cmd->add_option("--sphere", opt->sphere.radius,
                                 "instead of the study: print each engine's spin-friction setting for a sphere of this "
                                 "radius (m) on a plane, with --load, --modulus, --friction");
  auto* load = cmd->add_option("--load", opt->sphere.load, "--sphere: the normal load N (N)");
  auto* modulus = cmd->add_option("--modulus", opt->sphere.modulus, "--sphere: the sphere's Young's modulus (Pa)");
  cmd->add_option("--poisson", opt->sphere.poisson, "--sphere: its Poisson ratio")->capture_default_str();
  cmd->add_option("--plane-modulus", opt->sphere.plane_modulus, "--sphere: the plane's Young's modulus (Pa; default: rigid)");
  cmd->add_option("--plane-poisson", opt->sphere.plane_poisson, "--sphere: its Poisson ratio")->capture_default_str();
  auto* friction = cmd->add_option("--friction", opt->sphere.friction, "--sphere: the Coulomb friction coefficient k");
  load->needs(sphere);
  modulus->needs(sphere);
  friction->needs(sphere);
  sphere->needs(load)->needs(modulus)->needs(friction);
  cmd->callback([opt, cmd, sphere] {
    opt->sphere_given = sphere->count() > 0;
    opt->command = retypable_command(*cmd, {"--threads"});  // threads do not change the results
    run(*opt);
  });
}

}  // namespace frictionlab::cli
