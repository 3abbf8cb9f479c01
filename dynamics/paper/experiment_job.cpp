#include "dynamics/paper/experiment_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>

#include "dynamics/paper/along_motion.h"
#include "dynamics/paper/experiment_report.h"
#include "dynamics/paper/figure_scripts.h"
#include "friction/support/folder_lock.h"
#include "friction/support/gnuplot.h"
#include "dynamics/paper/run_progress.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

std::string now_text() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&t));
  return buf;
}

std::string short_num(double x) { return support::significant(x, 4); }

// "gamma3(0) = 0.97, omega(0) = (0, 0, 100) 1/s" from the scenario as run.
std::string initial_description(const RunSpec& spec) {
  if (!spec.scenario) return "";
  const auto& w = spec.scenario->initial.omega;
  return "γ_3(0) = " + short_num(spec.scenario->initial.gamma[2]) + ", ω(0) = (" + short_num(w[0]) + ", " +
         short_num(w[1]) + ", " + short_num(w[2]) + ") 1/s";
}

std::vector<FigureGroup> figure_groups(const std::vector<RunResult>& results) {
  std::vector<FigureGroup> groups;
  for (const auto& r : results) {
    if (!r.executed) continue;
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const FigureGroup& g) { return g.egg == r.spec.egg && g.case_id == r.spec.case_id; });
    if (it == groups.end()) {
      groups.push_back({r.spec.egg, r.spec.case_id, initial_description(r.spec), {}});
      it = groups.end() - 1;
    }
    FigureRun fr;
    fr.label = r.spec.label;
    fr.stem = plot_data_stem(r.spec);
    fr.baseline = r.spec.baseline;
    fr.stopped_early = !r.ended_normally();
    fr.t_final = r.summary.t_final;
    fr.ranges = r.figure_ranges;
    if (fr.stopped_early) fr.stop = std::string(to_string(r.summary.reason)) + " at t = " + short_num(r.summary.t_final) + " s";
    it->runs.push_back(fr);
  }
  return groups;
}

}  // namespace

JobOutcome run_paper_job(const JobOptions& options) {
  const std::vector<RunSpec> specs = plan_runs(options.plan);  // all input errors surface here
  const auto start = std::chrono::steady_clock::now();
  const std::string date = now_text();
  const std::filesystem::path out = options.plan.out_dir;
  const std::filesystem::path plots = out / "plots";
  // The folder is this job's until the report is written: two jobs resuming one folder would both
  // redo the runs it lacks, and write the same files.
  const support::FolderLock lock(out);

  JobOutcome outcome;
  const int workers = std::min<int>(worker_count(options.jobs), static_cast<int>(specs.size()));
  {
    std::unique_ptr<RunProgress> progress;
    if (options.log) progress = std::make_unique<RunProgress>(static_cast<int>(specs.size()), workers, options.log,
                                                              options.live_status);
    RunnerOptions ro;
    ro.jobs = workers;
    ro.plot_data_dir = plots / "data";
    ro.cancel = options.cancel;
    ro.progress = progress.get();
    ro.trajectory_every = options.trajectory_every;
    ro.resume = options.resume;
    outcome.results = run_experiments(specs, ro);
  }
  for (const auto& r : outcome.results) {
    if (!r.executed || !r.error.empty()) ++outcome.not_run;
    if (r.resumed) ++outcome.resumed;
    if (r.executed && r.summary.reason == Termination::interrupted) outcome.interrupted = true;
  }
  if (options.cancel && options.cancel->load()) outcome.interrupted = true;

  const std::vector<FigureGroup> groups = figure_groups(outcome.results);
  std::vector<std::string> scripts = write_figure_scripts(plots, groups);
  const AlongMotion along = write_along_motion(plots, outcome.results);
  scripts.insert(scripts.end(), along.scripts.begin(), along.scripts.end());
  if (options.figures) {
    outcome.figure_errors = support::run_gnuplot_scripts(plots, scripts);
  } else {
    outcome.figure_errors.push_back("--no-figures: scripts written to " + plots.string() + ", not drawn");
  }
  for (const auto& s : scripts) {
    const std::string png = std::filesystem::path(s).replace_extension(".png").string();
    if (std::filesystem::exists(plots / png)) outcome.figures.push_back(png);
  }

  const std::vector<LawComparison> comparisons = compare_runs(outcome.results);
  const std::vector<NarrativeVerdicts> verdicts = judge_narrative(outcome.results);
  outcome.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ReportContext ctx;
  ctx.command = options.command;
  ctx.date = date;
  ctx.machine = machine_description();
  ctx.jobs = workers;
  ctx.wall_time = outcome.wall_time;
  ctx.figures = outcome.figures;
  ctx.figure_errors = outcome.figure_errors;
  ctx.interrupted = outcome.interrupted;
  ctx.along_motion = along.report;
  write_report(out, outcome.results, comparisons, verdicts, ctx);
  return outcome;
}

}  // namespace frictionlab::dynamics::paper
