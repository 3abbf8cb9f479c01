#pragma once
// A whole `frictionlab ensemble` job: read the study, plan its runs, prepare the folder, run what
// is not done on this process's threads — or, when started by mpirun, over the MPI ranks
// (dynamics/ensemble/mpi_ensemble.h) — and, once every run is done, write the report.

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

#include "dynamics/ensemble/ensemble_session.h"

namespace frictionlab::dynamics::ensemble {

struct JobOptions {
  std::filesystem::path study;  ///< the study file
  std::filesystem::path out;    ///< DIR
  int threads = 0;              ///< worker threads per process (0: one per core; under MPI: 1)
  bool resume = false;
  bool trajectories = false;    ///< --hdf5
  bool figures = true;          ///< run gnuplot for the report's maps
  std::FILE* log = nullptr;     ///< progress and notes (stderr), or null
  bool live = false;            ///< stderr is a terminal
  const std::atomic<bool>* cancel = nullptr;  ///< Ctrl-C
  std::string command;          ///< as typed, for the manifest and the report
  std::function<void(long, long)> on_progress;  ///< (runs done, runs of the study) after each run, or empty
};

/// The job of `frictionlab ensemble STUDY --out OUT [--threads N] [--resume] [--hdf5]
/// [--no-figures]`, its command recorded as typed; the caller adds log, live, cancel and
/// on_progress. std::invalid_argument if threads < 0. The command and the Python module both
/// build their job here.
[[nodiscard]] JobOptions ensemble_job_options(const std::string& study, const std::string& out, int threads,
                                              bool resume, bool trajectories, bool figures);

/// What coordinating the MPI ranks cost (rank 0's view; zero without MPI).
struct CoordinationCost {
  double busy = 0.0;         ///< s rank 0 spent handling the other ranks' messages
  long runs_received = 0;    ///< finished runs the other ranks sent
  long tasks_sent = 0;       ///< tasks handed to the other ranks
  double worker_wait = 0.0;  ///< s the other ranks waited, in all, between asking for a task and getting it
};

struct JobOutcome {
  SessionSummary summary;
  bool interrupted = false;
  bool writer = true;          ///< this process wrote the folder (false: an MPI worker rank)
  bool quiet_failure = false;  ///< an MPI worker rank stopped because another rank failed (it reports)
  int threads = 1;             ///< worker threads of this process
  int ranks = 1;               ///< MPI ranks (1 without MPI)
  double wall_time = 0.0;      ///< s
  CoordinationCost coordination;
  std::filesystem::path report;  ///< DIR/report.md, when written
  std::vector<std::string> figure_errors;  ///< figures that could not be drawn
};

/// Runs the job (throws std::invalid_argument for a bad study or folder before anything runs).
[[nodiscard]] JobOutcome run_ensemble_job(const JobOptions& options);

/// The job on this process's threads only (what run_ensemble_job does without mpirun).
[[nodiscard]] JobOutcome run_ensemble_job_on_threads(const JobOptions& options);

/// The part after the session ran, on the writing process: closes it, and when the study is
/// complete writes the report and its figures.
[[nodiscard]] JobOutcome finish_job(EnsembleSession& session, const JobOptions& options, JobOutcome outcome);

}  // namespace frictionlab::dynamics::ensemble
