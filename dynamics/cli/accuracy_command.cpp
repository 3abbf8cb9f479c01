// `frictionlab accuracy`: the accuracy study of every friction law against `exact`
// (docs/accuracy.md). A thin layer over bench/accuracy: parse and check the options, run the
// study, write the files and figures.

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/accuracy/plots.h"
#include "bench/accuracy/report.h"
#include "bench/accuracy/study.h"
#include "dynamics/cli/commands.h"
#include "dynamics/cli/retypable_command.h"
#include "friction/law_spec.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

// The largest grid (points over mu, psi, sign of Omega and s): each point keeps ~170 bytes per law
// in memory, so this is ~2 GB, fifty times the default grid.
constexpr long long kMaxGridPoints = 10'000'000;

// Counts as typed (signed, so that -3 is an error rather than a huge unsigned number).
struct AccuracyOptions {
  std::string out;
  std::string laws;       // a list of specs (friction/law_spec.h)
  std::string reference;  // a spec; empty: the registry's reference law
  long long s_points = static_cast<long long>(accuracy::GridSpec{}.s_points);
  long long mu_points = static_cast<long long>(accuracy::GridSpec{}.mu_points);
  long long psi_points = static_cast<long long>(accuracy::GridSpec{}.psi_points);
  long long threads = 0;
  bool no_plots = false;
  bool points = false;
  std::string command;  // as typed, for the provenance line of the tables
};

// The sign only: the grid checks what else a count needs (bench/accuracy/grid.h).
std::size_t count(const char* option, long long value) {
  if (value < 0) throw support::invalid_value(option, value, "a count must not be negative");
  return static_cast<std::size_t>(value);
}

accuracy::GridSpec grid_of(const AccuracyOptions& opt) {
  accuracy::GridSpec grid;
  grid.s_points = count("--s-points", opt.s_points);
  grid.mu_points = count("--mu-points", opt.mu_points);
  grid.psi_points = count("--psi-points", opt.psi_points);
  const long double points = static_cast<long double>(grid.s_points) * grid.mu_points * grid.psi_points * 2;
  if (points > kMaxGridPoints)
    throw support::invalid_value("--s-points x --mu-points x --psi-points x 2", static_cast<double>(points),
                                 "it must be at most " + std::to_string(kMaxGridPoints) +
                                     " grid points (each keeps ~170 bytes per law in memory)");
  return grid;
}

void run(const AccuracyOptions& opt) {
  if (opt.out.empty()) throw std::invalid_argument("--out is empty: name the output folder");
  accuracy::StudyOptions so;
  so.grid = grid_of(opt);
  if (!opt.laws.empty()) so.laws = friction::split_law_list(opt.laws);
  so.reference = opt.reference;
  so.threads = count("--threads", opt.threads);
  const auto t0 = std::chrono::steady_clock::now();
  so.progress = &std::cerr;
  const auto study = accuracy::run_study(so);

  accuracy::RunInfo info = accuracy::describe_this_run();
  info.command = opt.command;
  info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::filesystem::path dir(opt.out);
  accuracy::StudyFiles files;
  files.point_tables = opt.points;
  accuracy::write_study_files(study, dir, info, &std::cerr, files);
  accuracy::PlotOptions po;
  po.draw = !opt.no_plots;
  (void)accuracy::write_plots(study, dir, po, &std::cerr);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "accuracy: done in " << total << " s; tables in " << (dir / "accuracy_tables.md").string()
            << std::endl;
}

}  // namespace

void register_accuracy_command(CLI::App& app) {
  auto opt = std::make_shared<AccuracyOptions>();
  auto* cmd = app.add_subcommand(
      "accuracy",
      "Accuracy study: every law against `exact` on a grid of slip ratio s = U/(a|Omega|), axis\n"
      "ratio mu = b/a, orientation psi and sign(Omega); writes CSV tables, markdown tables and\n"
      "gnuplot figures under --out (see DIR/README.md): ~5 MB on the default grid; --points adds the\n"
      "per-point tables, 18-26 MB per law (~165 MB for the default laws)");
  cmd->add_option("--out", opt->out, "output folder (created; existing files are replaced)")->required();
  cmd->add_option("--laws", opt->laws,
                  "law specs to compare with the reference, separated by ';' or ',' (default: every registered "
                  "law but exact and exact-reference; exact-reference only on a small grid)");
  cmd->add_option("--reference", opt->reference,
                  "the reference's spec, e.g. exact:pressure=uniform to study laws for a uniform pressure "
                  "(default: exact)");
  cmd->add_option("--s-points", opt->s_points, "slip ratios, log-spaced over [1e-3, 1e3] (>= 2)")
      ->capture_default_str();
  cmd->add_option("--mu-points", opt->mu_points, "axis ratios b/a, evenly over [0.05, 1] (>= 2)")
      ->capture_default_str();
  cmd->add_option("--psi-points", opt->psi_points,
                  "orientations, evenly over [0, pi] (odd, >= 3: 0, pi/2, pi are nodes)")
      ->capture_default_str();
  cmd->add_option("--threads", opt->threads, "worker threads (0: one per hardware thread)")
      ->capture_default_str();
  cmd->add_flag("--no-plots", opt->no_plots, "write the gnuplot data and scripts but do not run gnuplot");
  cmd->add_flag("--points", opt->points,
                "also write points/<law>.csv, one row per grid point (18-26 MB per law on the default grid)");
  cmd->callback([opt, cmd] {
    opt->command = retypable_command(*cmd, {"--threads"});  // threads do not change the results
    run(*opt);
  });
}

}  // namespace frictionlab::cli
