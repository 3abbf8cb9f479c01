#pragma once
// Runs a planned grid (dynamics/paper/experiment_plan.h) on a pool of worker threads. Each run
// goes through dynamics::run_scenario (trajectory.csv, summary.json, scenario.toml in its folder),
// recorded by a SeriesRecorder; right after it ends its worker measures its features, writes
// features.json beside the summary and the binned plot data (dynamics/paper/figure_data.h), and
// keeps only gamma3 in memory for the comparisons. A run that stops early (a law's pole, ...) is a
// result like any other; a run that cannot start (the law rejects the initial state, the folder is
// not writable) is recorded with its error, and the others go on.

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "dynamics/paper/experiment_plan.h"
#include "dynamics/paper/figure_data.h"
#include "dynamics/paper/run_features.h"
#include "dynamics/paper/run_progress.h"
#include "dynamics/simulation.h"

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
  std::vector<double> t;              ///< s, samples (kept for the comparisons)
  std::vector<double> gamma3;         ///< at the samples
  std::vector<double> gamma3_smooth;  ///< moving average (thresholds.smoothing_window)
  FigureRanges figure_ranges;         ///< axis caps of its figure data

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
};

/// The number of worker threads `jobs` asks for (>= 1).
[[nodiscard]] int worker_count(int jobs);

/// Runs every spec; results in the order of `specs`.
[[nodiscard]] std::vector<RunResult> run_experiments(const std::vector<RunSpec>& specs, const RunnerOptions& options);

/// "rolling at t = 173.1 s, 0.37 s wall" (or the error).
[[nodiscard]] std::string describe(const RunResult& r);

}  // namespace frictionlab::dynamics::paper
