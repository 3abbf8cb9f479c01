#pragma once
// Runs one task of an ensemble (dynamics/ensemble/ensemble_plan.h: a start, a pair of replicas,
// every law) on the calling thread, and hands each finished run to `emit` as soon as it ends.
//
// Per replica the reference law runs first, carrying the study's shadow laws (statistics only,
// EnsemblePlan::shadow_laws); its sampled gamma3(t) stays in memory until the task
// ends, for the divergence times of the other laws on that replica and of the reference on the
// pair's second replica (the chaos floor). Nothing else outlives its run: a task holds at most
// two reference series and the run in progress (~2.5 MB each for 1000 s at output_dt = 0.01 s),
// whatever the size of the ensemble.
//
// Runs listed as done are not emitted; the reference still runs if a run of the task that is not
// done needs its series (a task cut by a kill, resumed: its reference is recomputed — the same
// bit for bit — rather than stored). A run that fails (its scenario or law rejects it) is a
// record with reason "failed" and its message; the task goes on. A run interrupted by `cancel`
// is not emitted, and the task stops (returns false): it is not finished and will be redone.

#include <atomic>
#include <functional>
#include <vector>

#include "dynamics/ensemble/decimated_trajectory.h"
#include "dynamics/ensemble/ensemble_plan.h"
#include "dynamics/ensemble/run_record.h"

namespace frictionlab::dynamics::ensemble {

/// A task and the runs of it still to record (run indices).
struct TaskOrder {
  Task task;
  std::vector<long> todo;
};

struct FinishedRun {
  RunRecord record;
  DecimatedTrajectory trajectory;  ///< empty unless asked for
};

struct ExecuteOptions {
  bool trajectories = false;                  ///< record decimated trajectories (study.trajectory_dt)
  const std::atomic<bool>* cancel = nullptr;  ///< raised: the run in progress stops, the task ends
};

/// Runs the task; false if it was interrupted.
bool execute_task(const EnsemblePlan& plan, const TaskOrder& order, const ExecuteOptions& options,
                  const std::function<void(FinishedRun&&)>& emit);

}  // namespace frictionlab::dynamics::ensemble
