#include "dynamics/paper/divergence.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace frictionlab::dynamics::paper {

DistanceSeries axis_distance(const std::vector<double>& t_a, const std::array<std::vector<double>, 3>& a,
                             const std::vector<double>& t_b, const std::array<std::vector<double>, 3>& b) {
  DistanceSeries d;
  std::size_t n = std::min(t_a.size(), t_b.size());
  for (const auto* axis : {&a, &b}) {
    for (const auto& component : *axis) n = std::min(n, component.size());
  }
  for (std::size_t i = 0; i < n && t_a[i] == t_b[i]; ++i) {
    const Eigen::Vector3d u(a[0][i], a[1][i], a[2][i]);
    const Eigen::Vector3d v(b[0][i], b[1][i], b[2][i]);
    d.t.push_back(t_a[i]);
    d.angle.push_back(std::atan2(u.cross(v).norm(), u.dot(v)));
  }
  return d;
}

double parting_time(const DistanceSeries& d, double threshold) {
  for (std::size_t i = 0; i < d.t.size(); ++i) {
    if (d.angle[i] >= threshold) return d.t[i];
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace frictionlab::dynamics::paper
