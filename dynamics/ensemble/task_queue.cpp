#include "dynamics/ensemble/task_queue.h"

namespace frictionlab::dynamics::ensemble {

TaskQueue::TaskQueue(const EnsemblePlan& plan, std::set<long> done) : plan_(plan), done_(std::move(done)) {
  runs_to_do_ = plan.runs();
  for (const long run : done_)
    if (run >= 0 && run < plan.runs()) --runs_to_do_;
}

std::optional<TaskOrder> TaskQueue::next() {
  const std::lock_guard<std::mutex> lock(mutex_);
  while (next_task_ < plan_.tasks()) {
    TaskOrder order;
    order.task = plan_.task(next_task_++);
    for (long r = order.task.first_replica; r < order.task.first_replica + order.task.replica_count; ++r)
      for (int law = 0; law < plan_.laws(); ++law) {
        const long run = plan_.run_index({order.task.start, r, law});
        if (!done_.count(run)) order.todo.push_back(run);
      }
    if (!order.todo.empty()) return order;
  }
  return std::nullopt;
}

}  // namespace frictionlab::dynamics::ensemble
