#pragma once
// summary.json of a run (docs/dynamics.md §6): what ran, why it stopped, what it cost, and the
// final state. Non-finite numbers are written as null.

#include "dynamics/scenario.h"
#include "dynamics/simulation.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics {

/// The summary of a run of `scenario` (its body, its law).
[[nodiscard]] support::Json summary_json(const Scenario& scenario, const RunSummary& summary);

}  // namespace frictionlab::dynamics
