#pragma once
// The state vector of the body on the plane, and named access to its parts (docs/dynamics.md §3).
//
//   x = ( v (3), omega (3), gamma (3), eps, W_slide, W_spin, position (2), orientation (4) )
//
// v: velocity of the centre of mass (m/s), omega: angular velocity (1/s), gamma: upward unit
// vertical (dimensionless), all in the body frame; eps: height of the contact point over the plane
// (m, negative = penetration); W_slide = ∫ F1 U dt and W_spin = ∫ M Omega dt (J): the work done
// against sliding and against spinning friction, integrated along with the motion so that
// energy balance E + W_slide + W_spin = E(0) can be checked and the dissipation split reported.
//
// The pose rides along (docs/convex-bodies.md §11): position = (X, Y), the centre of mass on the
// plane (m, world axes), and orientation = the unit quaternion (w, x, y, z) that turns body-frame
// vectors into world ones. They are integrated beside the reduced state but never fed back: no
// force, torque or event reads them, and their absolute tolerance scale is infinite
// (dynamics/body/tolerance_scales.h), so the steps and every other component keep their bits.

#include <Eigen/Core>
#include <Eigen/Geometry>  // quaternions

namespace frictionlab::dynamics {

/// Offsets of the parts of the state vector.
struct StateLayout {
  static constexpr int kVelocity = 0;
  static constexpr int kAngularVelocity = 3;
  static constexpr int kVertical = 6;
  static constexpr int kHeight = 9;
  static constexpr int kSlideWork = 10;
  static constexpr int kSpinWork = 11;
  /// The components before the pose: they never read it (run.pose = false integrates only them).
  static constexpr int kPoseFreeSize = 12;
  static constexpr int kPosition = 12;     ///< X, Y on the plane (world), m
  static constexpr int kOrientation = 14;  ///< unit quaternion w, x, y, z: body -> world
  static constexpr int kSize = 18;
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

inline auto position(StateVector& x) { return x.segment<2>(StateLayout::kPosition); }
inline auto position(const StateVector& x) { return x.segment<2>(StateLayout::kPosition); }
inline auto orientation(StateVector& x) { return x.segment<4>(StateLayout::kOrientation); }
inline auto orientation(const StateVector& x) { return x.segment<4>(StateLayout::kOrientation); }

/// The orientation with the stored quaternion normalised (w, x, y, z), for outputs.
inline Eigen::Quaterniond orientation_quaternion(const StateVector& x) {
  const auto q = orientation(x);
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
}

/// The orientation whose upward vertical in the body frame is `gamma` (unit) and whose heading is
/// `heading` (rad): the shortest turn taking gamma to the world's up e_z, then a turn by `heading`
/// about e_z. As (w, x, y, z). (Out of line, dynamics/body/state.cpp: Eigen's FromTwoVectors
/// brings its SVD, ~5 s of compile time in every file that would include it.)
[[nodiscard]] Eigen::Vector4d orientation_from(const Eigen::Vector3d& gamma, double heading);

/// A state with zero accumulated work, at the plane's origin with heading 0.
[[nodiscard]] StateVector make_state(const Eigen::Vector3d& v, const Eigen::Vector3d& omega, const Eigen::Vector3d& gamma,
                                     double eps);

}  // namespace frictionlab::dynamics
