#pragma once
// summary.json of a puck run (docs/puck.md §2): what ran, why it stopped, when the slip and the
// spin stopped, the terminal ratio (measured, and predicted from the law for a circular patch,
// dynamics/puck/terminal_ratio.h), the path, the energy balance. Non-finite numbers are null.

#include "dynamics/puck/puck_run.h"
#include "dynamics/puck/puck_scenario.h"
#include "friction/law.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics::puck {

/// The summary of a run of `scenario` with `law` (the scenario's law, made once by the caller).
[[nodiscard]] support::Json puck_summary_json(const PuckScenario& scenario, const friction::FrictionLaw& law,
                                              const PuckRunSummary& summary);

/// The signed distance of `end` from the straight line through `start` along `direction` (left of
/// it positive), and the distance along it (m). A zero direction gives {0, 0}.
struct PathOffset {
  double along = 0.0;
  double lateral = 0.0;
};
[[nodiscard]] PathOffset path_offset(const Eigen::Vector2d& start, const Eigen::Vector2d& direction,
                                     const Eigen::Vector2d& end);

}  // namespace frictionlab::dynamics::puck
