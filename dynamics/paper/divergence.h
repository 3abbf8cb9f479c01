#pragma once
// How far two runs of the same case are apart along the motion: the angle between their bodies'
// symmetry axes in world axes (the pose, dynamics/body/state.h), which holds the tilt and the
// heading of the axis together (a body of revolution has no other orientation to compare). Two runs
// of the same law that differ only by the chaos floor's perturbation (the reference law with
// tightened tolerances, dynamics/paper/experiment_plan.h) part at some time anyway; a law parts
// from the reference because of its own error if it does so earlier (docs/experiments.md §3).

#include <array>
#include <numbers>
#include <vector>

namespace frictionlab::dynamics::paper {

/// The angle at which two axes have visibly parted: 1 degree (rad).
inline constexpr double kPartingAngle = std::numbers::pi / 180.0;

/// The angle between two runs' axes against time.
struct DistanceSeries {
  std::vector<double> t;      ///< s
  std::vector<double> angle;  ///< rad, in [0, pi]
};

/// The angle atan2(|a x b|, a . b) between the axes of runs a and b (each t ascending, the axis's
/// three components as long as t) at their common sample times: pairwise from the first sample
/// while both runs' times are equal bit for bit (the paper's runs share one output grid), up to the
/// first that is not (a run's last sample, at its own final time). Exactly 0 where the axes are
/// equal bit for bit. An axis without components (not recorded) gives an empty series.
[[nodiscard]] DistanceSeries axis_distance(const std::vector<double>& t_a, const std::array<std::vector<double>, 3>& a,
                                           const std::vector<double>& t_b, const std::array<std::vector<double>, 3>& b);

/// The first time the angle reaches `threshold` (rad); NaN if it never does.
[[nodiscard]] double parting_time(const DistanceSeries& d, double threshold = kPartingAngle);

}  // namespace frictionlab::dynamics::paper
