#include "dynamics/rigid_rolling/inertia_misalignment.h"

#include <cmath>

namespace frictionlab::dynamics::rigid_rolling {

Eigen::Matrix3d inertia_rotated_about_vertical(double a0, double b0, double c, double delta) {
  const double cs = std::cos(delta), sn = std::sin(delta);
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  j(0, 0) = a0 * cs * cs + b0 * sn * sn;
  j(1, 1) = a0 * sn * sn + b0 * cs * cs;
  j(0, 1) = j(1, 0) = (a0 - b0) * sn * cs;
  j(2, 2) = c;
  return j;
}

double misalignment_angle(const Eigen::Matrix3d& inertia) {
  return 0.5 * std::atan2(-2.0 * inertia(0, 1), inertia(1, 1) - inertia(0, 0));
}

}  // namespace frictionlab::dynamics::rigid_rolling
