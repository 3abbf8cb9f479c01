#include "dynamics/body/equations_of_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "dynamics/contact/hertz_ellipse.h"
#include "dynamics/shapes/hertz_orientation_torque.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

// The major axis in the slip frame (e1, e2) as the direction (cos psi, sin psi) the law reads: no
// angle is formed (friction/patch_angle.h). The major axis is a line: the direction is the one
// with psi in [0, pi), sin psi > 0 or sin psi = 0 < cos psi (the fold psi -> psi + pi). The dot
// products are scaled to unit length: e1 leaves the contact plane by the rounding of the slip,
// which is large against U when the contact point's velocity is mostly normal (a landing, a deep
// trial stage), and |(cos, sin)| then falls short of 1 by more than rounding.
inline friction::PatchAngle patch_direction(const Eigen::Vector3d& major, const Eigen::Vector3d& e1,
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

// BodyOnPlane::add_friction with the slip frame's e2 = gamma x e1 given (the right-hand side has it).
inline void add_friction_in_frame(ContactState& c, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
                                  const friction::FrictionForces& f) {
  c.friction = f;
  const Eigen::Vector3d F = -c.friction.F1 * e1 - c.friction.F2 * e2;  // Eq. (7)
  c.force += F;
  c.torque += c.point.r.cross(F) - c.friction.M * c.gamma;
}

}  // namespace

BodyOnPlane::BodyOnPlane(Body body, const PlaneContact& plane, const friction::FrictionLaw& law)
    : body_(std::move(body)), plane_(plane), law_(law), J_(body_.inertia) {
  if (!body_.shape) throw std::invalid_argument("BodyOnPlane: the body has no shape");
  plane_.validate();
  if (plane_.patch == PatchModel::hertz) hertz_.emplace(plane_.E_star);
  if (body_.axisymmetric) {
    const AxisymmetricBody& a = *body_.axisymmetric;
    geometry_.emplace(a.profile, a.com);
    inertia_ = Eigen::Vector3d(a.A, a.A, a.C);
    inv_inertia_ = Eigen::Vector3d(1.0 / a.A, 1.0 / a.A, 1.0 / a.C);
  } else {
    inertia_ = J_.diagonal();
    inv_inertia_ = inertia_.cwiseInverse();
  }
  diagonal_ = J_(0, 1) == 0.0 && J_(0, 2) == 0.0 && J_(1, 0) == 0.0 && J_(1, 2) == 0.0 && J_(2, 0) == 0.0 &&
              J_(2, 1) == 0.0;
  J_inv_ = diagonal_ ? Eigen::Matrix3d(inv_inertia_.asDiagonal()) : Eigen::Matrix3d(J_.inverse());
  disk_ = dynamic_cast<const shapes::ToroidalDisk*>(body_.shape.get());
}

std::string BodyOnPlane::point_contact_end(const StateVector& x, const ContactState& c) const {
  if (!disk_ || !c.in_contact) return {};
  const double depth = -height(x);
  const double clearance = disk_->face_clearance(c.gamma);
  if (depth < clearance) return {};
  using support::message_number;
  return "the face of the toroidal disk reaches the plane: penetration depth " + message_number(depth) +
         " m >= face clearance " + message_number(clearance) + " m at gamma3 = " + message_number(c.gamma.z()) +
         " (the disk lies down; its rim's point contact, the model's, ends here)";
}

const ContactGeometry& BodyOnPlane::geometry() const {
  if (!geometry_) throw std::logic_error("BodyOnPlane::geometry(): the body is not an axisymmetric body of revolution");
  return *geometry_;
}

