#include "dynamics/rigid_rolling/ellipsoid_surface.h"

#include <cmath>
#include <span>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {

EllipsoidSurface::EllipsoidSurface(const Eigen::Vector3d& semi_axes, const Eigen::Vector3d& centre)
    : semi_axes_(semi_axes), squares_(semi_axes.cwiseProduct(semi_axes)), centre_(centre) {
  if (!(semi_axes.allFinite() && semi_axes.minCoeff() > 0.0))
    throw support::invalid_value("ellipsoid.semi_axes", std::span<const double>(semi_axes.data(), 3),
                                 "each semi-axis must be finite and > 0 m");
  if (!centre.allFinite())
    throw support::invalid_value("ellipsoid.centre", std::span<const double>(centre.data(), 3),
                                 "it must be finite (m, from the centre of mass)");
}

Eigen::Vector3d EllipsoidSurface::contact_point(const Eigen::Vector3d& gamma) const {
  const Eigen::Vector3d d2g = squares_.cwiseProduct(gamma);
  return centre_ - d2g / std::sqrt(gamma.dot(d2g));
}

Eigen::Vector3d EllipsoidSurface::contact_point_rate(const Eigen::Vector3d& gamma,
                                                     const Eigen::Vector3d& gamma_rate) const {
  const Eigen::Vector3d d2g = squares_.cwiseProduct(gamma);
  const double s2 = gamma.dot(d2g);
  const double s = std::sqrt(s2);
  return (-squares_.cwiseProduct(gamma_rate) + d2g * (d2g.dot(gamma_rate) / s2)) / s;
}

}  // namespace frictionlab::dynamics::rigid_rolling
