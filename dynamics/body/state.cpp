#include "dynamics/body/state.h"

#include <Eigen/Geometry>
#include <cmath>

namespace frictionlab::dynamics {

namespace {

// The shortest rotation turning the unit vector g into e_z, as Eigen's Quaternion::FromTwoVectors
// computes it (the same operations in the same order, so the same bits) but for nearly opposite
// vectors, where Eigen instantiates an SVD (~10 s of compile time a build) and takes the rotation's
// angle from 1 + c, which has lost most of its digits. There the axis is the unit normal to both
// (v0 x v1 normalised; for exactly opposite vectors, the normal to g and to the coordinate axis g
// is least along) and the angle atan2(|v0 x v1|, c), exact to rounding.
Eigen::Quaterniond tilt_to_vertical(const Eigen::Vector3d& g) {
  const Eigen::Vector3d v0 = g.normalized();
  const Eigen::Vector3d v1 = Eigen::Vector3d::UnitZ();
  const double c = v1.dot(v0);
  if (c < -1.0 + Eigen::NumTraits<double>::dummy_precision()) {
    Eigen::Vector3d axis = v0.cross(v1);
    const double sine = axis.norm();
    if (!(sine > 0.0)) {
      Eigen::Index least = 0;
      v0.cwiseAbs().minCoeff(&least);
      axis = v0.cross(Eigen::Vector3d::Unit(least));
    }
    axis.normalize();
    const double half = 0.5 * std::atan2(sine, c);
    const Eigen::Vector3d vec = axis * std::sin(half);
    return {std::cos(half), vec.x(), vec.y(), vec.z()};
  }
  const Eigen::Vector3d axis = v0.cross(v1);
  const double s = std::sqrt((1.0 + c) * 2.0);
  const Eigen::Vector3d vec = axis * (1.0 / s);
  return {s * 0.5, vec.x(), vec.y(), vec.z()};
}

}  // namespace

Eigen::Vector4d orientation_from(const Eigen::Vector3d& gamma, double heading) {
  if (!(gamma.allFinite() && gamma.norm() > 0.0)) return {1.0, 0.0, 0.0, 0.0};  // no vertical: no tilt
  const Eigen::Quaterniond tilt = tilt_to_vertical(gamma);
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
