// `frictionlab ensemble STUDY.toml --out DIR [--threads N] [--resume] [--hdf5] [--no-figures]`:
// every (start x replica x law) run of a study on all cores, or over MPI ranks under mpirun, into
// DIR/runs.csv (a row per run as it finishes), then DIR/report.md with the statistics against the
// chaos floor and the maps (docs/ensembles.md). Progress on stderr, one summary line on stdout.
// Exit code 0 when every run of the study is done (runs that stop early or fail are results, in
// runs.csv with their reason); 3 when runs remain (interrupted: --resume continues) or the output
// failed; 1 for bad input (one line, nothing run).

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>

#include "dynamics/cli/commands.h"
#include "dynamics/cli/option_values.h"
#include "dynamics/ensemble/ensemble_job.h"
#include "dynamics/ensemble/mpi_ensemble.h"
#include "dynamics/io/shipped_data.h"
#include "friction/support/errors.h"
#include "friction/support/interrupt_guard.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

constexpr int kExitIncomplete = 3;

struct EnsembleCliOptions {
  std::string study;
  std::string out;
  long long threads = 0;
  bool resume = false;
  bool hdf5 = false;
  bool no_figures = false;
};

void run(const EnsembleCliOptions& opt) {
  namespace ens = dynamics::ensemble;
  const std::string study = dynamics::find_shipped_file(opt.study, "studies", "study").string();
  ens::JobOptions job = ens::ensemble_job_options(study, opt.out, int_option("--threads", opt.threads), opt.resume,
                                                  opt.hdf5, !opt.no_figures);
  job.log = stderr;
  job.live = isatty(STDERR_FILENO) != 0;
  ens::JobOutcome outcome;
  const std::string runs_csv = (std::filesystem::path(opt.out) / "runs.csv").string();
  // Under mpirun the signal is followed by SIGKILL within a second (friction/support/
  // interrupt_guard.h): rank 0 says at once what stopped it and what is kept.
  const bool announce = ens::launched_by_mpi() && ens::launcher_rank() == 0;
  int signal = 0;
  {
    // Ctrl-C, kill or a lost terminal: the runs in flight stop between steps (not recorded), the
    // finished ones are in runs.csv; --resume continues.
    const support::InterruptGuard interrupts(
        announce ? "frictionlab: ensemble: stopped by {signal}: every finished run is kept in " + runs_csv +
                       "; rerun with --resume to continue"
                 : std::string());
    job.cancel = &interrupts.flag();
    outcome = ens::run_ensemble_job(job);
    signal = interrupts.signal_number();
  }
  // What the guard already said (announce) is not said twice.
  const std::string stopped_by =
      signal != 0 ? std::string("stopped by ") + support::InterruptGuard::signal_name(signal) : "interrupted";
  // A worker rank stopped because another rank failed, and that rank (0) reports it and exits 1.
  // This one exits 0: mpirun aborts the whole job as soon as a process exits non-zero, which would
  // kill rank 0 before it prints the error if this one got there first (as on a loaded machine).
  if (outcome.quiet_failure) return;
  if (!outcome.writer) {
    if (outcome.interrupted) throw CLI::RuntimeError(kExitIncomplete);
    return;
  }
  const bool said = announce && signal != 0;
  const ens::SessionSummary& s = outcome.summary;
  std::printf("ensemble: %ld of %ld runs done (%ld this session: %ld failed, %ld stopped early) in %s s on %d rank%s x %d "
              "thread%s; wrote %s%s\n",
              s.done_before + s.done_now, s.total, s.done_now, s.failed_now, s.early_now,
              support::fixed(outcome.wall_time, 1).c_str(), outcome.ranks, outcome.ranks == 1 ? "" : "s", outcome.threads,
              outcome.threads == 1 ? "" : "s", (std::filesystem::path(opt.out) / "runs.csv").c_str(),
              outcome.report.empty() ? "" : (", " + outcome.report.string()).c_str());
  if (outcome.ranks > 1) {
    const ens::CoordinationCost& c = outcome.coordination;
    std::fprintf(stderr,
                 "ensemble: coordination: rank 0 spent %s s on the %ld runs the other ranks sent (%s ms a run); "
                 "they waited %s s in all for %ld tasks\n",
                 support::fixed(c.busy, 4).c_str(), c.runs_received,
                 support::fixed(c.runs_received > 0 ? 1e3 * c.busy / static_cast<double>(c.runs_received) : 0.0, 3).c_str(),
                 support::fixed(c.worker_wait, 4).c_str(), c.tasks_sent);
  }
  for (const auto& e : outcome.figure_errors) std::fprintf(stderr, "frictionlab: ensemble: %s\n", e.c_str());
  if (!s.output_error.empty()) {
    std::fprintf(stderr, "frictionlab: ensemble: the output failed: %s\n", support::one_line(s.output_error).c_str());
    throw CLI::RuntimeError(kExitIncomplete);
  }
  if (!s.complete) {
    if (!said)
      std::fprintf(stderr, "frictionlab: ensemble: %s; %ld runs are kept in %s, %ld remain: add --resume to continue\n",
                   outcome.interrupted ? stopped_by.c_str() : "incomplete", s.done_before + s.done_now,
                   runs_csv.c_str(), s.remaining());
    throw CLI::RuntimeError(kExitIncomplete);
  }
}

}  // namespace

void register_ensemble_command(CLI::App& app) {
  auto opt = std::make_shared<EnsembleCliOptions>();
  auto* cmd = app.add_subcommand(
      "ensemble", "Run a study: every (start x replica x law) run on all cores, or over MPI ranks under mpirun; "
                  "runs.csv and a report against the chaos floor (docs/ensembles.md); ~0.4 kB a run in runs.csv, "
                  "~0.1 MB of report and maps, --hdf5 up to ~50 kB a run");
  cmd->add_option("study", opt->study,
                  "The study file (TOML), or the name of a shipped one (smoke, egg-printed-a, ...: looked up in "
                  "data/studies here, then the installed data)")
      ->required();
  cmd->add_option("--out", opt->out, "Output folder (created if needed)")->required();
  cmd->add_option("--threads", opt->threads, "Worker threads (default 0: one per core; under MPI, of rank 0: 1)");
  cmd->add_flag("--resume", opt->resume,
                "Continue the ensemble in --out: redo only the runs not in its runs.csv (one job per folder: a "
                "folder another job holds is refused; SIGINT or SIGTERM stops a job, keeping every finished run)");
  cmd->add_flag("--hdf5", opt->hdf5, "Also write decimated trajectories to DIR/trajectories.h5");
  cmd->add_flag("--no-figures", opt->no_figures, "Write the maps' data and gnuplot scripts but do not run gnuplot");
  cmd->callback([opt] { run(*opt); });
}

}  // namespace frictionlab::cli
