// `frictionlab paper --out DIR [--laws L,...] [--eggs E,...] [--cases a,b,c] [--jobs N] [--set key=value]...
//  [--resume] [--full-trajectories] [--no-baseline] [--no-shadow] [--no-figures]`:
// the paper's experiments (section 2 of Munitsyna 2013) with every law, in parallel, with figures,
// comparisons and a report (docs/experiments.md). Writes DIR/runs/<egg>-<case>/<law>/,
// DIR/plots/, DIR/experiments.md and CSV tables; progress on stderr, one summary line on stdout
// (beginning "paper: INTERRUPTED:" when the job was stopped).
// Exit code 0 when every run ran (a law stopping early at its pole is a result, not an error) and
// every figure was drawn; 3 when some run could not run, the job was interrupted or a figure is
// missing (everything else is still written); 1 for bad input (one line, nothing run).

#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/cli/commands.h"
#include "dynamics/cli/option_values.h"
#include "dynamics/paper/experiment_job.h"
#include "friction/law_spec.h"
#include "friction/support/errors.h"
#include "friction/support/interrupt_guard.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

constexpr int kExitIncomplete = 3;

struct PaperCliOptions {
  std::string out;
  std::string laws;
  std::string eggs;
  std::string cases;
  std::string scenarios;
  long long jobs = 0;
  std::vector<std::string> set;
  bool no_baseline = false;
  bool no_shadow = false;
  bool no_figures = false;
  bool full_trajectories = false;
  bool resume = false;
  std::string command;
};

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ",") + s;
  return out;
}

void run(const PaperCliOptions& opt) {
  namespace paper = dynamics::paper;
  paper::JobOptions job;
  job.plan.out_dir = opt.out;
  job.plan.scenario_dir = opt.scenarios.empty() ? paper::default_scenario_dir() : std::filesystem::path(opt.scenarios);
  if (!opt.laws.empty()) job.plan.laws = friction::split_law_list(opt.laws);  // specs may hold commas
  if (!opt.eggs.empty()) job.plan.eggs = paper::split_list(opt.eggs, "--eggs");
  if (!opt.cases.empty()) job.plan.cases = paper::split_list(opt.cases, "--cases");
  job.plan.overrides = opt.set;
  job.plan.baseline = !opt.no_baseline;
  job.plan.shadow = !opt.no_shadow;
  if (opt.jobs < 0) throw support::invalid_value("--jobs", opt.jobs, "it must be >= 0 (0: one per core)");
  job.jobs = int_option("--jobs", opt.jobs);
  job.figures = !opt.no_figures;
  job.log = stderr;
  job.live_status = isatty(STDERR_FILENO) != 0;
  job.command = opt.command;
  job.trajectory_every = opt.full_trajectories ? 1 : paper::kTrajectoryEvery;
  job.resume = opt.resume;

  paper::JobOutcome outcome;
  {
    // Ctrl-C, kill or a lost terminal: running runs stop between steps, the report covers them.
    const support::InterruptGuard interrupts;
    job.cancel = &interrupts.flag();
    outcome = paper::run_paper_job(job);
  }

  int early = 0;
  for (const auto& r : outcome.results)
    if (r.executed && !r.ended_normally()) ++early;
  const std::string kept = opt.resume ? "; " + std::to_string(outcome.resumed) + " kept from an earlier job" : "";
  std::printf("paper: %s%zu runs (%d stopped early, %d not run%s), %zu figures in %s s; wrote %s\n",
              outcome.interrupted ? "INTERRUPTED: " : "", outcome.results.size(), early, outcome.not_run,
              kept.c_str(), outcome.figures.size(), support::fixed(outcome.wall_time, 1).c_str(),
              (std::filesystem::path(opt.out) / "experiments.md").c_str());
  if (!opt.no_figures)
    for (const auto& e : outcome.figure_errors) std::fprintf(stderr, "frictionlab: paper: %s\n", e.c_str());
  if (outcome.interrupted) std::fprintf(stderr, "frictionlab: paper: interrupted; the report covers what ran\n");
  for (const auto& r : outcome.results)
    if (!r.error.empty()) std::fprintf(stderr, "frictionlab: paper: %s: %s\n", r.name().c_str(), r.error.c_str());
  if (outcome.interrupted || outcome.not_run > 0 || (!opt.no_figures && !outcome.figure_errors.empty()))
    throw CLI::RuntimeError(kExitIncomplete);
}

}  // namespace

void register_paper_command(CLI::App& app) {
  namespace paper = dynamics::paper;
  auto opt = std::make_shared<PaperCliOptions>();
  auto* cmd = app.add_subcommand(
      "paper", "Reproduce the paper's experiments (cases a, b, c; both egg readings) with every law, in parallel, "
               "with figures and a report (docs/experiments.md); ~17 MB, ~330 MB with --full-trajectories");
  cmd->add_option("--out", opt->out, "Output directory (created if needed)")->required();
  cmd->add_option("--laws", opt->laws,
                  "Law specs, separated by ';' or ',' (default: " + join(paper::default_laws()) + ")");
  cmd->add_option("--eggs", opt->eggs, "Egg readings (default: " + join(paper::known_eggs()) + ")");
  cmd->add_option("--cases", opt->cases, "Cases (default: " + join(paper::known_cases()) + ")");
  cmd->add_option("--jobs", opt->jobs, "Runs in parallel (default 0: one per core)");
  cmd->add_option("--set", opt->set, "Override a scenario key in every run, e.g. --set run.t_end=60 (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--scenarios", opt->scenarios,
                  "Folder of <egg>-<case>.toml (default: data/scenarios here, else the source tree's)");
  cmd->add_flag("--no-baseline", opt->no_baseline,
                "Skip the reference law rerun with tolerances x0.1 (the chaos floor of the comparison)");
  cmd->add_flag("--no-shadow", opt->no_shadow,
                "Do not evaluate the compared laws along the reference run (its shadow.csv and the along-the-motion "
                "figures and table)");
  cmd->add_flag("--no-figures", opt->no_figures, "Write the plot data and gnuplot scripts but do not run gnuplot");
  cmd->add_flag("--full-trajectories", opt->full_trajectories,
                "Keep every sample (0.01 s) in trajectory.csv (default: every " +
                    std::to_string(paper::kTrajectoryEvery) + "th, 0.5 s); about 330 MB instead of 17 MB");
  cmd->add_flag("--resume", opt->resume,
                "Keep the runs an earlier job in --out completed with the same scenario; redo the others (one job "
                "per folder: a folder another job holds is refused)");
  cmd->callback([opt] {
    opt->command = "frictionlab paper";
    for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{
             {"--out", opt->out}, {"--laws", opt->laws}, {"--eggs", opt->eggs}, {"--cases", opt->cases},
             {"--scenarios", opt->scenarios}})
      if (!value.empty()) opt->command += " " + name + " " + value;
    if (opt->jobs != 0) opt->command += " --jobs " + std::to_string(opt->jobs);
    for (const auto& s : opt->set) opt->command += " --set " + s;
    if (opt->no_baseline) opt->command += " --no-baseline";
    if (opt->no_shadow) opt->command += " --no-shadow";
    if (opt->no_figures) opt->command += " --no-figures";
    if (opt->full_trajectories) opt->command += " --full-trajectories";
    run(*opt);
  });
}

}  // namespace frictionlab::cli
