// Predicted wall times on P cores (dynamics/ensemble/cluster_prediction.h) against closed forms.

#include "dynamics/ensemble/cluster_prediction.h"

#include <gtest/gtest.h>

namespace frictionlab::dynamics::ensemble {
namespace cluster_prediction_test {

TEST(EnsembleClusterPrediction, EqualTasksTakeCeilingOfTheirShareOfCores) {
  const std::vector<double> tasks(10, 2.0);
  EXPECT_EQ(predicted_wall_time(tasks, 1), 20.0);
  EXPECT_EQ(predicted_wall_time(tasks, 3), 8.0) << "ceil(10/3) = 4 rounds of 2 s";
  EXPECT_EQ(predicted_wall_time(tasks, 10), 2.0);
  EXPECT_EQ(predicted_wall_time(tasks, 1024), 2.0) << "more cores than tasks";
  EXPECT_EQ(predicted_wall_time(tasks, 5, 0.5), 5.0) << "2 rounds of 2.5 s";
}

TEST(EnsembleClusterPrediction, TheLongestTaskBoundsTheTimeAndOrderMatters) {
  // In plan order: the long task comes last and finishes alone.
  EXPECT_EQ(predicted_wall_time({1, 1, 1, 1, 10}, 2), 12.0);
  EXPECT_EQ(predicted_wall_time({10, 1, 1, 1, 1}, 2), 10.0) << "handed out first, the others fit beside it";
  EXPECT_EQ(predicted_wall_time({}, 4), 0.0);
}

TEST(EnsembleClusterPrediction, TasksAreAStartAndAPairOfReplicas) {
  std::vector<RunRecord> rows;
  for (long start = 0; start < 2; ++start)
    for (long replica = 0; replica < 3; ++replica)
      for (int law = 0; law < 2; ++law) {
        RunRecord r;
        r.start = start;
        r.replica = replica;
        r.wall_time = 1.0 + start;
        rows.push_back(r);
      }
  // Start 0: replicas (0, 1) -> 4 runs of 1 s, replica 2 -> 2 runs; start 1 the same at 2 s.
  EXPECT_EQ(task_costs(rows), (std::vector<double>{4.0, 2.0, 8.0, 4.0}));
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
