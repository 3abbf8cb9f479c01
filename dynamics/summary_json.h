#pragma once
// summary.json of a run (docs/dynamics.md §6): what ran, why it stopped, what it cost, and the
// final state. Non-finite numbers are written as null.

#include <ostream>
#include <string_view>

#include "dynamics/body.h"
#include "dynamics/scenario.h"
#include "dynamics/simulation.h"

namespace frictionlab::dynamics {

void write_summary_json(std::ostream& out, const Scenario& scenario, const Body& body, std::string_view law,
                        const RunSummary& summary);

}  // namespace frictionlab::dynamics
