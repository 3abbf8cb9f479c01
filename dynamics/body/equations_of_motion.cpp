#include "dynamics/body/equations_of_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

// The major axis in the slip frame (e1, e2) as the direction (cos psi, sin psi) the law reads: no
// angle is formed (friction/patch_angle.h). The major axis is a line: the direction is the one
// with psi in [0, pi), sin psi > 0 or sin psi = 0 < cos psi (the fold psi -> psi + pi). The dot
// products are scaled to unit length: e1 leaves the contact plane by the rounding of the slip,
// which is large against U when the contact point's velocity is mostly normal (a landing, a deep
// trial stage), and |(cos, sin)| then falls short of 1 by more than rounding.
friction::PatchAngle patch_direction(const Eigen::Vector3d& major, const Eigen::Vector3d& e1,
                                     const Eigen::Vector3d& e2) {
  double c = major.dot(e1);
  double s = major.dot(e2);
  if (s < 0.0 || (s == 0.0 && c < 0.0)) {
    c = -c;
    s = -s;
  }
  const double norm = std::sqrt(c * c + s * s);
  if (norm >= std::numeric_limits<double>::min()) return friction::PatchAngle::from_direction(c / norm, s / norm + 0.0);
  // e1 (nearly) along the normal, or not finite: the angle of the direction, atan2 as it was
  // (0 for a zero vector; NaN is refused by the law's input check).
  return friction::PatchAngle(friction::PatchAngle::from_direction(c, s).radians());
}

}  // namespace

BodyOnPlane::BodyOnPlane(Body body, const PlaneContact& plane, const friction::FrictionLaw& law)
    : body_(std::move(body)),
      plane_(plane),
      law_(law),
      geometry_(body_.profile, body_.com),
      inertia_(body_.A, body_.A, body_.C),
      inv_inertia_(1.0 / body_.A, 1.0 / body_.A, 1.0 / body_.C) {
  plane_.validate();
  if (plane_.patch == PatchModel::hertz) hertz_.emplace(plane_.E_star);
}

void BodyOnPlane::contact_state(const StateVector& x, ContactState& c, bool with_friction) const {
  c.a = 0.0;  // the fields set in contact only: zero out of contact
  c.b = 0.0;
  c.friction = {};
  c.gamma = vertical(x).normalized();
  const Eigen::Vector3d v = velocity(x);
  const Eigen::Vector3d w = angular_velocity(x);
  const double eps = height(x);

  c.point = geometry_.contact_point(c.gamma);
  c.u = v + w.cross(c.point.r);
  const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
  c.U = slip.norm();
  c.Omega = w.dot(c.gamma);
  c.in_contact = eps < 0.0;
  PatchShape patch;
  Eigen::Vector3d hertz_torque = Eigen::Vector3d::Zero();
  if (hertz_) {  // [contact] patch = "hertz" (dynamics/contact/hertz_patch.h)
    const HertzContact h = hertz_->evaluate(geometry_, c.point, c.gamma, eps);
    c.N = h.N;
    patch = h.patch;
    hertz_torque = h.torque;
  } else {
    c.N = plane_.normal_force(eps);
    patch = ContactGeometry::patch(c.point, c.gamma, c.in_contact ? -eps : 0.0);
  }
  // Below the smallest normal double the slip direction is noise: treat it as zero slip, e1 = major.
  if (c.U >= std::numeric_limits<double>::min()) {
    c.e1 = slip / c.U;
  } else {
    c.U = 0.0;
    c.e1 = patch.major;
  }
  c.major = patch.major;
  const Eigen::Vector3d e2 = c.gamma.cross(c.e1);
  if (patch.circle || c.U == 0.0) {
    c.psi = friction::PatchAngle();  // psi = 0: a circle has no axis; at zero slip e1 is the major axis
  } else {
    c.psi = patch_direction(patch.major, c.e1, e2);
  }

  c.force = c.N * c.gamma;
  c.torque = c.point.r.cross(c.force);
  if (hertz_) c.torque += hertz_torque;
  if (c.N > 0.0) {
    c.a = patch.a;
    c.b = patch.b;
    if (with_friction) add_friction(c, c.e1, law_.evaluate({c.U, c.Omega, c.a, c.b, c.psi, c.N, plane_.k}));
  }
}

