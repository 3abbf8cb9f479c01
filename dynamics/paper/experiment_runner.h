#pragma once
// Runs a planned grid (dynamics/paper/experiment_plan.h) on a pool of worker threads. Each run
// goes through dynamics::run_scenario (trajectory.csv, summary.json, scenario.toml in its folder),
// recorded by a SeriesRecorder; right after it ends its worker measures its features on every
// sample, writes the binned plot data (dynamics/paper/figure_data.h), thins trajectory.csv and
// writes gamma3.csv (dynamics/paper/run_record.h), then features.json (written last: a run
// without it is unfinished), and keeps only the comparison series in memory. A run that stops
// early (a law's pole, ...) is a result like any other; a run that cannot start (the law rejects
// the initial state, the folder is not writable) is recorded with its error, and the others go on.
//
// Resuming (RunnerOptions::resume): a run is kept, not rerun, when its folder holds a complete
// record of the run the plan would make: scenario.toml with the planned resolved scenario, a
// summary.json whose run was neither interrupted nor cut short by its output, features.json with
// the same feature thresholds and thinning, a trajectory.csv of the rows that summary promises,
// gamma3.csv and the plot data. Anything else is redone, and the progress line says why.

#include <array>
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/paper/figure_data.h"
#include "dynamics/paper/run_features.h"
#include "dynamics/paper/run_progress.h"
#include "dynamics/paper/run_record.h"
#include "dynamics/body/simulation.h"

namespace frictionlab::dynamics::paper {

struct RunResult {
  RunSpec spec;
  bool executed = false;  ///< the integration ran (whatever its termination reason)
  std::string error;      ///< why it did not run (empty if it ran)
  RunSummary summary;     ///< valid when executed
  double weight = 0.0;    ///< m g, N
  double t_end = 0.0;     ///< s, the scenario's end time
  /// +1 if the centre of mass is lowest with gamma3 = +1 (the pole at z_lo touching), else -1.
  int low_pole = 0;
  FeatureThresholds thresholds;
  RunFeatures features;
  /// The comparison series (every kComparisonEvery-th sample and the last; run_record.h).
  std::vector<double> t;              ///< s
  std::vector<double> gamma3;         ///< at t
  std::vector<double> gamma3_smooth;  ///< moving average (thresholds.smoothing_window), from every sample
  std::array<std::vector<double>, 3> axis;  ///< the symmetry axis in world axes at t (run_series.h)
  FigureRanges figure_ranges;         ///< axis caps of its figure data
  bool resumed = false;               ///< kept from an earlier job (--resume), not rerun

  /// The run ended as the model intends: t_end, rest or rolling.
  [[nodiscard]] bool ended_normally() const;
  /// The contact reached the stagnation region (rest or rolling).
  [[nodiscard]] bool stagnated() const;
  /// "egg-printed-a/exact".
  [[nodiscard]] std::string name() const { return spec.group() + "/" + spec.label; }
};

struct RunnerOptions {
  int jobs = 0;  ///< worker threads; 0 = std::thread::hardware_concurrency()
  FeatureThresholds thresholds;
  std::filesystem::path plot_data_dir;  ///< where <group>-<label>.{full,early,end}.dat go
  const std::atomic<bool>* cancel = nullptr;  ///< raised: running runs stop, queued ones are skipped
  RunProgress* progress = nullptr;            ///< may be null
  /// trajectory.csv keeps every this-many-th sample and the last (1: all; the paper job's default
  /// is kTrajectoryEvery).
  int trajectory_every = 1;
  /// Keep the runs whose folder holds a complete record of the planned run (see above).
  bool resume = false;

  /// trajectory_every >= 1 (std::invalid_argument).
  void validate() const;
};

/// The stem of a run's plot data files: "<egg>-<case>-<label>" (dynamics/paper/figure_data.h).
[[nodiscard]] std::string plot_data_stem(const RunSpec& spec);

/// The number of worker threads `jobs` asks for (>= 1).
[[nodiscard]] int worker_count(int jobs);

/// Runs every spec; results in the order of `specs`.
[[nodiscard]] std::vector<RunResult> run_experiments(const std::vector<RunSpec>& specs, const RunnerOptions& options);

/// Fills `r` from the files of a finished run of r.spec and returns "" if they hold a complete
/// record of it (see above); else returns why not, in a few words, and leaves `r` as it was.
[[nodiscard]] std::string keep_finished_run(RunResult& r, const RunnerOptions& options);

/// "rolling at t = 173.1 s, 0.37 s wall" (or the error).
[[nodiscard]] std::string describe(const RunResult& r);

}  // namespace frictionlab::dynamics::paper
