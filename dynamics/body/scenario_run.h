#pragma once
// A scenario run end to end: make the scenario's law, the right-hand side from its body, integrate,
// and write DIR/trajectory.csv, DIR/summary.json and DIR/scenario.toml (the resolved scenario:
// rerunning it reproduces the run). The summary is written whatever the termination reason.
//
// Every write is checked. A trajectory row that cannot be written stops the run at once (reason
// output-error; the CSV keeps its whole rows); the summary and scenario.toml are written to a
// temporary file and renamed, so they are whole or absent.

#include <atomic>
#include <filesystem>

#include "dynamics/core/observer.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"

namespace frictionlab::dynamics {

struct ScenarioRun {
  RunSummary summary;
  std::filesystem::path trajectory_csv;
  std::filesystem::path summary_json;
  /// Why trajectory.csv is incomplete (a write or its close failed), or empty. The summary was
  /// written and says so too.
  std::string output_error;
};

/// Runs `scenario` (its body, its law) into `out_dir`. `progress` (may be null) also receives
/// every sample and step. Throws std::invalid_argument before writing anything if the initial
/// state is rejected; support::OutputError (a std::runtime_error) if DIR, scenario.toml or
/// summary.json cannot be written. A failed trajectory is not thrown: see `output_error`.
[[nodiscard]] ScenarioRun run_scenario(const Scenario& scenario, const std::filesystem::path& out_dir,
                                       Observer* progress = nullptr, const std::atomic<bool>* cancel = nullptr);

}  // namespace frictionlab::dynamics
