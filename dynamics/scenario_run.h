#pragma once
// A scenario run end to end: build the body and the right-hand side, integrate, and write
// DIR/trajectory.csv, DIR/summary.json and DIR/scenario.toml (the scenario after overrides).
// The summary is written whatever the termination reason.

#include <atomic>
#include <filesystem>

#include "dynamics/observer.h"
#include "dynamics/scenario.h"
#include "dynamics/simulation.h"
#include "friction/law.h"

namespace frictionlab::dynamics {

struct ScenarioRun {
  RunSummary summary;
  std::filesystem::path trajectory_csv;
  std::filesystem::path summary_json;
};

/// Runs `scenario` with `law` (the caller resolves the name; scenario.law is not consulted).
/// `progress` (may be null) also receives every sample and step. Throws std::invalid_argument
/// before writing anything if the initial state is rejected, std::runtime_error if DIR is not
/// writable.
[[nodiscard]] ScenarioRun run_scenario(const Scenario& scenario, const friction::FrictionLaw& law,
                                       const std::filesystem::path& out_dir, Observer* progress = nullptr,
                                       const std::atomic<bool>* cancel = nullptr);

}  // namespace frictionlab::dynamics