void BodyOnPlane::shape_contact(const Eigen::Vector3d& gamma, double eps, ContactState& c, PatchShape& patch,
                                Eigen::Vector3d& hertz_torque) const {
  const shapes::SurfaceContact sc = body_.shape->contact(gamma);
  c.point.z = sc.r.z();
  c.point.r = sc.r - body_.centre_of_mass;
  c.point.R_meridian = sc.R_major;
  c.point.R_parallel = sc.R_minor;
  patch.major = sc.major;
  patch.circle = sc.R_major - sc.R_minor <= shapes::kUmbilicRelTol * sc.R_major;
  if (!(eps < 0.0)) {  // out of contact: no patch, no force
    patch.a = patch.b = 0.0;
    c.N = 0.0;
    return;
  }
  const double delta = -eps;
  if (!hertz_) {  // the section hypothesis: the Dupin indicatrix at depth |eps|
    c.N = plane_.normal_force(eps);
    patch.a = std::sqrt(2.0 * delta * sc.R_major);
    patch.b = patch.circle ? patch.a : std::sqrt(2.0 * delta * sc.R_minor);
    return;
  }
  const HertzEllipse e = hertz_ellipse(sc.R_major, sc.R_minor);
  const double stiffness = hertz_->modulus() * e.stiffness_per_modulus;
  c.N = stiffness * delta * std::sqrt(delta);
  patch.a = std::sqrt(e.a2_per_depth * delta);
  patch.b = patch.circle ? patch.a : e.mu * patch.a;
  hertz_torque = shapes::hertz_orientation_torque(
      gamma, delta, stiffness, shapes::log_stiffness_gradient(sc, body_.shape->radii_gradient(gamma, sc), e));
}

void BodyOnPlane::contact_state(const StateVector& x, ContactState& c, bool with_friction) const {
  c.a = 0.0;  // the fields set in contact only: zero out of contact
  c.b = 0.0;
  c.friction = {};
  c.gamma = vertical(x).normalized();
  const Eigen::Vector3d v = velocity(x);
  const Eigen::Vector3d w = angular_velocity(x);
  const double eps = height(x);

  PatchShape patch;
  Eigen::Vector3d hertz_torque = Eigen::Vector3d::Zero();
  if (geometry_) {  // today's body of revolution, today's arithmetic
    c.point = geometry_->contact_point(c.gamma);
    if (hertz_) {  // [contact] patch = "hertz" (dynamics/contact/hertz_patch.h)
      const HertzContact h = hertz_->evaluate(*geometry_, c.point, c.gamma, eps);
      c.N = h.N;
      patch = h.patch;
      hertz_torque = h.torque;
    } else {
      c.N = plane_.normal_force(eps);
      patch = ContactGeometry::patch(c.point, c.gamma, eps < 0.0 ? -eps : 0.0);
    }
  } else {
    shape_contact(c.gamma, eps, c, patch, hertz_torque);
  }
  c.u = v + w.cross(c.point.r);
  const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
  c.U = slip.norm();
  c.Omega = w.dot(c.gamma);
  c.in_contact = eps < 0.0;
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
    if (with_friction) {
      add_friction_in_frame(c, c.e1, e2, law_.evaluate({c.U, c.Omega, c.a, c.b, c.psi, c.N, plane_.k}));
    }
  }
  c.slide_power = c.friction.F1 * c.U;
}

void BodyOnPlane::add_friction(ContactState& c, const Eigen::Vector3d& e1, const friction::FrictionForces& f) {
  add_friction_in_frame(c, e1, c.gamma.cross(e1), f);
}

friction::FrictionForces BodyOnPlane::law_at_slip(const ContactState& c, const Eigen::Vector3d& slip, double Omega,
                                                  Eigen::Vector3d& e1, friction::PatchAngle& psi) const {
  const double U = slip.norm();
  if (U >= std::numeric_limits<double>::min()) {
    e1 = slip / U;
    psi = c.a == c.b ? friction::PatchAngle() : patch_direction(c.major, e1, c.gamma.cross(e1));
    return law_.evaluate({U, Omega, c.a, c.b, psi, c.N, plane_.k});
  }
  e1 = c.major;
  psi = friction::PatchAngle();
  return law_.evaluate({0.0, Omega, c.a, c.b, psi, c.N, plane_.k});
}

