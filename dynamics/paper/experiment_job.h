#pragma once
// The whole of `frictionlab paper`: plan the grid, run it in parallel with progress, draw the
// figures, compare the laws, judge the paper's narrative, write the report (docs/experiments.md).

#include <atomic>
#include <cstdio>
#include <string>
#include <vector>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/paper/experiment_runner.h"

namespace frictionlab::dynamics::paper {

struct JobOptions {
  PlanOptions plan;
  int jobs = 0;                  ///< worker threads; 0 = hardware cores
  bool figures = true;           ///< run gnuplot (the scripts and data are written either way)
  std::FILE* log = stderr;       ///< progress lines (null: none)
  bool live_status = false;      ///< also a live status line (stderr is a terminal)
  const std::atomic<bool>* cancel = nullptr;
  std::string command;           ///< the command line, for the report
};

struct JobOutcome {
  std::vector<RunResult> results;
  std::vector<std::string> figures;        ///< PNG names drawn in DIR/plots
  std::vector<std::string> figure_errors;
  int not_run = 0;                         ///< runs that could not run or were skipped
  bool interrupted = false;
  double wall_time = 0.0;                  ///< s
};

/// Throws std::invalid_argument for bad options before anything is written; afterwards every
/// failure of a single run is recorded in the outcome and the others go on.
[[nodiscard]] JobOutcome run_paper_job(const JobOptions& options);

}  // namespace frictionlab::dynamics::paper
