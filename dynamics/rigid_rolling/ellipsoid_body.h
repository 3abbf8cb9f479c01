#pragma once
// A rigid body whose rolling surface is a triaxial ellipsoid with its axes along the body axes and
// its centre on the body z-axis (the rattleback of docs/rigid-rolling.md): the centre of mass G lies
// on the ellipsoid's short vertical axis, below its centre by `centre_height`, and the body rests on
// the end of the a3 axis. Its steady-spin data follow in closed form: l = a3 - centre_height,
// R1 = a1^2/a3, R2 = a2^2/a3.

#include <Eigen/Core>

#include "dynamics/rigid_rolling/rigid_body.h"
#include "dynamics/rigid_rolling/steady_spin.h"

namespace frictionlab::dynamics::rigid_rolling {

struct EllipsoidBody {
  Eigen::Vector3d semi_axes = Eigen::Vector3d::Zero();  ///< (a1, a2, a3) along body x, y, z, m
  double centre_height = 0.0;  ///< height of the ellipsoid's centre above G, m, < a3 (G inside)
  double mass = 0.0;           ///< kg
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< J about G, body frame, kg m^2
  double gravity = 9.81;       ///< m/s^2
};

/// The rigid rolling body (dynamics/rigid_rolling/rolling_equations.h). Throws std::invalid_argument.
[[nodiscard]] RigidRollingBody rigid_body(const EllipsoidBody& body, double spin_damping = 0.0);
/// Its steady-spin data (dynamics/rigid_rolling/steady_spin.h). Throws std::invalid_argument.
[[nodiscard]] SteadySpinBody steady_spin_body(const EllipsoidBody& body);

}  // namespace frictionlab::dynamics::rigid_rolling
