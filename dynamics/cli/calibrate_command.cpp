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
#include "dynamics/cli/commands.h"
#include "dynamics/cli/retypable_command.h"
#include "friction/support/errors.h"

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
};

std::size_t count(const char* option, long long value) {
  if (value < 0) throw support::invalid_value(option, value, "a count must not be negative");
  return static_cast<std::size_t>(value);
}

void run(const CalibrateOptions& opt) {
  if (opt.out.empty()) throw std::invalid_argument("--out is empty: name the output folder");
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
  cmd->add_option("--out", opt->out, "output folder (created; existing files are replaced)")->required();
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
  cmd->callback([opt, cmd] {
    opt->command = retypable_command(*cmd, {"--threads"});  // threads do not change the results
    run(*opt);
  });
}

}  // namespace frictionlab::cli
