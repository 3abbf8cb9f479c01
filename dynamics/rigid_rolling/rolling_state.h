#pragma once
// The state of the rigid rolling model: the angular velocity omega and the upward vertical gamma,
// both in the body frame (docs/rigid-rolling.md §1). Position on the plane and heading are ignorable
// coordinates (they do not enter the equations) and are not carried.

#include <Eigen/Core>

namespace frictionlab::dynamics::rigid_rolling {

struct RollingState {
  static constexpr int kSize = 6;
  static constexpr int kOmega = 0;  ///< offset of omega (1/s) in the packed vector
  static constexpr int kGamma = 3;  ///< offset of gamma (unit) in the packed vector

  Eigen::Vector3d omega = Eigen::Vector3d::Zero();   ///< angular velocity, body frame, 1/s
  Eigen::Vector3d gamma = Eigen::Vector3d::UnitZ();  ///< upward vertical, body frame, unit

  /// The spin about the vertical, omega . gamma, 1/s.
  [[nodiscard]] double spin() const { return omega.dot(gamma); }

  [[nodiscard]] Eigen::Matrix<double, kSize, 1> packed() const {
    Eigen::Matrix<double, kSize, 1> x;
    x << omega, gamma;
    return x;
  }
  [[nodiscard]] static RollingState unpacked(const double* x) {
    return {Eigen::Vector3d(x[kOmega], x[kOmega + 1], x[kOmega + 2]), Eigen::Vector3d(x[kGamma], x[kGamma + 1], x[kGamma + 2])};
  }
  [[nodiscard]] static RollingState unpacked(const Eigen::Matrix<double, kSize, 1>& x) { return unpacked(x.data()); }
};

}  // namespace frictionlab::dynamics::rigid_rolling
