#pragma once
// A puck scenario run end to end (as dynamics/body/scenario_run.h for the body): make the law, integrate,
// write DIR/trajectory.csv, DIR/summary.json and DIR/scenario.toml (rerunning it reproduces the
// run). Every write is checked; the summary is written whatever the termination reason.

#include <atomic>
#include <filesystem>
#include <string>

#include "dynamics/puck/puck_run.h"
#include "dynamics/puck/puck_scenario.h"

namespace frictionlab::dynamics::puck {

struct PuckScenarioRun {
  PuckRunSummary summary;
  std::filesystem::path trajectory_csv;
  std::filesystem::path summary_json;
  std::string output_error;  ///< why trajectory.csv is incomplete, or empty
};

/// Runs `scenario` into `out_dir`. `progress` (may be null) also receives every sample and step.
/// Throws std::invalid_argument before writing anything if the law rejects the initial state;
/// support::OutputError if DIR, scenario.toml or summary.json cannot be written.
[[nodiscard]] PuckScenarioRun run_puck_scenario(const PuckScenario& scenario, const std::filesystem::path& out_dir,
                                                PuckObserver* progress = nullptr,
                                                const std::atomic<bool>* cancel = nullptr);

}  // namespace frictionlab::dynamics::puck
