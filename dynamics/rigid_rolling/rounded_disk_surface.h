#pragma once
// A disk with a toroidal rim: a body of revolution about body z whose rolling surface is the torus
// swept by a circle of radius rho (the rim radius) whose centre runs on the circle of radius
// Rc = R - rho in the plane z = c0z (R the outer radius of the disk); the faces are flat, the disk
// is 2 rho thick at the rim. For gamma not along the axis, with p = gamma - (gamma . e3) e3 (the
// part of gamma in the disk's plane) and u = -p/|p| (the in-plane direction towards the lowest
// rim point),
//
//   r(gamma) = c0 + Rc u - rho gamma/|gamma|.
//
// rho = 0 is the thin (knife-edge) disk. With gamma along the axis the disk lies flat and touches
// along a whole circle: the contact point is not defined there (std::domain_error).

#include "dynamics/rigid_rolling/rolling_surface.h"

namespace frictionlab::dynamics::rigid_rolling {

class RoundedDiskSurface final : public RollingSurface {
 public:
  /// `radius` R (m, finite, > 0), `rim_radius` rho (m, 0 <= rho < R), `centre` c0 (the disk's centre
  /// from the centre of mass, m; 0 for a symmetric disk). Throws std::invalid_argument.
  RoundedDiskSurface(double radius, double rim_radius, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());

  /// Throws std::domain_error when gamma is (within 1e-12 of) the axis: the disk lies flat.
  [[nodiscard]] Eigen::Vector3d contact_point(const Eigen::Vector3d& gamma) const override;
  [[nodiscard]] Eigen::Vector3d contact_point_rate(const Eigen::Vector3d& gamma,
                                                   const Eigen::Vector3d& gamma_rate) const override;

  [[nodiscard]] double radius() const { return radius_; }
  [[nodiscard]] double rim_radius() const { return rim_radius_; }
  /// Rc = R - rho, the radius of the circle of rim centres, m.
  [[nodiscard]] double rim_centre_radius() const { return radius_ - rim_radius_; }

 private:
  double radius_;
  double rim_radius_;
  Eigen::Vector3d centre_;
};

}  // namespace frictionlab::dynamics::rigid_rolling
