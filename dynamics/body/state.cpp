#include "dynamics/body/state.h"

#include <Eigen/Geometry>

namespace frictionlab::dynamics {

Eigen::Vector4d orientation_from(const Eigen::Vector3d& gamma, double heading) {
  if (!(gamma.allFinite() && gamma.norm() > 0.0)) return {1.0, 0.0, 0.0, 0.0};  // no vertical: no tilt
  const Eigen::Quaterniond tilt = Eigen::Quaterniond::FromTwoVectors(gamma, Eigen::Vector3d::UnitZ());
  const Eigen::Quaterniond q = Eigen::Quaterniond(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ())) * tilt;
  return {q.w(), q.x(), q.y(), q.z()};
}

StateVector make_state(const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Eigen::Vector3d& gamma,
                       double eps) {
  StateVector x = StateVector::Zero();
  velocity(x) = v;
  angular_velocity(x) = omega;
  vertical(x) = gamma;
  height(x) = eps;
  orientation(x) = orientation_from(gamma.normalized(), 0.0);
  return x;
}

}  // namespace frictionlab::dynamics
