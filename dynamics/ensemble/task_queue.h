#pragma once
// The tasks of an ensemble still to do, handed out one at a time in plan order to whoever asks
// (worker threads, MPI ranks): dynamic load balancing, since run costs differ a hundredfold (a
// law stopping at its pole after 2 ms, a run to rest after 450 s). Thread-safe.

#include <mutex>
#include <optional>
#include <set>

#include "dynamics/ensemble/ensemble_plan.h"
#include "dynamics/ensemble/task_execution.h"

namespace frictionlab::dynamics::ensemble {

class TaskQueue {
 public:
  /// Every task of `plan` with a run not in `done`.
  TaskQueue(const EnsemblePlan& plan, std::set<long> done);

  /// The next task with the runs of it still to do; empty when none is left.
  [[nodiscard]] std::optional<TaskOrder> next();
  /// Runs to do when the queue was made.
  [[nodiscard]] long runs_to_do() const { return runs_to_do_; }

 private:
  const EnsemblePlan& plan_;
  std::set<long> done_;
  long runs_to_do_ = 0;
  long next_task_ = 0;
  std::mutex mutex_;
};

}  // namespace frictionlab::dynamics::ensemble
