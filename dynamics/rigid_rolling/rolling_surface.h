#pragma once
// The surface of a convex rigid body as the rigid rolling model needs it (docs/rigid-rolling.md §1).
// For the upward vertical gamma (body frame) the surface answers
//
//   r(gamma)              the contact point: the surface point whose outward normal is -gamma,
//                         from the centre of mass, body frame, m;
//   dr/dt = r'(gamma)[gamma']   its rate of change in the body frame along a motion gamma(t).
//
// Both depend on the direction of gamma only (homogeneous of degree 0), so a gamma that an
// integrator lets drift off the unit sphere still gives the right point. This is the reference's
// own small geometry (independent of the compliant models' shapes on purpose: the two are compared).
// Adding a surface: derive from RollingSurface, write both functions, and test the rate against
// central differences of the point (tests/dynamics/rigid_rolling/*_surface_test.cpp).

#include <Eigen/Core>

namespace frictionlab::dynamics::rigid_rolling {

class RollingSurface {
 public:
  virtual ~RollingSurface() = default;

  /// The contact point r(gamma), m (gamma: the upward vertical in the body frame, nonzero).
  [[nodiscard]] virtual Eigen::Vector3d contact_point(const Eigen::Vector3d& gamma) const = 0;
  /// Its rate of change r'(gamma)[gamma_rate] in the body frame, m/s (gamma_rate in 1/s).
  [[nodiscard]] virtual Eigen::Vector3d contact_point_rate(const Eigen::Vector3d& gamma,
                                                           const Eigen::Vector3d& gamma_rate) const = 0;
};

}  // namespace frictionlab::dynamics::rigid_rolling
