#pragma once
// A rigid body for the rigid rolling model (docs/rigid-rolling.md): mass, the full inertia tensor
// about the centre of mass (body frame, principal axes anywhere), its rolling surface, gravity, and
// an optional linear spin damping (off by default).

#include <Eigen/Core>
#include <memory>

#include "dynamics/rigid_rolling/rolling_surface.h"

namespace frictionlab::dynamics::rigid_rolling {

struct RigidRollingBody {
  double mass = 0.0;                                ///< kg, finite, > 0
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< tensor J about the centre of mass, body frame, kg m^2
  std::shared_ptr<const RollingSurface> surface;    ///< the contact geometry (required)
  double gravity = 9.81;                            ///< g, m/s^2, finite, > 0
  /// c in the torque -c (omega . gamma) gamma about the vertical, N m s, >= 0 (0: none). A linear
  /// stand-in for spin friction at a rolling contact; a Coulomb spin moment (set-valued at zero
  /// spin, which a reversal passes through) is deliberately not offered here.
  double spin_damping = 0.0;

  /// Throws std::invalid_argument naming the value and the rule: mass, gravity, damping as above;
  /// J symmetric (to 1e-12 relative), with positive principal moments that satisfy the triangle
  /// inequality (each <= the sum of the other two, to 1e-12 relative) as for any real body.
  void validate() const;
};

}  // namespace frictionlab::dynamics::rigid_rolling
