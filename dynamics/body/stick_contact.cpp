// The body's contact in its stick, departing and slip-hold modes (BodyMode, dynamics/body/equations_of_motion.h;
// docs/dynamics.md §5 "stick"): the free contact without the law's friction, plus the stick wrench
// (dynamics/body/stick.h), the law's friction in the direction of the exit, or the force that holds
// the slip with the law's spin moment (dynamics/body/slip_hold.h).
#include <algorithm>
#include <cmath>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/body/slip_hold.h"
#include "dynamics/body/stick.h"

namespace frictionlab::dynamics {

void BodyOnPlane::contact_in_mode(const StateVector& x, const BodyMode& mode, ContactState& c) const {
  if (!mode.stick && !mode.hold && (mode.spin_hold || mode.spin_departing)) {
    // The spin held at zero (the law's force at zero spin, the moment that keeps the spin's rate at
    // spin_rate) or starting with the sign spin_exit; the slip is the state's.
    contact_state(x, c, false);
    if (!(c.N > 0.0)) return;
    const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
    const double Omega =
        mode.spin_hold ? 0.0 : mode.spin_exit * std::max(std::abs(c.Omega), zero_spin_speed(c));
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    friction::FrictionForces f = law_at_slip(c, slip, Omega, e1, psi);
    if (mode.spin_hold) f.M = spin_hold_moment(stick_problem(x, c), -f.F1 * e1 - f.F2 * c.gamma.cross(e1), mode.spin_rate);
    c.e1 = e1;
    c.psi = psi;
    add_friction(c, e1, f);
    c.slide_power = c.friction.F1 * e1.dot(slip) + c.friction.F2 * c.gamma.cross(e1).dot(slip);
    return;
  }
  if (!mode.stick && !mode.hold && mode.slip_departing) {
    // The slip starts along slip_exit at the state's own speed (kZeroSlipRatio a |Omega| at least:
    // the law's limit at zero slip, dynamics/body/slip_hold.h), the spin is the state's; the monitor
    // ends the mode between steps (a switch on U inside the steps would be a discontinuity there).
    contact_state(x, c, false);
    if (!(c.N > 0.0)) return;
    const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
    const Eigen::Vector3d e = (mode.slip_exit - mode.slip_exit.dot(c.gamma) * c.gamma).normalized();
    const double U = std::max(c.U, kZeroSlipRatio * c.a * std::max(std::abs(c.Omega), 1.0));
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const friction::FrictionForces f = law_at_slip(c, U * e, c.Omega, e1, psi);
    c.e1 = e1;
    c.psi = psi;
    add_friction(c, e1, f);
    c.slide_power = c.friction.F1 * e1.dot(slip) + c.friction.F2 * c.gamma.cross(e1).dot(slip);
    return;
  }
  if (!mode.stick && !mode.hold) {
    contact_state(x, c);
    // Departing: the slip and the spin are still the residue of stick: the law sees the exit direction.
    if (!(c.N > 0.0) || c.U >= mode.departure_slip || std::abs(c.Omega) >= mode.departure_spin) return;
    contact_state(x, c, false);
    const Eigen::Vector3d minor = c.gamma.cross(c.major);
    const double ca = std::cos(mode.departure_alpha), sa = std::sin(mode.departure_alpha);
    const Eigen::Vector3d e1 = ca * c.major + sa * minor;
    const double beta = mode.departure_beta;
    const bool pole = std::abs(beta) >= 0.5 * 3.141592653589793;
    const double U = pole ? 0.0 : std::cos(beta);
    const double Omega = beta == 0.0 ? 0.0 : (pole ? std::copysign(1.0, beta) : std::sin(beta)) / c.a;
    // psi from e1 to the major axis, -alpha, folded to sin psi >= 0 (the major axis is a line).
    double cp = ca, sp = -sa;
    if (sp < 0.0 || (sp == 0.0 && cp < 0.0)) {
      cp = -cp;
      sp = -sp;
    }
    c.e1 = e1;
    c.psi = friction::PatchAngle::from_direction(cp, sp + 0.0);
    add_friction(c, e1, law_.evaluate({U, Omega, c.a, c.b, c.psi, c.N, plane_.k}));
    const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;  // not along e1 in general
    c.slide_power = c.friction.F1 * e1.dot(slip) + c.friction.F2 * c.gamma.cross(e1).dot(slip);
    return;
  }
  contact_state(x, c, false);
  if (!(c.N > 0.0)) return;  // out of contact nothing holds the body; the monitor leaves stick or hold
  const StickProblem p = stick_problem(x, c);
  if (mode.hold) {
    // The slip held (dynamics/body/slip_hold.h): the law's spin moment at the state's own slip, the
    // tangential force that keeps the slip's rate at the monitor's slip_rate.
    const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const double M = law_at_slip(c, slip, c.Omega, e1, psi).M;
    const SlipHoldForce hold = slip_hold_force(p, mode.slip_rate);
    const Eigen::Vector3d F = hold.force0 + M * hold.force_per_M;
    c.e1 = e1;
    c.psi = psi;
    const Eigen::Vector3d e2 = c.gamma.cross(e1);
    c.friction.F1 = -F.dot(e1);
    c.friction.F2 = -F.dot(e2);
    c.friction.M = M;
    c.slide_power = -F.dot(slip);
    c.force += F;
    c.torque += c.point.r.cross(F) - M * c.gamma;
    return;
  }
  const StickWrench w = stick_wrench(p);
  // The wrench in the law's terms, in the frame of zero slip (e1 the major axis, psi = 0): the slip
  // in stick is the integrator's residue, whose direction is rounding noise (out of the contact
  // plane even, where the contact point moves along the normal). F = -F1 e1 - F2 e2; its power on
  // the residue, -F.u_t, and M Omega are ~0.
  c.e1 = c.major;
  c.psi = friction::PatchAngle();
  const Eigen::Vector3d e2 = c.gamma.cross(c.e1);
  friction::FrictionForces f;
  f.F1 = -w.force.dot(c.e1);
  f.F2 = -w.force.dot(e2);
  f.M = w.M;
  c.friction = f;
  c.slide_power = -w.force.dot(c.u - c.u.dot(c.gamma) * c.gamma);
  c.force += w.force;
  c.torque += c.point.r.cross(w.force) - w.M * c.gamma;
}

StickProblem BodyOnPlane::stick_problem(const StateVector& x, const ContactState& c) const {
  StateVector free;
  derivatives(x, c, free);
  StickProblem p;
  p.mass = body_.mass;
  p.inertia = inertia_tensor();
  p.r = c.point.r;
  const double R_major = std::max(c.point.R_meridian, c.point.R_parallel);
  const double R_minor = std::min(c.point.R_meridian, c.point.R_parallel);
  p.omega = angular_velocity(x);
  p.r_rate = contact_point_rate(c.gamma, p.omega, R_major, c.major, R_minor);
  p.gamma = c.gamma;
  p.u = c.u;
  p.accel_free = velocity(free);
  p.angular_accel_free = angular_velocity(free);
  return p;
}

}  // namespace frictionlab::dynamics
