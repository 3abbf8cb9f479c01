#include "dynamics/ensemble/ensemble_job.h"

#include <chrono>
#include <stdexcept>

#include "dynamics/ensemble/ensemble_report.h"
#include "dynamics/ensemble/mpi_ensemble.h"
#include "dynamics/ensemble/thread_pool.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::ensemble {

JobOptions ensemble_job_options(const std::string& study, const std::string& out, int threads, bool resume,
                                bool trajectories, bool figures) {
  if (threads < 0) throw support::invalid_value("--threads", static_cast<long long>(threads), "it must be >= 0 (0: one per core)");
  JobOptions job;
  job.study = study;
  job.out = out;
  job.threads = threads;
  job.resume = resume;
  job.trajectories = trajectories;
  job.figures = figures;
  job.command = "frictionlab ensemble " + study + " --out " + out;
  if (threads != 0) job.command += " --threads " + std::to_string(threads);
  if (trajectories) job.command += " --hdf5";
  return job;
}

JobOutcome finish_job(EnsembleSession& session, const JobOptions& options, JobOutcome outcome) {
  outcome.summary = session.finish();
  if (!outcome.summary.complete) return outcome;
  const ReportOutcome report = write_report(session.plan(), options.out, options.command, options.figures);
  outcome.report = report.report;
  outcome.figure_errors = report.figures.errors;
  return outcome;
}

JobOutcome run_ensemble_job(const JobOptions& options) {
  if (launched_by_mpi()) return run_ensemble_job_mpi(options);
  return run_ensemble_job_on_threads(options);
}

JobOutcome run_ensemble_job_on_threads(const JobOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const EnsemblePlan plan = EnsemblePlan::make(read_study(options.study));
  SessionOptions so;
  so.out = options.out;
  so.resume = options.resume;
  so.trajectories = options.trajectories;
  so.log = options.log;
  so.live = options.live;
  so.command = options.command;
  so.on_progress = options.on_progress;
  EnsembleSession session(plan, so);
  JobOutcome outcome;
  outcome.threads = thread_count(options.threads);
  run_on_threads(session, outcome.threads, options.cancel);
  outcome.interrupted = options.cancel && options.cancel->load();
  outcome = finish_job(session, options, outcome);
  outcome.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace frictionlab::dynamics::ensemble
