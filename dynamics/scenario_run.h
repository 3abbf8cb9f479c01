#pragma once
// A scenario run end to end: make the scenario's law, the right-hand side from its body, integrate,
// and write DIR/trajectory.csv, DIR/summary.json and DIR/scenario.toml (the resolved scenario:
// rerunning it reproduces the run). The summary is written whatever the termination reason.

#include <atomic>
#include <filesystem>

#include "dynamics/observer.h"
#include "dynamics/scenario.h"
#include "dynamics/simulation.h"

namespace frictionlab::dynamics {

struct ScenarioRun {
  RunSummary summary;
  std::filesystem::path trajectory_csv;
  std::filesystem::path summary_json;
};

/// Runs `scenario` (its body, its law) into `out_dir`. `progress` (may be null) also receives
/// every sample and step. Throws std::invalid_argument before writing anything if the initial
/// state is rejected, std::runtime_error if DIR is not writable.
[[nodiscard]] ScenarioRun run_scenario(const Scenario& scenario, const std::filesystem::path& out_dir,
                                       Observer* progress = nullptr, const std::atomic<bool>* cancel = nullptr);

}  // namespace frictionlab::dynamics
