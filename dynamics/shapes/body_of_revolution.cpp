#include "dynamics/shapes/body_of_revolution.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <cmath>

#include "dynamics/body/body_scales.h"
#include "dynamics/shapes/mass_properties.h"
#include "dynamics/shapes/polynomial.h"

namespace frictionlab::dynamics::shapes {

BodyOfRevolution::BodyOfRevolution(const Profile& profile) : geometry_(profile, 0.0) {}

SurfaceContact BodyOfRevolution::contact(const Eigen::Vector3d& gamma) const {
  const ContactPoint c = geometry_.contact_point(gamma);
  // The patch's major axis at depth 0: the orientation rule of ContactGeometry, by the same call.
  const PatchShape axes = ContactGeometry::patch(c, gamma, 0.0);
  const bool meridian_larger = c.R_meridian >= c.R_parallel;
  return {c.r, meridian_larger ? c.R_meridian : c.R_parallel, meridian_larger ? c.R_parallel : c.R_meridian,
          axes.major};
}

RadiiGradient BodyOfRevolution::radii_gradient(const Eigen::Vector3d& gamma, const SurfaceContact& c) const {
  ContactPoint p;
  p.z = c.r.z();  // r3 = z - 0: the profile coordinate, exactly (radii_slope reads only z)
  const RadiiSlope slope = geometry_.radii_slope(p);
  // grad gamma3 on the sphere: e3 - gamma3 gamma, written with gamma1^2 + gamma2^2 for 1 - gamma3^2.
  const double g3 = gamma.z();
  const Eigen::Vector3d grad_g3(-g3 * gamma.x(), -g3 * gamma.y(), gamma.x() * gamma.x() + gamma.y() * gamma.y());
  // The meridian direction has the vertical component rho, the parallel one none (see the header).
  const bool major_is_meridian = std::abs(c.major.z()) >= std::abs(gamma.cross(c.major).z());
  const double major = major_is_meridian ? slope.meridian : slope.parallel;
  const double minor = major_is_meridian ? slope.parallel : slope.meridian;
  return {major * grad_g3, minor * grad_g3};
}

SolidMassProperties BodyOfRevolution::homogeneous(double mass) const {
  validate_mass(mass);
  const MassProperties h = homogeneous_mass_properties(profile(), mass);
  SolidMassProperties m;
  m.mass = h.mass;
  m.volume = h.volume;
  m.centroid = Eigen::Vector3d(0.0, 0.0, h.centroid);
  m.inertia = Eigen::Vector3d(h.A, h.A, h.C).asDiagonal();
  return m;
}

double BodyOfRevolution::size() const { return body_size(profile(), 0.0); }

double BodyOfRevolution::radius_about(const Eigen::Vector3d& point) const {
  const double s2 = point.x() * point.x() + point.y() * point.y();
  const double p3 = point.z();
  if (s2 == 0.0) return body_size(profile(), p3);
  const double s = std::sqrt(s2);
  const Polynomial& P = profile().chi2();
  const auto d2 = [&](double z) {
    const double far = std::sqrt(std::max(0.0, P(z))) + s;
    return far * far + (z - p3) * (z - p3);
  };
  const double lo = profile().z_lo(), hi = profile().z_hi();
  double best = std::max(d2(lo), d2(hi));
  const Polynomial dP = P.derivative();
  const Polynomial half_slope_plus = 0.5 * dP + Polynomial({-p3, 1.0});  // P'/2 + z - p3
  const Polynomial Q = 4.0 * P * half_slope_plus * half_slope_plus + (-s2) * dP * dP;
  if (Q.degree() >= 1)
    for (const double z : real_roots(Q))
      if (z > lo && z < hi) best = std::max(best, d2(z));
  return std::sqrt(best);
}

bool BodyOfRevolution::contains(const Eigen::Vector3d& point) const {
  const double z = point.z();
  if (!(z > profile().z_lo() && z < profile().z_hi())) return false;
  return point.x() * point.x() + point.y() * point.y() < profile().chi2()(z);
}

}  // namespace frictionlab::dynamics::shapes
