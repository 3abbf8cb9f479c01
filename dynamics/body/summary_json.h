#pragma once
// summary.json of a run (docs/dynamics.md §6): what ran, why it stopped, what it cost, and the
// final state. Non-finite numbers are written as null.

#include <string>
#include <vector>

#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"
#include "dynamics/core/threshold.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics {

/// The "termination" record of a summary.json (the body's and the puck's): the reason, the
/// message, the rule that ended the run and the thresholds that decided it.
[[nodiscard]] support::Json termination_json(Termination reason, const std::string& message, const std::string& rule,
                                             const std::vector<Threshold>& thresholds);

/// The summary of a run of `scenario` (its body, its law).
[[nodiscard]] support::Json summary_json(const Scenario& scenario, const RunSummary& summary);

}  // namespace frictionlab::dynamics