void BodyOnPlane::add_friction(ContactState& c, const Eigen::Vector3d& e1, const friction::FrictionForces& f) {
  const Eigen::Vector3d e2 = c.gamma.cross(e1);
  c.friction = f;
  const Eigen::Vector3d F = -c.friction.F1 * e1 - c.friction.F2 * e2;  // Eq. (7)
  c.force += F;
  c.torque += c.point.r.cross(F) - c.friction.M * c.gamma;
}

void BodyOnPlane::operator()(double /*t*/, const StateVector& x, StateVector& dxdt) const {
  derivatives(x, contact_state(x), dxdt);
}

void BodyOnPlane::derivatives(const StateVector& x, const ContactState& c, StateVector& dxdt) const {
  const Eigen::Vector3d v = velocity(x);
  const Eigen::Vector3d w = angular_velocity(x);
  const Eigen::Vector3d Jw = inertia_.cwiseProduct(w);
  velocity(dxdt) = -w.cross(v) - plane_.g * c.gamma + c.force / body_.mass;              // Eq. (2)
  angular_velocity(dxdt) = inv_inertia_.cwiseProduct(c.torque - w.cross(Jw));           // Eq. (3)
  vertical(dxdt) = vertical(x).cross(w);                                                // Eq. (4)
  height(dxdt) = c.u.dot(c.gamma);                                                      // Eq. (5)
  slide_work(dxdt) = c.friction.F1 * c.U;
  spin_work(dxdt) = c.friction.M * c.Omega;
}

PoleWatch::Point BodyOnPlane::pole_point(const ContactState& c) {
  if (c.in_contact && c.a > 0.0) return PoleWatch::patch_point(c.U, c.Omega, c.a, c.b, c.psi.radians());
  PoleWatch::Point p;
  p.sign = c.Omega < 0.0 ? -1.0 : 1.0;
  p.psi = c.psi.radians();
  // Out of contact the patch has shrunk to nothing: s = inf, mu the limit of b/a.
  const double r_max = std::max(c.point.R_meridian, c.point.R_parallel);
  const double r_min = std::min(c.point.R_meridian, c.point.R_parallel);
  p.mu = r_max > 0.0 ? std::sqrt(r_min / r_max) : 1.0;
  p.t = 0.0;
  return p;
}

std::string BodyOnPlane::describe_friction(const StateVector& x, const BodyMode& /*mode*/) const {
  using support::message_number;
  try {
    const ContactState c = contact_state(x);
    return "friction law '" + std::string(law_.name()) + "' gives F1 = " + message_number(c.friction.F1) +
           " N, F2 = " + message_number(c.friction.F2) + " N, M = " + message_number(c.friction.M) +
           " N m at U = " + message_number(c.U) + " m/s, Omega = " + message_number(c.Omega) +
           " 1/s, a = " + message_number(c.a) + " m, b = " + message_number(c.b) +
           " m, psi = " + message_number(c.psi.radians()) + ", N = " + message_number(c.N) + " N";
  } catch (const std::exception& e) {
    return e.what();
  }
}

double BodyOnPlane::kinetic_energy(const StateVector& x) const {
  const Eigen::Vector3d w = angular_velocity(x);
  return 0.5 * body_.mass * velocity(x).squaredNorm() + 0.5 * w.dot(inertia_.cwiseProduct(w));
}

double BodyOnPlane::energy(const StateVector& x, const ContactState& c) const {
  const double eps = height(x);
  const double h = eps - c.point.r.dot(c.gamma);  // height of the centre of mass
  const double spring = hertz_ ? hertz_->energy(c.point, eps) : plane_.spring_energy(eps);
  return kinetic_energy(x) + body_.mass * plane_.g * h + spring;
}

}  // namespace frictionlab::dynamics
