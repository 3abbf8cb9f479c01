#pragma once
// The whole of `frictionlab paper`: plan the grid, run it in parallel with progress, draw the
// figures, compare the laws, judge the paper's narrative, write the report (docs/experiments.md).

#include <atomic>
#include <cstdio>
#include <string>
#include <vector>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/paper/experiment_runner.h"
#include "dynamics/paper/run_record.h"

namespace frictionlab::dynamics::paper {

struct JobOptions {
  PlanOptions plan;
  int jobs = 0;                  ///< worker threads; 0 = hardware cores
  bool figures = true;           ///< run gnuplot (the scripts and data are written either way)
  std::FILE* log = stderr;       ///< progress lines (null: none)
  bool live_status = false;      ///< also a live status line (stderr is a terminal)
  const std::atomic<bool>* cancel = nullptr;
  std::string command;           ///< the command line, for the report
  /// trajectory.csv keeps every this-many-th sample and the last (1: every sample;
  /// dynamics/paper/run_record.h).
  int trajectory_every = kTrajectoryEvery;
  bool resume = false;           ///< keep the runs an earlier job completed (experiment_runner.h)
};

struct JobOutcome {
  std::vector<RunResult> results;
  std::vector<std::string> figures;        ///< PNG names drawn in DIR/plots
  std::vector<std::string> figure_errors;
  int not_run = 0;                         ///< runs that could not run or were skipped
  int resumed = 0;                         ///< runs kept from an earlier job (resume)
  bool interrupted = false;
  double wall_time = 0.0;                  ///< s
};

/// Throws std::invalid_argument for bad options before anything is written, and
/// support::FolderInUse if another job holds the output folder (support/folder_lock.h: the job
/// holds it until it returns); afterwards every failure of a single run is recorded in the
/// outcome and the others go on.
[[nodiscard]] JobOutcome run_paper_job(const JobOptions& options);

}  // namespace frictionlab::dynamics::paper
