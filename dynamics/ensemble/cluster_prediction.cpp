#include "dynamics/ensemble/cluster_prediction.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>

namespace frictionlab::dynamics::ensemble {

std::vector<double> task_costs(const std::vector<RunRecord>& rows) {
  std::map<std::pair<long, long>, double> cost;
  for (const auto& r : rows)
    if (std::isfinite(r.wall_time)) cost[{r.start, r.replica / 2}] += r.wall_time;
  std::vector<double> out;
  out.reserve(cost.size());
  for (const auto& [task, c] : cost) out.push_back(c);
  return out;
}

double predicted_wall_time(const std::vector<double>& tasks, long cores, double overhead) {
  if (tasks.empty() || cores < 1) return 0.0;
  // The time each worker becomes free; the next task goes to the earliest.
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (long c = 0; c < std::min<long>(cores, static_cast<long>(tasks.size())); ++c) free_at.push(0.0);
  double end = 0.0;
  for (const double t : tasks) {
    const double start = free_at.top();
    free_at.pop();
    const double finish = start + t + overhead;
    end = std::max(end, finish);
    free_at.push(finish);
  }
  return end;
}

}  // namespace frictionlab::dynamics::ensemble
