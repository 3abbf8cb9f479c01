#pragma once
// The state vector of the body on the plane, and named access to its parts (docs/dynamics.md §3).
//
//   x = ( v (3), omega (3), gamma (3), eps, W_slide, W_spin )
//
// v: velocity of the centre of mass (m/s), omega: angular velocity (1/s), gamma: upward unit
// vertical (dimensionless), all in the body frame; eps: height of the contact point over the plane
// (m, negative = penetration); W_slide = ∫ F1 U dt and W_spin = ∫ M Omega dt (J): the work done
// against sliding and against spinning friction, integrated along with the motion so that
// energy balance E + W_slide + W_spin = E(0) can be checked and the dissipation split reported.

#include <Eigen/Core>

namespace frictionlab::dynamics {

/// Offsets of the parts of the state vector.
struct StateLayout {
  static constexpr int kVelocity = 0;
  static constexpr int kAngularVelocity = 3;
  static constexpr int kVertical = 6;
  static constexpr int kHeight = 9;
  static constexpr int kSlideWork = 10;
  static constexpr int kSpinWork = 11;
  static constexpr int kSize = 12;
};

using StateVector = Eigen::Matrix<double, StateLayout::kSize, 1>;

// Named accessors (mutable and const). Never index the state with bare numbers.
inline auto velocity(StateVector& x) { return x.segment<3>(StateLayout::kVelocity); }
inline auto velocity(const StateVector& x) { return x.segment<3>(StateLayout::kVelocity); }
inline auto angular_velocity(StateVector& x) { return x.segment<3>(StateLayout::kAngularVelocity); }
inline auto angular_velocity(const StateVector& x) { return x.segment<3>(StateLayout::kAngularVelocity); }
inline auto vertical(StateVector& x) { return x.segment<3>(StateLayout::kVertical); }
inline auto vertical(const StateVector& x) { return x.segment<3>(StateLayout::kVertical); }
inline double& height(StateVector& x) { return x[StateLayout::kHeight]; }
inline double height(const StateVector& x) { return x[StateLayout::kHeight]; }
inline double& slide_work(StateVector& x) { return x[StateLayout::kSlideWork]; }
inline double slide_work(const StateVector& x) { return x[StateLayout::kSlideWork]; }
inline double& spin_work(StateVector& x) { return x[StateLayout::kSpinWork]; }
inline double spin_work(const StateVector& x) { return x[StateLayout::kSpinWork]; }

/// A state with zero accumulated work.
inline StateVector make_state(const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Eigen::Vector3d& gamma,
                              double eps) {
  StateVector x = StateVector::Zero();
  velocity(x) = v;
  angular_velocity(x) = omega;
  vertical(x) = gamma;
  height(x) = eps;
  return x;
}

}  // namespace frictionlab::dynamics
