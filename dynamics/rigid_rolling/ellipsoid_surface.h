#pragma once
// A triaxial ellipsoid (xi - c0)^T D^-2 (xi - c0) = 1, D = diag(a1, a2, a3), its axes along the body
// axes, its centre c0 from the centre of mass (body frame). Its outward normal at xi is parallel to
// D^-2 (xi - c0), so the point whose normal is -gamma is
//
//   r(gamma) = c0 - D^2 gamma / s,    s = sqrt(gamma^T D^2 gamma),
//   r'(gamma)[g'] = -D^2 g' / s + D^2 gamma (gamma^T D^2 g') / s^3.
//
// At the lowest point of a body resting on its a3 end (gamma = e3) the principal radii of curvature
// are a1^2/a3 along body x and a2^2/a3 along body y (docs/rigid-rolling.md §1).

#include "dynamics/rigid_rolling/rolling_surface.h"

namespace frictionlab::dynamics::rigid_rolling {

class EllipsoidSurface final : public RollingSurface {
 public:
  /// `semi_axes` (a1, a2, a3) along body x, y, z, m, each finite and > 0; `centre` c0 from the
  /// centre of mass, m, finite. Throws std::invalid_argument naming the value and the rule.
  EllipsoidSurface(const Eigen::Vector3d& semi_axes, const Eigen::Vector3d& centre);

  [[nodiscard]] Eigen::Vector3d contact_point(const Eigen::Vector3d& gamma) const override;
  [[nodiscard]] Eigen::Vector3d contact_point_rate(const Eigen::Vector3d& gamma,
                                                   const Eigen::Vector3d& gamma_rate) const override;

  [[nodiscard]] const Eigen::Vector3d& semi_axes() const { return semi_axes_; }
  [[nodiscard]] const Eigen::Vector3d& centre() const { return centre_; }

 private:
  Eigen::Vector3d semi_axes_;
  Eigen::Vector3d squares_;  // a_i^2
  Eigen::Vector3d centre_;
};

}  // namespace frictionlab::dynamics::rigid_rolling
