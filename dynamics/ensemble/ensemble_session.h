#pragma once
// The writing side of an ensemble job: the output folder, its manifest, runs.csv, the optional
// trajectories file, the queue of tasks still to do and the progress line. One per job, on the
// process that writes (the only process without MPI, rank 0 with it). Thread-safe where marked.
//
// DIR/ensemble.json (the manifest) names the study and its hash (dynamics/ensemble/ensemble_plan.h);
// `--resume` continues a folder only if the hash is the same, reads runs.csv (runs_file.h) and
// queues what is not finished. Without `--resume` an existing runs.csv is an error (nothing is
// overwritten). The session holds DIR for its job (support::FolderLock): a second job on DIR,
// another process or another session, is refused while this one lives.

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "dynamics/ensemble/ensemble_plan.h"
#include "dynamics/ensemble/progress_meter.h"
#include "dynamics/ensemble/runs_file.h"
#include "dynamics/ensemble/task_queue.h"
#include "dynamics/ensemble/trajectory_store.h"
#include "friction/support/folder_lock.h"

namespace frictionlab::dynamics::ensemble {

struct SessionOptions {
  std::filesystem::path out;   ///< DIR
  bool resume = false;
  bool trajectories = false;   ///< --hdf5
  std::FILE* log = nullptr;    ///< progress (stderr), or null
  bool live = false;           ///< redraw the progress line (a terminal)
  std::string command;         ///< the command line, for the manifest and the report
  /// Called after each run is recorded, from the worker threads, with (runs done, runs of the
  /// study); must be thread-safe and quick (the Python module polls what it stores). May be empty.
  std::function<void(long, long)> on_progress;
};

struct SessionSummary {
  long total = 0;          ///< runs of the study
  long done_before = 0;    ///< finished by earlier sessions
  long done_now = 0;       ///< finished in this one
  long failed_now = 0;     ///< of which could not run
  long early_now = 0;      ///< of which stopped early (a law's pole, max-steps, ...)
  bool complete = false;   ///< every run of the study is in runs.csv
  std::string output_error;  ///< why the output stopped (empty if it did not)
  [[nodiscard]] long remaining() const { return total - done_before - done_now; }
};

class EnsembleSession {
 public:
  /// Prepares DIR (see the header comment). std::invalid_argument for a folder that cannot be
  /// used (another study's, runs.csv without --resume, another job's: support::FolderInUse);
  /// support::OutputError if it cannot be written.
  EnsembleSession(const EnsemblePlan& plan, SessionOptions options);

  [[nodiscard]] TaskQueue& queue() { return *queue_; }
  [[nodiscard]] long runs_to_do() const { return queue_->runs_to_do(); }

  /// Writes one finished run (row, flushed; trajectory). Thread-safe. If the output fails, the
  /// error is kept, the halt flag raised, and later records are dropped.
  void record(FinishedRun&& run);

  /// Raised when the job must stop (the output failed, or halt() was called): pass it to the runs
  /// as their cancel flag.
  [[nodiscard]] const std::atomic<bool>& halt_flag() const { return halt_; }
  void halt() { halt_ = true; }

  /// Closes the files; if every run is done, sorts runs.csv by run index. Call once, after the
  /// last record().
  SessionSummary finish();

  [[nodiscard]] const EnsemblePlan& plan() const { return plan_; }
  [[nodiscard]] const SessionOptions& options() const { return options_; }
  [[nodiscard]] std::filesystem::path runs_csv() const { return options_.out / "runs.csv"; }

 private:
  const EnsemblePlan& plan_;
  SessionOptions options_;
  std::unique_ptr<support::FolderLock> lock_;  // DIR is this job's while the session lives
  std::unique_ptr<TaskQueue> queue_;
  std::unique_ptr<RunsWriter> writer_;
  std::unique_ptr<TrajectoryStore> trajectories_;
  std::unique_ptr<ProgressMeter> progress_;
  SessionSummary summary_;
  std::atomic<bool> halt_{false};
  std::mutex mutex_;
};

/// The manifest's text for `plan` (JSON).
[[nodiscard]] std::string manifest_text(const EnsemblePlan& plan, const std::string& command);

}  // namespace frictionlab::dynamics::ensemble
