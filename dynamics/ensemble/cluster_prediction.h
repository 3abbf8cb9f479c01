#pragma once
// How long a study would take on P cores, from the measured cost of its runs: the tasks
// (dynamics/ensemble/ensemble_plan.h) are handed out in plan order, each to the first core that is
// free (what the task queue does, on threads or MPI ranks), and the prediction is when the last
// one ends (greedy list scheduling). A task's cost is the sum of its runs' wall times. Assumed:
// one worker per core, each as fast as the core the runs were measured on; per task a fixed
// overhead (the coordination, measured in docs/ensembles.md §6), and no start-up or I/O cost.

#include <vector>

#include "dynamics/ensemble/run_record.h"

namespace frictionlab::dynamics::ensemble {

/// The tasks' costs (s), in plan order, from a study's rows: runs grouped by (start, replica / 2).
[[nodiscard]] std::vector<double> task_costs(const std::vector<RunRecord>& rows);

/// When the last of `tasks` (costs in s, handed out in this order) ends on `cores` workers, each
/// task costing `overhead` s more.
[[nodiscard]] double predicted_wall_time(const std::vector<double>& tasks, long cores, double overhead = 0.0);

}  // namespace frictionlab::dynamics::ensemble