void BodyOnPlane::operator()(double /*t*/, const StateVector& x, StateVector& dxdt) const {
  derivatives(x, contact_state(x), dxdt);
}

void BodyOnPlane::derivatives_without_pose(const StateVector& x, const ContactState& c, StateVector& dxdt) const {
  const Eigen::Vector3d v = velocity(x);
  const Eigen::Vector3d w = angular_velocity(x);
  velocity(dxdt) = -w.cross(v) - plane_.g * c.gamma + c.force / body_.mass;              // Eq. (2)
  if (diagonal_) {
    const Eigen::Vector3d Jw = inertia_.cwiseProduct(w);
    angular_velocity(dxdt) = inv_inertia_.cwiseProduct(c.torque - w.cross(Jw));         // Eq. (3)
  } else {
    const Eigen::Vector3d Jw = J_ * w;
    angular_velocity(dxdt) = J_inv_ * (c.torque - w.cross(Jw));                         // Eq. (3)
  }
  vertical(dxdt) = vertical(x).cross(w);                                                // Eq. (4)
  height(dxdt) = c.u.dot(c.gamma);                                                      // Eq. (5)
  slide_work(dxdt) = c.slide_power;
  spin_work(dxdt) = c.friction.M * c.Omega;
}

void BodyOnPlane::derivatives(const StateVector& x, const ContactState& c, StateVector& dxdt) const {
  derivatives_without_pose(x, c, dxdt);
  const Eigen::Vector3d v = velocity(x);
  const Eigen::Vector3d w = angular_velocity(x);
  // The pose, not fed back: q' = q (0, omega)/2; X' = horizontal part of R(q) v.
  const auto q = orientation(x);
  orientation(dxdt) << -0.5 * (q[1] * w[0] + q[2] * w[1] + q[3] * w[2]), 0.5 * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]),
      0.5 * (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]), 0.5 * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]);
  // R(q) v for the unit quaternion q/|q|: the first two rows of the rotation matrix of q, divided
  // by |q|^2 (no square root: the rates are evaluated at every stage of every step).
  const double qn2 = q.squaredNorm();
  if (qn2 > 0.0) {
    const double w0 = q[0], qx = q[1], qy = q[2], qz = q[3];
    const double vx = (w0 * w0 + qx * qx - qy * qy - qz * qz) * v[0] + 2.0 * (qx * qy - w0 * qz) * v[1] +
                      2.0 * (qx * qz + w0 * qy) * v[2];
    const double vy = 2.0 * (qx * qy + w0 * qz) * v[0] + (w0 * w0 - qx * qx + qy * qy - qz * qz) * v[1] +
                      2.0 * (qy * qz - w0 * qx) * v[2];
    position(dxdt) << vx / qn2, vy / qn2;
  } else {
    position(dxdt).setZero();
  }
}

ShadowPoint BodyOnPlane::shadow_point(const StateVector& /*x*/, const ContactState& c, const BodyMode& mode) const {
  ShadowPoint p;
  p.in_contact = c.in_contact && c.N > 0.0 && c.a > 0.0;
  p.input = {c.U, c.Omega, c.a, c.b, c.psi, c.N, plane_.k};  // what contact_state hands the law
  p.own = c.friction;
  p.own_known = mode.free();  // else c.friction is the mode's wrench, not the law's
  p.normal_speed = c.u.dot(c.gamma);  // eps', Eq. (5)
  return p;
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
  return 0.5 * body_.mass * velocity(x).squaredNorm() + 0.5 * w.dot(angular_momentum(w));
}

double BodyOnPlane::energy(const StateVector& x, const ContactState& c) const {
  const double eps = height(x);
  const double h = eps - c.point.r.dot(c.gamma);  // height of the centre of mass
  const double spring = hertz_ ? hertz_->energy(c.point, eps) : plane_.spring_energy(eps);
  return kinetic_energy(x) + body_.mass * plane_.g * h + spring;
}

}  // namespace frictionlab::dynamics
