#pragma once
// The rigid body rolling without slip on a horizontal plane (the nonholonomic model; derivation in
// docs/rigid-rolling.md §1). Body frame at the centre of mass G; r = r(gamma) the contact point from
// G (dynamics/rigid_rolling/rolling_surface.h); no slip: v_G = -omega x r. Eliminating the contact
// force from Newton's and Euler's equations:
//
//   gamma' = gamma x omega,
//   [J + m (|r|^2 1 - r r^T)] omega' = -omega x J omega - m r x (omega x r')
//                                      - m r x (omega x (omega x r)) + m g r x gamma - c (omega . gamma) gamma,
//
// r' = r'(gamma)[gamma']. Equivalently d/dt of K = J omega + m r x (omega x r), the angular momentum
// about the contact point, as in the docs. Energy E = omega . J omega/2 + m |omega x r|^2/2
// - m g (r . gamma) is conserved when c = 0 and falls at the rate c (omega . gamma)^2 otherwise.

#include <Eigen/Core>

#include "dynamics/rigid_rolling/rigid_body.h"
#include "dynamics/rigid_rolling/rolling_state.h"

namespace frictionlab::dynamics::rigid_rolling {

class RigidRollingModel {
 public:
  /// Throws std::invalid_argument for an invalid body (RigidRollingBody::validate).
  explicit RigidRollingModel(RigidRollingBody body);

  /// d(state)/dt. Throws what the surface throws (e.g. std::domain_error for a disk lying flat).
  [[nodiscard]] RollingState derivative(const RollingState& x) const;
  /// The total energy (J): kinetic + gravity, the potential zero with G on the plane.
  [[nodiscard]] double energy(const RollingState& x) const;
  /// The rate at which the spin damping removes energy, c (omega . gamma)^2, W.
  [[nodiscard]] double dissipation(const RollingState& x) const;
  /// The contact point from G, body frame, m.
  [[nodiscard]] Eigen::Vector3d contact_point(const RollingState& x) const { return body_.surface->contact_point(x.gamma); }
  /// The velocity of G, -omega x r, body frame, m/s.
  [[nodiscard]] Eigen::Vector3d centre_velocity(const RollingState& x) const;
  /// The contact force on the body (normal and tangential), body frame, N: m (v' + omega x v) + m g gamma.
  [[nodiscard]] Eigen::Vector3d contact_force(const RollingState& x) const;

  [[nodiscard]] const RigidRollingBody& body() const { return body_; }

 private:
  RigidRollingBody body_;
};

}  // namespace frictionlab::dynamics::rigid_rolling
