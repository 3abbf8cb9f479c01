#include "dynamics/rigid_rolling/rounded_disk_surface.h"

#include <cmath>
#include <span>
#include <stdexcept>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::rigid_rolling {
namespace {

// |p| below this fraction of |gamma|: the disk is flat (within 1e-12 rad) and u is undefined.
constexpr double kFlatTolerance = 1e-12;

}  // namespace

RoundedDiskSurface::RoundedDiskSurface(double radius, double rim_radius, const Eigen::Vector3d& centre)
    : radius_(radius), rim_radius_(rim_radius), centre_(centre) {
  if (!(std::isfinite(radius) && radius > 0.0))
    throw support::invalid_value("disk.radius", radius, "it must be finite and > 0 m");
  if (!(std::isfinite(rim_radius) && rim_radius >= 0.0 && rim_radius < radius))
    throw support::invalid_value("disk.rim_radius", rim_radius, "it must be finite, >= 0 m and < disk.radius");
  if (!centre.allFinite())
    throw support::invalid_value("disk.centre", std::span<const double>(centre.data(), 3),
                                 "it must be finite (m, from the centre of mass)");
}

Eigen::Vector3d RoundedDiskSurface::contact_point(const Eigen::Vector3d& gamma) const {
  const double norm = gamma.norm();
  const Eigen::Vector3d p(gamma.x(), gamma.y(), 0.0);
  const double pn = p.norm();
  if (!(pn > kFlatTolerance * norm)) throw std::domain_error("the rounded disk lies flat: its contact is a circle");
  return centre_ - rim_centre_radius() / pn * p - rim_radius_ / norm * gamma;
}

Eigen::Vector3d RoundedDiskSurface::contact_point_rate(const Eigen::Vector3d& gamma,
                                                       const Eigen::Vector3d& gamma_rate) const {
  const double norm = gamma.norm();
  const Eigen::Vector3d p(gamma.x(), gamma.y(), 0.0);
  const Eigen::Vector3d p_rate(gamma_rate.x(), gamma_rate.y(), 0.0);
  const double pn = p.norm();
  if (!(pn > kFlatTolerance * norm)) throw std::domain_error("the rounded disk lies flat: its contact is a circle");
  // d(v/|v|) = (v' - v (v . v')/|v|^2) / |v|
  const Eigen::Vector3d u_rate = -(p_rate - p * (p.dot(p_rate) / (pn * pn))) / pn;
  const Eigen::Vector3d n_rate = (gamma_rate - gamma * (gamma.dot(gamma_rate) / (norm * norm))) / norm;
  return rim_centre_radius() * u_rate - rim_radius_ * n_rate;
}

}  // namespace frictionlab::dynamics::rigid_rolling
