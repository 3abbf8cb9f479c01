#include "dynamics/shapes/toroidal_disk.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::shapes {
namespace {

std::string flat_face_message(double sigma, double limit) {
  return "toroidal disk: the axis is " + support::message_number(std::asin(std::min(sigma, 1.0))) +
         " rad from the vertical (|gamma_h| = " + support::message_number(sigma) +
         "), below the least tilt " + support::message_number(limit) +
         ": a flat face lies on the plane, which the rim's point contact does not describe";
}

void require_positive(std::string_view key, double value) {
  if (!(std::isfinite(value) && value > 0.0)) throw support::invalid_value(key, value, "it must be finite and > 0 m");
}

}  // namespace

FlatFaceContact::FlatFaceContact(double sigma, double limit)
    : std::domain_error(flat_face_message(sigma, limit)), sigma_(sigma) {}

ToroidalDisk::ToroidalDisk(double radius, double rim_radius, std::string_view radius_key, std::string_view rim_key)
    : R_(radius), rho_(rim_radius) {
  require_positive(radius_key, radius);
  require_positive(rim_key, rim_radius);
}

SurfaceContact ToroidalDisk::contact(const Eigen::Vector3d& gamma) const {
  const double sigma = std::sqrt(gamma.x() * gamma.x() + gamma.y() * gamma.y());
  if (!(sigma >= kMinTilt)) throw FlatFaceContact(sigma, kMinTilt);
  const Eigen::Vector3d outward(-gamma.x() / sigma, -gamma.y() / sigma, 0.0);  // azimuth of the contact
  return {R_ * outward - rho_ * gamma, R_ / sigma + rho_, rho_,
          Eigen::Vector3d(gamma.y() / sigma, -gamma.x() / sigma, 0.0)};
}

RadiiGradient ToroidalDisk::radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact&) const {
  const double sigma2 = gamma.x() * gamma.x() + gamma.y() * gamma.y();
  const double sigma = std::sqrt(sigma2);
  const double g3 = gamma.z();
  const Eigen::Vector3d grad_g3(-g3 * gamma.x(), -g3 * gamma.y(), sigma2);  // e3 - gamma3 gamma
  return {R_ * g3 / (sigma2 * sigma) * grad_g3, Eigen::Vector3d::Zero()};
}

SolidMassProperties ToroidalDisk::homogeneous(double mass) const {
  validate_mass(mass);
  constexpr double pi = std::numbers::pi;
  const double R = R_, r = rho_;
  const double R2 = R * R, r2 = r * r;
  // Cylinder of radius R and height 2 rho, plus the outer half torus (the half disk t >= 0 of the
  // tube swept round the axis at distance R + t).
  const double volume = 2.0 * pi * R2 * r + pi * pi * R * r2 + 4.0 / 3.0 * pi * r2 * r;
  const double s2 = pi * R2 * R2 * r + 2.0 * pi * (pi * R2 * R * r2 / 2.0 + 2.0 * R2 * r2 * r +
                                                   3.0 * pi * R * r2 * r2 / 8.0 + 4.0 * r2 * r2 * r / 15.0);
  const double z2 = 2.0 / 3.0 * pi * R2 * r2 * r + 2.0 * pi * (pi * R * r2 * r2 / 8.0 + 2.0 * r2 * r2 * r / 15.0);
  const double density = mass / volume;
  const double C = density * s2;
  const double A = density * (0.5 * s2 + z2);
  SolidMassProperties m;
  m.mass = mass;
  m.volume = volume;
  m.inertia = Eigen::Vector3d(A, A, C).asDiagonal();
  return m;
}

double ToroidalDisk::size() const { return R_ + rho_; }

double ToroidalDisk::radius_about(const Eigen::Vector3d& p) const {
  const double far = R_ + std::sqrt(p.x() * p.x() + p.y() * p.y());
  return std::sqrt(far * far + p.z() * p.z()) + rho_;
}

bool ToroidalDisk::contains(const Eigen::Vector3d& p) const {
  // Distance from the flat disk below rho.
  const double out = std::sqrt(p.x() * p.x() + p.y() * p.y()) - R_;
  const double d2 = (out > 0.0 ? out * out : 0.0) + p.z() * p.z();
  return d2 < rho_ * rho_;
}

double ToroidalDisk::face_clearance(const Eigen::Vector3d& gamma) const {
  const double sigma2 = gamma.x() * gamma.x() + gamma.y() * gamma.y();
  return rho_ * sigma2 / (1.0 + std::abs(gamma.z()));
}

}  // namespace frictionlab::dynamics::shapes
