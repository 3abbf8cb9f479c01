#include "dynamics/contact/hertz_patch.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

#include "dynamics/contact/hertz_ellipse.h"

namespace frictionlab::dynamics {
namespace {

// The upward vertical with third component g3 in the plane xi1-xi3 (a body of revolution only
// sees gamma3); exactly the pole for g3 = ±1.
Eigen::Vector3d vertical_at(double g3) { return {std::sqrt((1.0 - g3) * (1.0 + g3)), 0.0, g3}; }

// lambda' = lambda d ln S/d gamma3, through the two radii.
double stiffness_slope_at(const ContactGeometry& geometry, const ContactPoint& c, const HertzEllipse& e, double lambda) {
  const RadiiSlope r = geometry.radii_slope(c);
  return lambda * (e.dlnS_dlnR1 * r.meridian / c.R_meridian + e.dlnS_dlnR2 * r.parallel / c.R_parallel);
}

}  // namespace

HertzNormalContact::HertzNormalContact(double E_star) : E_star_(E_star) {
  if (!(std::isfinite(E_star) && E_star > 0.0))
    throw std::invalid_argument("HertzNormalContact: the effective modulus must be finite and > 0 Pa");
}

double HertzNormalContact::stiffness(const ContactPoint& c) const {
  return E_star_ * hertz_ellipse(c.R_meridian, c.R_parallel).stiffness_per_modulus;
}

double HertzNormalContact::stiffness(const ContactGeometry& geometry, double gamma3) const {
  return stiffness(geometry.contact_point(vertical_at(std::clamp(gamma3, -1.0, 1.0))));
}

double HertzNormalContact::stiffness_slope(const ContactGeometry& geometry, double gamma3) const {
  const ContactPoint c = geometry.contact_point(vertical_at(std::clamp(gamma3, -1.0, 1.0)));
  const HertzEllipse e = hertz_ellipse(c.R_meridian, c.R_parallel);
  return stiffness_slope_at(geometry, c, e, E_star_ * e.stiffness_per_modulus);
}

double HertzNormalContact::energy(const ContactPoint& c, double eps) const {
  if (!(eps < 0.0)) return 0.0;
  return 0.4 * stiffness(c) * eps * eps * std::sqrt(-eps);
}

HertzContact HertzNormalContact::evaluate(const ContactGeometry& geometry, const ContactPoint& c,
                                          const Eigen::Vector3d& gamma, double eps) const {
  HertzContact h;
  // Orientation: the same axes as the section hypothesis (meridian / parallel, the major one along
  // the larger radius, circle within ContactGeometry::kCircleRelTol).
  h.patch = ContactGeometry::patch(c, gamma, 0.0);
  if (!(eps < 0.0)) return h;
  const double delta = -eps;
  const HertzEllipse e = hertz_ellipse(c.R_meridian, c.R_parallel);
  h.stiffness = E_star_ * e.stiffness_per_modulus;
  const double d15 = delta * std::sqrt(delta);
  h.N = h.stiffness * d15;
  h.energy = 0.4 * h.stiffness * delta * d15;
  h.patch.a = std::sqrt(e.a2_per_depth * delta);
  h.patch.b = h.patch.circle ? h.patch.a : e.mu * h.patch.a;
  // gamma x e3 = (gamma2, -gamma1, 0): zero at the poles, where lambda' needs no value.
  const Eigen::Vector3d gxe3(gamma.y(), -gamma.x(), 0.0);
  if (gxe3.squaredNorm() > 0.0)
    h.torque = 0.4 * delta * d15 * stiffness_slope_at(geometry, c, e, h.stiffness) * gxe3;
  return h;
}

double modulus_matching_stiffness(const ContactGeometry& geometry, double lambda, double gamma3) {
  assert(lambda > 0.0);
  // lambda is proportional to E*: one evaluation at E* = 1 Pa gives the factor.
  return lambda / HertzNormalContact(1.0).stiffness(geometry, gamma3);
}

}  // namespace frictionlab::dynamics
